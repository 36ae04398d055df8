#include "lms100_driver/lmd_scandata_parser.hpp"

#include <cstring>
#include <string>

#include "lms100_driver/cola_a_tokenizer.hpp"

namespace refloc {

const LmdChannel* LmdScanData::find_channel(const char* channel_name, int* bits) const {
  for (const auto& c : channels16) {
    if (c.name == channel_name) {
      if (bits) *bits = 16;
      return &c;
    }
  }
  for (const auto& c : channels8) {
    if (c.name == channel_name) {
      if (bits) *bits = 8;
      return &c;
    }
  }
  return nullptr;
}

bool is_lmd_scandata(std::string_view payload) {
  return payload.rfind("sSN LMDscandata ", 0) == 0 || payload.rfind("sRA LMDscandata ", 0) == 0;
}

namespace {

/// Walks the telegram field by field; the first failure records which field it was.
class LmdParser {
 public:
  LmdParser(std::string_view payload, LmdScanData& out, const LmdParseLimits& limits)
      : tok_(payload), out_(out), limits_(limits) {}

  ParseResult run() {
    if (!header() || !device_block() || !frequency_block() || !encoder_block() ||
        !channel_block(16, out_.channels16) || !channel_block(8, out_.channels8) || !trailer()) {
      return ParseResult::failure(std::string("LMDscandata field '") + field_ + "' near token " +
                                  std::to_string(tok_.tokens_read()) + ": " + message());
    }
    if (!tok_.at_end()) {
      return ParseResult::failure("LMDscandata: " + std::to_string(tok_.remaining_chars()) +
                                  " characters left after the event block (a count field is wrong)");
    }
    return ParseResult::success();
  }

 private:
  bool u32(const char* field, uint32_t& v, uint32_t max = 0xFFFFFFFFu) {
    field_ = field;
    return tok_.hex_u32(v, max);
  }
  bool flag(const char* field, bool& v) {
    uint32_t raw = 0;
    if (!u32(field, raw, 1)) return false;
    v = raw == 1;
    return true;
  }

  bool header() {
    field_ = "command type";
    std::string_view t;
    if (!tok_.token(t)) return false;
    if (t == "sSN") {
      out_.is_stream_event = true;
    } else if (t == "sRA") {
      out_.is_stream_event = false;
    } else {
      return fail_here("expected sSN or sRA");
    }
    field_ = "command name";
    if (!tok_.token(t)) return false;
    if (t != "LMDscandata") return fail_here("expected LMDscandata");
    return true;
  }

  bool device_block() {
    return u32("version", out_.version, 0xFFFF) && u32("device number", out_.device_number, 0xFFFF) &&
           u32("serial number", out_.serial_number) && u32("device status", out_.device_status[0], 0xFF) &&
           u32("device status", out_.device_status[1], 0xFF) &&
           u32("telegram counter", out_.telegram_counter, 0xFFFF) &&
           u32("scan counter", out_.scan_counter, 0xFFFF) &&
           u32("time since start-up", out_.time_since_startup_us) &&
           u32("time of transmission", out_.time_of_transmission_us) &&
           u32("digital inputs", out_.digital_inputs[0], 0xFF) &&
           u32("digital inputs", out_.digital_inputs[1], 0xFF) &&
           u32("digital outputs", out_.digital_outputs[0], 0xFF) &&
           u32("digital outputs", out_.digital_outputs[1], 0xFF) &&
           u32("reserved/layer angle", out_.reserved_layer_angle, 0xFFFF);
  }

  bool frequency_block() {
    return u32("scan frequency", out_.scan_frequency_1e2hz) &&
           u32("measurement frequency", out_.measurement_frequency_1e1khz);
  }

  bool encoder_block() {
    uint32_t count = 0;
    if (!u32("number of encoders", count, 0xFFFF)) return false;
    if (count > limits_.max_encoders) return fail_here("more encoders than the limit");
    out_.encoders.resize(count);
    for (auto& e : out_.encoders) {
      if (!u32("encoder position", e.position_ticks) || !u32("encoder speed", e.speed_ticks_per_mm, 0xFFFF)) {
        return false;
      }
    }
    return true;
  }

