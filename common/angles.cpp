#include "common/angles.hpp"

namespace refloc {

double wrap_angle(double angle_rad) {
  double wrapped = std::remainder(angle_rad, 2.0 * M_PI);  // in [-pi, pi]
  if (wrapped <= -M_PI) wrapped += 2.0 * M_PI;
  return wrapped;
}

double angle_diff(double a_rad, double b_rad) { return wrap_angle(a_rad - b_rad); }

double circular_mean(const std::vector<double>& angles_rad) {
  double s = 0.0, c = 0.0;
  for (double a : angles_rad) {
    s += std::sin(a);
    c += std::cos(a);
  }
  if (s == 0.0 && c == 0.0) return 0.0;
  return std::atan2(s, c);
}

double circular_mean(const std::vector<double>& angles_rad, const std::vector<double>& weights) {
  double s = 0.0, c = 0.0;
  for (size_t i = 0; i < angles_rad.size() && i < weights.size(); ++i) {
    s += weights[i] * std::sin(angles_rad[i]);
    c += weights[i] * std::cos(angles_rad[i]);
  }
  if (s == 0.0 && c == 0.0) return 0.0;
  return std::atan2(s, c);
}

}  // namespace refloc
