#pragma once
// A progress bar on stderr: redrawn in place on a terminal, else a line every 10 %.

#include <cstddef>
#include <cstdio>
#include <string>

namespace refloc {

class PlanProgressBar {
 public:
  PlanProgressBar(std::FILE* out, std::string label, bool terminal);
  /// done of total steps.
  void update(size_t done, size_t total);

 private:
  std::FILE* out_;
  std::string label_;
  bool terminal_;
  int last_percent_ = -1;
};

}  // namespace refloc
