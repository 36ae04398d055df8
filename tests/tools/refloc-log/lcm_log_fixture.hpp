#pragma once
// Writing LCM log files in tests with LCM's own writer (lcm::LogFile), so the
// reader under test sees exactly what lcm-logger would have written.

#include <gtest/gtest.h>
#include <unistd.h>
#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace refloc::testing {

class LcmLogWriter {
 public:
  explicit LcmLogWriter(const std::string& path) : log_(std::make_unique<lcm::LogFile>(path, "w")) {}
  bool good() const { return log_->good(); }

  /// Log an encoded message as received at log_utime [us].
  template <class Message>
  void write(const std::string& channel, int64_t log_utime, Message message) {
    std::vector<uint8_t> bytes(static_cast<size_t>(message.getEncodedSize()));
    message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    write_raw(channel, log_utime, bytes);
  }

  void write_raw(const std::string& channel, int64_t log_utime, std::vector<uint8_t> bytes) {
    lcm::LogEvent e{};
    e.timestamp = log_utime;
    e.channel = channel;
    e.datalen = static_cast<int32_t>(bytes.size());
    e.data = bytes.data();
    log_->writeEvent(&e);
  }

 private:
  std::unique_ptr<lcm::LogFile> log_;
};

/// A fresh file path under the test temp dir.
inline std::string temp_path(const std::string& name) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return ::testing::TempDir() + "refloc_ops_" + std::to_string(getpid()) + "_" + info->name() + "_" + name;
}

inline std::vector<std::string> read_lines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

inline std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream ss(text);
  for (std::string part; std::getline(ss, part, separator);) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.emplace_back();
  return parts;
}

/// Start of the test logs' time axis [us] (2024-01-01).
constexpr int64_t kT0 = 1'704'067'200'000'000;

}  // namespace refloc::testing
