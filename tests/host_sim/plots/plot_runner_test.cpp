// SPDX-License-Identifier: Apache-2.0
// The plot launcher (plots/plot_runner.hpp): every figure of a command is
// drawn by one Python process, each job's exit status comes back to its
// caller, and a process that dies fails only the job in hand. A stand-in
// script (through KESTREL_PLOT_SCRIPT) writes the server's pid and exits
// with the status it is given.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "plots/plot_runner.hpp"

namespace {

namespace fs = std::filesystem;
using kestrel::sim::run_plot_script;

// A folder of this test process's own, with the stand-in script in it.
struct StandIn {
  fs::path dir = fs::temp_directory_path() / ("kestrel_plot_runner_" + std::to_string(getpid()));
  fs::path script = dir / "stand_in.py";

  StandIn() {
    fs::create_directories(dir);
    std::ofstream(script) << "import os, sys\n"
                             "if sys.argv[2] == 'die':\n"
                             "    os._exit(0)\n"
                             "if sys.argv[2] == 'raise':\n"
                             "    raise RuntimeError('a bug in a plot script')\n"
                             "with open(sys.argv[1], 'w') as f:\n"
                             "    f.write(str(os.getpid()))\n"
                             "sys.exit(int(sys.argv[2]))\n";
    setenv("KESTREL_PLOT_SCRIPT", script.c_str(), 1);
  }
  ~StandIn() {
    unsetenv("KESTREL_PLOT_SCRIPT");
    unsetenv("KESTREL_PYTHON");
    std::error_code ec;
    fs::remove_all(dir, ec);
  }

  // The job's result, and the pid of the process that ran it ("" if none).
  bool job(const std::string& name, const std::string& how, std::string& pid) const {
    const fs::path out = dir / name;
    const bool ok = run_plot_script({out.string(), how});
    std::ifstream in(out);
    pid.clear();
    std::getline(in, pid);
    return ok;
  }
};

}  // namespace

TEST_CASE("One plot process runs every job and reports each exit status", "[host_sim][plots]") {
  const StandIn s;
  std::string a, b, c;
  CHECK(s.job("a", "0", a));
  CHECK_FALSE(s.job("b", "3", b));  // the script ran and failed
  CHECK_FALSE(s.job("r", "raise", c));
  CHECK(s.job("c", "0", c));
  REQUIRE_FALSE(a.empty());
  CHECK(b == a);  // the same process drew all of them
  CHECK(c == a);
}

TEST_CASE("A plot process that dies fails its job and the next job starts another", "[host_sim][plots]") {
  const StandIn s;
  std::string a, dead, b;
  REQUIRE(s.job("a", "0", a));
  CHECK_FALSE(s.job("dead", "die", dead));
  CHECK(dead.empty());
  REQUIRE(s.job("b", "0", b));
  CHECK(b != a);
}

TEST_CASE("A plot interpreter that cannot start fails the job without ending the command", "[host_sim][plots]") {
  const StandIn s;
  std::string pid;
  CHECK_FALSE(s.job("d", "die", pid));  // a process started before this case is gone
  setenv("KESTREL_PYTHON", (s.dir / "no_such_python").c_str(), 1);
  CHECK_FALSE(s.job("a", "0", pid));
  CHECK(pid.empty());
  unsetenv("KESTREL_PYTHON");
  CHECK(s.job("b", "0", pid));  // a working interpreter again
  CHECK_FALSE(pid.empty());
}
