#include "map_update.hpp"

#include "common/guarded_main.hpp"
#include "common/json_config.hpp"
#include "common/output_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace refloc {
namespace {

std::string xy(const Eigen::Vector2d& p) { return fmt::format("({:.3f}, {:.3f})", p.x(), p.y()); }

std::string sigma_text(const Eigen::Vector2d& s) {
  return fmt::format("+- ({:.1f}, {:.1f}) mm", s.x() * 1e3, s.y() * 1e3);
}

// The survey covariance of a position the robot measured: its std devs, when both are known.
std::optional<Eigen::Matrix2d> covariance_of(const Eigen::Vector2d& sigma) {
  if (!(sigma.x() > 0.0 && sigma.y() > 0.0)) return std::nullopt;
  return Eigen::Vector2d(sigma.x() * sigma.x(), sigma.y() * sigma.y()).asDiagonal().toDenseMatrix();
}

void plan_reflectors(const ReflectorMap& map, const MapHealthReport& evidence, const MapUpdateSelection& s,
                     MapUpdatePlan& plan) {
  for (const MapReflector& r : map.reflectors) {
    const auto e = std::find_if(evidence.reflectors.begin(), evidence.reflectors.end(),
                                [&](const ReflectorHealthEntry& h) { return h.id == r.id; });
    const ReflectorHealth state = e == evidence.reflectors.end() ? ReflectorHealth::kUnconfirmed : e->state;
    if (state == ReflectorHealth::kMissing) {
      plan.lines.push_back(fmt::format("{} reflector {} at {}: missing (seen {}, expected and unseen {})",
                                       s.remove_missing ? "remove" : "keep (no --remove-missing)", r.id,
                                       xy(r.map_p_center), e->seen, e->expected_missing));
      if (s.remove_missing) {
        ++plan.removed;
        continue;
      }
    }
    MapReflector next = r;
    if (state == ReflectorHealth::kMoved) {
      next.map_p_center = r.map_p_center + e->offset;
      plan.lines.push_back(fmt::format("{} reflector {} from {} to {} {} (offset {:.3f} m)",
                                       s.move_moved ? "move" : "keep (no --move-moved)", r.id,
                                       xy(r.map_p_center), xy(next.map_p_center), sigma_text(e->offset_sigma),
                                       e->offset.norm()));
      if (s.move_moved) {
        next.map_cov_center = covariance_of(e->offset_sigma);
        ++plan.moved;
      } else {
        next = r;
      }
    }
    plan.next.reflectors.push_back(next);
  }
}

void plan_candidates(const MapHealthReport& evidence, const MapUpdateSelection& s, MapUpdatePlan& plan) {
  int next_id = 0;
  for (const MapReflector& r : plan.next.reflectors) next_id = std::max(next_id, r.id + 1);
  for (const MapCandidate& c : evidence.candidates) {
    if (c.moved_reflector_id >= 0) continue;  // a moved reflector's new place, not a new reflector
    if (!s.add_candidates) {
      plan.lines.push_back(fmt::format("keep out (no --add-candidates) candidate at {} {} ({} sightings)",
                                       xy(c.map_p), sigma_text(c.sigma), c.sightings));
      continue;
    }
    MapReflector r;
    r.id = next_id++;
    r.map_p_center = c.map_p;
    r.map_cov_center = covariance_of(c.sigma);
    plan.next.reflectors.push_back(r);
    ++plan.added;
    plan.lines.push_back(fmt::format("add reflector {} at {} {} ({} sightings, seen from {:.1f} m apart)",
                                     r.id, xy(c.map_p), sigma_text(c.sigma), c.sightings,
                                     c.viewpoint_spread));
  }
}

}  // namespace

void check_evidence_is_for(const ReflectorMap& map, const MapHealthReport& evidence,
                           const std::string& source) {
  if (evidence.map_id != map.info.map_id || evidence.map_version != map.info.version) {
    throw ConfigError(fmt::format("{}: the evidence is for map \"{}\" version {}, not \"{}\" version {}",
                                  source, evidence.map_id, evidence.map_version, map.info.map_id,
                                  map.info.version));
  }
  for (const ReflectorHealthEntry& e : evidence.reflectors) {
    const int i = map.index_of(e.id);
    if (i < 0 || (map.reflectors[static_cast<size_t>(i)].map_p_center - e.map_p).norm() > 1e-6) {
      throw ConfigError(fmt::format(
          "{}: the evidence has reflector {} at {}, the map {}: evidence of another map", source, e.id,
          xy(e.map_p), i < 0 ? "has no such id" : xy(map.reflectors[static_cast<size_t>(i)].map_p_center)));
    }
  }
}

