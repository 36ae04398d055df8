#pragma once
// What refloc-plan assumes about the sensor, the matcher and the grid: plain settings with
// defaults in the declaration, the deployed values where a service file sets them.

#include "beam_crlb.hpp"
#include "pose_solver/solver_config.hpp"
#include "reflector_extractor/extractor.hpp"
#include "reflector_matcher/matcher_config.hpp"
#include "world_renderer/lms100_error_model.hpp"

#include "common/se2.hpp"

#include <cmath>

namespace refloc {

/// The scan the laser takes (the LMS100 as the renderer models it).
struct PlanScanGeometry {
  double start_angle = -135.0 * M_PI / 180.0;   ///< beam 0 in the laser frame [rad]
  double angle_increment = 0.5 * M_PI / 180.0;  ///< [rad]
  int num_beams = 541;                          ///< [-]
};

struct PlanConfig {
  double resolution = 0.25;  ///< grid cell side [m]
  int headings = 8;          ///< robot headings per cell, evenly spaced from 0 [-]
  /// A cell whose worst heading's CRLB position sigma is above this counts as inaccurate [m].
  double crlb_limit = 0.010;
  Pose2 robot_T_laser{0.30, 0.0, 0.0};  ///< laser mount (robot.json's laser_mount) [m, m, rad]
  PlanScanGeometry scan;
  double range_sigma = 0.012;  ///< LMS100 statistical range noise, 1 sigma [m]
  /// The beam-spot model of refloc-eval's bound, its 201 rays: with 51 the central differences
  /// (1 mm steps) straddle single rays and a cell's bound moved by up to -64 % / +29 % against
  /// 201 on the demo hall (101: -18 % / +12 %).
  BeamSpotModel spot;

  /// The LMS100 model (world_renderer's, the emulator's defaults): a visible reflector's beams
  /// are traced noise-free with it for their RSSI.
  sim::Lms100ErrorModel sensor;
  /// The extractor as deployed (deploy/config/reflector_extractor.json): a reflector counts as
  /// seen when at least min_beams of its beams return at or above energy_threshold_8bit.
  ExtractorConfig extractor;
  /// The solver as deployed (deploy/config/pose_solver.json): a relocalized pose counts only
  /// when the solver makes a pose of the matches.
  SolverConfig solver;

  /// The matcher as deployed (deploy/config/reflector_matcher.json): range, field of view,
  /// triangle index, verification and the rival rule.
  MatcherConfig matcher;
  /// A pose whose exact detections relocalize AMBIGUOUS (or wrong) is relocalized again this
  /// many times with range_sigma of noise on each detection centre, and stays ambiguous only
  /// when the noisy copies are (the rival rule's margin is often finer than the noise); 0 = the
  /// exact verdict [-].
  int rival_noise_samples = 8;
  /// Skip the relocalization check (no ambiguity figures; for quick CRLB-only grids).
  bool check_ambiguity = true;
  /// Threads predicting cells, each with its own predictor on the shared map index; the plan is
  /// the same for any number (each cell is predicted alone) [-].
  int threads = 1;
};

}  // namespace refloc
