#pragma once
// Parses an LMDscandata CoLa-A payload (without STX/ETX) into LmdScanData.

#include <string_view>

#include "lms100_driver/lmd_scandata.hpp"
#include "lms100_driver/parse_result.hpp"

namespace refloc {

/// Limits that keep a corrupt telegram from asking for absurd sizes.
struct LmdParseLimits {
  uint32_t max_channels = 16;  ///< per block
  uint32_t max_encoders = 8;
};

/// True when the payload is an LMDscandata telegram ("sSN LMDscandata ..." or "sRA LMDscandata ...").
bool is_lmd_scandata(std::string_view payload);

/// Decodes every field in order. out's vectors keep their capacity between calls, so
/// parsing scans of the same shape does not allocate. On failure out is partly filled
/// and the result names the field that is wrong.
ParseResult parse_lmd_scandata(std::string_view payload, LmdScanData& out, const LmdParseLimits& limits = {});

}  // namespace refloc
