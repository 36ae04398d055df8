#include "child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <thread>

namespace refloc {

std::string describe_wait_status(int status) {
  if (WIFEXITED(status)) return "exit " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status))
    return "killed by signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
  return "status " + std::to_string(status);
}

ChildProcess::ChildProcess(std::vector<std::string> argv) : argv_(std::move(argv)) {}

ChildProcess::~ChildProcess() {
  if (running()) stop(0.5);
  if (stderr_fd_ >= 0) close(stderr_fd_);
}

bool ChildProcess::start() {
  if (running() || argv_.empty()) return running();
  int pipe_fds[2];
  if (pipe2(pipe_fds, O_CLOEXEC) != 0) {
    last_exit_ = std::string("cannot start: pipe: ") + std::strerror(errno);
    return false;
  }
  // Everything the child needs is built before fork: after it only async-signal-safe calls.
  std::vector<char*> args;
  for (auto& a : argv_) args.push_back(a.data());
  args.push_back(nullptr);
  static const char kExecFailed[] = "refloc-logger-watch: cannot execute the logger command\n";
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    last_exit_ = std::string("cannot start: fork: ") + std::strerror(errno);
    close(pipe_fds[0]);
    close(pipe_fds[1]);
    return false;
  }
  if (pid == 0) {
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(127);  // the parent died before prctl took effect
    dup2(pipe_fds[1], STDERR_FILENO);
    execvp(args[0], args.data());
    (void)!write(STDERR_FILENO, kExecFailed, sizeof kExecFailed - 1);
    _exit(127);
  }
  close(pipe_fds[1]);
  if (stderr_fd_ >= 0) close(stderr_fd_);
  stderr_fd_ = pipe_fds[0];
  fcntl(stderr_fd_, F_SETFL, O_NONBLOCK);
  pid_ = pid;
  last_line_.clear();
  partial_line_.clear();
  return true;
}

void ChildProcess::drain_stderr() {
  if (stderr_fd_ < 0) return;
  char buffer[4096];
  for (;;) {
    const ssize_t n = read(stderr_fd_, buffer, sizeof buffer);
    if (n <= 0) return;  // EAGAIN: nothing more now; 0: the child closed it
    (void)!write(STDERR_FILENO, buffer, static_cast<size_t>(n));
    partial_line_.append(buffer, static_cast<size_t>(n));
    size_t newline;
    while ((newline = partial_line_.find('\n')) != std::string::npos) {
      if (newline > 0) last_line_ = partial_line_.substr(0, newline);
      partial_line_.erase(0, newline + 1);
    }
    // A child that never ends its line must not grow us without bound.
    if (partial_line_.size() > 4096) partial_line_.erase(0, partial_line_.size() - 4096);
  }
}

bool ChildProcess::poll() {
  drain_stderr();
  if (!running()) return false;
  int status = 0;
  if (waitpid(pid_, &status, WNOHANG) != pid_) return true;
  drain_stderr();
  if (!partial_line_.empty()) last_line_ = partial_line_;
  last_exit_ = describe_wait_status(status) + (last_line_.empty() ? "" : ": " + last_line_);
  pid_ = -1;
  ++exits_;
  return false;
}

void ChildProcess::keep_running(double now_s) {
  if (poll()) return;
  if (exits_ > exits_handled_) {
    exits_handled_ = exits_;
    // Ran long enough: it was a fault, not a start-up failure; come back soon.
    const bool ran_long = now_s - started_s_ >= kLongRunS;
    restart_delay_s_ = ran_long ? kMinRestartDelayS : std::min(kMaxRestartDelayS, 2.0 * restart_delay_s_);
    next_start_s_ = now_s + restart_delay_s_;
  }
  if (now_s < next_start_s_) return;
  started_s_ = now_s;
  if (!start()) {
    restart_delay_s_ = std::min(kMaxRestartDelayS, 2.0 * restart_delay_s_);
    next_start_s_ = now_s + restart_delay_s_;
  }
}

void ChildProcess::stop(double grace_s) {
  if (!running()) return;
  kill(pid_, SIGINT);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(grace_s);
  while (poll() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  if (running()) {
    kill(pid_, SIGKILL);
    int status = 0;
    waitpid(pid_, &status, 0);
    pid_ = -1;
  }
}

}  // namespace refloc
