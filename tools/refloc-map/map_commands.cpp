#include "map_commands.hpp"

#include "common/bounded_file_read.hpp"
#include "common/json_config.hpp"
#include "common/output_file.hpp"
#include "reflector_csv.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace refloc {
namespace {

void print_warnings(const ReflectorMap& map) {
  for (const std::string& w : map.warnings) std::fprintf(stderr, "refloc-map: warning: %s\n", w.c_str());
}

long count_with_covariance(const ReflectorMap& map) {
  return std::count_if(map.reflectors.begin(), map.reflectors.end(),
                       [](const MapReflector& r) { return r.map_cov_center.has_value(); });
}

// The larger standard deviation of a 2x2 covariance: its largest eigenvalue's root [m].
double major_sigma(const Eigen::Matrix2d& c) {
  const double mean = 0.5 * (c(0, 0) + c(1, 1));
  const double half_difference = 0.5 * (c(0, 0) - c(1, 1));
  return std::sqrt(mean + std::hypot(half_difference, c(0, 1)));
}

}  // namespace

CLI::App* add_import_command(CLI::App& app, ImportCommandOptions& o) {
  CLI::App* command = app.add_subcommand(
      "import", "a format-2 map (source imported, version 1) from a CSV of id,x,y[,radius_m][,sigma_m]");
  command->add_option("--csv", o.csv_path, "the CSV file (tools/refloc-map/README.md)")->required();
  command->add_option("--out", o.out_path, "the map file to write")->required();
  command->add_option("--map-id", o.map_id, "the map's id (default: the CSV file's name without extension)");
  command->add_option("--default-radius-m", o.default_radius_m, "radius of rows without radius_m [m]")
      ->check(CLI::Range(1e-3, 5.0))
      ->capture_default_str();
  command->add_flag("--force", o.force, "replace an existing --out file");
  return command;
}

int run_import_command(const ImportCommandOptions& o) {
  refuse_to_replace(o.out_path, o.force);
  CsvImportOptions options;
  options.map_id = o.map_id.empty() ? std::filesystem::path(o.csv_path).stem().string() : o.map_id;
  options.default_radius_m = o.default_radius_m;
  const ReflectorMap map =
      import_reflector_csv(json_config_detail::read_bounded_file(o.csv_path), o.csv_path, options);
  print_warnings(map);
  write_reflector_map(map, o.out_path);
  fmt::print("{}: map {} version 1, imported, {} reflectors ({} with covariance)\n", o.out_path,
             map.info.map_id, map.reflectors.size(), count_with_covariance(map));
  return 0;
}

CLI::App* add_export_command(CLI::App& app, ExportCommandOptions& o) {
  CLI::App* command = app.add_subcommand(
      "export", "a map's reflectors as CSV: id,x,y,radius_m,sigma_x_m,sigma_y_m,correlation_xy,type");
  command->add_option("--map", o.map_path, "the map file (format 1 or 2)")->required();
  command->add_option("--csv", o.csv_path, "the CSV file to write")->required();
  command->add_flag("--force", o.force, "replace an existing --csv file");
  return command;
}

int run_export_command(const ExportCommandOptions& o) {
  const ReflectorMap map = load_reflector_map(o.map_path);
  refuse_to_replace(o.csv_path, o.force);
  std::ofstream out(o.csv_path, std::ios::binary | std::ios::trunc);
  out << reflector_csv_text(map);
  out.close();
  if (!out) throw std::runtime_error(fmt::format("{}: cannot write", o.csv_path));
  fmt::print("{}: {} reflectors ({} with covariance)\n", o.csv_path, map.reflectors.size(),
             count_with_covariance(map));
  return 0;
}

CLI::App* add_info_command(CLI::App& app, InfoCommandOptions& o) {
  CLI::App* command = app.add_subcommand("info", "what a map file holds: header, counts, extent, accuracy");
  command->add_option("--map", o.map_path, "the map file (format 1 or 2)")->required();
  return command;
}

int run_info_command(const InfoCommandOptions& o) {
  const ReflectorMap map = load_reflector_map(o.map_path);
  fmt::print("{}: {}", o.map_path, map_info_text(map));
  return 0;
}

std::string map_info_text(const ReflectorMap& map) {
  std::string text = map.info.format == 1
                         ? "format 1 (no header)\n"
                         : fmt::format("format 2, map {} version {}, {}, created {}\n", map.info.map_id,
                                       map.info.version, map.info.source, map.info.created);
  const long with = count_with_covariance(map);
  text += fmt::format("{} reflectors ({} with covariance, {} without), {} occluders\n", map.reflectors.size(),
                      with, static_cast<long>(map.reflectors.size()) - with, map.occluders.size());
  Eigen::Vector2d low = map.reflectors.front().map_p_center;
  Eigen::Vector2d high = low;
  std::vector<std::pair<double, int>> sigmas;
  for (const MapReflector& r : map.reflectors) {
    low = low.cwiseMin(r.map_p_center);
    high = high.cwiseMax(r.map_p_center);
    if (r.map_cov_center) sigmas.emplace_back(major_sigma(*r.map_cov_center), r.id);
  }
  text += fmt::format("reflectors span x [{:.3f}, {:.3f}] m, y [{:.3f}, {:.3f}] m\n", low.x(), high.x(),
                      low.y(), high.y());
  if (!sigmas.empty()) {
    std::sort(sigmas.begin(), sigmas.end());
    text +=
        fmt::format("largest sigma of a centre: median {:.2f} mm, worst {:.2f} mm (id {})\n",
                    sigmas[sigmas.size() / 2].first * 1e3, sigmas.back().first * 1e3, sigmas.back().second);
  }
  for (const std::string& w : map.warnings) text += "warning: " + w + "\n";
  return text;
}

}  // namespace refloc
