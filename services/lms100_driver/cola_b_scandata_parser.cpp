#include "lms100_driver/cola_b_scandata_parser.hpp"

#include "common/cola_a_framing.hpp"

#include <cstring>
#include <string>

namespace refloc {

namespace {

/// Big-endian reader that fails instead of reading past the end.
class BigEndianReader {
 public:
  explicit BigEndianReader(std::string_view data) : data_(data) {}
  bool u8(uint32_t& v) { return read(1, v); }
  bool u16(uint32_t& v) { return read(2, v); }
  bool u32(uint32_t& v) { return read(4, v); }
  bool i32(int32_t& v) {
    uint32_t bits = 0;
    if (!u32(bits)) return false;
    std::memcpy(&v, &bits, sizeof v);
    return true;
  }
  bool f32(float& v) {
    uint32_t bits = 0;
    if (!u32(bits)) return false;
    std::memcpy(&v, &bits, sizeof v);
    return true;
  }
  bool bytes(size_t n, std::string_view& out) {
    if (n > data_.size() - pos_) return false;
    out = data_.substr(pos_, n);
    pos_ += n;
    return true;
  }
  size_t remaining() const { return data_.size() - pos_; }
  size_t position() const { return pos_; }

 private:
  bool read(size_t n, uint32_t& v) {
    if (n > data_.size() - pos_) return false;
    v = 0;
    for (size_t i = 0; i < n; ++i) v = (v << 8) | static_cast<uint8_t>(data_[pos_ + i]);
    pos_ += n;
    return true;
  }
  std::string_view data_;
  size_t pos_ = 0;
};

ParseResult fail_at(const char* field, const BigEndianReader& r) {
  return ParseResult::failure(std::string("CoLa-B LMDscandata field '") + field + "' at byte " +
                              std::to_string(r.position()) + ": telegram ends early or value is invalid");
}

bool read_channel(BigEndianReader& r, int bits, LmdChannel& c, const char*& field) {
  std::string_view name;
  field = "channel name";
  if (!r.bytes(5, name)) return false;
  c.name.assign(name);
  field = "channel header";
  uint32_t step = 0;
  uint32_t count = 0;
  if (!r.f32(c.scale) || !r.f32(c.offset) || !r.i32(c.start_angle_1e4deg) || !r.u16(step) || !r.u16(count)) {
    return false;
  }
  c.step_1e4deg = step;
  field = "channel data";
  const size_t width = bits == 16 ? 2 : 1;
  if (count * width > r.remaining()) return false;  // sized from the count, checked before allocating
  c.values.resize(count);
  for (auto& v : c.values) {
    uint32_t raw = 0;
    if (!(bits == 16 ? r.u16(raw) : r.u8(raw))) return false;
    v = static_cast<uint16_t>(raw);
  }
  return true;
}

bool read_string(BigEndianReader& r, std::string& out) {
  uint32_t length = 0;
  std::string_view chars;
  if (!r.u16(length) || !r.bytes(length, chars)) return false;
  out.assign(chars);
  return true;
}

}  // namespace

ParseResult unframe_cola_b(std::string_view frame, std::string_view& payload) {
  if (frame.size() < cola::kColaBOverheadBytes ||
      frame.substr(0, cola::kColaBMagic.size()) != cola::kColaBMagic) {
    return ParseResult::failure("CoLa-B frame: no 02020202 magic");
  }
  BigEndianReader header(frame.substr(cola::kColaBMagic.size(), 4));
  uint32_t length = 0;
  header.u32(length);
  if (length != frame.size() - cola::kColaBOverheadBytes) {
    return ParseResult::failure("CoLa-B frame: length field " + std::to_string(length) + " but " +
                                std::to_string(frame.size() - cola::kColaBOverheadBytes) + " payload bytes");
  }
  payload = frame.substr(cola::kColaBHeaderBytes, length);
  uint8_t checksum = 0;
  for (const char c : payload) checksum ^= static_cast<uint8_t>(c);
  if (checksum != static_cast<uint8_t>(frame.back()))
    return ParseResult::failure("CoLa-B frame: wrong XOR checksum");
  return ParseResult::success();
}

ParseResult parse_lmd_scandata_cola_b(std::string_view payload, LmdScanData& out) {
  if (payload.rfind("sSN LMDscandata ", 0) == 0) {
    out.is_stream_event = true;
  } else if (payload.rfind("sRA LMDscandata ", 0) == 0) {
    out.is_stream_event = false;
  } else {
    return ParseResult::failure("CoLa-B payload is not LMDscandata");
  }
  BigEndianReader r(payload.substr(16));
  const char* field = "device block";
  uint32_t n = 0;
  bool ok = r.u16(out.version) && r.u16(out.device_number) && r.u32(out.serial_number) &&
            r.u8(out.device_status[0]) && r.u8(out.device_status[1]) && r.u16(out.telegram_counter) &&
            r.u16(out.scan_counter) && r.u32(out.time_since_startup_us) &&
            r.u32(out.time_of_transmission_us) && r.u8(out.digital_inputs[0]) &&
            r.u8(out.digital_inputs[1]) && r.u8(out.digital_outputs[0]) && r.u8(out.digital_outputs[1]) &&
            r.u16(out.reserved_layer_angle) && r.u32(out.scan_frequency_1e2hz) &&
            r.u32(out.measurement_frequency_1e1khz);
  if (!ok) return fail_at(field, r);
  field = "encoders";
  if (!r.u16(n) || n > 8) return fail_at(field, r);
  out.encoders.resize(n);
  for (auto& e : out.encoders) {
    if (!r.u32(e.position_ticks) || !r.u16(e.speed_ticks_per_mm)) return fail_at(field, r);
  }
  for (const int bits : {16, 8}) {
    auto& channels = bits == 16 ? out.channels16 : out.channels8;
    field = bits == 16 ? "number of 16-bit channels" : "number of 8-bit channels";
    if (!r.u16(n) || n > 16) return fail_at(field, r);
    channels.resize(n);
    for (auto& c : channels) {
      if (!read_channel(r, bits, c, field)) return fail_at(field, r);
    }
  }
  field = "position";
  if (!r.u16(n) || n > 1) return fail_at(field, r);
  out.has_position = n == 1;
  if (out.has_position) {
    auto& p = out.position;
    if (!r.f32(p.x) || !r.f32(p.y) || !r.f32(p.z) || !r.f32(p.x_rotation) || !r.f32(p.y_rotation) ||
        !r.f32(p.z_rotation) || !r.u8(p.rotation_type) || !r.u8(p.transmits_name)) {
      return fail_at(field, r);
    }
  }
  field = "device name";
  if (!r.u16(n) || n > 1) return fail_at(field, r);
  out.has_name = n == 1;
  if (out.has_name && !read_string(r, out.name)) return fail_at(field, r);
  field = "comment";
  if (!r.u16(n) || n > 1) return fail_at(field, r);
  out.has_comment = n == 1;
  if (out.has_comment && !read_string(r, out.comment)) return fail_at(field, r);
  field = "time info";
  if (!r.u16(n) || n > 1) return fail_at(field, r);
  out.has_time_info = n == 1;
  if (out.has_time_info) {
    auto& t = out.time_info;
    if (!r.u16(t.year) || !r.u8(t.month) || !r.u8(t.day) || !r.u8(t.hour) || !r.u8(t.minute) ||
        !r.u8(t.second) || !r.u32(t.microsecond)) {
      return fail_at(field, r);
    }
  }
  field = "event";
  if (!r.u16(n) || n > 1) return fail_at(field, r);
  out.has_event = n == 1;
  if (out.has_event) {
    std::string_view type;
    if (!r.bytes(4, type) || !r.u32(out.event.encoder_position) || !r.u32(out.event.time_us) ||
        !r.i32(out.event.angle_1e4deg)) {
      return fail_at(field, r);
    }
    out.event.type.assign(type);
  }
  if (r.remaining() != 0) {
    return ParseResult::failure("CoLa-B LMDscandata: " + std::to_string(r.remaining()) +
                                " bytes left after the event block (a count field is wrong)");
  }
  return ParseResult::success();
}

}  // namespace refloc
