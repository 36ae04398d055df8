#pragma once
// The progress of a static survey on stderr: a bar redrawn in place on a terminal, else (a log
// file, a pipe, CI) one line every 10 %, so a log does not fill with carriage returns.

#include <cstdio>
#include <string>

namespace refloc {

class SurveyProgress {
 public:
  /// total: scans wanted; terminal: redraw a bar (isatty), else lines at every 10 %.
  SurveyProgress(std::FILE* out, int total, bool terminal);
  /// done scans of total, found reflectors in the last scan.
  void update(int done, int found);
  /// Ends the bar's line (terminal only).
  void finish();

 private:
  std::FILE* out_;
  int total_;
  bool terminal_;
  int last_decile_ = -1;
  bool drawn_ = false;
};

}  // namespace refloc
