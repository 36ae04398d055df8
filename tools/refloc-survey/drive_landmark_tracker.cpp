#include "drive_landmark_tracker.hpp"

#include "pose_solver/pose_solver.hpp"
#include "pose_solver/range_bias_filter.hpp"
#include "reflector_matcher/map_grid.hpp"
#include "reflector_matcher/tracking_associator.hpp"

#include <cmath>
#include <memory>

namespace refloc {
namespace {

/// A laser correction further than this from dead reckoning over one scan is not believed.
constexpr double kMaxCorrection_m = 0.5;
constexpr double kMaxCorrection_rad = 10.0 * M_PI / 180.0;

class Tracker {
 public:
  Tracker(const Pose2& robot_T_laser, const OdometryNoise& noise, const LandmarkTrackerConfig& config)
      : robot_T_laser_(robot_T_laser),
        noise_(noise),
        config_(config),
        solver_(config.solver, robot_T_laser),
        range_bias_(config.solver.range_bias) {}

  void run(const std::vector<DriveScan>& scans, const Pose2& start, TrackerResult& out) {
    out.scans.resize(scans.size());
    association_.resize(scans.size());
    Pose2 pose = start;
    for (size_t k = 0; k < scans.size(); ++k) {
      if (k > 0) {
        const Pose2 step = scans[k - 1].odom_T_robot.inverse() * scans[k].odom_T_robot;
        pose = pose * step;
        covariance_ += increment_covariance(step, noise_);
      }
      TrackedScan& t = out.scans[k];
      association_[k].assign(scans[k].detections.size(), -1);
      rebuild_pose_map();
      t.laser_corrected = correct(scans[k], pose, association_[k]);
      if (!t.laser_corrected) ++out.scans_dead_reckoned;
      t.map_T_robot = pose;
      t.matched = record_sightings(static_cast<int>(k), scans[k], pose, association_[k]);
      count_expected(scans[k], pose);
    }
    finish(out);
  }

 private:
  /// The pose from the landmarks mapped so far; association[d] = track index of detection d.
  bool correct(const DriveScan& scan, Pose2& pose, std::vector<int>& association) {
    if (!associator_ || static_cast<int>(scan.detections.size()) < config_.min_matches) return false;
    const PosePrior prior{pose * robot_T_laser_, covariance_};
    if (!associator_->associate(scan.detections, prior, match_)) return false;
    // The range offset as pose_solver keeps it: an uncorrected +30 mm moves every sighting
    // 30 mm along its beam, and a centre seen from all sides then scatters like a distractor's.
    solver_.set_range_bias_prior(range_bias_.prior_at(scan.utime));
    solver_.solve(scan.detections, match_.matches, solution_);
    if (solution_.status == SolveStatus::kLost || solution_.reflectors_used < config_.min_matches)
      return false;
    if (solution_.status == SolveStatus::kOk && solution_.range_bias_use == RangeBiasUse::kEstimated)
      range_bias_.update(solution_.range_bias, solution_.range_bias_sigma);
    const Pose2 delta = pose.inverse() * solution_.map_T_robot;
    if (std::hypot(delta.x, delta.y) > kMaxCorrection_m || std::abs(delta.theta) > kMaxCorrection_rad)
      return false;
    pose = solution_.map_T_robot;
    covariance_ = solution_.covariance;
    for (size_t m = 0; m < match_.matches.size(); ++m) {
      if (!solution_.used[m]) continue;
      association[static_cast<size_t>(match_.matches[m].detection_index)] =
          track_of_[static_cast<size_t>(match_.matches[m].map_id)];
    }
    return true;
  }

  int record_sightings(int k, const DriveScan& scan, const Pose2& pose, std::vector<int>& association) {
    const Pose2 map_T_laser = pose * robot_T_laser_;
    int matched = 0;
    for (size_t d = 0; d < scan.detections.size(); ++d) {
      const Eigen::Vector2d& laser_p = scan.detections[d].laser_p_center;
      const Eigen::Vector2d map_direction = map_T_laser.rotation() * laser_p.normalized();
      const Eigen::Vector2d raw_map_p = map_T_laser * laser_p;
      const Eigen::Vector2d map_p = raw_map_p - range_bias_.mean() * map_direction;
      int track = association[d];
      if (track >= 0) {
        ++matched;
      } else {
        if (near_landmark(map_p)) continue;
        track = nearest_candidate(map_p);
        if (track < 0) {
          tracks_.emplace_back();
          is_landmark_.push_back(0);
          track = static_cast<int>(tracks_.size()) - 1;
        }
        association[d] = track;
      }
      LandmarkTrack& t = tracks_[static_cast<size_t>(track)];
      t.add({k, static_cast<int>(d), raw_map_p, map_direction});
      seen_this_scan_.push_back(track);
      if (!is_landmark_[static_cast<size_t>(track)] && t.promotion_failure(rule(), bias()).empty()) {
        is_landmark_[static_cast<size_t>(track)] = 1;
        ++landmarks_;
      }
    }
    return matched;
  }

  double bias() const { return range_bias_.mean(); }

