// SPDX-License-Identifier: Apache-2.0
#include "plots/plot_runner.hpp"

#include <cstdio>
#include <cstdlib>
#include <sys/wait.h>

#ifndef KESTREL_SIM_PLOT_SCRIPT
#error "KESTREL_SIM_PLOT_SCRIPT must name plots/plot_results.py (set by host_sim/CMakeLists.txt)"
#endif

namespace kestrel::sim {

namespace {
// Single-quote for the POSIX shell: ' becomes '\''.
std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (const char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string env_or(const char* name, const char* fallback) {
  const char* v = std::getenv(name);
  return v != nullptr && *v != '\0' ? v : fallback;
}
}  // namespace

bool run_plot_script(const std::vector<std::string>& args) {
  std::string cmd = shell_quote(env_or("KESTREL_PYTHON", "/usr/bin/python3")) + " " +
                    shell_quote(env_or("KESTREL_PLOT_SCRIPT", KESTREL_SIM_PLOT_SCRIPT));
  for (const std::string& a : args) cmd += " " + shell_quote(a);
  std::fflush(stdout);
  const int rc = std::system(cmd.c_str());
  if (rc == 0) return true;
  std::fprintf(stderr, "warning: plotting failed (exit status %d); results are unaffected. Command: %s\n",
               rc != -1 && WIFEXITED(rc) ? WEXITSTATUS(rc) : rc, cmd.c_str());
  return false;
}

bool plot_run(const std::filesystem::path& steps_csv, const std::filesystem::path& tracks_csv,
              const std::filesystem::path& prefix, const std::string& title, double loss_threshold_m) {
  return run_plot_script({"run", "--steps", steps_csv.string(), "--tracks", tracks_csv.string(), "--out-prefix",
                          prefix.string(), "--title", title, "--loss-threshold-m", std::to_string(loss_threshold_m)});
}

bool plot_modes(const std::filesystem::path& modes_csv, const std::filesystem::path& steps_csv,
                const std::filesystem::path& png, const std::string& title) {
  return run_plot_script({"modes", "--modes", modes_csv.string(), "--steps", steps_csv.string(), "--out", png.string(),
                          "--title", title});
}

bool plot_gospa(const std::filesystem::path& steps_csv, const std::filesystem::path& png, const std::string& title) {
  std::error_code ec;
  std::filesystem::remove(png, ec);  // a stale figure must not pass for a new one
  return run_plot_script({"gospa", "--steps", steps_csv.string(), "--out", png.string(), "--title", title}) &&
         std::filesystem::exists(png, ec);
}

bool plot_summary(const std::filesystem::path& summary_json, const std::filesystem::path& png) {
  return run_plot_script({"summary", "--summary", summary_json.string(), "--out", png.string()});
}

}  // namespace kestrel::sim
