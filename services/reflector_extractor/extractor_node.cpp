#include "reflector_extractor/extractor_node.hpp"

#include "reflector_extractor/extractor_input_checks.hpp"

namespace refloc {

ExtractorNode::ExtractorNode(const ExtractorServiceConfig& config, const Pose2& robot_T_laser)
    : extractor_(config.extractor),
      compensator_(config.motion_compensation, config.odometry_max_age, robot_T_laser, config.fix_velocity),
      rssi_scale_(config.rssi_scale),
      no_reflector_(config.no_reflector_timeout, config.extractor.energy_threshold_8bit) {
  output_.detections.reserve(64);
}

const std::vector<NodeEvent>& ExtractorNode::on_odometry(const OdometrySample& sample, int64_t host_utime) {
  odometry_events_.clear();
  if (const InputFault fault = check_odometry_twist(sample)) {
    odometry_events_.push_back(odometry_checks_.rejected(fault.reason, fault.detail, host_utime));
  } else if (odometry_checks_.stamp_accepted(sample.utime, host_utime, odometry_events_)) {
    odometry_checks_.accepted(host_utime);
    compensator_.on_odometry(sample);
  }
  return odometry_events_;
}

const std::vector<NodeEvent>& ExtractorNode::on_laser_pose(const LaserPoseFix& fix, int64_t host_utime) {
  laser_pose_events_.clear();
  if (!fix.ok) return laser_pose_events_;  // no pose to fit; not a fault
  if (const InputFault fault = check_laser_pose(fix)) {
    laser_pose_events_.push_back(laser_pose_checks_.rejected(fault.reason, fault.detail, host_utime));
  } else if (laser_pose_checks_.stamp_accepted(fix.utime, host_utime, laser_pose_events_)) {
    laser_pose_checks_.accepted(host_utime);
    compensator_.on_laser_pose(fix);
  }
  return laser_pose_events_;
}

const ExtractorOutput& ExtractorNode::on_scan(const LaserScan& scan, int64_t host_utime) {
  output_.events.clear();
  output_.accepted = false;
  output_.missing_scans = 0;
  if (const InputFault fault = check_scan(scan)) {
    output_.events.push_back(scan_checks_.rejected(fault.reason, fault.detail, host_utime));
    return output_;
  }
  if (!scan_checks_.stamp_accepted(scan.utime, host_utime, output_.events)) return output_;
  scan_checks_.accepted(host_utime);
  output_.accepted = true;
  output_.missing_scans = scan_checks_.missing_before(scan.scan_counter, scan.utime, output_.events);
  output_.utime = scan.utime;
  output_.scan_counter = scan.scan_counter;
  rssi_scale_.observe(scan, output_.events);
  rssi_scale_was_8bit_ = rssi_scale_was_8bit_ || rssi_scale_.scale() == RssiScale::k8bitIn16bit;
  make_beam_table(scan, table_, rssi_scale_.scale());
  output_.detections = extractor_.extract(table_);  // copy into reused storage
  output_.stats = extractor_.stats();
  output_.clusters = extractor_.clusters();
  output_.energy_threshold_8bit = extractor_.config().energy_threshold_8bit;
  output_.energy_threshold_raw =
      rssi_from_8bit(output_.energy_threshold_8bit, scan.rssi_bits, rssi_scale_.scale());
  output_.rssi_read_as_8bit = scan.rssi_bits == 16 && rssi_scale_.scale() == RssiScale::k8bitIn16bit;
  no_reflector_.observe(table_, output_.stats, output_.detections.size(), host_utime, output_.events);
  output_.compensation = compensator_.apply(output_.detections, scan.utime);
  if (output_.compensation != last_compensation_ || !compensation_chosen_) {
    // The first choice is logged once; a change of source is counted and its line
    // rate-limited by that counter (a source flapping scan by scan logs once a second).
    output_.events.push_back({compensation_chosen_ ? "motion_source_changes" : nullptr,
                              NodeEvent::Level::kInfo,
                              compensator_.describe(output_.compensation, scan.utime)});
    compensation_chosen_ = true;
    last_compensation_ = output_.compensation;
  }
  return output_;
}

ExtractorHealth ExtractorNode::health(int64_t messages_in, int64_t host_utime,
                                      const std::string& input_channel) const {
  if (messages_in == 0) return {ExtractorHealth::State::kStarting, "waiting for " + input_channel};
  if (scan_checks_.starved(host_utime))
    return {ExtractorHealth::State::kDegraded, scan_checks_.starved_detail(host_utime)};
  ExtractorHealth h{ExtractorHealth::State::kOk, rssi_scale_.detail()};
  if (rssi_scale_was_8bit_) h.rssi_scale_8bit = rssi_scale_.scale() == RssiScale::k8bitIn16bit ? 1 : 0;
  if (no_reflector_.firing()) {
    h.state = ExtractorHealth::State::kDegraded;
    h.detail = no_reflector_.detail() + (h.detail.empty() ? "" : "; " + h.detail);
  }
  return h;
}

}  // namespace refloc
