// `contact` and `fretting`: the roller–tooth contact with axis skew and the latent period of
// fretting (seed 001) as the analysis interface describes them — their parameters, run (the
// effective load of eqs. (2)–(3), the design skew, the slice model, a sweep over the skew) and
// describe (JSON fields, table, CSV, report charts).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "catena/analysis/analysis.hpp"
#include "catena/contact/fretting.hpp"
#include "catena/contact/roller_tooth.hpp"

namespace catena::contact {

/// The contact at one skew: the paper's effective load and stress beside the slice model.
struct SkewPoint {
  double skew = 0.0;             ///< [rad] measured φ
  double load_factor = 0.0;      ///< Q_n/Q_nom (eq. 2)
  double effective_load = 0.0;   ///< [N] Q_n
  double paper_stress = 0.0;     ///< [Pa] eq. (3) at Q_n
  double hertz_effective = 0.0;  ///< [Pa] Hertz p0 at Q_n
  double slice_peak = 0.0;       ///< [Pa] the slice model's peak stress at the design skew
  double slice_length = 0.0;     ///< [m] the slice model's loaded length
};

/// What `contact` computed: the inputs as the model took them, and one skew or a sweep.
struct ContactAnalysis {
  RollerTooth contact;
  double load = 0.0;                           ///< [N] Q_nom
  double pitch = 0.0;                          ///< [m] selects γ
  double skew = 0.0;                           ///< [rad] measured φ (one skew)
  double skew_factor = 1.0;                    ///< K_φ
  double design_skew = 0.0;                    ///< [rad] φ·K_φ (one skew)
  double gamma = 0.0;                          ///< [1/arcmin²] γ of eq. (2)
  std::optional<std::array<double, 3>> sweep;  ///< from, to, step [rad]
  int slices = 201;
  HertzResult nominal;  ///< Hertz at Q_nom (aligned)
  // one skew
  SkewPoint point;
  SliceResult slice;      ///< at the design skew
  HertzResult effective;  ///< Hertz at Q_n
  /// The slice model's caveat: loaded length < 5 peak half-widths, a short patch where the
  /// plane-strain strips are rough (shown in the text table only; not part of the JSON).
  bool short_patch = false;
  /// findings: the short-patch caveat of the slice model (kInfo)
  std::vector<Diagnostic> diagnostics;
  // a sweep
  std::vector<SkewPoint> rows;
};

/// What `fretting` computed.
struct FrettingAnalysis {
  Fretting fretting;
  double latent_period = 0.0;  ///< [s] τ
  double exponent = 0.0;       ///< K2 A N f / Ra
  double cycles = 0.0;         ///< τ f
};

/// The analysis descriptions (registered as "contact" and "fretting").
const analysis::Analysis& contact_analysis();
const analysis::Analysis& fretting_analysis();

/// Run them on bound inputs (throw InputError, fields named by parameter key).
ContactAnalysis contact_analysis_run(const analysis::Inputs& inputs);
FrettingAnalysis fretting_analysis_run(const analysis::Inputs& inputs);

}  // namespace catena::contact
