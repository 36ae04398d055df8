#pragma once
// Fusion of wheel odometry with laser measurements that arrive late: the matched
// reflector detections of each scan (the default) or the solver's single-scan pose fixes.
//
// A scan describes the robot at its scan's time, typically 20-80 ms before it
// arrives, while odometry has moved on. The filter keeps a short history of
// odometry steps with the estimate after each; a measurement is applied AT ITS OWN
// TIME (the step spanning that time is split), and every later step is
// re-applied on top. Accepted measurements stay in the history, so one older than
// another that already arrived is still handled exactly. The state carries the
// laser's range bias and the odometry's calibration error besides the pose (pose_ekf.hpp).
//
// Detections are gated one by one against the estimate at their scan's time (chi-square,
// 2 dof): a wrong association is dropped and counted, it never pulls the pose. A scan
// with more detections refused than accepted is refused whole (the estimate, not the
// detections, is then the suspect) and counts towards max_consecutive_rejections. A scan
// is a fresh fix for the status when at least min_detections_for_fix were accepted.
// Detections never initialise the filter: a pose fix (the solver's OK) does.
//
// Status: INITIALIZING until the first good fix; OK while the last accepted fix
// is at most degraded_after old; DEGRADED after that; LOST after lost_after, or
// after max_consecutive_rejections gated-out fixes in a row. From LOST the
// filter re-initialises from the next good fix, without the gate, but never from a
// fix that fails the time checks: a fix newer than the latest odometry by more than
// the history (ahead of anything odometry can confirm), or older than the history,
// is refused whatever the state, so a fix stamped in the future can neither make
// the filter look lost nor re-initialise it. Every comparison fails for NaN.

#include "common/se2.hpp"
#include "pose_fusion/pose_ekf.hpp"
#include "pose_fusion/usable_fix_agreement.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <deque>
#include <utility>
#include <vector>

