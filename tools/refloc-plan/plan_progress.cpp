#include "plan_progress.hpp"

#include <fmt/format.h>

namespace refloc {

PlanProgressBar::PlanProgressBar(std::FILE* out, std::string label, bool terminal)
    : out_(out), label_(std::move(label)), terminal_(terminal) {}

void PlanProgressBar::update(size_t done, size_t total) {
  const int percent = total == 0 ? 100 : static_cast<int>(100 * done / total);
  if (percent == last_percent_ || (!terminal_ && percent / 10 == last_percent_ / 10 && done != total)) return;
  last_percent_ = percent;
  if (terminal_) {
    const int filled = percent * 40 / 100;
    fmt::print(out_, "\r{} [{}{}] {:3d} % ({}/{})", label_, std::string(static_cast<size_t>(filled), '#'),
               std::string(static_cast<size_t>(40 - filled), ' '), percent, done, total);
    if (done == total) fmt::print(out_, "\n");
  } else {
    fmt::print(out_, "{} {} % ({}/{})\n", label_, percent, done, total);
  }
  std::fflush(out_);
}

}  // namespace refloc
