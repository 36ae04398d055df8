#pragma once
// Reflector lists as CSV, for total-station surveys and spreadsheets (tools/refloc-map/README.md).
// Import: id,x,y[,radius_m][,sigma_m] by position, or any of the columns below named in a header
// line; '#' starts a comment. Export: id,x,y,radius_m,sigma_x_m,sigma_y_m,correlation_xy,type,
// which import reads back (the same numbers: shortest round-trip text).

#include "common/reflector_map.hpp"

#include <string>

namespace refloc {

/// What import adds that the CSV does not say.
struct CsvImportOptions {
  std::string map_id;              ///< the v2 header's map_id (refloc-map: the CSV file's stem)
  double default_radius_m = 0.06;  ///< radius of rows without radius_m [m]
};

/// The columns import knows, in export's order: id, x, y, radius_m, sigma_m, sigma_x_m, sigma_y_m,
/// correlation_xy, type.
const std::vector<std::string>& reflector_csv_columns();

/// A v2 map (source "imported", version 1, created now, no occluders) from CSV text. sigma_m
/// gives an isotropic covariance (sigma_m^2 on the diagonal); sigma_x_m + sigma_y_m (+
/// correlation_xy) a full one. Throws ConfigError "<source>:<line>: <reason>" for a bad line, and
/// names the line of a reflector the map reader refuses (two touching, fewer than 3).
ReflectorMap import_reflector_csv(const std::string& text, const std::string& source,
                                  const CsvImportOptions& options);

/// The reflectors as CSV with a header line: id,x,y,radius_m,sigma_x_m,sigma_y_m,correlation_xy,type
/// (sigma and correlation empty where the covariance is unknown; type quoted when it must be).
std::string reflector_csv_text(const ReflectorMap& map);

}  // namespace refloc