namespace refloc {

/// The states besides the pose: their priors and random walks.
struct FusionModel {
  bool estimate_range_bias = true;
  double range_bias_prior_sigma_m = 0.03;         ///< the LMS100's systematic error spec [m]
  double range_bias_drift_m_per_sqrt_s = 0.0002;  ///< [m/sqrt(s)]
  bool estimate_odometry_error = true;
  double odometry_error_prior_sigma = 0.02;        ///< per element of E (2 %: worn rollers)
  double odometry_error_walk_per_sqrt_m = 0.0005;  ///< per element of E [1/sqrt(m)]
  double map_sigma_m = 0.001;                      ///< the map positions' error, per axis [m]
  double detection_gate_chi2 = 13.82;              ///< chi-square 2 dof at 99.9 %
  int min_detections_for_fix = 2;                  ///< accepted detections that make a scan a fresh fix
  /// Upper bound of the detection covariance's inflation when the kept detections' squared
  /// Mahalanobis distances average above 2 (covariance matching); 1: never inflated.
  double max_noise_inflation = 10.0;
  /// The scans' time offset (true measurement time - stamp) is estimated: a link delay no clock
  /// fit can see (a real LMS100's Ethernet ~0.4 ms), stamping. Until the robot has moved and
  /// turned enough to tell it, the pose's covariance carries its prior.
  bool estimate_scan_time_offset = true;
  double scan_time_offset_prior_sigma_s = 0.001;      ///< [s]
  double scan_time_offset_drift_s_per_sqrt_s = 1e-5;  ///< [s/sqrt(s)]
  Pose2 robot_T_laser{0.30, 0.0, 0.0};                ///< the laser mount (robot.json)
};

struct FusionConfig {
  FusionModel model;
  double history = 1.0;  ///< how far back a fix can be applied [s]
  /// A fix newer than the latest odometry by more than this waits for odometry
  /// to reach its time (odometry is late or its service is restarting). Applied
  /// to an older estimate it would be gated out while the robot moves [s].
  double max_fix_lead = 0.0;
  size_t max_deferred_fixes = 100;      ///< fixes kept while odometry is missing
  double gate_chi2 = 16.27;             ///< Mahalanobis^2 gate, chi-square 3 dof at 99.9 %
  double degraded_after = 1.0;          ///< no accepted fix this long: DEGRADED [s]
  double lost_after = 5.0;              ///< no accepted fix this long: LOST [s]
  int max_consecutive_rejections = 10;  ///< this many gated-out fixes in a row: LOST
  /// With no OK fix to start from, this many DEGRADED fixes (three reflectors) within
  /// start_window that agree through the odometry (gate_chi2) start the filter; 0: OK only.
  int start_agreeing_usable_fixes = 3;
  double start_window = 5.0;  ///< [s]
};

enum class FusionStatus { kInitializing, kOk, kDegraded, kLost };

/// How a fix may be used: kGood (solver OK) may (re-)initialise the filter,
/// kUsable (solver DEGRADED: few reflectors) corrects an initialised one, and starts it only
/// when FusionConfig::start_agreeing_usable_fixes of them agree.
enum class FixQuality { kGood, kUsable };

struct PoseFix {
  int64_t utime = 0;  ///< time the pose refers to [us]
  Pose2 map_T_robot;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();  ///< [m^2, m rad, rad^2]
  FixQuality quality = FixQuality::kGood;
};

/// The matched detections of one scan, compensated to its time.
struct DetectionScan {
  int64_t utime = 0;  ///< the scan's time [us]
  std::vector<MatchedDetection> detections;
};

enum class FixResult {
  kAccepted,
  kInitialised,      ///< the filter was (re-)initialised from this fix
  kRejectedGate,     ///< Mahalanobis distance above the gate
  kTooOld,           ///< older than the history
  kWaitingForGood,   ///< not initialised and the fix is not good enough to start from
  kDeferred,         ///< ahead of odometry: applied when odometry reaches its time
  kAheadOfOdometry,  ///< newer than the latest odometry by more than the history: refused
};

/// What became of one scan's detections.
struct ScanResult {
  FixResult result = FixResult::kWaitingForGood;
  int accepted = 0;  ///< detections applied
  int rejected = 0;  ///< detections outside the gate
};

class PoseFusion {
 public:
  explicit PoseFusion(const FusionConfig& config);

  /// Odometry displacement delta (body frame, covariance q) from the previous
  /// odometry time to utime [us]. Returns false (ignored) when not after the last one.
  bool add_odometry(int64_t utime, const Pose2& delta, const Eigen::Matrix3d& q);
  /// An odometry step across a seam (restarted odometry, long gap): q includes the
  /// motion nobody observed. Status stays DEGRADED until a fix newer than the
  /// seam's start is accepted. Returns false (ignored) when not after the last step.
  bool add_odometry_seam(int64_t utime, const Pose2& delta, const Eigen::Matrix3d& q);

  /// An absolute pose fix; applied at fix.utime.
  FixResult add_fix(const PoseFix& fix);
  /// One scan's matched detections, applied at scan.utime (kWaitingForGood while the filter
  /// needs a pose fix to start).
  ScanResult add_detections(const DetectionScan& scan);
  /// True when only a pose fix can go on: not initialised, or lost at the latest odometry time.
  bool needs_initialisation() const { return !initialised_ || lost(utime()); }

