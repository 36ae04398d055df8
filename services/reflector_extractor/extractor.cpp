#include "reflector_extractor/extractor.hpp"

#include "reflector_extractor/energy_filter.hpp"
#include "reflector_extractor/spot_background.hpp"

#include <algorithm>
#include <cmath>

namespace refloc {

const char* cluster_outcome_name(ClusterOutcome outcome) {
  switch (outcome) {
    case ClusterOutcome::kAccepted:
      return "accepted";
    case ClusterOutcome::kTooFewBeams:
      return "too_few_beams";
    case ClusterOutcome::kTooWide:
      return "too_wide";
    case ClusterOutcome::kTooNarrow:
      return "too_narrow";
    case ClusterOutcome::kNotRound:
      return "not_round";
    case ClusterOutcome::kRadius:
      return "radius";
    case ClusterOutcome::kOccluded:
      return "occluded";
    case ClusterOutcome::kFitFailed:
      return "fit_failed";
  }
  return "unknown";
}

void ExtractionStats::count(ClusterOutcome outcome) {
  switch (outcome) {
    case ClusterOutcome::kAccepted:
      break;
    case ClusterOutcome::kTooFewBeams:
      ++rejected_too_few_beams;
      break;
    case ClusterOutcome::kTooWide:
      ++rejected_too_wide;
      break;
    case ClusterOutcome::kTooNarrow:
      ++rejected_too_narrow;
      break;
    case ClusterOutcome::kNotRound:
      ++rejected_not_round;
      break;
    case ClusterOutcome::kRadius:
      ++rejected_radius;
      break;
    case ClusterOutcome::kOccluded:
      ++rejected_occluded;
      break;
    case ClusterOutcome::kFitFailed:
      ++rejected_fit_failed;
      break;
  }
}

ExtractorConfig ExtractorConfig::paper() {
  ExtractorConfig config;
  config.mode = Mode::kPaper;
  // The paper screens by energy first and clusters the surviving points.
  config.clustering.max_gap_beams = -1;
  config.min_beams = 3;  // d-bar without the first and last point needs a third
  config.paper_centre = PaperCentreReading::kKnownRadius;
  return config;
}

ExtractorConfig mapping_corrections(ExtractorConfig config) {
  config.fit.spot.background = true;
  config.fit.second_order_bias_correction = true;
  return config;
}

ReflectorExtractor::ReflectorExtractor(ExtractorConfig config)
    : config_(config), clusterer_(config.clustering) {
  detections_.reserve(64);
  clusters_.reserve(64);
  beams_.reserve(128);
  beam_rssi_.reserve(128);
  records_.reserve(64);
}

const std::vector<ReflectorDetection>& ReflectorExtractor::extract(const LaserScan& scan,
                                                                   RssiScale rssi_scale) {
  make_beam_table(scan, table_, rssi_scale);
  return extract(table_);
}

const std::vector<ReflectorDetection>& ReflectorExtractor::extract(const BeamTable& table) {
  stats_ = ExtractionStats{};
  detections_.clear();
  records_.clear();
  select_high_energy_beams(table, config_.energy_threshold_8bit, high_energy_);
  clusterer_.cluster(table, high_energy_, clusters_);
  for (const BeamCluster& cluster : clusters_) {
    ++stats_.clusters_considered;
    ClusterRecord record = describe(table, cluster);
    record.outcome = config_.mode == ExtractorConfig::Mode::kPaper ? process_cluster_paper(table, cluster)
                                                                   : process_cluster_default(table, cluster);
    stats_.count(record.outcome);
    records_.push_back(record);
  }
  return detections_;
}

ClusterRecord ReflectorExtractor::describe(const BeamTable& table, const BeamCluster& cluster) const {
  ClusterRecord r;
  r.first_beam = cluster.first;
  r.last_beam = cluster.last;
  r.num_beams = cluster.num_selected;
  double range_sum = 0.0;
  for (int i = cluster.first; i <= cluster.last; ++i) {
    const auto k = static_cast<size_t>(i);
    if (high_energy_[k] == 0) continue;
    range_sum += table.beams[k].range;
    r.max_rssi_8bit = std::max(r.max_rssi_8bit, table.beams[k].rssi_8bit);
  }
  r.range = range_sum / std::max(cluster.num_selected, 1);
  const Eigen::Vector2d& middle =
      table.beams[static_cast<size_t>((cluster.first + cluster.last) / 2)].direction;
  r.bearing = std::atan2(middle.y(), middle.x());
  return r;
}

void ReflectorExtractor::gather_beams(const BeamTable& table, const BeamCluster& cluster) {
  beams_.clear();
  beam_rssi_.clear();
  const double weight = 1.0 / (config_.clustering.range_sigma * config_.clustering.range_sigma);
  for (int i = cluster.first; i <= cluster.last; ++i) {
    const size_t k = static_cast<size_t>(i);
    if (high_energy_[k] == 0) continue;
    const TableBeam& t = table.beams[k];
    FitBeam b;
    b.direction = t.direction;
    b.range = t.range;
    b.point = t.point;
    b.weight = weight;
    beams_.push_back(b);
    beam_rssi_.push_back(t.rssi_8bit);
  }
  if (config_.mode == ExtractorConfig::Mode::kDefault && config_.fit.spot.applies() &&
      config_.fit.spot.background)
    find_spot_background(table, cluster, high_energy_, beam_rssi_,
                         config_.fit.spot.background_merge_distance_m, beams_);
}

bool ReflectorExtractor::occluded(const BeamTable& table, const BeamCluster& cluster) const {
  const int n = static_cast<int>(table.size());
  const int neighbours[2] = {cluster.first - 1, cluster.last + 1};
  const int edges[2] = {cluster.first, cluster.last};
  for (int side = 0; side < 2; ++side) {
    const int j = neighbours[side];
    if (j < 0 || j >= n) continue;
    const TableBeam& neighbour = table.beams[static_cast<size_t>(j)];
    if (neighbour.kind == BeamKind::kDazzled && config_.reject_next_to_dazzled) return true;
    if (config_.reject_occluded && neighbour.kind == BeamKind::kEcho &&
        neighbour.range < table.beams[static_cast<size_t>(edges[side])].range - config_.occlusion_margin) {
      return true;
    }
  }
  return false;
}

ClusterOutcome ReflectorExtractor::process_cluster_paper(const BeamTable& table, const BeamCluster& cluster) {
  if (cluster.num_selected < std::max(config_.min_beams, 3)) return ClusterOutcome::kTooFewBeams;
  gather_beams(table, cluster);
  CircleFit fit;
  bool fitted = false;
  switch (config_.paper_centre) {
    case PaperCentreReading::kAlgebraicFreeRadius:
      fitted = fit_circle_algebraic(beams_, config_.clustering.range_sigma, fit);
      break;
    case PaperCentreReading::kKnownRadius:
      fitted = paper_known_radius_centre(beams_, config_.reflector_radius, fit);
      break;
    case PaperCentreReading::kPolar:
      fitted = paper_polar_centre(beams_, config_.reflector_radius, config_.paper_drop_points,
                                  config_.clustering.range_sigma, fit);
      break;
  }
  if (!fitted) return ClusterOutcome::kFitFailed;
  const double d_bar = paper_roundness_index(beams_, fit.center, fit.radius, config_.paper_drop_points);
  if (d_bar < 0.0) return ClusterOutcome::kTooFewBeams;
  if (!config_.paper_roundness.accepts(d_bar, fit.center.norm())) return ClusterOutcome::kNotRound;
  emit(table, cluster, fit, d_bar, fit.radius);
  return ClusterOutcome::kAccepted;
}

ClusterOutcome ReflectorExtractor::process_cluster_default(const BeamTable& table,
                                                           const BeamCluster& cluster) {
  if (cluster.num_selected < config_.min_beams) return ClusterOutcome::kTooFewBeams;
  if (occluded(table, cluster)) return ClusterOutcome::kOccluded;
  gather_beams(table, cluster);
  // Partial hits at the edges: drop at most one beam a side, never below min_beams.
  const double brightest = *std::max_element(beam_rssi_.begin(), beam_rssi_.end());
  const double edge_floor = config_.edge_rssi_ratio * brightest;
  if (static_cast<int>(beams_.size()) > config_.min_beams && beam_rssi_.back() < edge_floor) {
    beams_.pop_back();
    beam_rssi_.pop_back();
  }
  if (static_cast<int>(beams_.size()) > config_.min_beams && beam_rssi_.front() < edge_floor) {
    beams_.erase(beams_.begin());
    beam_rssi_.erase(beam_rssi_.begin());
  }
  CircleFit fit;
  if (!fit_circle_known_radius(beams_, config_.reflector_radius, config_.fit, fit))
    return ClusterOutcome::kFitFailed;
  // The radius check is a shape test and, like the residual test, must not depend on how
  // closely the sensor follows our spot model: it fits central rays.
  KnownRadiusFitConfig shape_fit = config_.fit;
  shape_fit.spot.enabled = false;
  CircleFit free_fit;
  const bool have_free = static_cast<int>(beams_.size()) >= config_.roundness.min_beams_for_radius_check &&
                         fit_circle_free_radius(beams_, fit.center, fit.radius, shape_fit, free_fit);
  const double flat_chi2 = flat_surface_chi2(beams_, config_.fit.min_incidence_cos);
  switch (check_known_radius_roundness(beams_, fit, have_free ? &free_fit : nullptr, flat_chi2,
                                       config_.roundness)) {
    case RoundnessVerdict::kRound:
      break;
    case RoundnessVerdict::kTooWide:
      return ClusterOutcome::kTooWide;
    case RoundnessVerdict::kTooNarrow:
      return ClusterOutcome::kTooNarrow;
    case RoundnessVerdict::kResidual:
    case RoundnessVerdict::kFlat:
      return ClusterOutcome::kNotRound;
    case RoundnessVerdict::kRadiusMismatch:
      return ClusterOutcome::kRadius;
  }
  const double range = fit.center.norm();
  if (range > 0.0) {
    const Eigen::Vector2d along = fit.center / range;
    const Eigen::Vector2d across(-along.y(), along.x());
    if (beams_.size() == 1) {
      // One beam (min_beams = 1, far reflectors): the centre is somewhere across the beam
      // step, uniformly: the fit's rank-deficient information says nothing useful there.
      const double step = std::abs(table.angle_increment) * range;
      const double sigma_r = config_.clustering.range_sigma;
      fit.covariance =
          sigma_r * sigma_r * along * along.transpose() + step * step / 12.0 * across * across.transpose();
    }
    const double sigma = config_.angle_sigma * range;
    fit.covariance += sigma * sigma * across * across.transpose();
  }
  emit(table, cluster, fit, mean_abs_range_residual(beams_, fit, config_.fit),
       have_free ? free_fit.radius : fit.radius);
  return ClusterOutcome::kAccepted;
}

void ReflectorExtractor::emit(const BeamTable& table, const BeamCluster& cluster, const CircleFit& fit,
                              double roundness, double fitted_radius) {
  ReflectorDetection d;
  d.laser_p_center = fit.center;
  d.covariance = fit.covariance;
  d.range = fit.center.norm();
  d.bearing = std::atan2(fit.center.y(), fit.center.x());
  d.utime = table.beam_utime(static_cast<size_t>((cluster.first + cluster.last) / 2));
  d.first_beam = cluster.first;
  d.num_beams = cluster.num_selected;
  double rssi_sum = 0.0;
  for (int i = cluster.first; i <= cluster.last; ++i) {
    if (high_energy_[static_cast<size_t>(i)] != 0) rssi_sum += table.beams[static_cast<size_t>(i)].rssi_8bit;
  }
  d.mean_rssi = rssi_sum / static_cast<double>(std::max(cluster.num_selected, 1));
  d.roundness_m = roundness;
  d.fitted_radius_m = fitted_radius;
  detections_.push_back(d);
}

}  // namespace refloc
