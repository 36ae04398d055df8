#pragma once
// refloc-status's text table. The default fits a 100-column terminal: one row per service with
// state, rates, p99, heartbeat age, how many error counters are non-zero and the state detail
// (cut to fit); the error counters themselves, and details that were cut, follow below the
// table. --wide prints every column on one row per service, however long.

#include "heartbeat_table.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace refloc {

/// The width the default table and everything printed with it fit.
constexpr size_t kStatusColumns = 100;

/// The table with its summary lines (alive / MISSING or stale / IN ERROR / RUNNING MORE THAN
/// ONCE) and, unless wide, the errors and details sections below it.
std::string format_status_table(const std::vector<ServiceStatus>& rows, bool wide = false);

/// Every line longer than width broken at spaces (a word longer than the width at the width),
/// continuation lines indented by four spaces.
std::string wrap_to_width(const std::string& text, size_t width = kStatusColumns);

}  // namespace refloc
