#pragma once
// refloc-map's subcommands: their options and what they run (main.cpp only dispatches).
// import and export convert between CSV and format-2 maps, info describes a map. A subcommand is
// a pair add_<name>_command (options into a struct) / run_<name>_command; `update` (the next
// version from MAP_HEALTH evidence) and `merge` (several surveys) are in their own files.

#include "common/reflector_map.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace refloc {

struct ImportCommandOptions {
  std::string csv_path;
  std::string out_path;
  std::string map_id;              ///< default: the CSV file's name without extension
  double default_radius_m = 0.06;  ///< radius of rows without radius_m [m]
  bool force = false;              ///< replace an existing out_path
};

struct ExportCommandOptions {
  std::string map_path;
  std::string csv_path;
  bool force = false;
};

struct InfoCommandOptions {
  std::string map_path;
};

CLI::App* add_import_command(CLI::App& app, ImportCommandOptions& o);
int run_import_command(const ImportCommandOptions& o);

CLI::App* add_export_command(CLI::App& app, ExportCommandOptions& o);
int run_export_command(const ExportCommandOptions& o);

CLI::App* add_info_command(CLI::App& app, InfoCommandOptions& o);
int run_info_command(const InfoCommandOptions& o);

/// What `refloc-map info` prints: header, counts, extent, covariance summary, warnings.
std::string map_info_text(const ReflectorMap& map);

}  // namespace refloc
