#include "refresh_schedule.hpp"

#include <algorithm>

namespace refloc {

RefreshSchedule::RefreshSchedule(double start_s, bool once, double wait_s)
    : once_(once), next_s_(once ? start_s + wait_s : start_s + 1.0) {}

bool RefreshSchedule::due(double now_s) {
  if (done_ || now_s < next_s_) return false;
  if (once_) {
    done_ = true;
    return true;
  }
  next_s_ += 1.0;
  if (next_s_ < now_s) next_s_ = now_s + 1.0;
  return true;
}

double RefreshSchedule::seconds_until_due(double now_s) const { return std::max(0.0, next_s_ - now_s); }

}  // namespace refloc
