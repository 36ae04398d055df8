// refloc-map update's evidence: the last MAP_HEALTH about the map in an LCM log.

#include "map_update.hpp"

#include "common/json_config.hpp"
#include "common/lcm_bounded_decode.hpp"
#include "reflector_matcher/map_health_messages.hpp"

#include <fmt/format.h>
#include <lcm/lcm-cpp.hpp>

#include <filesystem>
#include <map>

namespace refloc {

MapHealthReport last_map_health(const std::string& path, const std::string& channel,
                                const ReflectorMap& map) {
  if (!std::filesystem::is_regular_file(path)) throw ConfigError(fmt::format("{}: no such log file", path));
  lcm::LogFile log(path, "r");
  if (!log.good()) throw ConfigError(fmt::format("{}: cannot be read as an LCM log", path));
  std::optional<MapHealthReport> last;
  std::map<std::pair<std::string, int>, int> other_maps;  // (map id, version) -> messages
  int undecodable = 0;
  map_health_t message;
  for (const lcm::LogEvent* e = log.readNextEvent(); e != nullptr; e = log.readNextEvent()) {
    if (e->channel != channel) continue;
    if (!decode_lcm_bounded(e->data, static_cast<size_t>(e->datalen), message).ok) {
      ++undecodable;
      continue;
    }
    if (message.map_id == map.info.map_id && message.map_version == map.info.version) {
      last = from_message(message);
    } else {
      ++other_maps[{message.map_id, message.map_version}];
    }
  }
  if (last) return *last;
  std::string others;
  for (const auto& [id, count] : other_maps)
    others += fmt::format("{}\"{}\" version {} ({} messages)", others.empty() ? "" : ", ", id.first,
                          id.second, count);
  if (!others.empty()) {
    throw ConfigError(
        fmt::format("{}: {} holds evidence for map {}, none for \"{}\" version {}: refusing to "
                    "update this map from another map's evidence",
                    path, channel, others, map.info.map_id, map.info.version));
  }
  throw ConfigError(fmt::format("{}: no {} message (map_health_t){}", path, channel,
                                undecodable > 0 ? fmt::format(", {} that do not decode", undecodable) : ""));
}

}  // namespace refloc
