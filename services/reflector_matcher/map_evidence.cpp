#include "reflector_matcher/map_evidence.hpp"

#include "common/angles.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>

namespace refloc {
namespace {

// The larger standard deviation of a 2x2 covariance: its largest eigenvalue's root [m].
double major_sigma(const Eigen::Matrix2d& c) {
  const double mean = 0.5 * (c(0, 0) + c(1, 1));
  const double half_difference = 0.5 * (c(0, 0) - c(1, 1));
  return std::sqrt(std::max(0.0, mean + std::hypot(half_difference, c(0, 1))));
}

// Covariance of the mean of n points with the given scatter, plus the floor on each axis [m^2].
Eigen::Matrix2d mean_covariance(const Eigen::Matrix2d& scatter, int n, double floor) {
  return scatter / n + floor * floor * Eigen::Matrix2d::Identity();
}

Eigen::Vector2d axis_sigmas(const Eigen::Matrix2d& c) { return {std::sqrt(c(0, 0)), std::sqrt(c(1, 1))}; }

}  // namespace

void MapEvidence::PointSums::add(const Eigen::Vector2d& p) {
  if (n++ == 0) origin = p;
  sum += p - origin;
  sum_outer += (p - origin) * (p - origin).transpose();
}

void MapEvidence::RecentPoints::add(const Eigen::Vector2d& p) {
  ring[static_cast<size_t>(next)] = p;
  next = (next + 1) % kSize;
  n = std::min(n + 1, kSize);
}

double MapEvidence::RecentPoints::robust_sigma() const {
  if (n == 0) return 0.0;
  std::array<double, kSize> values{};
  const auto median = [&](int count) {
    const auto middle = values.begin() + count / 2;
    std::nth_element(values.begin(), middle, values.begin() + count);
    return *middle;
  };
  Eigen::Vector2d center;
  for (int axis = 0; axis < 2; ++axis) {
    for (int i = 0; i < n; ++i) values[static_cast<size_t>(i)] = ring[static_cast<size_t>(i)][axis];
    center[axis] = median(n);
  }
  for (int i = 0; i < n; ++i) values[static_cast<size_t>(i)] = (ring[static_cast<size_t>(i)] - center).norm();
  return median(n) / 1.1774;
}

Eigen::Matrix2d MapEvidence::PointSums::covariance() const {
  const Eigen::Vector2d m = sum / n;
  Eigen::Matrix2d c = sum_outer / n - m * m.transpose();
  c(0, 0) = std::max(c(0, 0), 0.0);  // rounding of nearly equal points
  c(1, 1) = std::max(c(1, 1), 0.0);
  return c;
}

MapEvidence::MapEvidence(const ReflectorMap& map, const MapHealthConfig& config)
    : map_(map), config_(config), tracks_(map.reflectors.size()) {
  clusters_.reserve(static_cast<size_t>(config_.max_clusters));
}

void MapEvidence::push_expectation(ReflectorTrack& t, bool seen) const {
  const auto size = static_cast<size_t>(config_.window_expectations);
  if (t.window.size() < size) {
    t.window.push_back(seen);
  } else {
    t.window_seen -= t.window[static_cast<size_t>(t.window_next)];
    t.window[static_cast<size_t>(t.window_next)] = seen;
    t.window_next = (t.window_next + 1) % config_.window_expectations;
  }
  t.window_seen += seen;
}

void MapEvidence::push_offset(ReflectorTrack& t, const Eigen::Vector2d& offset) const {
  if (t.offsets.size() < static_cast<size_t>(config_.window_sightings)) {
    t.offsets.push_back(offset);
    return;
  }
  t.offsets[static_cast<size_t>(t.offsets_next)] = offset;
  t.offsets_next = (t.offsets_next + 1) % config_.window_sightings;
}

void MapEvidence::add(const ScanEvidence& scan) {
  ++scans_used_;
  for (const ReflectorSighting& s : scan.seen) {
    ReflectorTrack& t = tracks_[static_cast<size_t>(s.map_index)];
    push_expectation(t, true);
    t.unseen_spread = -1.0;
    if (s.has_offset)
      push_offset(t, s.map_p - map_.reflectors[static_cast<size_t>(s.map_index)].map_p_center);
  }
  for (int index : scan.expected_unseen) {
    ReflectorTrack& t = tracks_[static_cast<size_t>(index)];
    push_expectation(t, false);
    if (t.unseen_spread < 0.0) {
      t.unseen_from = scan.map_p_laser;
      t.unseen_spread = 0.0;
    }
    t.unseen_spread = std::max(t.unseen_spread, (scan.map_p_laser - t.unseen_from).norm());
  }
  for (const Eigen::Vector2d& p : scan.unmapped) add_unmapped(p, scan.map_p_laser, scan.utime);
}

void MapEvidence::add_unmapped(const Eigen::Vector2d& map_p, const Eigen::Vector2d& map_p_laser,
                               int64_t utime) {
  Cluster* nearest = nullptr;
  double best = config_.candidate_gate;
  for (Cluster& c : clusters_) {
    const double d = (c.points.mean() - map_p).norm();
    if (d <= best) best = d, nearest = &c;
  }
  if (nearest == nullptr) {
    if (clusters_.size() < static_cast<size_t>(config_.max_clusters)) {
      nearest = &clusters_.emplace_back();
    } else {  // forget the stalest cluster that is not a candidate (all candidates: the stalest)
      auto stalest = [&](bool spare_candidates) {
        Cluster* s = nullptr;
        for (Cluster& c : clusters_) {
          if ((!spare_candidates || standing(c) != ClusterStanding::kCandidate) &&
              (s == nullptr || c.last_utime < s->last_utime))
            s = &c;
        }
        return s;
      };
      nearest = stalest(true);
      if (nearest == nullptr) nearest = stalest(false);
      *nearest = Cluster();
    }
    nearest->key = next_cluster_key_++;
    nearest->first_viewpoint = map_p_laser;
    nearest->first_view_angle = std::atan2(map_p_laser.y() - map_p.y(), map_p_laser.x() - map_p.x());
  }
  Cluster& c = *nearest;
  const Eigen::Vector2d to_laser = map_p_laser - map_p;
  const double range = to_laser.norm();
  const Eigen::Vector2d front =
      range > 0.0 ? Eigen::Vector2d(map_p + config_.candidate_radius / range * to_laser) : map_p;
  c.points.add(map_p);
  c.recent_points.add(map_p);
  c.fronts.add(front);
  c.viewpoint_spread = std::max(c.viewpoint_spread, (map_p_laser - c.first_viewpoint).norm());
  const double turn = angle_diff(std::atan2(to_laser.y(), to_laser.x()), c.first_view_angle);
  c.view_angle_low = std::min(c.view_angle_low, turn);
  c.view_angle_high = std::max(c.view_angle_high, turn);
  c.last_utime = utime;
}

MapEvidence::ClusterStanding MapEvidence::standing(const Cluster& c) const {
  if (c.points.n < config_.candidate_min_sightings ||
      c.viewpoint_spread < config_.candidate_min_viewpoint_spread)
    return ClusterStanding::kNone;
  // The robust spread of the last 64 sightings: a handful of strays (a scan placed with a pose a
  // few centimetres off while turning) inflated the plain standard deviation of an added wall
  // reflector to > 2 cm while its centre was right within 1 mm, and it was never proposed.
  const double scatter = c.recent_points.robust_sigma();
  if (scatter > config_.candidate_max_scatter) return ClusterStanding::kNone;
  const double view_span = c.view_angle_high - c.view_angle_low;
  if (view_span >= config_.candidate_min_view_angle && scatter < major_sigma(c.fronts.covariance()))
    return ClusterStanding::kCandidate;
  return view_span >= config_.moved_min_view_angle ? ClusterStanding::kMovedPlace : ClusterStanding::kNone;
}

MapCandidate MapEvidence::candidate_of(const Cluster& c) const {
  MapCandidate m;
  m.map_p = c.points.mean();
  m.sigma = axis_sigmas(mean_covariance(c.points.covariance(), c.points.n, config_.offset_sigma_floor));
  m.sightings = c.points.n;
  m.viewpoint_spread = c.viewpoint_spread;
  m.key = c.key;
  return m;
}

ReflectorHealthEntry MapEvidence::entry(size_t index) const {
  const ReflectorTrack& t = tracks_[index];
  ReflectorHealthEntry e;
  e.id = map_.reflectors[index].id;
  e.map_p = map_.reflectors[index].map_p_center;
  e.seen = t.window_seen;
  e.expected_missing = static_cast<int>(t.window.size()) - t.window_seen;
  bool moved = false;
  const bool placed = static_cast<int>(t.offsets.size()) >= config_.min_offset_sightings;
  if (!t.offsets.empty()) {
    PointSums offsets;
    for (const Eigen::Vector2d& o : t.offsets) offsets.add(o);
    const Eigen::Matrix2d covariance =
        mean_covariance(offsets.covariance(), offsets.n, config_.offset_sigma_floor);
    e.offset = offsets.mean();
    e.offset_sigma = axis_sigmas(covariance);
    const double mahalanobis2 = e.offset.dot(covariance.ldlt().solve(e.offset));
    moved = placed && e.offset.norm() >= config_.moved_min_offset &&
            mahalanobis2 >= config_.moved_sigma_factor * config_.moved_sigma_factor;
  }
  const int expected = static_cast<int>(t.window.size());
  const bool missing = expected >= config_.min_expectations &&
                       t.window_seen <= config_.missing_max_seen_fraction * expected &&
                       t.unseen_spread >= config_.missing_min_viewpoint_spread;
  if (moved) {
    e.state = ReflectorHealth::kMoved;
  } else if (missing) {
    e.state = ReflectorHealth::kMissing;
  } else if (t.window_seen >= config_.min_sightings && placed) {
    e.state = ReflectorHealth::kOk;
  } else {
    e.state = ReflectorHealth::kUnconfirmed;
  }
  return e;
}

// A moved reflector's new place claims the candidate there; a missing reflector (or one unseen
// more often than seen, not yet judged) with a candidate near its mapped place moved there: a
// short move is sometimes matched with its offset and sometimes not. Failing a candidate, a
// missing reflector takes a moved place near it: driving straight at a reflector moved along its
// wall took ~10 s to see its new place from the 20 degrees the face test needs, and a bright
// spot that appears beside a reflector that vanished is that reflector more likely than not.
void MapEvidence::attach_candidates(MapHealthReport& out,
                                    const std::vector<MapCandidate>& moved_places) const {
  std::vector<bool> place_taken(moved_places.size(), false);
  for (ReflectorHealthEntry& r : out.reflectors) {
    const bool missing = r.state == ReflectorHealth::kMissing ||
                         (r.state == ReflectorHealth::kUnconfirmed && r.expected_missing > r.seen);
    if (!missing && r.state != ReflectorHealth::kMoved) continue;
    const Eigen::Vector2d where = r.map_p + r.offset;
    const double radius = missing ? config_.moved_candidate_radius : 2.0 * config_.candidate_gate;
    MapCandidate* nearest = nullptr;
    double best = std::numeric_limits<double>::max();
    for (MapCandidate& c : out.candidates) {
      const double d = ((missing ? r.map_p : where) - c.map_p).norm();
      if (c.moved_reflector_id < 0 && d <= radius && d < best) best = d, nearest = &c;
    }
    if (nearest == nullptr && r.state == ReflectorHealth::kMissing) {
      size_t nearest_place = moved_places.size();
      for (size_t i = 0; i < moved_places.size(); ++i) {
        const double d = (r.map_p - moved_places[i].map_p).norm();
        if (!place_taken[i] && d <= radius && d < best) best = d, nearest_place = i;
      }
      if (nearest_place < moved_places.size()) {
        place_taken[nearest_place] = true;
        nearest = &out.candidates.emplace_back(moved_places[nearest_place]);
      }
    }
    if (nearest == nullptr) continue;
    nearest->moved_reflector_id = r.id;
    // The cluster of unmatched sightings is the better estimate: matched ones are the subset
    // that fell inside the tracking gate.
    r.state = ReflectorHealth::kMoved;
    r.offset = nearest->map_p - r.map_p;
    r.offset_sigma = nearest->sigma;
  }
}

void MapEvidence::report(int64_t utime, MapHealthReport& out) const {
  out.utime = utime;
  out.map_id = map_.info.map_id;
  out.map_version = map_.info.version;
  out.scans_used = scans_used_;
  out.reflectors.clear();
  for (size_t i = 0; i < tracks_.size(); ++i) out.reflectors.push_back(entry(i));
  out.candidates.clear();
  std::vector<MapCandidate> moved_places;
  for (const Cluster& c : clusters_) {
    switch (standing(c)) {
      case ClusterStanding::kCandidate:
        out.candidates.push_back(candidate_of(c));
        break;
      case ClusterStanding::kMovedPlace:
        moved_places.push_back(candidate_of(c));
        break;
      case ClusterStanding::kNone:
        break;
    }
  }
  attach_candidates(out, moved_places);
}

}  // namespace refloc
