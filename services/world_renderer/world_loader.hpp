#pragma once
// Loading a simulated world from JSON, with the same validation style as every
// refloc config: each error names the file and the JSON pointer of the value.
//
// The world file REFERENCES its map file rather than embedding it, so the map
// the localization loads and the reflectors the simulator renders are one file:
//
//   {
//     "description": "factory hall 20 m x 12 m",          (optional)
//     "map_file": "map_demo.json",           (relative to the world file's folder)
//     "walls":     [{"name": "hall", "points": [[0,0],[20,0],[20,12],[0,12]],
//                    "closed": true, "remission": 0.6}],
//     "obstacles": [{"name": "rack 1", "points": [...], "closed": true, "remission": 0.3}],
//     "distractors": [{"name": "door tape", "surface": "tape" | "metal",
//                      "points": [[x,y],[x,y]], "closed": false, "remission": 0.05}],
//     "unmapped_reflectors": [{"id": 900, "x": 3.0, "y": 4.0, "radius_m": 0.06}],
//     "moved_reflectors": [{"id": 7, "x": 6.45, "y": 11.9}],     (stands elsewhere than mapped)
//     "missing_reflector_ids": [12],                        (mapped, but not in the world)
//     "drivable_areas": [{"x_min": 1, "y_min": 1, "x_max": 19, "y_max": 11}]
//   }
//
// The last three model map errors for robustness tests. Only "map_file" is required; "name", "closed"
// (default false) and "remission" (defaults: walls/obstacles 0.5, tape 0.8, metal 0.05 for its diffuse part)
// are optional. Coordinates are metres in the map frame.

#include "world_renderer/world.hpp"

#include <string>

namespace refloc {
class JsonConfig;
}

namespace refloc::sim {

/// Load and validate a world file and the map file it names; rejects unknown keys.
/// Throws ConfigError "<file>: <pointer>: <what>".
World load_world(const std::string& path);

/// Same validation on a document already loaded (the world may sit inside another
/// config); pointer is where the world object sits; base_dir resolves "map_file".
/// Does not call reject_unknown_keys (the caller owns the whole document).
World parse_world(const JsonConfig& config, const std::string& pointer, const std::string& base_dir);

}  // namespace refloc::sim
