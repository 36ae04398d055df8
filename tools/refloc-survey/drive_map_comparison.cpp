#include "drive_map_comparison.hpp"

#include "reflector_matcher/rigid_fit_2d.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>

namespace refloc {
namespace {

/// Map pairs tried for the alignment: the first this many entries give every pair.
constexpr size_t kSeedReflectors = 12;
/// Two map distances agree with a truth distance within this [m].
constexpr double kPairTolerance = 0.05;

struct Pair {
  int map_index;
  int truth_index;
  double distance2;
};

/// Unique nearest pairs within gate, closest first.
std::vector<Pair> associate(const ReflectorMap& map, const ReflectorMap& truth, const Pose2& truth_T_map,
                            double gate) {
  std::vector<Pair> all;
  for (size_t i = 0; i < map.reflectors.size(); ++i) {
    const Eigen::Vector2d p = truth_T_map * map.reflectors[i].map_p_center;
    for (size_t k = 0; k < truth.reflectors.size(); ++k) {
      const double d2 = (truth.reflectors[k].map_p_center - p).squaredNorm();
      if (d2 <= gate * gate) all.push_back({static_cast<int>(i), static_cast<int>(k), d2});
    }
  }
  std::sort(all.begin(), all.end(), [](const Pair& a, const Pair& b) { return a.distance2 < b.distance2; });
  std::vector<char> map_used(map.reflectors.size(), 0), truth_used(truth.reflectors.size(), 0);
  std::vector<Pair> out;
  for (const Pair& p : all) {
    if (map_used[static_cast<size_t>(p.map_index)] || truth_used[static_cast<size_t>(p.truth_index)])
      continue;
    map_used[static_cast<size_t>(p.map_index)] = truth_used[static_cast<size_t>(p.truth_index)] = 1;
    out.push_back(p);
  }
  return out;
}

bool refit(const ReflectorMap& map, const ReflectorMap& truth, const std::vector<Pair>& pairs,
           Pose2& truth_T_map) {
  RigidFit2d fit;
  for (const Pair& p : pairs)
    fit.add(map.reflectors[static_cast<size_t>(p.map_index)].map_p_center,
            truth.reflectors[static_cast<size_t>(p.truth_index)].map_p_center);
  return fit.solve(truth_T_map);
}

/// Most pairs, then the smallest squared error: every two-point correspondence whose distances
/// agree is a hypothesis (a symmetric hall has several; the errors pick the right one).
bool find_alignment(const ReflectorMap& map, const ReflectorMap& truth, double gate, Pose2& best) {
  size_t best_count = 0;
  double best_error = std::numeric_limits<double>::max();
  const size_t seeds = std::min(map.reflectors.size(), kSeedReflectors);
  for (size_t i = 0; i < seeds; ++i) {
    for (size_t j = i + 1; j < seeds; ++j) {
      const Eigen::Vector2d a = map.reflectors[i].map_p_center, b = map.reflectors[j].map_p_center;
      const double d = (a - b).norm();
      if (d < 0.5) continue;  // a short baseline gives a poor heading
      for (size_t k = 0; k < truth.reflectors.size(); ++k) {
        for (size_t l = 0; l < truth.reflectors.size(); ++l) {
          if (k == l) continue;
          const Eigen::Vector2d c = truth.reflectors[k].map_p_center, e = truth.reflectors[l].map_p_center;
          if (std::abs((c - e).norm() - d) > kPairTolerance) continue;
          RigidFit2d fit;
          fit.add(a, c);
          fit.add(b, e);
          Pose2 hypothesis;
          if (!fit.solve(hypothesis)) continue;
          std::vector<Pair> pairs = associate(map, truth, hypothesis, gate);
          if (pairs.size() < 2 || !refit(map, truth, pairs, hypothesis)) continue;
          pairs = associate(map, truth, hypothesis, gate);
          double error = 0.0;
          for (const Pair& p : pairs) error += p.distance2;
          if (pairs.size() > best_count || (pairs.size() == best_count && error < best_error)) {
            best_count = pairs.size();
            best_error = error;
            best = hypothesis;
          }
        }
      }
    }
  }
  return best_count >= 2;
}

ReflectorComparison compare_one(const MapReflector& m, const MapReflector& t, const Pose2& truth_T_map) {
  ReflectorComparison c;
  c.map_id = m.id;
  c.truth_id = t.id;
  c.truth_p_map = truth_T_map * m.map_p_center;
  c.truth_p = t.map_p_center;
  c.error = (c.truth_p_map - c.truth_p).norm();
  if (m.map_cov_center) {
    const Eigen::Matrix2d r = truth_T_map.rotation();
    const Eigen::Matrix2d covariance = r * *m.map_cov_center * r.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(covariance);
    c.sigma = std::sqrt(std::max(0.0, eigen.eigenvalues()(1)));
    const Eigen::FullPivLU<Eigen::Matrix2d> lu(covariance);
    if (lu.isInvertible()) {
      const Eigen::Vector2d e = c.truth_p_map - c.truth_p;
      c.has_covariance = true;
      c.mahalanobis = std::sqrt(e.dot(lu.inverse() * e));
    }
  }
  return c;
}

/// scale_ppm and rms_after_scale of c from its matched pairs.
void fit_scale(MapComparison& c) {
  if (c.matched.size() < 2) return;
  Eigen::Vector2d map_mean = Eigen::Vector2d::Zero(), truth_mean = Eigen::Vector2d::Zero();
  for (const ReflectorComparison& r : c.matched) {
    map_mean += r.truth_p_map;
    truth_mean += r.truth_p;
  }
  const double n = static_cast<double>(c.matched.size());
  map_mean /= n;
  truth_mean /= n;
  double ab = 0.0, aa = 0.0;
  for (const ReflectorComparison& r : c.matched) {
    ab += (r.truth_p_map - map_mean).dot(r.truth_p - truth_mean);
    aa += (r.truth_p_map - map_mean).squaredNorm();
  }
  if (aa <= 0.0) return;
  const double scale = ab / aa;  // truth = scale * map about the centroids
  double sum2 = 0.0;
  for (const ReflectorComparison& r : c.matched)
    sum2 += (truth_mean + scale * (r.truth_p_map - map_mean) - r.truth_p).squaredNorm();
  c.scale_ppm = (1.0 / scale - 1.0) * 1e6;  // the map's size against the truth's
  c.rms_after_scale = std::sqrt(sum2 / n);
}

}  // namespace

MapComparison compare_maps(const ReflectorMap& map, const ReflectorMap& truth,
                           const MapComparisonOptions& options) {
  MapComparison out;
  Pose2 truth_T_map;
  out.aligned = !options.align || find_alignment(map, truth, options.match_gate, truth_T_map);
  if (out.aligned && options.align) {
    // The final fit over every pair, then the pairs again from it.
    const std::vector<Pair> pairs = associate(map, truth, truth_T_map, options.match_gate);
    refit(map, truth, pairs, truth_T_map);
  }
  out.truth_T_map = truth_T_map;
  std::vector<Pair> pairs =
      out.aligned ? associate(map, truth, truth_T_map, options.match_gate) : std::vector<Pair>{};
  std::sort(pairs.begin(), pairs.end(),
            [](const Pair& a, const Pair& b) { return a.map_index < b.map_index; });
  std::vector<char> map_matched(map.reflectors.size(), 0), truth_matched(truth.reflectors.size(), 0);
  double sum2 = 0.0;
  for (const Pair& p : pairs) {
    map_matched[static_cast<size_t>(p.map_index)] = truth_matched[static_cast<size_t>(p.truth_index)] = 1;
    const ReflectorComparison c =
        compare_one(map.reflectors[static_cast<size_t>(p.map_index)],
                    truth.reflectors[static_cast<size_t>(p.truth_index)], truth_T_map);
    sum2 += c.error * c.error;
    if (c.error >= out.worst) {
      out.worst = c.error;
      out.worst_map_id = c.map_id;
    }
    if (c.has_covariance) {
      ++out.with_covariance;
      if (c.mahalanobis <= 3.0) ++out.within_3_sigma;
    }
    out.matched.push_back(c);
  }
  if (!out.matched.empty()) out.rms = std::sqrt(sum2 / static_cast<double>(out.matched.size()));
  fit_scale(out);
  for (size_t i = 0; i < map.reflectors.size(); ++i)
    if (!map_matched[i]) out.extra_map_ids.push_back(map.reflectors[i].id);
  for (size_t k = 0; k < truth.reflectors.size(); ++k)
    if (!truth_matched[k]) out.missing_truth_ids.push_back(truth.reflectors[k].id);
  return out;
}

std::string comparison_text(const MapComparison& c) {
  if (!c.aligned) return "no alignment: fewer than 2 map entries lie at truth distances\n";
  std::string text = fmt::format("truth_T_map: x {:.4f} m, y {:.4f} m, theta {:.4f} deg\n", c.truth_T_map.x,
                                 c.truth_T_map.y, c.truth_T_map.theta * 180.0 / M_PI);
  text += "map_id truth_id  error_mm  sigma_mm  error/sigma(Mahalanobis)\n";
  for (const ReflectorComparison& r : c.matched) {
    text += fmt::format("{:6d} {:8d} {:9.2f}", r.map_id, r.truth_id, r.error * 1e3);
    text += r.has_covariance ? fmt::format(" {:9.2f} {:9.2f}{}\n", r.sigma * 1e3, r.mahalanobis,
                                           r.mahalanobis <= 3.0 ? "" : "  outside 3 sigma")
                             : "         -         -\n";
  }
  text += fmt::format("matched {}; RMS error {:.2f} mm, worst {:.2f} mm (map id {})\n", c.matched.size(),
                      c.rms * 1e3, c.worst * 1e3, c.worst_map_id);
  text += fmt::format(
      "the map is {:+.0f} ppm the size of the truth; RMS error {:.2f} mm with that scale taken out\n",
      c.scale_ppm, c.rms_after_scale * 1e3);
  if (c.with_covariance > 0)
    text += fmt::format("inside 3 sigma: {} of {} ({:.0f} %)\n", c.within_3_sigma, c.with_covariance,
                        100.0 * c.within_3_sigma / c.with_covariance);
  text +=
      fmt::format("map entries without a real reflector: {}{}\n", c.extra_map_ids.size(),
                  c.extra_map_ids.empty() ? "" : fmt::format(" (ids {})", fmt::join(c.extra_map_ids, ", ")));
  text += fmt::format(
      "real reflectors not in the map: {}{}\n", c.missing_truth_ids.size(),
      c.missing_truth_ids.empty() ? "" : fmt::format(" (ids {})", fmt::join(c.missing_truth_ids, ", ")));
  return text;
}

std::string comparison_csv(const MapComparison& c) {
  std::string csv = "map_id,truth_id,error_x_mm,error_y_mm,error_mm,sigma_mm,mahalanobis\n";
  const Eigen::Matrix2d map_R_truth = c.truth_T_map.rotation().transpose();
  for (const ReflectorComparison& r : c.matched) {
    const Eigen::Vector2d e = map_R_truth * (r.truth_p_map - r.truth_p) * 1e3;
    csv += fmt::format("{},{},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f}\n", r.map_id, r.truth_id, e.x(), e.y(),
                       r.error * 1e3, r.sigma * 1e3, r.has_covariance ? r.mahalanobis : -1.0);
  }
  return csv;
}

}  // namespace refloc
