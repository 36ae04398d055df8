#pragma once
// The lcm-logger child of refloc-logger-watch: started, watched, restarted with a
// growing delay, stopped with SIGINT (lcm-logger then closes its file). Its stderr
// passes through to ours, and its last line is kept for the reason of an exit.
// No LCM in here.

#include <sys/types.h>

#include <string>
#include <vector>

namespace refloc {

/// "exit 3", "killed by signal 9 (Killed)", ... from a waitpid status.
std::string describe_wait_status(int status);

class ChildProcess {
 public:
  /// argv[0] is looked up in PATH. The child dies with us (PR_SET_PDEATHSIG).
  explicit ChildProcess(std::vector<std::string> argv);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  /// Start it; false (and last_exit() says why) when fork or exec failed.
  bool start();
  /// Reap it if it ended and copy its stderr through; true while it runs.
  bool poll();
  bool running() const { return pid_ > 0; }
  pid_t pid() const { return pid_; }
  /// How it last ended: "exit 1: <last stderr line>"; "" while it never ended.
  const std::string& last_exit() const { return last_exit_; }
  int exits() const { return exits_; }
  /// Start it now, or restart it after it ended: 1 s after a run of kLongRunS or more,
  /// doubling (to kMaxRestartDelayS) while it keeps ending sooner. now_s: monotonic [s].
  void keep_running(double now_s);
  /// SIGINT, then SIGKILL after grace_s [s].
  void stop(double grace_s = 2.0);

 private:
  void drain_stderr();

  std::vector<std::string> argv_;
  pid_t pid_ = -1;
  int stderr_fd_ = -1;
  std::string partial_line_;
  std::string last_line_;
  std::string last_exit_;
  int exits_ = 0;
  int exits_handled_ = 0;  ///< exits keep_running has scheduled a restart for
  double started_s_ = 0.0;
  double next_start_s_ = 0.0;
  double restart_delay_s_ = kMinRestartDelayS;

 public:
  static constexpr double kMinRestartDelayS = 1.0;
  static constexpr double kMaxRestartDelayS = 16.0;
  static constexpr double kLongRunS = 10.0;
};

}  // namespace refloc
