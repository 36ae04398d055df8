#pragma once
// Evidence about the map gathered while localizing, fed once per OK scan with what the matcher
// decided: which map reflectors were seen and where, which detections no map reflector
// explains, which reflectors were expected (in view, clear line of sight) but not seen. From
// it: per reflector ok / missing / moved / unconfirmed, and candidates (unmapped reflectors seen
// repeatedly at one place). Windows count scans, not seconds, so the evidence about a corner
// stays while the robot is elsewhere.

#include "reflector_matcher/map_health_config.hpp"
#include "reflector_matcher/map_health_report.hpp"

#include "common/reflector_map.hpp"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace refloc {

/// A map reflector matched in one OK scan.
struct ReflectorSighting {
  int map_index = -1;
  /// The detection's centre in the map frame [m]; with has_offset, from a pose fitted to the
  /// scan's other matches, so a moved reflector does not drag the pose it is measured from.
  Eigen::Vector2d map_p = Eigen::Vector2d::Zero();
  bool has_offset = false;  ///< the scan had >= 3 other matches to fit that pose
};

/// What one OK scan says about the map (scan_evidence.hpp builds it from a MatchResult).
struct ScanEvidence {
  int64_t utime = 0;                                      ///< [us]
  Eigen::Vector2d map_p_laser = Eigen::Vector2d::Zero();  ///< the viewpoint [m]
  std::vector<ReflectorSighting> seen;
  std::vector<Eigen::Vector2d> unmapped;  ///< detections no map reflector explains, map frame [m]
  std::vector<int> expected_unseen;       ///< map indices expected with a clear line of sight, unseen
};

class MapEvidence {
 public:
  /// map must outlive this object.
  MapEvidence(const ReflectorMap& map, const MapHealthConfig& config);

  void add(const ScanEvidence& scan);
  /// The states now (map order) and the candidates; out's vectors are reused.
  void report(int64_t utime, MapHealthReport& out) const;
  int64_t scans_used() const { return scans_used_; }

 private:
  /// Running sums of 2D points (about the first, so far from the origin a small scatter is
  /// not lost to rounding): their mean and scatter.
  struct PointSums {
    int n = 0;
    Eigen::Vector2d origin = Eigen::Vector2d::Zero();
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    Eigen::Matrix2d sum_outer = Eigen::Matrix2d::Zero();
    void add(const Eigen::Vector2d& p);
    Eigen::Vector2d mean() const { return origin + sum / n; }
    Eigen::Matrix2d covariance() const;  ///< population covariance of the points [m^2]
  };
  struct ReflectorTrack {
    std::vector<unsigned char> window;  ///< ring of the last expectations: 1 seen, 0 unseen
    int window_next = 0;
    int window_seen = 0;
    std::vector<Eigen::Vector2d> offsets;  ///< ring of the last sightings' offsets [m]
    int offsets_next = 0;
    /// Where the laser was when the reflector was first expected and unseen since its last
    /// sighting, and the farthest it got from there [m].
    Eigen::Vector2d unseen_from = Eigen::Vector2d::Zero();
    double unseen_spread = -1.0;  ///< -1: seen since (or never expected)
  };
  /// The last sightings of a cluster, for a spread that a few stray ones do not inflate.
  struct RecentPoints {
    static constexpr int kSize = 64;
    std::array<Eigen::Vector2d, kSize> ring{};
    int n = 0;     ///< filled entries
    int next = 0;  ///< where the next one goes
    void add(const Eigen::Vector2d& p);
    /// Robust standard deviation per axis of the points (median distance from the
    /// component-wise median / 1.1774, the Rayleigh median of a 2-D Gaussian) [m].
    double robust_sigma() const;
  };
  struct Cluster {
    PointSums points;
    RecentPoints recent_points;
    RecentPoints recent_fronts;
    /// The sightings moved candidate_radius toward the laser: where a flat strip's face would be.
    /// A cylinder's centres scatter less than these, a strip's more.
    PointSums fronts;
    Eigen::Vector2d first_viewpoint = Eigen::Vector2d::Zero();
    double viewpoint_spread = 0.0;
    double first_view_angle = 0.0;  ///< direction from the cluster to the laser, first sighting [rad]
    double view_angle_low = 0.0;    ///< the others' directions relative to it [rad]
    double view_angle_high = 0.0;
    int64_t last_utime = 0;
    int64_t key = 0;
  };

  void push_expectation(ReflectorTrack& t, bool seen) const;
  void push_offset(ReflectorTrack& t, const Eigen::Vector2d& offset) const;
  void add_unmapped(const Eigen::Vector2d& map_p, const Eigen::Vector2d& map_p_laser, int64_t utime);
  /// kCandidate: sightings, viewpoint spread, scatter, view span and the face test all pass;
  /// kMovedPlace: all but the view span and face test, seen over moved_min_view_angle: good enough
  /// for the new place of a reflector that went missing near it (never reported alone).
  enum class ClusterStanding { kNone, kMovedPlace, kCandidate };
  ClusterStanding standing(const Cluster& c) const;
  MapCandidate candidate_of(const Cluster& c) const;
  ReflectorHealthEntry entry(size_t index) const;
  /// moved_places: the clusters of standing kMovedPlace, claimed only by a missing
  /// reflector near them (then reported as candidates).
  void attach_candidates(MapHealthReport& out, const std::vector<MapCandidate>& moved_places) const;

  const ReflectorMap& map_;
  MapHealthConfig config_;
  std::vector<ReflectorTrack> tracks_;  ///< one per map reflector
  std::vector<Cluster> clusters_;
  int64_t next_cluster_key_ = 1;
  int64_t scans_used_ = 0;
};

}  // namespace refloc
