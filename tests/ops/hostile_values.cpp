// Bad values in well-formed messages: stamps far from now, absurd twists, non-finite and huge
// fields. Each message is the latest real one on its channel with utime + 1 us (a plausible new
// sample, so a service cannot reject it merely as a duplicate) and one thing changed.

#include "hostile_messages.hpp"

#include <cmath>
#include <limits>

namespace refloc {
namespace {

constexpr int64_t kHourUs = 3'600'000'000LL;

/// One numeric field of a message type, as something the catalogue can overwrite.
template <class Message>
struct NumericField {
  std::string name;
  bool is_float;  ///< float fields cannot hold 1e300: their huge value is 3e38
  std::function<void(Message&, double)> set;
};

template <class Message>
using Fields = std::vector<NumericField<Message>>;

template <class Message, size_t N>
void add_array(Fields<Message>& f, const std::string& name, double (Message::*array)[N]) {
  for (size_t i = 0; i < N; ++i)
    f.push_back({name + "[" + std::to_string(i) + "]", false,
                 [array, i](Message& m, double v) { (m.*array)[i] = v; }});
}

#define REFLOC_DOUBLE(T, field)                         \
  {                                                     \
#field, false, [](T & m, double v) { m.field = v; } \
  }
#define REFLOC_FLOAT(T, field)                                             \
  {                                                                        \
#field, true, [](T & m, double v) { m.field = static_cast<float>(v); } \
  }

Fields<pose2d_t> pose_fields() {
  Fields<pose2d_t> f{REFLOC_DOUBLE(pose2d_t, x), REFLOC_DOUBLE(pose2d_t, y), REFLOC_DOUBLE(pose2d_t, theta),
                     REFLOC_DOUBLE(pose2d_t, residual)};
  add_array(f, "covariance", &pose2d_t::covariance);
  return f;
}

Fields<odometry_t> odometry_fields() {
  Fields<odometry_t> f{REFLOC_DOUBLE(odometry_t, x),        REFLOC_DOUBLE(odometry_t, y),
                       REFLOC_DOUBLE(odometry_t, theta),    REFLOC_DOUBLE(odometry_t, vx),
                       REFLOC_DOUBLE(odometry_t, vy),       REFLOC_DOUBLE(odometry_t, wz),
                       REFLOC_DOUBLE(odometry_t, distance), REFLOC_DOUBLE(odometry_t, slip_indicator)};
  add_array(f, "covariance", &odometry_t::covariance);
  return f;
}

Fields<reflector_t> reflector_fields() {
  Fields<reflector_t> f{REFLOC_DOUBLE(reflector_t, x),
                        REFLOC_DOUBLE(reflector_t, y),
                        REFLOC_DOUBLE(reflector_t, range),
                        REFLOC_DOUBLE(reflector_t, bearing),
                        REFLOC_FLOAT(reflector_t, mean_rssi),
                        REFLOC_FLOAT(reflector_t, roundness_m),
                        REFLOC_FLOAT(reflector_t, fitted_radius_m)};
  add_array(f, "covariance", &reflector_t::covariance);
  return f;
}

Fields<laser_scan_t> scan_fields() {
  return {REFLOC_FLOAT(laser_scan_t, start_angle),
          REFLOC_FLOAT(laser_scan_t, angle_increment),
          REFLOC_FLOAT(laser_scan_t, time_increment),
          REFLOC_FLOAT(laser_scan_t, scan_period),
          REFLOC_FLOAT(laser_scan_t, range_min),
          REFLOC_FLOAT(laser_scan_t, range_max),
          {"ranges[middle]", true, [](laser_scan_t& m, double v) {
             if (!m.ranges.empty()) m.ranges[m.ranges.size() / 2] = static_cast<float>(v);
           }}};
}

Fields<reflector_detections_t> detections_fields() {
  Fields<reflector_detections_t> f;
  for (const auto& r : reflector_fields())
    f.push_back({"reflectors[0]." + r.name, r.is_float, [set = r.set](reflector_detections_t& m, double v) {
                   if (!m.reflectors.empty()) set(m.reflectors[0], v);
                 }});
  return f;
}

Fields<reflector_matches_t> matches_fields() {
  Fields<reflector_matches_t> f{
      REFLOC_DOUBLE(reflector_matches_t, hypothesis_score),
      REFLOC_DOUBLE(reflector_matches_t, runner_up_score), REFLOC_DOUBLE(reflector_matches_t, hypothesis_x),
      REFLOC_DOUBLE(reflector_matches_t, hypothesis_y), REFLOC_DOUBLE(reflector_matches_t, hypothesis_theta)};
  for (const auto& r : reflector_fields())
    f.push_back(
        {"matches[0].detection." + r.name, r.is_float, [set = r.set](reflector_matches_t& m, double v) {
           if (!m.matches.empty()) set(m.matches[0].detection, v);
         }});
  const Fields<reflector_match_t> map_fields{REFLOC_DOUBLE(reflector_match_t, map_x),
                                             REFLOC_DOUBLE(reflector_match_t, map_y),
                                             REFLOC_DOUBLE(reflector_match_t, map_radius)};
  for (const auto& r : map_fields)
    f.push_back({"matches[0]." + r.name, false, [set = r.set](reflector_matches_t& m, double v) {
                   if (!m.matches.empty()) set(m.matches[0], v);
                 }});
  return f;
}

Fields<twist_t> twist_fields() {
  return {REFLOC_DOUBLE(twist_t, vx), REFLOC_DOUBLE(twist_t, vy), REFLOC_DOUBLE(twist_t, wz)};
}

Fields<nav_goal_t> goal_fields() {
  return {REFLOC_DOUBLE(nav_goal_t, xy_tolerance),
          REFLOC_DOUBLE(nav_goal_t, heading_tolerance),
          REFLOC_DOUBLE(nav_goal_t, max_speed),
          {"x[0]", false, [](nav_goal_t& m, double v) { m.x.at(0) = v; }},
          {"y[0]", false, [](nav_goal_t& m, double v) { m.y.at(0) = v; }},
          {"theta[0]", false, [](nav_goal_t& m, double v) { m.theta.at(0) = v; }}};
}

#undef REFLOC_DOUBLE
#undef REFLOC_FLOAT

/// NaN, +inf and the largest finite value the field can hold (roughly) in each field.
template <class Message>
HostilePhase nonfinite_phase(const std::string& channel, Message Bases::*base,
                             const Fields<Message>& fields) {
  HostilePhase phase{"nonfinite:" + channel, {}};
  for (const auto& field : fields) {
    const double huge = field.is_float ? 3e38 : 1e300;
    const std::pair<const char*, double> values[] = {{"nan", std::numeric_limits<double>::quiet_NaN()},
                                                     {"inf", HUGE_VAL},
                                                     {field.is_float ? "3e38" : "1e300", huge}};
    for (const auto& [label, value] : values) {
      phase.recipes.push_back({channel, std::string(Message::getTypeName()) + "." + field.name + "=" + label,
                               [base, set = field.set, value = value](const Bases& b, int64_t) {
                                 Message m = b.*base;
                                 m.utime += 1;
                                 set(m, value);
                                 return encode_message(m);
                               }});
    }
  }
  return phase;
}

template <class Message>
void add_stamps(HostilePhase& phase, const std::string& channel, Message Bases::*base) {
  const std::pair<const char*, std::function<int64_t(int64_t)>> stamps[] = {
      {"now+1h", [](int64_t now) { return now + kHourUs; }},
      {"INT64_MAX", [](int64_t) { return std::numeric_limits<int64_t>::max(); }},
      {"now-1h", [](int64_t now) { return now - kHourUs; }},
      {"0", [](int64_t) { return int64_t{0}; }}};
  for (const auto& [label, stamp] : stamps)
    phase.recipes.push_back({channel, std::string(Message::getTypeName()) + ".utime=" + label,
                             [base, stamp = stamp](const Bases& b, int64_t now) {
                               Message m = b.*base;
                               m.utime = stamp(now);
                               return encode_message(m);
                             }});
}

template <class Message>
HostileRecipe absurd(const std::string& channel, Message Bases::*base, const std::string& what, double vx,
                     double vy, double wz) {
  return {channel, std::string(Message::getTypeName()) + " " + what, [=](const Bases& b, int64_t) {
            Message m = b.*base;
            m.utime += 1;
            if (!std::isnan(vx)) m.vx = vx;
            if (!std::isnan(vy)) m.vy = vy;
            if (!std::isnan(wz)) m.wz = wz;
            return encode_message(m);
          }};
}

}  // namespace

HostilePhase stamp_phase() {
  HostilePhase phase{"stamp", {}};
  add_stamps(phase, "LMS100_SCAN", &Bases::scan);
  add_stamps(phase, "REFLECTORS", &Bases::detections);
  add_stamps(phase, "REFLECTOR_MATCHES", &Bases::matches);
  add_stamps(phase, "LASER_POSE", &Bases::laser_pose);
  add_stamps(phase, "POSE", &Bases::pose);
  add_stamps(phase, "ODOMETRY", &Bases::odometry);
  add_stamps(phase, "WHEEL_ENCODERS", &Bases::encoders);
  add_stamps(phase, "CMD_VEL", &Bases::command);
  add_stamps(phase, "NAV_GOAL", &Bases::goal);
  return phase;
}

HostilePhase twist_phase() {
  const double keep = std::numeric_limits<double>::quiet_NaN();
  return {"twist",
          {absurd("CMD_VEL", &Bases::command, "vx=1e308", 1e308, keep, keep),
           absurd("CMD_VEL", &Bases::command, "vy=-1e308", keep, -1e308, keep),
           absurd("CMD_VEL", &Bases::command, "wz=1e6", keep, keep, 1e6),
           absurd("CMD_VEL", &Bases::command, "vx=vy=1e308,wz=-1e6", 1e308, 1e308, -1e6),
           absurd("ODOMETRY", &Bases::odometry, "vx=1e308", 1e308, keep, keep),
           absurd("ODOMETRY", &Bases::odometry, "wz=1e6", keep, keep, 1e6)}};
}

std::vector<HostilePhase> nonfinite_phases() {
  return {nonfinite_phase("LMS100_SCAN", &Bases::scan, scan_fields()),
          nonfinite_phase("REFLECTORS", &Bases::detections, detections_fields()),
          nonfinite_phase("REFLECTOR_MATCHES", &Bases::matches, matches_fields()),
          nonfinite_phase("LASER_POSE", &Bases::laser_pose, pose_fields()),
          nonfinite_phase("POSE", &Bases::pose, pose_fields()),
          nonfinite_phase("ODOMETRY", &Bases::odometry, odometry_fields()),
          nonfinite_phase("CMD_VEL", &Bases::command, twist_fields()),
          nonfinite_phase("NAV_GOAL", &Bases::goal, goal_fields())};
}

std::vector<HostilePhase> hostile_plan() {
  std::vector<HostilePhase> plan{length_phase(), stamp_phase(), twist_phase()};
  for (auto& p : nonfinite_phases()) plan.push_back(std::move(p));
  return plan;
}

}  // namespace refloc
