#include "map_merge.hpp"

#include "common/json_config.hpp"
#include "common/output_file.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace refloc {
namespace {

// A survey's covariance is not independent of another survey's (the same sensor's systematic
// range error is in both), so the weights only say which survey saw a reflector better; the
// merged covariance is the better input's, not their combined information.
double weight_of(const MapReflector& r) {
  return r.map_cov_center ? 1.0 / std::max(r.map_cov_center->trace(), 1e-12) : 1.0;
}

struct Merged {
  MapReflector reflector;
  Eigen::Vector2d weighted_sum = Eigen::Vector2d::Zero();
  double weight = 0.0;
};

void add_entry(Merged& m, const MapReflector& r) {
  const double w = weight_of(r);
  m.weighted_sum += w * r.map_p_center;
  m.weight += w;
  if (r.map_cov_center &&
      (!m.reflector.map_cov_center || r.map_cov_center->trace() < m.reflector.map_cov_center->trace()))
    m.reflector.map_cov_center = r.map_cov_center;
}

}  // namespace

MapMergePlan plan_map_merge(const std::vector<ReflectorMap>& maps, const std::vector<std::string>& names,
                            double gate_m, const std::string& created) {
  MapMergePlan plan;
  if (maps.empty()) return plan;
  plan.merged.info = maps.front().info;
  plan.merged.info.format = 2;
  plan.merged.info.version = maps.front().info.version + 1;
  plan.merged.info.created = created;
  plan.merged.info.source = "merged";
  std::vector<Merged> merged;
  int next_id = 0;
  for (const MapReflector& r : maps.front().reflectors) {
    merged.push_back({r, Eigen::Vector2d::Zero(), 0.0});
    add_entry(merged.back(), r);
    next_id = std::max(next_id, r.id + 1);
  }
  for (size_t k = 0; k < maps.size(); ++k)
    plan.merged.occluders.insert(plan.merged.occluders.end(), maps[k].occluders.begin(),
                                 maps[k].occluders.end());
  for (size_t k = 1; k < maps.size(); ++k) {
    // The id in map k that merged into (or was added as) entry j: one per entry and map.
    std::vector<int> taken_by(merged.size(), -1);
    for (const MapReflector& r : maps[k].reflectors) {
      size_t nearest = merged.size();
      double nearest_d = std::numeric_limits<double>::infinity();
      for (size_t j = 0; j < merged.size(); ++j) {
        const double d = (merged[j].reflector.map_p_center - r.map_p_center).norm();
        if (d < nearest_d) {
          nearest_d = d;
          nearest = j;
        }
      }
      if (nearest < merged.size() && nearest_d <= gate_m) {
        if (taken_by[nearest] >= 0)
          throw ConfigError(
              fmt::format("{}: reflectors {} and {} both lie within --gate-m {:.3f} m of reflector "
                          "{}: a smaller gate, or maps in different frames?",
                          names[k], taken_by[nearest], r.id, gate_m, merged[nearest].reflector.id));
        taken_by[nearest] = r.id;
        Merged& m = merged[nearest];
        add_entry(m, r);
        plan.lines.push_back(fmt::format("reflector {}: {} reflector {} is {:.1f} mm from it: averaged",
                                         m.reflector.id, names[k], r.id, nearest_d * 1e3));
        ++plan.averaged;
      } else {
        Merged m{r, Eigen::Vector2d::Zero(), 0.0};
        m.reflector.id = next_id++;
        add_entry(m, r);
        plan.lines.push_back(
            fmt::format("reflector {}: {} reflector {} at ({:.3f}, {:.3f}) matches none: added",
                        m.reflector.id, names[k], r.id, r.map_p_center.x(), r.map_p_center.y()));
        merged.push_back(std::move(m));
        taken_by.push_back(r.id);
        ++plan.added;
      }
    }
  }
  for (Merged& m : merged) {
    m.reflector.map_p_center = m.weighted_sum / m.weight;
    plan.merged.reflectors.push_back(m.reflector);
  }
  return plan;
}

CLI::App* add_merge_command(CLI::App& app, MergeCommandOptions& o) {
  CLI::App* command = app.add_subcommand(
      "merge",
      "one map from several surveys of the same hall in the same frame: entries within --gate-m are one "
      "reflector (positions averaged, weighted by their covariances), the others added; every entry printed");
  command->add_option("maps", o.map_paths, "two or more map files (the first one's ids and header are kept)")
      ->required()
      ->expected(2, 1000);
  command->add_option("--out", o.out_path, "the merged map (format 2, version the first map's + 1)")
      ->required();
  command->add_option("--map-id", o.map_id, "map id of the merged map (default: the first map's)");
  command->add_option("--gate-m", o.gate_m, "entries closer than this are one reflector [m]")
      ->capture_default_str()
      ->check(CLI::Range(0.001, 1.0));
  command->add_flag("--force", o.force, "replace an existing --out file");
  return command;
}

int run_merge_command(const MergeCommandOptions& o) {
  std::vector<ReflectorMap> maps;
  for (const std::string& path : o.map_paths) maps.push_back(load_reflector_map(path));
  refuse_to_replace(o.out_path, o.force, "or another --out");
  MapMergePlan plan = plan_map_merge(maps, o.map_paths, o.gate_m, iso8601_utc_now());
  if (!o.map_id.empty()) plan.merged.info.map_id = o.map_id;
  for (const std::string& line : plan.lines) fmt::print("{}\n", line);
  write_reflector_map(plan.merged, o.out_path);
  fmt::print("{}: map {} version {}: {} reflectors ({} entries averaged in, {} added)\n", o.out_path,
             plan.merged.info.map_id, plan.merged.info.version, plan.merged.reflectors.size(), plan.averaged,
             plan.added);
  return 0;
}

}  // namespace refloc
