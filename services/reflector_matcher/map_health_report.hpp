#pragma once
// What the matcher's map evidence says, as plain data: the content of one MAP_HEALTH message
// (map_health_t), made by MapEvidence and read back by `refloc-map update`.

#include <Eigen/Core>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace refloc {

/// Same values as map_reflector_health_t::STATE_*.
enum class ReflectorHealth : int8_t { kOk = 0, kMissing = 1, kMoved = 2, kUnconfirmed = 3 };

inline const char* reflector_health_name(ReflectorHealth h) {
  switch (h) {
    case ReflectorHealth::kOk:
      return "ok";
    case ReflectorHealth::kMissing:
      return "missing";
    case ReflectorHealth::kMoved:
      return "moved";
    case ReflectorHealth::kUnconfirmed:
      return "unconfirmed";
  }
  return "?";
}

struct ReflectorHealthEntry {
  int id = 0;
  ReflectorHealth state = ReflectorHealth::kUnconfirmed;
  Eigen::Vector2d map_p = Eigen::Vector2d::Zero();  ///< the mapped centre [m]
  int seen = 0;                                     ///< matched, in its evidence window
  int expected_missing = 0;                         ///< expected with a clear sight, unseen, in the window
  /// Seen minus mapped position [m] (moved: the correction); zero without an estimate.
  Eigen::Vector2d offset = Eigen::Vector2d::Zero();
  Eigen::Vector2d offset_sigma = Eigen::Vector2d::Zero();  ///< std dev per axis [m]; 0: no estimate
};

struct MapCandidate {
  Eigen::Vector2d map_p = Eigen::Vector2d::Zero();  ///< estimated centre [m]
  Eigen::Vector2d sigma = Eigen::Vector2d::Zero();  ///< std dev per axis [m]
  int sightings = 0;
  double viewpoint_spread = 0.0;  ///< largest distance between the laser positions it was seen from [m]
  int moved_reflector_id = -1;    ///< the missing map reflector it replaces, or -1: a new reflector
  int64_t key = 0;                ///< stays the same for one cluster while it exists (not published)
};

struct MapHealthReport {
  int64_t utime = 0;  ///< [us]
  std::string map_id;
  int map_version = 0;
  int64_t scans_used = 0;                        ///< OK scans fed since start
  std::vector<ReflectorHealthEntry> reflectors;  ///< in map order
  std::vector<MapCandidate> candidates;

  int count(ReflectorHealth state) const {
    return static_cast<int>(
        std::count_if(reflectors.begin(), reflectors.end(),
                      [state](const ReflectorHealthEntry& r) { return r.state == state; }));
  }
  /// Calls set(name, value) for each heartbeat counter: reflectors_missing, reflectors_moved,
  /// map_candidates (new reflectors).
  template <class Set>
  void for_each_counter(Set&& set) const {
    set("reflectors_missing", count(ReflectorHealth::kMissing));
    set("reflectors_moved", count(ReflectorHealth::kMoved));
    set("map_candidates", new_candidates());
  }
  /// Candidates that are new reflectors (not a missing one's new place).
  int new_candidates() const {
    return static_cast<int>(std::count_if(candidates.begin(), candidates.end(),
                                          [](const MapCandidate& c) { return c.moved_reflector_id < 0; }));
  }
};

}  // namespace refloc