  /// Status at now_utime [us] (normally the latest odometry time).
  FusionStatus status(int64_t now_utime) const;
  /// The pose estimate after the latest odometry step.
  PoseEstimate estimate() const { return state().pose(); }
  /// The whole state after the latest odometry step.
  const FusionState& state() const;
  /// Time of estimate() [us].
  int64_t utime() const;
  bool initialised() const { return initialised_; }
  /// The last (re-)initialisation came from this many agreeing usable fixes (0: an OK fix), over
  /// start_span_s() seconds.
  int start_agreeing_fixes() const { return start_agreeing_fixes_; }
  double start_span_s() const { return start_span_s_; }
  /// True once any odometry step was added (the fix time checks need it).
  bool has_odometry() const { return has_odometry_; }
  int consecutive_rejections() const { return consecutive_rejections_; }
  double last_mahalanobis_squared() const { return last_mahalanobis_squared_; }
  size_t deferred_fixes() const { return deferred_.size(); }
  /// Results of deferred measurements applied by the last add_odometry call (scans: their
  /// whole-scan result).
  const std::vector<FixResult>& deferred_results() const { return deferred_results_; }
  /// Sum and count of the squared Mahalanobis distances of accepted detections since the
  /// last take_detection_nis() (an honest filter averages 2).
  std::pair<double, int> take_detection_nis();
  /// The factor the detections' covariance is multiplied by now (1: the extractor's own).
  double noise_inflation() const { return noise_inflation_; }

 private:
  /// A pose fix, or the accepted detections of one scan.
  struct Measurement {
    int64_t utime = 0;
    bool is_scan = false;
    PoseFix fix;
    std::vector<MatchedDetection> detections;
    ScanTiming timing;  ///< the laser's twist at the scan, from the odometry step it falls in
  };
  struct Step {
    int64_t utime = 0;  ///< end of the step (start: the previous step's or the base's utime)
    Pose2 delta;
    Eigen::Matrix3d q = Eigen::Matrix3d::Zero();
    std::vector<Measurement> measurements;  ///< accepted at utime, re-applied on every rollback
    FusionState posterior;                  ///< after delta and the measurements
  };

  bool lost(int64_t now_utime) const;
  /// fix's pose and covariance carried by the odometry from its time to the latest.
  std::pair<Pose2, Eigen::Matrix3d> carried_to_latest(const PoseFix& fix);
  /// The laser's twist over step i (constant over a step) and the model's timing variance.
  ScanTiming scan_timing(long i) const;
  void initialise(const PoseFix& fix);
  /// The refusal every measurement at t meets first, also before (re-)initialisation: newer than
  /// the latest odometry by more than the history (kAheadOfOdometry) or older than the history
  /// (kTooOld); kAccepted when it passes. No checks before the first odometry.
  FixResult time_refusal(int64_t t) const;
  /// A measurement at t is ahead of odometry by more than max_fix_lead.
  bool waits_for_odometry(int64_t t) const;
  void defer(Measurement m);
  void apply(FusionState& state, const Measurement& m) const;
  /// Index of a step ending exactly at t (splitting the step spanning t), or -1
  /// for the base. Requires base_utime_ <= t <= utime().
  long step_ending_at(int64_t t);
  /// Store m (accepted) at step i and re-apply everything after it.
  void commit(long i, Measurement m);
  ScanResult apply_scan(const DetectionScan& scan);
  const FusionState& posterior(long i) const;
  /// Recompute step i's posterior from its predecessor, its delta and its fixes.
  void recompute(size_t i);
  void repropagate_from(size_t first);
  void trim_history();
  void apply_deferred_fixes();

  FusionConfig config_;
  StateRandomWalk walk_;
  bool initialised_ = false;
  bool has_odometry_ = false;
  bool lost_by_rejections_ = false;
  FusionState base_;
  int64_t base_utime_ = 0;
  std::deque<Step> steps_;
  int64_t last_accepted_fix_utime_ = 0;
  int consecutive_rejections_ = 0;
  double last_mahalanobis_squared_ = 0.0;
  int64_t seam_utime_ = -1;  ///< start of the latest odometry seam [us]
  std::vector<Measurement> deferred_;
  std::vector<FixResult> deferred_results_;
  double nis_sum_ = 0.0;
  double equivalent_nis_mean_ = 2.0;  ///< moving mean of the kept detections' Mahalanobis^2 at inflation 1
  double noise_inflation_ = 1.0;
  int nis_count_ = 0;
  UsableFixAgreement agreement_;
  int start_agreeing_fixes_ = 0;
  double start_span_s_ = 0.0;
};

const char* to_string(FusionStatus status);

}  // namespace refloc
