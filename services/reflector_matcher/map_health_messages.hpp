#pragma once
// MAP_HEALTH's LCM edge: MapHealthReport <-> map_health_t. Header only and outside the
// LCM-free library (like matcher_messages.hpp): the matcher's main publishes with it and
// `refloc-map update` reads logged messages back with it.

#include "reflector_matcher/map_health_report.hpp"

#include <refloc/map_health_t.hpp>

#include <algorithm>

namespace refloc {

/// Most reflectors and candidates a map_health_t carries (its "// max" comments).
inline constexpr size_t kMapHealthMaxReflectors = 10000;
inline constexpr size_t kMapHealthMaxCandidates = 1024;

inline void to_message(const MapHealthReport& r, map_health_t& out) {
  out.utime = r.utime;
  out.map_id = r.map_id.substr(0, 4096);
  out.map_version = r.map_version;
  out.scans_used = r.scans_used;
  out.reflectors_ok = r.count(ReflectorHealth::kOk);
  out.reflectors_missing = r.count(ReflectorHealth::kMissing);
  out.reflectors_moved = r.count(ReflectorHealth::kMoved);
  out.reflectors_unconfirmed = r.count(ReflectorHealth::kUnconfirmed);
  out.reflectors.clear();
  for (size_t i = 0; i < std::min(r.reflectors.size(), kMapHealthMaxReflectors); ++i) {
    const ReflectorHealthEntry& e = r.reflectors[i];
    out.reflectors.push_back({e.id, static_cast<int8_t>(e.state), e.map_p.x(), e.map_p.y(), e.seen,
                              e.expected_missing, e.offset.x(), e.offset.y(), e.offset_sigma.x(),
                              e.offset_sigma.y()});
  }
  out.nreflectors = static_cast<int32_t>(out.reflectors.size());  // encode trusts the length field
  out.candidates.clear();
  for (size_t i = 0; i < std::min(r.candidates.size(), kMapHealthMaxCandidates); ++i) {
    const MapCandidate& c = r.candidates[i];
    out.candidates.push_back({c.map_p.x(), c.map_p.y(), c.sigma.x(), c.sigma.y(), c.sightings,
                              c.viewpoint_spread, c.moved_reflector_id});
  }
  out.ncandidates = static_cast<int32_t>(out.candidates.size());
}

/// The report a message carries (candidate keys are not published: 0). A state outside the
/// known values reads as unconfirmed, which no update acts on.
inline MapHealthReport from_message(const map_health_t& m) {
  MapHealthReport r;
  r.utime = m.utime;
  r.map_id = m.map_id;
  r.map_version = m.map_version;
  r.scans_used = m.scans_used;
  for (const map_reflector_health_t& e : m.reflectors) {
    ReflectorHealthEntry h;
    h.id = e.id;
    h.state =
        e.state >= 0 && e.state <= 3 ? static_cast<ReflectorHealth>(e.state) : ReflectorHealth::kUnconfirmed;
    h.map_p = {e.map_x, e.map_y};
    h.seen = e.seen;
    h.expected_missing = e.expected_missing;
    h.offset = {e.offset_x, e.offset_y};
    h.offset_sigma = {e.offset_sigma_x, e.offset_sigma_y};
    r.reflectors.push_back(h);
  }
  for (const map_candidate_t& c : m.candidates) {
    r.candidates.push_back(
        {{c.x, c.y}, {c.sigma_x, c.sigma_y}, c.sightings, c.viewpoint_spread, c.moved_reflector_id, 0});
  }
  return r;
}

}  // namespace refloc
