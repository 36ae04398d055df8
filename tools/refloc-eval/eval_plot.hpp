#pragma once
// refloc-eval's pictures: the study's CSV (and the paper's own Table 1 errors) drawn by
// tools/refloc-plot with matplotlib, a separate program so the C++ tools need no plotting library.

#include <string>
#include <vector>

namespace refloc {

/// The paper's own Table 1 errors (measured minus actual) as "err_x_mm,err_y_mm" rows [mm].
std::string paper_reported_errors_csv();

/// Runs `<refloc root>/tools/refloc-plot/refloc-plot.py args...` and waits for it.
/// Returns its exit status; -1 when it could not be started (no script or no /usr/bin/python3).
int run_refloc_plot(const std::vector<std::string>& args);

}  // namespace refloc
