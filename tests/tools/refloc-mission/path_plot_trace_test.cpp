// The CSV refloc-mission writes beside the log for tools/refloc-plot: one row per sample and
// per waypoint, times from the start of driving, errors in mm, empty where unknown.

#include "path_plot_trace.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(PathTraceCsv, RowsPerSampleAndWaypointWithTimesFromTheStartAndErrorsInMm) {
  PathTrace trace;
  trace.start_utime = 1'000'000;
  trace.samples = {{"GROUND_TRUTH", 1'000'000, {1.0, 2.0, 0.5}, NAN},
                   {"LASER_POSE", 1'250'000, {1.001, 2.0, 0.5}, 0.0012345}};
  trace.waypoints = {{{3.0, 4.0, 1.0}, true, 3'500'000, 0.0042}, {{5.0, 6.0, 0.0}, false, 0, NAN}};
  EXPECT_EQ(path_trace_csv(trace),
            "kind,t_s,x_m,y_m,theta_rad,error_mm\n"
            "GROUND_TRUTH,0.0000,1.00000,2.00000,0.500000,\n"
            "LASER_POSE,0.2500,1.00100,2.00000,0.500000,1.234\n"
            "WAYPOINT,2.5000,3.00000,4.00000,1.000000,4.200\n"
            "WAYPOINT,,5.00000,6.00000,0.000000,\n");
}

TEST(PathTraceCsv, UnwritablePathIsReported) {
  EXPECT_FALSE(write_path_trace_csv("/nonexistent-dir/trace.csv", PathTrace{}));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
