#pragma once
// Reading a config or map file without trusting it: only a regular file, at most
// kMaxConfigFileBytes, never blocking on a FIFO or a device.

#include <string>

namespace refloc::json_config_detail {

/// The file's bytes; throws ConfigError naming the file when it is not a regular file, is
/// larger than kMaxConfigFileBytes or cannot be read.
std::string read_bounded_file(const std::string& path);

}  // namespace refloc::json_config_detail
