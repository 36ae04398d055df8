#include "eval_plot.hpp"

#include "common/child_program.hpp"
#include "common/program_version.hpp"

#include <fmt/format.h>

namespace refloc {

std::string paper_reported_errors_csv() {
  const int errors_mm[30][2] = {
      {5, 10},   {-12, 9},  {12, 13}, {8, 11}, {-9, 12}, {17, -14}, {10, -11}, {6, 9},   {-11, 15}, {7, 11},
      {10, 9},   {-12, 15}, {20, 9},  {-9, 7}, {6, 10},  {-6, 7},   {6, 11},   {8, 10},  {60, 15},  {7, 8},
      {-10, 13}, {14, 17},  {23, 8},  {9, 4},  {15, 1},  {-10, 18}, {12, 11},  {16, 19}, {11, 13},  {12, 15}};
  std::string csv = "err_x_mm,err_y_mm\n";
  for (const auto& e : errors_mm) csv += fmt::format("{},{}\n", e[0], e[1]);
  return csv;
}

int run_refloc_plot(const std::vector<std::string>& args) {
  // The script's #!/usr/bin/python3 is Debian's, where python3-matplotlib is installed.
  std::vector<std::string> words = {shipped_path("tools/refloc-plot/refloc-plot.py")};
  words.insert(words.end(), args.begin(), args.end());
  return run_child_program(words);
}

}  // namespace refloc
