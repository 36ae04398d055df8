#pragma once
// How refloc-status shows the heartbeat table: a fixed-width text table for a
// terminal, or one JSON document for scripts.

#include "heartbeat_table.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace refloc {

/// The text table, one line per service, with a summary line naming missing services.
std::string format_status_table(const std::vector<ServiceStatus>& rows);

/// {"ok", "missing": [...], "services": [{...}]}; unknown rates and ages are null.
nlohmann::json status_to_json(const std::vector<ServiceStatus>& rows);

/// One refresh as printed: the JSON on one line (with "heartbeat_decode_errors"), or the
/// table (after a clear-screen sequence when clear_screen) and a line about undecodable
/// HEARTBEATs when there were any.
std::string format_status(const std::vector<ServiceStatus>& rows, int64_t heartbeat_decode_errors, bool json,
                          bool clear_screen);

}  // namespace refloc
