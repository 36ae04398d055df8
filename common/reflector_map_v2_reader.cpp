#include "common/reflector_map_v2_reader.hpp"

#include "common/json_config.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <set>

namespace refloc {
namespace {

// Variance up to (100 m)^2: no survey is worse; a larger number is mm^2 written as m^2.
constexpr double kMaxVariance_m2 = 1e4;
constexpr size_t kMaxNameLength = 200;

void refuse_in_format_1(const JsonConfig& config, const std::string& pointer, int format) {
  if (format != 1 || !config.has(pointer)) return;
  config.fail(pointer,
              "a format-2 key in a format-1 map: add \"format\": 2 (and map_id, version, created, "
              "source) to the file, see docs/map-format.md");
}

std::string required_text(const JsonConfig& config, const ConfigKey& key, const std::string& expected) {
  if (!config.has(key.pointer)) config.fail(key.pointer, "missing; expected " + expected);
  const std::string text = config.string(key, "");
  const bool control = std::any_of(text.begin(), text.end(), [](char c) { return c >= 0 && c < 0x20; });
  if (text.empty() || text.size() > kMaxNameLength || control) {
    config.fail(key.pointer, fmt::format("expected {} (1 to {} characters, no control characters), got {}",
                                         expected, kMaxNameLength, nlohmann::json(text).dump()));
  }
  return text;
}

Eigen::Matrix2d read_covariance(const JsonConfig& config, const std::string& pointer) {
  const size_t n =
      config.array_size({pointer, "m^2",
                         "covariance of the centre in the map frame [xx, xy, yy], symmetric "
                         "positive definite (refloc-survey, or a stated sigma); absent: unknown"},
                        false);
  if (n != 3) config.fail(pointer, fmt::format("expected [xx, xy, yy], got an array of {}", n));
  const double xx = config.required_number(
      {pointer + "/0", "m^2", "xx, xy, yy in that order: variance of x, covariance x-y, variance of y"},
      -kMaxVariance_m2, kMaxVariance_m2);
  const double xy = config.required_number(pointer + "/1", -kMaxVariance_m2, kMaxVariance_m2);
  const double yy = config.required_number(pointer + "/2", -kMaxVariance_m2, kMaxVariance_m2);
  // xy^2 < xx yy without forming the determinant, which underflows for tiny variances.
  if (!(xx > 0.0 && yy > 0.0 && std::fabs(xy) < std::sqrt(xx) * std::sqrt(yy))) {
    config.fail(pointer,
                fmt::format("expected a positive definite covariance (xx > 0, yy > 0, xy^2 < xx*yy), "
                            "got [{}, {}, {}]",
                            xx, xy, yy));
  }
  Eigen::Matrix2d cov;
  cov << xx, xy, xy, yy;
  return cov;
}

Eigen::Vector2d read_point(const JsonConfig& config, const std::string& pointer) {
  const size_t n = config.array_size({pointer, "m", "a corner [x, y] in the map frame"});
  if (n != 2) config.fail(pointer, fmt::format("expected a point [x, y], got an array of {}", n));
  return {config.required_number({pointer + "/0", "m", "x, then y, of the corner in the map frame"},
                                 -kMaxMapCoordinate_m, kMaxMapCoordinate_m),
          config.required_number(pointer + "/1", -kMaxMapCoordinate_m, kMaxMapCoordinate_m)};
}

MapOccluder read_occluder(const JsonConfig& config, const std::string& item) {
  MapOccluder occluder;
  occluder.name = required_text(config, {item + "/name", "", "what it is, for people and logs (\"rack 1\")"},
                                "a name for the occluder");
  occluder.closed = config.boolean(
      {item + "/closed", "", "true: the last point joins the first (a room, a rack's outline)"}, false);
  const std::string points = item + "/points";
  const size_t count = config.array_size(
      {points, "m", "the polyline's corners [[x, y], ...] in the map frame: at least 2, 3 when closed"});
  if (count < 2) config.fail(points, fmt::format("expected at least 2 points, got {}", count));
  if (occluder.closed && count < 3)
    config.fail(item + "/closed", "a closed polyline needs at least 3 points");
  for (size_t k = 0; k < count; ++k) {
    const std::string point = fmt::format("{}/{}", points, k);
    occluder.map_points.push_back(read_point(config, point));
    if (k > 0 && (occluder.map_points[k] - occluder.map_points[k - 1]).norm() < 1e-6)
      config.fail(point, "repeats the previous point (a zero-length segment)");
  }
  return occluder;
}

}  // namespace

bool is_iso8601_utc(const std::string& text) {
  static const std::regex pattern(R"((\d{4})-(\d{2})-(\d{2})T(\d{2}):(\d{2}):(\d{2})(\.\d{1,9})?Z)");
  std::smatch m;
  if (!std::regex_match(text, m, pattern)) return false;
  const int year = std::stoi(m[1]);
  const int month = std::stoi(m[2]);
  const int day = std::stoi(m[3]);
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  const int days_in_month[] = {31, leap ? 29 : 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (month < 1 || month > 12 || day < 1 || day > days_in_month[month - 1]) return false;
  // Second 60: a leap second, as ISO 8601 allows.
  return std::stoi(m[4]) <= 23 && std::stoi(m[5]) <= 59 && std::stoi(m[6]) <= 60;
}

MapInfo read_map_info(const JsonConfig& config, const std::string& pointer) {
  MapInfo info;
  info.format = static_cast<int>(config.integer(
      {pointer + "/format", "",
       "file format: 2 for this header, reflector type and covariance, occluders; absent or 1: "
       "reflectors only (the first format, still read)"},
      1, 1, 2));
  for (const char* key : {"/map_id", "/version", "/created", "/source"})
    refuse_in_format_1(config, pointer + key, info.format);
  if (info.format == 1) return info;
  info.map_id =
      required_text(config,
                    {pointer + "/map_id", "",
                     "required in format 2: names the hall or layout; the same in every version of this map"},
                    "a map id naming the hall or layout");
  const std::string version = pointer + "/version";
  info.version = static_cast<int>(config.required_integer(
      {version, "",
       "required in format 2: revision of this map: 1 when first written, +1 for each refloc-map update"},
      1, 1000000000));
  const std::string created = pointer + "/created";
  if (!config.has(created))
    config.fail(created, "missing; expected an ISO 8601 UTC time like 2026-12-03T06:30:58Z");
  info.created = config.string(
      {created, "",
       "required in format 2: when the file was written, ISO 8601 UTC: YYYY-MM-DDTHH:MM:SS[.fraction]Z"},
      "");
  if (!is_iso8601_utc(info.created)) {
    config.fail(created, fmt::format("expected an ISO 8601 UTC time like 2026-12-03T06:30:58Z, got {}",
                                     nlohmann::json(info.created).dump()));
  }
  const std::string source = pointer + "/source";
  if (!config.has(source))
    config.fail(source, "missing; expected typed, imported, surveyed, updated or merged");
  info.source = config.choice(
      {source, "",
       "required in format 2: where the positions come from: typed (by hand), imported (refloc-map import, "
       "e.g. a total station), surveyed (refloc-survey), updated (refloc-map update), merged (refloc-map "
       "merge)"},
      "typed", {"typed", "imported", "surveyed", "updated", "merged"});
  return info;
}

void read_reflector_v2_keys(const JsonConfig& config, const std::string& item, int format, MapReflector& r) {
  refuse_in_format_1(config, item + "/type", format);
  refuse_in_format_1(config, item + "/covariance_m2", format);
  if (format == 1) return;
  r.type = config.string({item + "/type", "",
                          "reflector kind, free text for people and tools (\"cylinder_120\"); the radius is "
                          "radius_m, not derived from it"},
                         "");
  if (config.has(item + "/covariance_m2"))
    r.map_cov_center = read_covariance(config, item + "/covariance_m2");
}

std::vector<MapOccluder> read_occluders(const JsonConfig& config, const std::string& pointer, int format) {
  const std::string list = pointer + "/occluders";
  refuse_in_format_1(config, list, format);
  std::vector<MapOccluder> occluders;
  if (format == 1) return occluders;
  const size_t n = config.array_size({list, "",
                                      "walls, racks, pillars the laser cannot see through: [{name, points, "
                                      "closed}]; no reflector is expected behind one. Absent: none"},
                                     false);
  for (size_t i = 0; i < n; ++i) occluders.push_back(read_occluder(config, fmt::format("{}/{}", list, i)));
  return occluders;
}

}  // namespace refloc
