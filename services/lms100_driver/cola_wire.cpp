#include "lms100_driver/cola_wire.hpp"

#include "lms100_driver/cola_a_format.hpp"
#include "lms100_driver/cola_b_commands.hpp"
#include "lms100_driver/cola_b_scandata_parser.hpp"
#include "lms100_driver/lmd_scandata_parser.hpp"

namespace refloc {

const char* to_string(ColaDialect dialect) { return dialect == ColaDialect::kColaB ? "cola_b" : "cola_a"; }

uint16_t default_port(ColaDialect dialect) { return dialect == ColaDialect::kColaB ? 2112 : 2111; }

ColaWire::ColaWire(ColaDialect dialect, size_t max_frame_bytes)
    : dialect_(dialect), splitter_a_(max_frame_bytes), splitter_b_(max_frame_bytes) {}

ParseResult ColaWire::frame_request(const std::string& request, std::string& bytes) const {
  if (dialect_ == ColaDialect::kColaA) {
    bytes = frame_cola_a(request);
    return ParseResult::success();
  }
  std::string payload;
  if (ParseResult r = encode_cola_b_request(request, payload); !r) return r;
  bytes = frame_cola_b(payload);
  return ParseResult::success();
}

void ColaWire::feed(const uint8_t* data, size_t size) {
  if (dialect_ == ColaDialect::kColaA) {
    splitter_a_.feed(data, size);
  } else {
    splitter_b_.feed(data, size);
  }
}

bool ColaWire::next(std::string& payload) {
  return dialect_ == ColaDialect::kColaA ? splitter_a_.next(payload) : splitter_b_.next(payload);
}

void ColaWire::reset() {
  splitter_a_.reset();
  splitter_b_.reset();
}

ParseResult ColaWire::parse_scan(const std::string& payload, LmdScanData& out) const {
  return dialect_ == ColaDialect::kColaA ? parse_lmd_scandata(payload, out)
                                         : parse_lmd_scandata_cola_b(payload, out);
}

ParseResult ColaWire::to_text(const std::string& payload, std::string& text) const {
  if (dialect_ == ColaDialect::kColaB) return decode_cola_b_reply(payload, text);
  text = payload;
  return ParseResult::success();
}

uint64_t ColaWire::garbage_bytes() const {
  return dialect_ == ColaDialect::kColaA ? splitter_a_.garbage_bytes() : splitter_b_.garbage_bytes();
}
uint64_t ColaWire::resyncs() const {
  return dialect_ == ColaDialect::kColaA ? splitter_a_.resyncs() : splitter_b_.resyncs();
}
uint64_t ColaWire::oversized_frames() const {
  return dialect_ == ColaDialect::kColaA ? splitter_a_.oversized_frames() : splitter_b_.oversized_frames();
}

}  // namespace refloc
