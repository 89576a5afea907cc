// `hinge` and `hinge_sweep`: the rolling-friction hinge of seed 000 §1.2–1.3 as the analysis
// interface describes it — `hinge` (synthesis, kinematics, pitch change, the aperture drawing)
// and `hinge_sweep` (`hinge sweep`: the design sweep over R1).
#pragma once

#include <optional>
#include <vector>

#include "catena/analysis/analysis.hpp"
#include "catena/hinge/aperture.hpp"
#include "catena/hinge/sweep.hpp"
#include "catena/hinge/synthesis.hpp"

namespace catena::hinge {

/// What `hinge` computed: the inputs as the model took them, the synthesis, the pitch change and
/// trajectories sampled over [0, φmax], and the aperture when a drawing was asked for.
struct HingeAnalysis {
  Hinge hinge;
  Loads loads;
  std::optional<double> pitch;  ///< [m] chain pitch t, for Δt/t
  Synthesis synthesis;
  double max_pitch_change = 0.0;  ///< [m] largest |Δt| over [0, φmax]
  std::vector<double> phi, dt, dt_over_t, m1x, m1y, o2x, o2y;  ///< [rad], [m], [-], [m] …
  std::optional<Aperture> aperture;  ///< with a drawing (--svg, --dxf, reports)
};

/// What `hinge_sweep` computed.
struct SweepAnalysis {
  Hinge hinge;
  Loads loads;
  int count = 20;
  Sweep sweep;
};

/// The analysis descriptions (registered as "hinge" and "hinge_sweep").
const analysis::Analysis& hinge_analysis();
const analysis::Analysis& sweep_analysis();

/// Run them on bound inputs (throw InputError, fields named by parameter key).
HingeAnalysis hinge_analysis_run(const analysis::Inputs& inputs);
SweepAnalysis sweep_analysis_run(const analysis::Inputs& inputs);

}  // namespace catena::hinge
