// Format-2 map files (docs/map-format.md), written so that loading gives back the same doubles.

#include "common/json_config.hpp"
#include "common/reflector_map.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <map>
#include <stdexcept>

namespace refloc {
namespace {

// fmt's "{}" is the shortest text that reads back as the same double (1.5, 0.1, 1e-06).
std::string number(double v) { return fmt::format("{}", v); }

std::string quoted(const std::string& text) { return nlohmann::json(text).dump(); }

// The radius most reflectors share becomes default_radius_m, so a line names only exceptions.
double most_common_radius(const std::vector<MapReflector>& reflectors) {
  std::map<double, int> count;
  for (const MapReflector& r : reflectors) ++count[r.radius];
  double best = 0.06;
  int best_count = 0;
  for (const auto& [radius, n] : count) {
    if (n > best_count) best = radius, best_count = n;
  }
  return best;
}

std::string reflector_text(const MapReflector& r, double default_radius) {
  std::string text = fmt::format(R"({{"id": {}, "x": {}, "y": {})", r.id, number(r.map_p_center.x()),
                                 number(r.map_p_center.y()));
  if (r.radius != default_radius) text += fmt::format(R"(, "radius_m": {})", number(r.radius));
  if (!r.type.empty()) text += R"(, "type": )" + quoted(r.type);
  if (r.map_cov_center) {
    const Eigen::Matrix2d& c = *r.map_cov_center;
    // The file holds one off-diagonal term; the mean of two equal doubles is that double.
    text += fmt::format(R"(, "covariance_m2": [{}, {}, {}])", number(c(0, 0)),
                        number(0.5 * (c(0, 1) + c(1, 0))), number(c(1, 1)));
  }
  return text + "}";
}

std::string occluder_text(const MapOccluder& o) {
  std::string points;
  for (const Eigen::Vector2d& p : o.map_points)
    points += fmt::format("{}[{}, {}]", points.empty() ? "" : ", ", number(p.x()), number(p.y()));
  return fmt::format(R"({{"name": {}, "closed": {}, "points": [{}]}})", quoted(o.name),
                     o.closed ? "true" : "false", points);
}

template <typename T, typename Text>
std::string json_list(const std::vector<T>& items, const Text& text_of) {
  if (items.empty()) return "[]";
  std::string text = "[\n";
  for (size_t i = 0; i < items.size(); ++i)
    text += "    " + text_of(items[i]) + (i + 1 < items.size() ? ",\n" : "\n");
  return text + "  ]";
}

void write_all(int fd, const std::string& text) {
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error(std::strerror(n < 0 ? errno : EIO));
    done += static_cast<size_t>(n);
  }
}

}  // namespace

std::string iso8601_utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

std::string reflector_map_v2_text(const ReflectorMap& map) {
  const double default_radius = most_common_radius(map.reflectors);
  const std::string created = map.info.created.empty() ? iso8601_utc_now() : map.info.created;
  return fmt::format(
      "{{\n  \"format\": 2,\n  \"map_id\": {},\n  \"version\": {},\n  \"created\": {},\n  \"source\": {},\n"
      "  \"default_radius_m\": {},\n  \"reflectors\": {},\n  \"occluders\": {}\n}}\n",
      quoted(map.info.map_id), map.info.version, quoted(created), quoted(map.info.source),
      number(default_radius),
      json_list(map.reflectors, [&](const MapReflector& r) { return reflector_text(r, default_radius); }),
      json_list(map.occluders, occluder_text));
}

void write_reflector_map(const ReflectorMap& map, const std::string& path) {
  const std::string text = reflector_map_v2_text(map);
  // A map that would not load is not written: the reader's validation, run on the text.
  const JsonConfig check = JsonConfig::parse_text(text, path + " (not written)");
  parse_reflector_map(check);
  check.reject_unknown_keys();
  if (text.size() > kMaxConfigFileBytes) {
    throw ConfigError(fmt::format("{} (not written): {} bytes, more than a map file may hold ({})", path,
                                  text.size(), kMaxConfigFileBytes));
  }
  // Same directory, so the rename is atomic: a reader sees the old map or the new one.
  const std::string temporary = fmt::format("{}.tmp-{}", path, ::getpid());
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0)
    throw std::runtime_error(fmt::format("{}: cannot write the map: {}", temporary, std::strerror(errno)));
  std::string failure;
  try {
    write_all(fd, text);
    if (::fsync(fd) != 0) failure = std::strerror(errno);
  } catch (const std::runtime_error& e) {
    failure = e.what();
  }
  if (::close(fd) != 0 && failure.empty()) failure = std::strerror(errno);
  if (!failure.empty()) {
    ::unlink(temporary.c_str());
    throw std::runtime_error(fmt::format("{}: cannot write the map: {}", temporary, failure));
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    ::unlink(temporary.c_str());
    throw std::runtime_error(fmt::format("{}: cannot write the map: rename: {}", path, reason));
  }
}

}  // namespace refloc
