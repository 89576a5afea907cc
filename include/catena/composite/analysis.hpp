// The composite link (seed 002) as the analysis interface describes it: `ring` (the orthotropic
// ring on two rigid half-discs: stresses, contact pressure, load), `ring_capacity` (eq. (9) and
// the mass comparison) and `ring_design` (sizing a fibre-wound link for a breaking force) — their
// parameters, run and describe (JSON fields, table, CSV, report charts).
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "catena/analysis/analysis.hpp"
#include "catena/composite/capacity.hpp"
#include "catena/composite/ring.hpp"

namespace catena::composite {

/// What `ring` computed: the ring and options as the model took them, and its result.
struct RingAnalysis {
  Ring ring;
  Options options;
  Result result;
  /// |P − P_contact| / |P|: the load from the sections against the load from the contact
  /// pressure (equilibrium of the half-disc).
  double equilibrium_residual = 0.0;
  bool field = false;  ///< --field: the stresses over the quarter ring are part of the result
};

/// What `ring_capacity` computed (eq. (9), from given coefficients or from a ring analysis).
struct CapacityAnalysis {
  bool analysed = false;    ///< α, Σσ̃_r and K from a ring analysis of the elastic constants
  Eq9 eq9;                  ///< the coefficients used (analysed: from the ring)
  bool area_given = false;  ///< F given (P follows) rather than sized for a load
  double fibre_area = 0.0;  ///< [m²] F
  double load = 0.0;        ///< [N] P_max by eq. (9)
  double eq9_factor = 0.0;  ///< Σσ̃_r/(α(1−α)K)
  double load_concentration = 0.0;              ///< [N] 2Fσ^a/K
  double load_uniform = 0.0;                    ///< [N] 2Fσ^a
  double consistent_sum_sigma_r = 0.0;          ///< α(1−α)
  double ring_sum_sigma_r = NAN;                ///< analysed: the ring's own Σσ̃_r ((1−α)/α)
  Summary summary;                              ///< analysed: the ring solver's summary
  std::optional<double> steel_mass, link_mass;  ///< [kg] the mass comparison, both or neither
  std::vector<Diagnostic> diagnostics;
};

/// What `ring_design` computed.
struct DesignAnalysis {
  DesignInput input;
  Design design;
};

/// The analysis descriptions (registered as "ring", "ring_capacity", "ring_design").
const analysis::Analysis& ring_analysis();
const analysis::Analysis& ring_capacity_analysis();
const analysis::Analysis& ring_design_analysis();

/// Run them on bound inputs (throw InputError, fields named by parameter key).
RingAnalysis ring_analysis_run(const analysis::Inputs& inputs);
CapacityAnalysis ring_capacity_analysis_run(const analysis::Inputs& inputs);
DesignAnalysis ring_design_analysis_run(const analysis::Inputs& inputs);

}  // namespace catena::composite