  bool channel_block(int bits, std::vector<LmdChannel>& channels) {
    uint32_t count = 0;
    if (!u32(bits == 16 ? "number of 16-bit channels" : "number of 8-bit channels", count, 0xFFFF))
      return false;
    if (count > limits_.max_channels) return fail_here("more channels than the limit");
    channels.resize(count);
    for (auto& c : channels) {
      if (!channel(bits, c)) return false;
    }
    return true;
  }

  bool channel(int bits, LmdChannel& c) {
    field_ = "channel name";
    std::string_view name;
    if (!tok_.token(name)) return false;
    if (name.size() != 5) return fail_here("channel name must have 5 characters");
    c.name.assign(name);
    field_ = "scale factor";
    if (!tok_.hex_float(c.scale)) return false;
    field_ = "scale offset";
    if (!tok_.hex_float(c.offset)) return false;
    field_ = "start angle";
    if (!tok_.hex_i32(c.start_angle_1e4deg)) return false;
    uint32_t count = 0;
    if (!u32("angular step", c.step_1e4deg, 0xFFFF) || !u32("number of data", count, 0xFFFF)) return false;
    // Each value needs at least one digit and one space: a count beyond that is a lie.
    if (count > tok_.remaining_chars() / 2 + 1) return fail_here("number of data exceeds the telegram");
    c.values.resize(count);
    const uint32_t max_value = bits == 16 ? 0xFFFFu : 0xFFu;
    for (auto& v : c.values) {
      uint32_t raw = 0;
      if (!u32("data value", raw, max_value)) return false;
      v = static_cast<uint16_t>(raw);
    }
    return true;
  }

  bool trailer() {
    if (!flag("position flag", out_.has_position)) return false;
    if (out_.has_position) {
      auto& p = out_.position;
      field_ = "position";
      if (!tok_.hex_float(p.x) || !tok_.hex_float(p.y) || !tok_.hex_float(p.z) ||
          !tok_.hex_float(p.x_rotation) || !tok_.hex_float(p.y_rotation) || !tok_.hex_float(p.z_rotation) ||
          !u32("rotation type", p.rotation_type, 0xFF) || !u32("transmits name", p.transmits_name, 0xFF)) {
        return false;
      }
    }
    if (!flag("name flag", out_.has_name)) return false;
    field_ = "device name";
    if (out_.has_name && !tok_.length_prefixed_string(out_.name)) return false;
    if (!flag("comment flag", out_.has_comment)) return false;
    field_ = "comment";
    if (out_.has_comment && !tok_.length_prefixed_string(out_.comment)) return false;
    if (!flag("time info flag", out_.has_time_info)) return false;
    if (out_.has_time_info) {
      auto& t = out_.time_info;
      if (!u32("year", t.year, 0xFFFF) || !u32("month", t.month, 0xFF) || !u32("day", t.day, 0xFF) ||
          !u32("hour", t.hour, 0xFF) || !u32("minute", t.minute, 0xFF) || !u32("second", t.second, 0xFF) ||
          !u32("microsecond", t.microsecond)) {
        return false;
      }
    }
    if (!flag("event flag", out_.has_event)) return false;
    if (out_.has_event) {
      field_ = "event type";
      std::string_view type;
      if (!tok_.token(type)) return false;
      out_.event.type.assign(type);
      if (!u32("event encoder position", out_.event.encoder_position) ||
          !u32("event time", out_.event.time_us)) {
        return false;
      }
      field_ = "event angle";
      if (!tok_.hex_i32(out_.event.angle_1e4deg)) return false;
    }
    return true;
  }

  /// A semantic error found by the parser rather than the tokenizer.
  bool fail_here(const char* why) {
    custom_error_ = why;
    has_custom_error_ = true;
    return false;
  }

  std::string message() const { return has_custom_error_ ? std::string(custom_error_) : tok_.error(); }

 private:
  ColaATokenizer tok_;
  LmdScanData& out_;
  const LmdParseLimits& limits_;
  const char* field_ = "";
  const char* custom_error_ = "";
  bool has_custom_error_ = false;
};

}  // namespace

ParseResult parse_lmd_scandata(std::string_view payload, LmdScanData& out, const LmdParseLimits& limits) {
  LmdParser parser(payload, out, limits);
  return parser.run();
}

}  // namespace refloc
