// refloc-plan: where in a hall the laser localization will be accurate, blind or fooled,
// predicted from the map alone, and where to add reflectors (tools/refloc-plan/README.md).

#include "plan_options.hpp"

#include "common/guarded_main.hpp"
#include "common/program_version.hpp"

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{
      "Reflector layout planner: per grid cell the reflectors the laser sees, the CRLB of a single-scan fix "
      "and whether the matcher's relocalization could take it for another place; suggestions for new "
      "reflectors. Exit 0 written, 2 bad input file, 64 bad command line."};
  refloc::add_version_flag(app, "refloc-plan");
  refloc::PlanOptions o;
  // Shipped files from the refloc root, so refloc-plan runs from any working directory.
  for (std::string* file : {&o.robot_file, &o.matcher_file, &o.extractor_file, &o.solver_file})
    *file = refloc::shipped_path(*file);
  refloc::add_plan_options(app, o);
  try {
    app.parse(argc, argv);
    if (o.map_file.empty() && o.world_file.empty()) throw CLI::ValidationError("give --map, --world or both");
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : refloc::kExitUsageError;  // --help/--version: 0
  }
  return refloc::guarded_main("refloc-plan", [&] { return refloc::run_plan(o); });
}
