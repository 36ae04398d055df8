#include "common/bounded_file_read.hpp"

#include "common/json_config.hpp"
#include "common/json_config_nesting.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace refloc::json_config_detail {
namespace {

const char* file_kind(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

}  // namespace

// Reads at most kMaxConfigFileBytes of a regular file. O_NONBLOCK: opening a FIFO must not
// wait for a writer; fstat on the open descriptor, so the file checked is the file read.
std::string read_bounded_file(const std::string& path) {
  const std::string name = printable(path, 400);
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) throw ConfigError(fmt::format("{}: cannot open the file: {}", name, std::strerror(errno)));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0)
    throw ConfigError(fmt::format("{}: cannot open the file: {}", name, std::strerror(errno)));
  if (!S_ISREG(st.st_mode))
    throw ConfigError(
        fmt::format("{}: is {}; config and map files must be regular files", name, file_kind(st.st_mode)));
  const auto too_big = [&] {
    return ConfigError(
        fmt::format("{}: larger than {} bytes; config and map files are smaller", name, kMaxConfigFileBytes));
  };
  if (static_cast<unsigned long long>(st.st_size) > kMaxConfigFileBytes) throw too_big();
  std::string text(kMaxConfigFileBytes + 1, '\0');
  size_t used = 0;
  while (used < text.size()) {  // the size may have changed since fstat (or be 0 in /proc)
    const ssize_t n = ::read(fd, text.data() + used, text.size() - used);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw ConfigError(fmt::format("{}: cannot read the file: {}", name, std::strerror(errno)));
    if (n == 0) break;
    used += static_cast<size_t>(n);
  }
  if (used > kMaxConfigFileBytes) throw too_big();
  text.resize(used);
  return text;
}

}  // namespace refloc::json_config_detail
