#include "world_renderer/scan_render_beam.hpp"

#include "common/plane_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace refloc::sim {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct SubrayHit {
  double t = kInf;  ///< distance from the sub-ray's start [m]
  double cos_incidence = 0.0;
  HitKind kind = HitKind::kNone;
  int id = -1;
  double remission = 0.0;
};

/// Whether the segment a-b can meet the spot's cone |y| <= h0 + tan * x, 0 <= x <= x_max,
/// in beam coordinates: a 1-D feasibility test on the segment parameter s in [0, 1].
bool segment_may_meet_cone(double ax, double ay, double bx, double by, double h0, double tan_half,
                           double x_max) {
  double lo = 0.0;
  double hi = 1.0;
  // Each constraint is g0 + s * g1 <= 0.
  const auto clip = [&](double g0, double g1) {
    if (std::abs(g1) < 1e-15) return g0 <= 0.0;
    const double s = -g0 / g1;
    if (g1 > 0.0)
      hi = std::min(hi, s);
    else
      lo = std::max(lo, s);
    return lo <= hi;
  };
  const double dx = bx - ax;
  const double dy = by - ay;
  return clip(-ax, -dx) && clip(ax - x_max, dx) && clip(ay - h0 - tan_half * ax, dy - tan_half * dx) &&
         clip(-ay - h0 - tan_half * ax, -dy - tan_half * dx);
}

double full_rssi(const Lms100ErrorModel& model, const SubrayHit& hit) {
  switch (hit.kind) {
    case HitKind::kReflector:
      return retro_reflector_rssi(model, hit.cos_incidence, hit.t);
    case HitKind::kDiffuse:
      return diffuse_rssi(model, hit.remission, hit.cos_incidence, hit.t);
    case HitKind::kTape:
      return tape_rssi(model, hit.remission, hit.cos_incidence, hit.t);
    case HitKind::kMetal:
      return metal_rssi(model, hit.remission, hit.cos_incidence, hit.t);
    case HitKind::kNone:
      break;
  }
  return 0.0;
}

HitKind hit_kind_of(SurfaceKind surface) {
  switch (surface) {
    case SurfaceKind::kDiffuse:
      return HitKind::kDiffuse;
    case SurfaceKind::kReflectiveTape:
      return HitKind::kTape;
    case SurfaceKind::kMetal:
      return HitKind::kMetal;
  }
  return HitKind::kDiffuse;
}

}  // namespace

BeamProfile make_beam_profile(const Lms100ErrorModel& model) {
  BeamProfile p;
  p.count = std::clamp(model.beam_subrays, 1, kMaxBeamSubrays);
  p.half_divergence_tan = std::tan(0.5 * model.beam_divergence);
  p.half_exit_diameter = 0.5 * model.beam_exit_diameter;
  double sum = 0.0;
  for (int k = 0; k < p.count; ++k) {
    const double u = p.count == 1 ? 0.0 : -1.0 + 2.0 * k / (p.count - 1);
    const double angle = u * 0.5 * model.beam_divergence;
    p.lateral_offset[k] = u * p.half_exit_diameter;
    p.cos_angle[k] = std::cos(angle);
    p.sin_angle[k] = std::sin(angle);
    p.weight[k] = std::exp(-2.0 * u * u);  // Gaussian, 1/e^2 at the spot's rim
    sum += p.weight[k];
  }
  for (int k = 0; k < p.count; ++k) p.weight[k] /= sum;
  return p;
}

