// SPDX-License-Identifier: Apache-2.0
#include "plots/plot_runner.hpp"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <mutex>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

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

// One Python process (plots/plot_server.py) draws every figure of the
// command, so matplotlib is imported once, not once per figure. Jobs go to
// its stdin as JSON arrays, one per line; each exit status comes back as a
// line on its file descriptor 3. A server that dies fails the job in hand;
// the next job starts a new one.
class PlotServer {
 public:
  PlotServer() = default;
  PlotServer(const PlotServer&) = delete;
  PlotServer& operator=(const PlotServer&) = delete;
  ~PlotServer() { stop(); }

  /// @return the script's exit status, or -1 if the server could not run it.
  int run(const std::vector<std::string>& job) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (jobs_ == nullptr && !start()) return -1;
    std::fflush(stdout);  // what the command printed comes before the script's lines
    if (std::fprintf(jobs_, "%s\n", nlohmann::json(job).dump().c_str()) < 0 || std::fflush(jobs_) != 0) {
      stop();
      return -1;
    }
    char line[32];
    if (std::fgets(line, sizeof line, replies_) == nullptr) {
      stop();
      return -1;
    }
    return std::atoi(line);
  }

 private:
  bool start() {
    std::signal(SIGPIPE, SIG_IGN);  // a dead server is an error return, not the end of kestrel-sim
    const std::string python = env_or("KESTREL_PYTHON", "/usr/bin/python3");
    const std::string server =
        (std::filesystem::path(KESTREL_SIM_PLOT_SCRIPT).parent_path() / "plot_server.py").string();
    int to_child[2];
    int from_child[2];
    if (pipe2(to_child, O_CLOEXEC) != 0) return false;
    if (pipe2(from_child, O_CLOEXEC) != 0) {
      close(to_child[0]);
      close(to_child[1]);
      return false;
    }
    char* const argv[] = {const_cast<char*>(python.c_str()), const_cast<char*>(server.c_str()), nullptr};
    std::fflush(stdout);
    std::fflush(stderr);
    pid_ = fork();
    if (pid_ == 0) {  // child: only async-signal-safe calls until exec
      dup2(to_child[0], STDIN_FILENO);
      if (from_child[1] == 3) {
        fcntl(3, F_SETFD, 0);
      } else {
        dup2(from_child[1], 3);
      }
      execvp(argv[0], argv);
      _exit(127);
    }
    close(to_child[0]);
    close(from_child[1]);
    if (pid_ < 0) {
      close(to_child[1]);
      close(from_child[0]);
      return false;
    }
    jobs_ = fdopen(to_child[1], "w");
    replies_ = fdopen(from_child[0], "r");
    if (jobs_ == nullptr || replies_ == nullptr) {
      if (jobs_ == nullptr) close(to_child[1]);
      if (replies_ == nullptr) close(from_child[0]);
      stop();
      return false;
    }
    return true;
  }

  void stop() {
    if (jobs_ != nullptr) std::fclose(jobs_);  // end of input: the server returns
    if (replies_ != nullptr) std::fclose(replies_);
    jobs_ = nullptr;
    replies_ = nullptr;
    if (pid_ > 0) waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }

  std::mutex mutex_;
  FILE* jobs_ = nullptr;
  FILE* replies_ = nullptr;
  pid_t pid_ = -1;
};

// Every plot script is run here, so all share the interpreter, the server
// and the warning.
bool launch_plot_script(const std::filesystem::path& script, const std::vector<std::string>& args) {
  static PlotServer server;
  std::vector<std::string> job{script.string()};
  job.insert(job.end(), args.begin(), args.end());
  const int status = server.run(job);
  if (status == 0) return true;
  std::string cmd = shell_quote(env_or("KESTREL_PYTHON", "/usr/bin/python3"));
  for (const std::string& a : job) cmd += " " + shell_quote(a);
  std::fprintf(stderr, "warning: plotting failed (%s); results are unaffected. Command: %s\n",
               status < 0 ? "the plot server did not answer" : ("status " + std::to_string(status)).c_str(),
               cmd.c_str());
  return false;
}
}  // namespace

bool run_named_plot_script(const std::string& script_name, const std::vector<std::string>& args) {
  return launch_plot_script(std::filesystem::path(KESTREL_SIM_PLOT_SCRIPT).parent_path() / script_name, args);
}

bool run_plot_script(const std::vector<std::string>& args) {
  return launch_plot_script(env_or("KESTREL_PLOT_SCRIPT", KESTREL_SIM_PLOT_SCRIPT), args);
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
