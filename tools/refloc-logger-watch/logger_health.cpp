#include "logger_health.hpp"

#include <fmt/format.h>

namespace refloc {
namespace {

constexpr int8_t kStateOk = 1;     // heartbeat_t::STATE_OK
constexpr int8_t kStateError = 3;  // heartbeat_t::STATE_ERROR
constexpr double kBytesPerMb = 1024.0 * 1024.0;

}  // namespace

LoggerVerdict LoggerHealth::evaluate(const LoggerObservation& seen) {
  const bool changed =
      !have_reference_ || seen.log_file_bytes != reference_bytes_ || seen.log_file_inode != reference_inode_;
  if (changed) {
    have_reference_ = true;
    reference_bytes_ = seen.log_file_bytes;
    reference_inode_ = seen.log_file_inode;
    reference_bus_messages_ = seen.bus_messages;
    unlogged_since_s_ = -1.0;
  }
  // From the first look that saw traffic the file has not caught up with: a quiet bus is no stall.
  if (seen.bus_messages > reference_bus_messages_ && unlogged_since_s_ < 0.0) unlogged_since_s_ = seen.now_s;
  if (seen.free_bytes >= 0 && seen.free_bytes < config_.min_free_bytes) {
    const auto free_mb = static_cast<int64_t>(static_cast<double>(seen.free_bytes) / kBytesPerMb);
    if (seen.free_bytes < 64 * 1024)
      return {kStateError, fmt::format("disk full: {} MB free in {}", free_mb, config_.log_dir_label)};
    return {kStateError,
            fmt::format("disk almost full: {} MB free in {} (minimum {} MB)", free_mb, config_.log_dir_label,
                        static_cast<int64_t>(static_cast<double>(config_.min_free_bytes) / kBytesPerMb))};
  }
  if (!seen.logger_running)
    return {kStateError, "lcm-logger exits: " + (seen.last_exit.empty() ? "not running" : seen.last_exit)};
  if (unlogged_since_s_ >= 0.0 && seen.now_s - unlogged_since_s_ >= config_.stall_s) {
    return {kStateError,
            fmt::format("log not growing: messages on the bus, {} unchanged for {:.0f} s",
                        seen.log_file_bytes < 0 ? "no log file" : "the log file", config_.stall_s)};
  }
  return {kStateOk, ""};
}

}  // namespace refloc

#include <sys/stat.h>
#include <sys/statvfs.h>

namespace refloc {

void probe_log_file(const std::string& log_file, LoggerObservation& seen) {
  struct stat file_stat {};
  if (stat(log_file.c_str(), &file_stat) == 0) {
    seen.log_file_bytes = static_cast<int64_t>(file_stat.st_size);
    seen.log_file_inode = static_cast<uint64_t>(file_stat.st_ino);
  } else {
    seen.log_file_bytes = -1;
    seen.log_file_inode = 0;
  }
  const auto slash = log_file.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : log_file.substr(0, slash + 1);
  struct statvfs fs {};
  seen.free_bytes = statvfs(dir.c_str(), &fs) == 0
                        ? static_cast<int64_t>(fs.f_bavail) * static_cast<int64_t>(fs.f_frsize)
                        : -1;
}

}  // namespace refloc
