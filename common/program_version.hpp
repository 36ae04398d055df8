#pragma once
// What every refloc binary answers to --version, and where its shipped files are: the
// checkout or install prefix that holds deploy/config, found from the binary's own path so
// a service started from any working directory reads the same default files.

#include <CLI/CLI.hpp>

#include <string>

namespace refloc {

/// "refloc 0.2.0 (git 82f9e2b)": the project version and the commit the build was configured at.
std::string refloc_version();

/// Adds --version to a command line: prints "<program> from refloc VERSION (git COMMIT)" and exits 0.
void add_version_flag(CLI::App& app, const std::string& program);

/// The refloc root: $REFLOC_ROOT when set, else the nearest ancestor of the running binary's
/// directory that holds deploy/config (<repo>/build/bin/x -> <repo>; /opt/refloc/bin/x ->
/// /opt/refloc). Empty when neither exists.
std::string refloc_root();

/// A shipped file named relative to the refloc root ("deploy/config/robot.json") as a path that
/// does not depend on the working directory; the relative path itself when no root is found.
std::string shipped_path(const std::string& relative_to_root);

}  // namespace refloc
