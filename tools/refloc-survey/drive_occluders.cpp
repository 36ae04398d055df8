#include "drive_occluders.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>

namespace refloc {
namespace {

struct Line {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();
  double distance(const Eigen::Vector2d& p) const {
    const Eigen::Vector2d d = p - point;
    return std::abs(direction.x() * d.y() - direction.y() * d.x());
  }
};

/// The Hough peak over the cells still free: the line with the most cells within half a bin.
int hough_peak(const std::vector<Eigen::Vector2d>& cells, const std::vector<char>& used,
               const OccluderConfig& config, Line& line) {
  const int angles = std::max(1, static_cast<int>(std::round(M_PI / config.angle_step)));
  double max_norm = 0.0;
  for (const Eigen::Vector2d& c : cells) max_norm = std::max(max_norm, c.norm());
  const double rho_step = config.cell_size;
  const int rhos = 2 * static_cast<int>(std::ceil(max_norm / rho_step)) + 1;
  std::vector<int> votes(static_cast<size_t>(angles) * static_cast<size_t>(rhos), 0);
  for (size_t i = 0; i < cells.size(); ++i) {
    if (used[i]) continue;
    for (int a = 0; a < angles; ++a) {
      const double angle = a * M_PI / angles;
      const double rho = std::cos(angle) * cells[i].x() + std::sin(angle) * cells[i].y();
      const int r = static_cast<int>(std::lround(rho / rho_step)) + rhos / 2;
      ++votes[static_cast<size_t>(a) * static_cast<size_t>(rhos) + static_cast<size_t>(r)];
    }
  }
  // Votes of two neighbouring offsets together: a wall two cells thick then counts whole at its
  // true direction, where a slanted line through a thick blob used to win.
  int best = -1, best_a = 0, best_r = 0;
  for (int a = 0; a < angles; ++a) {
    const int* row = votes.data() + static_cast<size_t>(a) * static_cast<size_t>(rhos);
    for (int r = 0; r + 1 < rhos; ++r) {
      if (row[r] + row[r + 1] <= best) continue;
      best = row[r] + row[r + 1];
      best_a = a;
      best_r = r;
    }
  }
  const double angle = best_a * M_PI / angles;
  const double rho = (best_r + 0.5 - rhos / 2) * rho_step;
  line.point = rho * Eigen::Vector2d(std::cos(angle), std::sin(angle));
  line.direction = Eigen::Vector2d(-std::sin(angle), std::cos(angle));
  return best;
}

/// Total least squares through the cells within tolerance of line; their indices in members.
void refit(const std::vector<Eigen::Vector2d>& cells, const std::vector<char>& used, double tolerance,
           Line& line, std::vector<size_t>& members) {
  for (int pass = 0; pass < 2; ++pass) {
    members.clear();
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (size_t i = 0; i < cells.size(); ++i) {
      if (used[i] || line.distance(cells[i]) > tolerance) continue;
      members.push_back(i);
      mean += cells[i];
    }
    if (members.size() < 2) return;
    mean /= static_cast<double>(members.size());
    Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
    for (size_t i : members) scatter += (cells[i] - mean) * (cells[i] - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(scatter);
    line.point = mean;
    line.direction = eigen.eigenvectors().col(1);  // largest eigenvalue: along the wall
  }
}

/// The runs of members along line without a gap over max_gap, long enough to keep.
void split_runs(const std::vector<Eigen::Vector2d>& cells, const std::vector<size_t>& members,
                const Line& line, const OccluderConfig& config, std::vector<MapOccluder>& out) {
  std::vector<double> t;
  t.reserve(members.size());
  for (size_t i : members) t.push_back(line.direction.dot(cells[i] - line.point));
  std::sort(t.begin(), t.end());
  size_t first = 0;
  for (size_t i = 1; i <= t.size(); ++i) {
    if (i < t.size() && t[i] - t[i - 1] <= config.max_gap) continue;
    // A cell stands for its whole width: the segment reaches half a cell past the outer centres.
    const double from = t[first] - 0.5 * config.cell_size, to = t[i - 1] + 0.5 * config.cell_size;
    // Dense along its length: a surface, not a few cells of a blob that a line happens to cross.
    const double density = static_cast<double>(i - first) * config.cell_size / (to - from);
    if (to - from >= config.min_segment_length && density >= config.min_density) {
      MapOccluder o;
      o.map_points = {line.point + from * line.direction, line.point + to * line.direction};
      out.push_back(std::move(o));
    }
    first = i;
  }
}

/// The beam (unit direction u, echo at range) passed within clearance of a reflector before
/// its echo: its range may blend cylinder and wall (a mixed pixel), so it says nothing sure.
bool grazes_landmark(const Eigen::Vector2d& u, double range,
                     const std::vector<Eigen::Vector2d>& laser_p_landmark, double clearance) {
  for (const Eigen::Vector2d& l : laser_p_landmark) {
    const double along = u.dot(l);
    if (along <= 0.0 || along > range + clearance) continue;
    if (std::abs(u.x() * l.y() - u.y() * l.x()) < clearance) return true;
  }
  return false;
}

}  // namespace

std::vector<MapOccluder> segments_from_cells(std::vector<Eigen::Vector2d> cells,
                                             const OccluderConfig& config) {
  std::vector<MapOccluder> out;
  std::vector<char> used(cells.size(), 0);
  std::vector<size_t> members;
  const int min_votes = std::max(2, static_cast<int>(config.min_segment_length / config.cell_size * 0.5));
  while (static_cast<int>(out.size()) < config.max_segments) {
    Line line;
    if (hough_peak(cells, used, config, line) < min_votes) break;
    refit(cells, used, config.line_tolerance, line, members);
    if (members.size() < 2) break;
    split_runs(cells, members, line, config, out);
    for (size_t i : members) used[i] = 1;
  }
  std::stable_sort(out.begin(), out.end(), [](const MapOccluder& a, const MapOccluder& b) {
    return (a.map_points[1] - a.map_points[0]).norm() > (b.map_points[1] - b.map_points[0]).norm();
  });
  if (static_cast<int>(out.size()) > config.max_segments)
    out.resize(static_cast<size_t>(config.max_segments));
  for (size_t i = 0; i < out.size(); ++i) out[i].name = "wall " + std::to_string(i + 1);
  return out;
}

std::vector<MapOccluder> trace_occluders(const std::vector<DriveScan>& scans,
                                         const std::vector<Pose2>& map_T_robot, const Pose2& robot_T_laser,
                                         double range_bias, const std::vector<Eigen::Vector2d>& landmarks,
                                         const OccluderConfig& config) {
  std::unordered_map<uint64_t, int> hits;
  const auto key = [&](const Eigen::Vector2d& p) {
    const auto ix = static_cast<int32_t>(std::floor(p.x() / config.cell_size));
    const auto iy = static_cast<int32_t>(std::floor(p.y() / config.cell_size));
    return (static_cast<uint64_t>(static_cast<uint32_t>(ix)) << 32) | static_cast<uint32_t>(iy);
  };
  std::vector<Eigen::Vector2d> laser_p_landmark;
  for (size_t k = 0; k < scans.size() && k < map_T_robot.size(); ++k) {
    const Pose2 map_T_laser = map_T_robot[k] * robot_T_laser;
    const Pose2 laser_T_map = map_T_laser.inverse();
    laser_p_landmark.clear();
    for (const Eigen::Vector2d& l : landmarks) laser_p_landmark.push_back(laser_T_map * l);
    for (const Eigen::Vector2f& p : scans[k].laser_p_diffuse) {
      Eigen::Vector2d laser_p = p.cast<double>();
      const double range = laser_p.norm();
      if (range > config.max_range || range <= 0.0) continue;  // also keeps the cell indices within int32
      if (grazes_landmark(laser_p / range, range, laser_p_landmark, config.landmark_clearance)) continue;
      laser_p *= (range - range_bias) / range;
      ++hits[key(map_T_laser * laser_p)];
    }
  }
  std::vector<Eigen::Vector2d> cells;
  for (const auto& [k, n] : hits) {
    if (n < config.min_hits) continue;
    const auto ix = static_cast<double>(static_cast<int32_t>(static_cast<uint32_t>(k >> 32)));
    const auto iy = static_cast<double>(static_cast<int32_t>(static_cast<uint32_t>(k & 0xffffffffu)));
    cells.emplace_back((ix + 0.5) * config.cell_size, (iy + 0.5) * config.cell_size);
  }
  // The hash map's order is not reproducible across library versions; the segments should be.
  std::sort(cells.begin(), cells.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  return segments_from_cells(std::move(cells), config);
}

}  // namespace refloc
