#include "static_progress.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace refloc {

SurveyProgress::SurveyProgress(std::FILE* out, int total, bool terminal)
    : out_(out), total_(std::max(total, 1)), terminal_(terminal) {}

void SurveyProgress::update(int done, int found) {
  const int percent = std::clamp(done * 100 / total_, 0, 100);
  if (terminal_) {
    constexpr int kWidth = 30;
    const int filled = percent * kWidth / 100;
    fmt::print(out_, "\rscans [{}{}] {:>3} % {}/{}, {} reflectors in the last", std::string(filled, '#'),
               std::string(kWidth - filled, '.'), percent, done, total_, found);
    std::fflush(out_);
    drawn_ = true;
    return;
  }
  const int decile = percent / 10;
  if (decile == last_decile_) return;
  last_decile_ = decile;
  fmt::print(out_, "scans {:>3} % ({}/{}), {} reflectors in the last\n", decile * 10, done, total_, found);
  std::fflush(out_);
}

void SurveyProgress::finish() {
  if (terminal_ && drawn_) fmt::print(out_, "\n");
  drawn_ = false;
}

}  // namespace refloc