MapUpdatePlan plan_map_update(const ReflectorMap& map, const MapHealthReport& evidence,
                              const MapUpdateSelection& selection, const std::string& created) {
  MapUpdatePlan plan;
  plan.next.info = map.info;
  plan.next.info.format = 2;
  plan.next.info.version = map.info.version + 1;
  plan.next.info.created = created;
  plan.next.info.source = "updated";
  plan.next.occluders = map.occluders;
  plan_reflectors(map, evidence, selection, plan);
  plan_candidates(evidence, selection, plan);
  return plan;
}

CLI::App* add_update_command(CLI::App& app, UpdateCommandOptions& o) {
  CLI::App* command = app.add_subcommand(
      "update",
      "the next map version from the matcher's MAP_HEALTH evidence in an LCM log: candidates added, missing "
      "reflectors removed, moved ones corrected (all three unless some are chosen); every change printed");
  command->add_option("--map", o.map_path, "the map the evidence was gathered with (format 1 or 2)")
      ->required();
  command->add_option("--evidence", o.evidence_path, "an LCM log holding MAP_HEALTH for that map")
      ->required();
  command->add_option("--out", o.out_path, "the next version's file (never the input: it exists)");
  command->add_option("--channel", o.channel, "the MAP_HEALTH channel in the log")->capture_default_str();
  command->add_option("--map-id", o.map_id,
                      "map id of the new version when the map has none (format 1): "
                      "default the map file's name without extension");
  command->add_flag("--add-candidates", o.add_candidates, "add the candidates (unmapped reflectors)");
  command->add_flag("--remove-missing", o.remove_missing, "remove the missing reflectors");
  command->add_flag("--move-moved", o.move_moved, "move the moved reflectors to where they were seen");
  command->add_flag("--dry-run", o.dry_run, "print the changes, write nothing");
  command->add_flag("--force", o.force, "replace an existing --out file");
  return command;
}

int run_update_command(const UpdateCommandOptions& o) {
  if (o.out_path.empty() && !o.dry_run) {
    std::fprintf(stderr, "refloc-map update: --out FILE is required (or --dry-run)\n");
    return kExitUsageError;
  }
  const ReflectorMap map = load_reflector_map(o.map_path);
  if (!o.dry_run) refuse_to_replace(o.out_path, o.force, "or another --out");
  const MapHealthReport evidence = last_map_health(o.evidence_path, o.channel, map);
  check_evidence_is_for(map, evidence, o.evidence_path);
  const bool any = o.add_candidates || o.remove_missing || o.move_moved;
  const MapUpdateSelection selection{!any || o.add_candidates, !any || o.remove_missing,
                                     !any || o.move_moved};
  MapUpdatePlan plan = plan_map_update(map, evidence, selection, iso8601_utc_now());
  if (plan.next.info.map_id.empty())
    plan.next.info.map_id = o.map_id.empty() ? std::filesystem::path(o.map_path).stem().string() : o.map_id;
  fmt::print(
      "evidence: {} scans, {} ok, {} missing, {} moved, {} unconfirmed (kept as they are), {} candidates\n",
      evidence.scans_used, evidence.count(ReflectorHealth::kOk), evidence.count(ReflectorHealth::kMissing),
      evidence.count(ReflectorHealth::kMoved), evidence.count(ReflectorHealth::kUnconfirmed),
      evidence.new_candidates());
  for (const std::string& line : plan.lines) fmt::print("{}\n", line);
  const std::string summary =
      fmt::format("map {} version {}: {} reflectors ({} added, {} removed, {} moved)", plan.next.info.map_id,
                  plan.next.info.version, plan.next.reflectors.size(), plan.added, plan.removed, plan.moved);
  if (o.dry_run) {
    fmt::print("dry run, nothing written: would be {}\n", summary);
    return 0;
  }
  write_reflector_map(plan.next, o.out_path);
  fmt::print("{}: {}\n", o.out_path, summary);
  return 0;
}

}  // namespace refloc