  /// Until min_matches landmarks exist nothing corrects dead reckoning, whose drift then spreads
  /// every candidate: the first ones need no view span, only consistent sightings. The batch's
  /// checks judge them like every other landmark.
  PromotionRule rule() const {
    PromotionRule r = config_.promotion;
    if (landmarks_ < config_.min_matches) r.min_view_span = 0.0;
    return r;
  }

  bool near_landmark(const Eigen::Vector2d& map_p) const {
    for (size_t i = 0; i < tracks_.size(); ++i) {
      if (is_landmark_[i] && (tracks_[i].mean(bias()) - map_p).norm() < config_.landmark_exclusion)
        return true;
    }
    return false;
  }

  int nearest_candidate(const Eigen::Vector2d& map_p) const {
    int best = -1;
    double best_distance = config_.candidate_gate;
    for (size_t i = 0; i < tracks_.size(); ++i) {
      if (is_landmark_[i]) continue;
      const double distance = (tracks_[i].mean(bias()) - map_p).norm();
      if (distance < best_distance) {
        best_distance = distance;
        best = static_cast<int>(i);
      }
    }
    return best;
  }

  /// Every track in view (field of view, expected_range) counts the scan, seen or not.
  void count_expected(const DriveScan&, const Pose2& pose) {
    const Pose2 laser_T_map = (pose * robot_T_laser_).inverse();
    seen_flag_.assign(tracks_.size(), 0);
    for (int t : seen_this_scan_) seen_flag_[static_cast<size_t>(t)] = 1;
    seen_this_scan_.clear();
    for (size_t i = 0; i < tracks_.size(); ++i) {
      const Eigen::Vector2d p = laser_T_map * tracks_[i].mean(bias());
      const bool in_view = p.norm() <= config_.expected_range &&
                           std::abs(std::atan2(p.y(), p.x())) <= 0.5 * config_.sensor.field_of_view;
      if (in_view || seen_flag_[i]) tracks_[i].count_expected();
    }
  }

  /// What the pose is corrected against: the landmarks and the candidates already seen
  /// consistently, so the front end stays locked while new reflectors come into view (a
  /// distractor among them is one outlier for the pose solver). id = index into track_of_.
  void rebuild_pose_map() {
    pose_map_.reflectors.clear();
    track_of_.clear();
    for (size_t i = 0; i < tracks_.size(); ++i) {
      const LandmarkTrack& t = tracks_[i];
      const bool anchor = is_landmark_[i] || (t.sightings() >= config_.anchor_min_sightings &&
                                              t.scatter(bias()) <= config_.promotion.max_scatter);
      if (!anchor) continue;
      MapReflector r;
      r.id = static_cast<int>(track_of_.size());
      r.map_p_center = t.mean(bias());
      pose_map_.reflectors.push_back(r);
      track_of_.push_back(static_cast<int>(i));
    }
    associator_.reset();
    if (static_cast<int>(pose_map_.reflectors.size()) < config_.min_matches) return;
    grid_ = std::make_unique<MapGrid>(pose_map_, 0.5 * config_.sensor.max_range);
    associator_ = std::make_unique<TrackingAssociator>(pose_map_, *grid_, config_.tracking, config_.sensor,
                                                       config_.relocalization, config_.min_matches);
  }

  void finish(TrackerResult& out) {
    std::vector<int> landmark_index(tracks_.size(), -1);
    for (size_t i = 0; i < tracks_.size(); ++i) {
      if (is_landmark_[i]) {
        landmark_index[i] = static_cast<int>(out.landmarks.size());
        out.landmarks.push_back(std::move(tracks_[i]));
      } else {
        out.candidates.push_back(std::move(tracks_[i]));
      }
    }
    out.association = std::move(association_);
    out.range_bias = bias();
    for (auto& scan : out.association)
      for (int& a : scan) a = a >= 0 ? landmark_index[static_cast<size_t>(a)] : -1;
  }

  Pose2 robot_T_laser_;
  OdometryNoise noise_;
  LandmarkTrackerConfig config_;
  PoseSolver solver_;
  RangeBiasFilter range_bias_;
  Eigen::Matrix3d covariance_ = Eigen::Matrix3d::Zero();  ///< of the pose since the last correction
  std::vector<LandmarkTrack> tracks_;
  std::vector<char> is_landmark_;
  int landmarks_ = 0;
  std::vector<std::vector<int>> association_;  ///< per scan, per detection: track index or -1
  ReflectorMap pose_map_;                      ///< what the pose is corrected against (rebuild_pose_map)
  std::vector<int> track_of_;
  std::unique_ptr<MapGrid> grid_;
  std::unique_ptr<TrackingAssociator> associator_;
  MatchResult match_;
  PoseSolution solution_;
  std::vector<int> seen_this_scan_;
  std::vector<char> seen_flag_;
};

}  // namespace

TrackerResult track_landmarks(const std::vector<DriveScan>& scans, const Pose2& robot_T_laser,
                              const OdometryNoise& odometry_noise, const Pose2& start,
                              const LandmarkTrackerConfig& config) {
  TrackerResult out;
  Tracker tracker(robot_T_laser, odometry_noise, config);
  tracker.run(scans, start, out);
  return out;
}

}  // namespace refloc
