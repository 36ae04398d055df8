#include "reflector_matcher/startup_relocalization.hpp"

namespace refloc {

StartupRelocalization::StartupRelocalization(double window)
    : window_us_(static_cast<int64_t>(window * 1e6)), gave_up_(window <= 0.0) {}

bool StartupRelocalization::prior_allowed(int64_t scan_utime) {
  if (done()) return true;
  if (first_scan_utime_ < 0) first_scan_utime_ = scan_utime;
  if (scan_utime - first_scan_utime_ > window_us_) gave_up_ = true;
  return gave_up_;
}

void StartupRelocalization::on_result(MatchStatus status, MatchMode mode) {
  if (!done() && status == MatchStatus::kOk && mode == MatchMode::kGlobal) relocalized_ = true;
}

}  // namespace refloc