BeamEcho trace_beam(const World& world, const BeamProfile& profile, const Lms100ErrorModel& model,
                    const Eigen::Vector2d& map_p_origin, double map_angle, const BeamCandidates* candidates) {
  const Eigen::Vector2d axis(std::cos(map_angle), std::sin(map_angle));
  const Eigen::Vector2d lateral(-axis.y(), axis.x());
  // Returns beyond this can neither be reported nor blend into a reportable echo.
  const double x_max = model.range_max + model.echo_merge_distance + 0.1;
  const double h0 = profile.half_exit_diameter;
  const double tan_half = profile.half_divergence_tan;
  const int n = profile.count;

  std::array<Eigen::Vector2d, kMaxBeamSubrays> origin;
  std::array<Eigen::Vector2d, kMaxBeamSubrays> dir;
  std::array<SubrayHit, kMaxBeamSubrays> hit;
  for (int k = 0; k < n; ++k) {
    origin[k] = map_p_origin + profile.lateral_offset[k] * lateral;
    dir[k] = profile.cos_angle[k] * axis + profile.sin_angle[k] * lateral;
  }

  const auto visit_reflector = [&](const MapReflector& r) {
    const Eigen::Vector2d rel = r.map_p_center - map_p_origin;
    const double cx = rel.dot(axis);
    const double cy = rel.dot(lateral);
    if (cx < -r.radius || cx > x_max + r.radius) return;
    if (std::abs(cy) - r.radius > h0 + std::max(cx + r.radius, 0.0) * tan_half) return;
    const double r2 = r.radius * r.radius;
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector2d f = origin[k] - r.map_p_center;
      const double b = f.dot(dir[k]);
      const double disc = b * b - (f.squaredNorm() - r2);
      if (disc < 0.0) continue;
      const double root = std::sqrt(disc);
      const double t = -b - root;  // the near side; a sensor inside a reflector sees nothing of it
      if (t <= 0.0 || t >= hit[k].t) continue;
      hit[k].t = t;
      hit[k].cos_incidence = root / r.radius;  // -dir . normal at the hit
      hit[k].kind = HitKind::kReflector;
      hit[k].id = r.id;
    }
  };

  const auto visit_segment = [&](size_t i) {
    const WorldSegment& s = world.segments[i];
    const Eigen::Vector2d a = s.map_p_a - map_p_origin;
    const Eigen::Vector2d b = s.map_p_b - map_p_origin;
    if (!segment_may_meet_cone(a.dot(axis), a.dot(lateral), b.dot(axis), b.dot(lateral), h0, tan_half,
                               x_max)) {
      return;
    }
    const Eigen::Vector2d e = s.map_p_b - s.map_p_a;
    for (int k = 0; k < n; ++k) {
      const double denom = cross2(dir[k], e);
      if (std::abs(denom) < 1e-12) continue;  // parallel: grazing, no echo anyway
      const Eigen::Vector2d w = s.map_p_a - origin[k];
      const double t = cross2(w, e) / denom;
      const double u = cross2(w, dir[k]) / denom;
      if (t <= 0.0 || t >= hit[k].t || u < 0.0 || u > 1.0) continue;
      hit[k].t = t;
      hit[k].cos_incidence = std::abs(denom) / e.norm();
      hit[k].kind = hit_kind_of(s.surface);
      hit[k].id = static_cast<int>(i);
      hit[k].remission = s.remission;
    }
  };

  if (candidates != nullptr) {
    for (const int32_t* c = candidates->begin; c != candidates->end; ++c) {
      if (*c >= 0) {
        visit_reflector(world.reflectors.reflectors[static_cast<size_t>(*c)]);
      } else {
        visit_segment(static_cast<size_t>(-(*c + 1)));
      }
    }
  } else {
    for (const MapReflector& r : world.reflectors.reflectors) visit_reflector(r);
    for (size_t i = 0; i < world.segments.size(); ++i) visit_segment(i);
  }

  // Order the returns by range, then blend neighbours into echoes.
  std::array<int, kMaxBeamSubrays> order;
  std::array<double, kMaxBeamSubrays> energy;
  int m = 0;
  int previous = -1;
  double previous_rssi = 0.0;
  for (int k = 0; k < n; ++k) {
    if (hit[k].kind == HitKind::kNone) continue;
    // Neighbouring sub-rays on the same flat segment differ by microradians of
    // incidence and millimetres of range: reuse the RSSI (log10 and cos are the
    // renderer's hottest calls). Cylinders vary across the spot and are exact.
    const bool same_segment = previous >= 0 && hit[k].kind != HitKind::kReflector &&
                              hit[k].kind == hit[previous].kind && hit[k].id == hit[previous].id &&
                              std::abs(hit[k].t - hit[previous].t) < 0.02;
    const double rssi = same_segment ? previous_rssi : full_rssi(model, hit[k]);
    previous = k;
    previous_rssi = rssi;
    energy[k] = profile.weight[k] * rssi;
    int j = m++;
    while (j > 0 && hit[order[j - 1]].t > hit[k].t) {
      order[j] = order[j - 1];
      --j;
    }
    order[j] = k;
  }

  BeamEcho echo;
  for (int begin = 0; begin < m;) {
    int end = begin + 1;
    while (end < m && hit[order[end]].t - hit[order[end - 1]].t <= model.echo_merge_distance) ++end;
    double sum = 0.0;
    double covered = 0.0;
    double weighted_range = 0.0;
    int strongest = order[begin];
    for (int j = begin; j < end; ++j) {
      const int k = order[j];
      sum += energy[k];
      covered += profile.weight[k];
      const bool retro = hit[k].kind == HitKind::kReflector || hit[k].kind == HitKind::kTape;
      weighted_range += energy[k] * (hit[k].t + (retro ? model.retro_range_bias : 0.0));
      if (energy[k] > energy[strongest]) strongest = k;
    }
    // Exponent 1: RSSI proportional to coverage; below 1 partial hits dim less (log-like).
    const double rssi = model.rssi_coverage_exponent == 1.0 || covered <= 0.0
                            ? sum
                            : sum / covered * std::pow(covered, model.rssi_coverage_exponent);
    if (sum > 0.0 && rssi >= model.rssi_at_detection_limit) {
      echo.range = weighted_range / sum;
      echo.rssi = rssi;
      echo.truth.kind = hit[strongest].kind;
      echo.truth.id = hit[strongest].id;
      echo.truth.range = echo.range;
      for (int k = 0; k < n; ++k) {
        if (hit[k].kind == hit[strongest].kind && hit[k].id == hit[strongest].id) {
          echo.truth.coverage += profile.weight[k];
        }
      }
      break;
    }
    begin = end;
  }
  return echo;
}

BeamEcho render_beam(const World& world, const BeamProfile& profile, const Lms100ErrorModel& model,
                     const Pose2& map_T_laser, double laser_angle, std::mt19937_64& rng,
                     const BeamCandidates* candidates) {
  BeamEcho echo = trace_beam(world, profile, model, map_T_laser.translation(),
                             map_T_laser.theta + laser_angle, candidates);
  if (echo.truth.kind == HitKind::kNone) return echo;
  if (echo.truth.kind == HitKind::kReflector && echo.truth.range < model.dazzle_range) {
    echo.range = 0.001;
    echo.rssi = 65535.0;
    return echo;
  }
  std::normal_distribution<double> normal(0.0, 1.0);
  double range = echo.range + systematic_range_error(model, echo.range, echo.rssi) +
                 range_sigma_for(model, echo.rssi) * normal(rng);
  const double rssi = echo.rssi + model.rssi_sigma * normal(rng);
  if (model.quantize_to_mm) range = std::round(range * 1000.0) / 1000.0;
  if (range < model.range_min || range > model.range_max) {
    echo.range = 0.0;
    echo.rssi = 0.0;
    return echo;
  }
  echo.range = range;
  echo.rssi = std::round(std::clamp(rssi, 1.0, 65534.0));  // 65535 means dazzled
  return echo;
}

}  // namespace refloc::sim
