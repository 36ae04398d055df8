#pragma once
// Plugs the scan renderer into the LMS100 emulator (scan_source.hpp): each scan
// the emulator requests is rendered beam by beam at the request's beam times and
// angles, then coded as the sensor sends it (mm with codes 0/1, RSSI in 8 or 16 bit).

#include "lms100_emulator/scan_source.hpp"
#include "world_renderer/scan_renderer.hpp"
#include "world_renderer/world.hpp"

#include <cstdint>
#include <memory>
#include <vector>

namespace refloc::sim {

/// A ScanSource rendering `world` as seen from map_T_laser_at(beam time). The source
/// owns its renderer and a std::mt19937_64 seeded with `seed`, so a run is repeatable.
/// map_T_laser_at is called from the emulator's server thread (once per beam) and
/// must be thread-safe with whatever moves the pose; it must not throw (if it does,
/// the scan is sent with no echoes). The scan geometry comes from each request;
/// config.geometry is ignored.
ScanSource make_rendered_scan_source(std::shared_ptr<const World> world, PoseAtTime map_T_laser_at,
                                     const ScanRenderConfig& config, uint64_t seed);

/// Code a rendered LaserScan (16-bit RSSI) for the wire: dist 0 = no echo, 1 = dazzled,
/// else millimetres clamped to [16, 65535]; RSSI converted to rssi_bits (0: zeros).
/// dist_mm and rssi must already have scan.ranges.size() elements.
void code_scan_for_wire(const LaserScan& scan, int rssi_bits, std::vector<uint16_t>& dist_mm,
                        std::vector<uint16_t>& rssi);

}  // namespace refloc::sim
