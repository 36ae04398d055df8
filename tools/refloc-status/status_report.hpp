#pragma once
// One refresh of refloc-status: the table (status_table.hpp) and the pose line for a terminal,
// or one JSON document for scripts.

#include "heartbeat_table.hpp"
#include "pose_watch.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace refloc {

/// What one refresh shows.
struct StatusPage {
  std::vector<ServiceStatus> rows;
  int64_t heartbeat_decode_errors = 0;  ///< HEARTBEATs refloc-status could not decode
  std::optional<PoseReport> pose;       ///< the pose line; none: not shown
};

struct PageStyle {
  bool json = false;          ///< one JSON document on one line instead of the table
  bool clear_screen = false;  ///< live mode: clear the terminal first
  bool wide = false;          ///< every column, one row per service, no width limit
};

/// {"ok", "missing": [...], "in_error": [...], "services": [{...}]}; unknown rates and ages are
/// null; "error_counters" holds a service's non-zero error counters, "counters" every counter.
nlohmann::json status_to_json(const std::vector<ServiceStatus>& rows);

/// The page as printed: JSON (with "heartbeat_decode_errors" and "pose"), or the table, the pose
/// line and a line about undecodable HEARTBEATs, within 100 columns unless style.wide.
std::string format_status(const StatusPage& page, const PageStyle& style);

}  // namespace refloc
