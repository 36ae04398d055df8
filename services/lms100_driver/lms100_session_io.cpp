// Lms100Session's link I/O: one request and its reply (scans in between go to the scan
// path), the frame pump with its deadline, scan parsing and counters, the polite stop.
#include "lms100_driver/lms100_session.hpp"

#include <poll.h>

#include <algorithm>

#include <fmt/format.h>

#include "common/clock.hpp"
#include "lms100_driver/lmd_scandata_parser.hpp"
#include "lms100_driver/scan_conversion.hpp"

namespace refloc {

Lms100Session::Wait Lms100Session::transact(const std::string& request, double timeout_s, std::string& reply,
                                            std::string& why) {
  if (stop_.load()) {
    why = "stopped";
    return Wait::kStopped;
  }
  std::string bytes;
  if (const ParseResult framed = wire_.frame_request(request, bytes); !framed) {
    why = framed.error;  // a request this dialect has no layout for: a bug, not a link failure
    return Wait::kClosed;
  }
  const IoStatus s = link_.send_all(bytes, timeout_s, wake_pipe_[0]);
  if (s != IoStatus::kOk) {
    if (s == IoStatus::kTimeout) ++counters_.timeouts;
    why = s == IoStatus::kStopped ? "stopped" : "send failed: " + link_.last_error();
    return s == IoStatus::kStopped ? Wait::kStopped : Wait::kClosed;
  }
  const Wait w = pump(&request, monotonic_us() + static_cast<int64_t>(timeout_s * 1e6), false, reply, why);
  if (w == Wait::kTimeout) {
    ++counters_.timeouts;
    why = fmt::format("no reply to '{}' within {:.1f} s", request, timeout_s);
  }
  return w;
}

Lms100Session::Wait Lms100Session::pump(const std::string* request, int64_t deadline_us, bool return_on_scan,
                                        std::string& reply, std::string& why) {
  for (;;) {
    // Frames already buffered first: one read can carry a reply and several scans. Every
    // scan of the read reaches the clock filter before any is stamped (scan_stamper.hpp).
    bool got_scan = false;
    while (wire_.next(frame_)) {
      if (is_lmd_scandata(frame_)) {  // the same head in both dialects
        if (handle_scan(frame_, last_read_utime_)) {
          got_scan = true;
        } else if (parse_error_streak_ >= config_.max_parse_error_streak) {
          why = fmt::format("{} unparsable scans in a row", parse_error_streak_);
          return Wait::kParseErrors;
        }
        continue;
      }
      if (!wire_.to_text(frame_, frame_text_)) {
        ++counters_.unexpected_frames;  // a CoLa-B frame shorter than its reply's layout
        continue;
      }
      const std::string& frame = frame_text_;
      uint32_t code = 0;
      if (request != nullptr && parse_sopas_error(frame, code)) {
        ++counters_.sfa_errors;
        why = fmt::format("sensor answered '{}' with sFA {:X} ({})", *request, code, sopas_error_name(code));
        return Wait::kSopasError;
      }
      if (request != nullptr && is_reply_to(*request, frame)) {
        ColaAMessage m;
        if (split_cola_a(frame, m) && m.type == "sMA") continue;  // acknowledged; the sAN follows
        reply = frame;
        return Wait::kReply;
      }
      if (parse_sopas_error(frame, code)) ++counters_.sfa_errors;
      ++counters_.unexpected_frames;  // a late or duplicated reply (seen on real LMS111s)
    }
    publish_stamped_scans();
    if (got_scan && return_on_scan) return Wait::kScan;
    if (stop_.load()) {
      why = "stopped";
      return Wait::kStopped;
    }
    const int64_t left_us = deadline_us - monotonic_us();
    if (left_us <= 0) {
      why = "timeout";
      return Wait::kTimeout;
    }
    size_t received = 0;
    const int timeout_ms = static_cast<int>(std::min<int64_t>(left_us / 1000 + 1, kMaxPollMs));
    const IoStatus s =
        link_.receive(receive_buffer_.data(), receive_buffer_.size(), timeout_ms, wake_pipe_[0], received);
    switch (s) {
      case IoStatus::kOk:
        last_read_utime_ = now_utime();
        wire_.feed(receive_buffer_.data(), received);
        sync_wire_counters();
        break;
      case IoStatus::kTimeout:
        break;
      case IoStatus::kStopped:
        why = "stopped";
        return Wait::kStopped;
      case IoStatus::kClosed:
      case IoStatus::kError:
        why = "link lost: " + link_.last_error();
        return Wait::kClosed;
    }
  }
}

bool Lms100Session::handle_scan(const std::string& payload, int64_t receive_utime) {
  ParseResult r = wire_.parse_scan(payload, scan_data_);
  if (r) r = to_laser_scan(scan_data_, scan_);
  if (!r) {
    ++counters_.parse_errors;
    ++parse_error_streak_;
    return false;
  }
  parse_error_streak_ = 0;
  const ScanPlausibility plausible = check_scan_plausibility(scan_data_, config_.device);
  counters_.reserved_distance_codes += count_reserved_distance_codes(scan_data_);
  if (have_last_scan_counter_) {
    const uint32_t missing = (scan_data_.scan_counter - last_scan_counter_ - 1) & 0xFFFFu;
    if (missing != 0 && missing < 0x8000u) {
      ++counters_.scan_counter_gaps;
      counters_.lost_scans += missing;
    }
  }
  have_last_scan_counter_ = true;
  last_scan_counter_ = scan_data_.scan_counter;
  if (!plausible) {  // the link works (no parse error, no reconnect); the content is refused
    count_rejection(plausible);
    return true;
  }

  scan_.range_min = config_.device.range_min_m;
  scan_.range_max = config_.device.range_max_m;
  stamper_.add(scan_, scan_data_.time_since_startup_us, scan_data_.time_of_transmission_us, receive_utime);
  return true;
}

void Lms100Session::publish_stamped_scans() {
  if (stamper_.held() > 0) {
    stamper_.release(now_utime(), [this](const LaserScan& scan) {
      ++counters_.scans;
      if (on_scan_) on_scan_(scan);
    });
  }
  const ScanStamperCounts& c = stamper_.counts();
  counters_.scans_in_bursts.store(c.scans_in_bursts);
  counters_.held_scans.store(c.held_scans);
  counters_.held_scans_dropped.store(c.held_scans_dropped);
  counters_.utime_not_increasing.store(c.utime_not_increasing);
  counters_.held_scan_max_delay_us.store(c.held_scan_max_delay_us);
  counters_.clock_restarts.store(stamper_.clock().resets());
}

void Lms100Session::count_rejection(const ScanPlausibility& verdict) {
  ++counters_.implausible_scans;
  switch (verdict.reason) {
    case ScanImplausibility::kNone:
      return;
    case ScanImplausibility::kLayerAngle:
      ++counters_.multi_layer_scans;
      break;
    case ScanImplausibility::kScale:
      ++counters_.implausible_scale;
      break;
    case ScanImplausibility::kOffset:
      ++counters_.implausible_offset;
      break;
    case ScanImplausibility::kScanFrequency:
      ++counters_.implausible_scan_frequency;
      break;
    case ScanImplausibility::kBeamCount:
      ++counters_.implausible_beam_count;
      break;
    case ScanImplausibility::kAngles:
      ++counters_.implausible_angles;
      break;
    case ScanImplausibility::kBeamTiming:
      ++counters_.implausible_beam_timing;
      break;
  }
  if (on_rejected_) on_rejected_(verdict);
}

void Lms100Session::stop_streaming_politely() {
  // The stop pipe stays readable, so wait on the link alone for these last replies.
  const int saved = wake_pipe_[0];
  wake_pipe_[0] = -1;
  const bool was_stopped = stop_.exchange(false);
  std::string reply;
  std::string why;
  transact(request_scandata_stream(false), config_.stop_reply_timeout_s, reply, why);
  if (transact(request_login(), config_.stop_reply_timeout_s, reply, why) == Wait::kReply) {
    transact(request_stop_measurement(), config_.stop_reply_timeout_s, reply, why);
  }
  stop_.store(was_stopped || stop_.load());
  wake_pipe_[0] = saved;
}

void Lms100Session::sync_wire_counters() {
  counters_.garbage_bytes.store(wire_.garbage_bytes());
  counters_.resyncs.store(wire_.resyncs());
  counters_.oversized_frames.store(wire_.oversized_frames());
}

}  // namespace refloc
