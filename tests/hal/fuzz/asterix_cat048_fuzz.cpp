// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: arbitrary bytes as one CAT048 record and as a stream of
// ASTERIX data blocks through the CAT048 reader, checking the invariants of
// asterix_cat048_invariants.hpp; a broken invariant aborts with its
// description. Built and run by tests/fuzz (CTest fuzz.asterix_cat048).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>

#include "asterix_cat048_invariants.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> in(data, size);
  const char* why = kestrel::test::check_cat048_record_invariants(in);
  if (why == nullptr) why = kestrel::test::check_cat048_reader_invariants(in);
  if (why != nullptr) {
    std::fprintf(stderr, "CAT048 invariant broken: %s\n", why);
    std::abort();
  }
  return 0;
}
