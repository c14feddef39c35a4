// SPDX-License-Identifier: Apache-2.0
// Catch2 v2 main for every test executable, with a listener that appends the
// name of every case it runs to $KESTREL_CASE_LOG when that is set (CTest
// sets it; tools/ci/check_cases_ran.py compares the log with the listing).
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

class CaseLog : public Catch::TestEventListenerBase {
 public:
  using TestEventListenerBase::TestEventListenerBase;
  void testCaseStarting(const Catch::TestCaseInfo& info) override {
    const char* path = std::getenv("KESTREL_CASE_LOG");
    if (path == nullptr || *path == '\0') return;
    // One fputs of one line on a file opened for append: parallel CTest
    // processes add whole lines.
    const std::string line = info.name + "\n";
    if (std::FILE* f = std::fopen(path, "a")) {
      std::fputs(line.c_str(), f);
      std::fclose(f);
    }
  }
};

}  // namespace

CATCH_REGISTER_LISTENER(CaseLog)
