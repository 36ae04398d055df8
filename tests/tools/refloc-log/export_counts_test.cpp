// What refloc-log prints on stderr after an export: lines and channels of the JSON lines,
// one line per CSV file, rows skipped, and a warning when --channel matched nothing.

#include "log_analysis.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(ExportCounts, JsonlAndCsvCountsAndFiles) {
  LogExportRequest request;
  request.jsonl_path = "out.jsonl";
  request.csv_path = "out.csv";
  LogExportResult result;
  result.channels = {"POSE", "LASER_POSE"};
  result.jsonl.written = 120;
  result.jsonl.undecoded = 2;
  result.csv.written = 118;
  result.csv.undecoded = 2;
  result.csv.type_changed = 1;
  result.csv_files = {{"LASER_POSE", "out_LASER_POSE.csv"}, {"POSE", "out_POSE.csv"}};
  EXPECT_EQ(format_export_counts(request, result),
            "out.jsonl: 120 lines (2 not decodable) from 2 channels\n"
            "out_LASER_POSE.csv: channel LASER_POSE\n"
            "out_POSE.csv: channel POSE\n"
            "CSV: 118 rows, 2 not decodable (skipped), 1 of a changed type (skipped)\n");
}

TEST(ExportCounts, NoMatchingChannelIsAWarning) {
  LogExportRequest request;
  request.jsonl_path = "out.jsonl";
  const std::string text = format_export_counts(request, LogExportResult{});
  EXPECT_NE(text.find("refloc-log: warning: no channel of the log matches --channel\n"), std::string::npos)
      << text;
}

TEST(ExportCounts, NothingExportedPrintsNothing) {
  EXPECT_EQ(format_export_counts(LogExportRequest{}, LogExportResult{}), "");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
