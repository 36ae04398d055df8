#pragma once
// Start a real service binary from a test and stop it again. The child gets
// its own process group so a kill reaches everything it started, and dies with
// the test process.

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

namespace refloc::testing {

class ChildProcess {
 public:
  ChildProcess() = default;
  /// Start argv[0] with the given arguments; stdout/stderr go to log_path when not empty.
  explicit ChildProcess(const std::vector<std::string>& argv, const std::string& log_path = "") {
    start(argv, log_path);
  }
  ~ChildProcess() { stop(); }
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  bool start(const std::vector<std::string>& argv, const std::string& log_path = "") {
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const pid_t parent = getpid();
    pid_ = fork();
    if (pid_ == 0) {
      // Only async-signal-safe calls between fork and exec.
      setpgid(0, 0);
      // A test that crashes must not leave its services running (they would keep the
      // test's network namespace, and ctest, waiting).
      prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (getppid() != parent) _exit(127);
      if (!log_path.empty()) {
        const int fd = open(log_path.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
        if (fd >= 0) {
          dup2(fd, 1);
          dup2(fd, 2);
          close(fd);
        }
      }
      execv(args[0], args.data());
      _exit(127);
    }
    return pid_ > 0;
  }

  pid_t pid() const { return pid_; }
  bool running() {
    if (pid_ <= 0) return false;
    int status = 0;
    const pid_t r = waitpid(pid_, &status, WNOHANG);
    if (r == pid_) {
      exit_status_ = status;
      pid_ = -1;
      return false;
    }
    return true;
  }

  void signal(int sig) {
    if (pid_ > 0) ::kill(-pid_, sig);
  }

  /// SIGTERM, wait up to timeout, then SIGKILL. Returns the exit code (128+signal if killed).
  int stop(std::chrono::milliseconds timeout = std::chrono::milliseconds(3000)) {
    if (pid_ > 0) {
      signal(SIGTERM);
      const auto deadline = std::chrono::steady_clock::now() + timeout;
      while (running() && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      if (running()) {
        signal(SIGKILL);
        int status = 0;
        waitpid(pid_, &status, 0);
        exit_status_ = status;
        pid_ = -1;
      }
    }
    return exit_code();
  }

  int exit_code() const {
    if (WIFEXITED(exit_status_)) return WEXITSTATUS(exit_status_);
    if (WIFSIGNALED(exit_status_)) return 128 + WTERMSIG(exit_status_);
    return -1;
  }

 private:
  pid_t pid_ = -1;
  int exit_status_ = 0;
};

}  // namespace refloc::testing
