// Chain–sprocket engagement forces for sliding and rolling hinges (seed 000 §1.6.1–1.6.2).
//
// One roller (hinge 4 of figs. 23–26) seated on a tooth while the link entering engagement
// (link 1, tension F1, constant) turns relative to the engaged link 2 by the mutual turn angle
// γ from 0 to γΣ = 360°·m/z (§1.6.2). NOTE: γ here is the mutual turn of the links (the §1.6
// notation); the hinge model's `gamma` (§1.2) is the roller's turn relative to one plate, γ/2
// for a symmetric hinge. The two are kept apart: this module calls the mutual turn `gamma` and
// the roller's turn relative to link 1 `xi` (ξ of eq. 28).
//
// Frame (docs/models/engagement.md, figure E1): origin at the roller centre, x along link 1
// towards the roller (link 1 pulls the roller along −x with F1), link 2 pulls along
// (cos γ, sin γ), the tooth pushes the roller along n = (sin β1, −cos β1) through its centre.
// The tooth turns with the sprocket, i.e. with link 2: β1(γ) = γ − γΣ/2 + ψ, the radius of the
// sprocket polygon at the seated roller tilted by the flank angle ψ towards the motion (ψ = 0:
// radial normal). In the angles of eqs. (26)–(27): φ = γΣ (the sprocket's pitch angle),
// α = 90° − γΣ/2 (polygon side to radius), θ = φ + α − ψ (between F2 and the normal, constant)
// and ε(γ) = θ − γ = 90° − β1(γ) (between F1 and the normal).
#pragma once

#include <vector>

#include "catena/core/error.hpp"
#include "catena/hinge/hinge.hpp"

namespace catena::engagement {

/// [rad] γΣ = 360°·m/z, the mutual turn of the links over one engagement (§1.6.2).
double gamma_sigma(int teeth, int strokes);

/// The angles of eqs. (26)–(27), reconstructed (fig. 25 is missing from the summary).
struct Angles {
  double gamma_sigma = 0.0;  ///< [rad] 360°·m/z
  double alpha = 0.0;        ///< [rad] 90° − γΣ/2, polygon side to the radius at the vertex
  double psi = 0.0;          ///< [rad] flank angle: tooth normal's tilt from the radius
  double theta = 0.0;    ///< [rad] φ + α − ψ = 90° + γΣ/2 − ψ, between F2 and the normal
  double epsilon = 0.0;  ///< [rad] ε at γ = γΣ: α − ψ, between F1 and the line of N
  double beta1 = 0.0;    ///< [rad] β1 at γ = γΣ: γΣ/2 + ψ, direction of F_N (eq. 28)
};
Angles angles(int teeth, int strokes, double flank_angle);
/// [rad] ε(γ) = θ − γ, between F1 and the line of N at mutual turn γ.
double epsilon_at(const Angles& a, double gamma);
/// [rad] β1(γ) = 90° − ε(γ) = γ − γΣ/2 + ψ, the direction of F_N in the frame of link 1.
double beta1_at(const Angles& a, double gamma);

/// Sliding-friction hinge (§1.6.1).
struct SlidingInput {
  double tension = 0.0;           ///< [N] F1, link entering engagement (constant)
  int teeth = 0;                  ///< [-] z
  int strokes = 1;                ///< [-] m
  double flank_angle = 0.0;       ///< [rad] ψ (default 0: radial tooth normal)
  double friction = 0.0;          ///< [-] f = f1, roller–plate friction (braking force f1·F1)
  double tooth_friction = -1.0;   ///< [-] roller–tooth friction in (24)/(25); < 0: = friction
  double journal_diameter = 0.0;  ///< [m] d1 of (24)/(25), roller–plate surface
  double tooth_diameter = 0.0;    ///< [m] d2 of (24)/(25), roller–tooth surface
  int points = 91;                ///< samples over [0, γΣ], both ends
};
std::vector<Issue> validate(const SlidingInput& in);

/// Rolling-friction hinge (§1.6.2).
struct RollingInput {
  hinge::Hinge hinge;                 ///< geometry (concave faces); teeth/strokes give γΣ
  double tension = 0.0;               ///< [N] F1
  double flank_angle = 0.0;           ///< [rad] ψ, β1 = γΣ/2 + ψ
  double rolling_coefficient = 1e-3;  ///< [-] c_r: F_jk = c_r·F_j (rolling resistance law)
  double tooth_arm = 0.0;             ///< [m] λ1, rolling-resistance arm of F_N at the tooth
  int points = 91;                    ///< samples over [0, γΣ], both ends
};
std::vector<Issue> validate(const RollingInput& in);

struct Sample {
  double gamma = 0.0;           ///< [rad] mutual turn of link 1 relative to link 2
  double f2 = 0.0;              ///< [N] F2
  double fn = 0.0;              ///< [N] F_N (N of eq. 27)
  double xi = 0.0;              ///< [rad] ξ, roller turn relative to link 1 (rolling only)
  double f1k = 0.0;             ///< [N] rolling resistance at link 1 (rolling only)
  double f2k = 0.0;             ///< [N] rolling resistance at link 2 (rolling only)
  double friction_force = 0.0;  ///< [N] braking force f1·F1 (sliding only)
  bool roller_turns = false;    ///< sliding: criterion (25) holds
  double residual = 0.0;        ///< [-] largest equilibrium residual / F1 (moment / (F1·a))
};

struct Range {
  double from = 0.0;  ///< [rad] γ
  double to = 0.0;    ///< [rad] γ
};

struct Result {
  Angles angles;
  std::vector<Sample> series;
  std::vector<Range> roller_turns;  ///< sliding: where (25) holds; rolling: where ξ grows
  double max_residual = 0.0;
  std::vector<Diagnostic> diagnostics;
};

/// Eqs. (24)–(27) over 0 ≤ γ ≤ γΣ. Throws InputError for invalid input.
Result solve_sliding(const SlidingInput& in);

/// One solution of system (28) at mutual turn `gamma` (see the .cpp for the equations).
Sample solve_rolling_at(const RollingInput& in, double r2, double gamma);
/// System (28) over 0 ≤ γ ≤ γΣ. Throws InputError for invalid input.
Result solve_rolling(const RollingInput& in);

/// Beyond the paper: the whole wrap. Every seated roller passes the ratio F2/F1 and F_N/F1 of a
/// completed engagement (γ = γΣ) on to the next: the equations are homogeneous in the forces.
struct Wrap {
  double pitch_radius = 0.0;       ///< [m] R = t/(2 sin(γΣ/2)), the engaged rollers' polygon
  int rollers = 0;                 ///< [-] seated rollers K = round(wrap angle / γΣ)
  std::vector<double> tension;     ///< [N] link tension before roller k (K + 1 values)
  std::vector<double> tooth_load;  ///< [N] F_N on the tooth under roller k (K values)
  double torque = 0.0;             ///< [N·m] Σ R·F_N,k·sin ψ: tooth normals through the roller
                                   ///< centres (the λ1 arm is not counted)
};
/// `r` from solve_sliding/solve_rolling with the same F1; throws InputError for invalid input.
Wrap wrap(const Result& r, double tension, double pitch, double wrap_angle);

/// The contact offset of a plate on the roller, M1 − O2 in the plate frame (hinge model), for a
/// roller turned by `theta` relative to that plate (θ < 0 mirrored: y negated).
struct Offset {
  double x = 0.0;  ///< [m]
  double y = 0.0;  ///< [m]
};
Offset contact_offset(const hinge::Hinge& h, double r2, double theta);

}  // namespace catena::engagement
