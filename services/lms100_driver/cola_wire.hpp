#pragma once
// The session's view of the link in either dialect: requests out as CoLa-A text, frames in,
// scans parsed by the dialect's own parser, everything else as CoLa-A text. So login, config,
// start, readiness, watchdog and reconnect are one piece of session logic for both
// (docs/lms100-protocol.md §2, §3).

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "lms100_driver/cola_a_splitter.hpp"
#include "lms100_driver/cola_b_splitter.hpp"
#include "lms100_driver/lmd_scandata.hpp"
#include "lms100_driver/parse_result.hpp"

namespace refloc {

enum class ColaDialect { kColaA, kColaB };

/// "cola_a" / "cola_b", the config file's spelling.
const char* to_string(ColaDialect dialect);
/// The port SICK scanners serve the dialect on by convention: 2111 CoLa-A, 2112 CoLa-B.
uint16_t default_port(ColaDialect dialect);

class ColaWire {
 public:
  ColaWire(ColaDialect dialect, size_t max_frame_bytes);

  ColaDialect dialect() const { return dialect_; }
  /// A CoLa-A request framed for the wire; fails only for a request CoLa-B has no layout for.
  ParseResult frame_request(const std::string& cola_a_request, std::string& bytes) const;

  void feed(const uint8_t* data, size_t size);
  /// The next complete frame's payload (either dialect); false if none is complete.
  bool next(std::string& payload);
  void reset();

  /// A payload for which is_lmd_scandata() holds, by the dialect's own parser.
  ParseResult parse_scan(const std::string& payload, LmdScanData& out) const;
  /// Any other payload as the CoLa-A text the reply checks read (the payload itself in CoLa-A).
  ParseResult to_text(const std::string& payload, std::string& text) const;

  uint64_t garbage_bytes() const;
  uint64_t resyncs() const;
  uint64_t oversized_frames() const;

 private:
  ColaDialect dialect_;
  ColaASplitter splitter_a_;
  ColaBSplitter splitter_b_;
};

}  // namespace refloc
