// Strength checks of the rolling/sliding-friction hinge conveyor chain's roller (pin) and plates
// (seed 000 §1.5, figs. 20–21, eqs. (22)–(23)).
//
// The thesis names the method in words only: load layouts 1 and 2 (fig. 20: the hinges whose
// inner plates and whose outer plates are seated on the sprocket alternate), the roller's
// bending-moment and shear diagrams for both, the contact projection c ≈ 2r·sin(γ/2) (22), the
// pressure p = N/A with A = C_nom·B (23) and the plate's dangerous sections (fig. 21). The load
// layouts and the checks below are our reconstruction (docs/models/strength.md):
//
//  * the roller is a free beam along z (heights as in catena warp: lower outer, lower inner,
//    upper inner, upper outer plate mid-planes, bottom to top); every load acts along the chain
//    line x and is spread uniformly over its plate's thickness B_i (the tooth load over the
//    tooth width, a point load when that is 0);
//  * the free link (tension S) pulls the roller through its two plates, S/2 each; the seated
//    link pulls with S2 at the link angle θ, its two plates split by the roller's statics (two
//    supports: statically determinate, in each of the two directions x, y); the tooth pushes
//    with the balance N at height L1 (collinear θ = 0: N = S − S2);
//  * layout 1: the seated (engaged) link is the inner link, S enters through the outer plates;
//    layout 2: the seated link is the outer link, S enters through the inner plates.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "catena/core/error.hpp"

namespace catena::strength {

enum class HingeKind { kSliding, kRolling };

/// Plate index, bottom to top (the same order as catena warp's joints).
enum Plate : int { kLowerOuter = 0, kLowerInner = 1, kUpperInner = 2, kUpperOuter = 3 };

struct Hinge {
  std::array<double, 4> heights{};    ///< [m] plate mid-plane z, strictly increasing
  std::array<double, 4> widths{};     ///< [m] plate thickness B_i (= s of the plate checks)
  double pin_diameter = 0.0;          ///< [m] d of the roller's bending section
  double bore = 0.0;                  ///< [m] inner diameter of a hollow roller (0: solid)
  double hole_diameter = 0.0;         ///< [m] d_h of the plate's hole/aperture (0: = d)
  double plate_width = 0.0;           ///< [m] b, the plate's depth across the chain line
  double end_distance = 0.0;          ///< [m] e, from the hole centre to the plate's end
  double stress_concentration = 1.0;  ///< [-] K_t on the net section (1: nominal stress)
  HingeKind kind = HingeKind::kSliding;
  double contact_angle = 3.141592653589793;  ///< [rad] γ of the sliding pin's contact arc
  double r1 = 0.0;                           ///< [m] rolling hinge: plate convex working radius R1
  double r2 = 0.0;         ///< [m] rolling hinge: roller concave working radius R2 > R1
  double modulus = 210e9;  ///< [Pa] E of roller and plates (Hertz)
  double poisson = 0.3;    ///< [-] ν
};

struct Loads {
  double tension = 0.0;       ///< [N] S, the free link's tension (along +x)
  double exit_tension = 0.0;  ///< [N] S2 ≥ 0, the seated link's tension (0: all onto the tooth)
  double link_angle = 0.0;  ///< [rad] θ between the two links' lines, 0 ≤ θ < π (0: collinear)
  double load_height = 0.0;  ///< [m] L1, centre of the tooth load (same datum as the heights)
  double tooth_width = 0.0;  ///< [m] width of the tooth load along z (0: a point load)
};

/// [N] (x, y) of the tooth's force on the roller, which balances the free link's pull S·x̂ and the
/// seated link's pull S2·û, û = (−cos θ, sin θ): N = (S2 cos θ − S, −S2 sin θ). Collinear
/// (θ = 0): N = S − S2 against the free link.
std::array<double, 2> tooth_force(const Loads& loads);

struct Material {
  double roller_yield = 0.0;        ///< [Pa] σ_y of the roller
  double plate_yield = 0.0;         ///< [Pa] σ_y of the plates
  double plate_ultimate = 0.0;      ///< [Pa] σ_u of the plates (0: no ultimate check)
  double allowable_pressure = 0.0;  ///< [Pa] sliding hinge: allowable specific pressure [p]
  double allowable_contact = 0.0;   ///< [Pa] rolling hinge: allowable Hertz stress [σ_H]
  double required = 1.5;            ///< [-] required safety factor against yield/ultimate
};

enum class Layouts { kOne, kTwo, kBoth };

struct Input {
  Hinge hinge;
  Loads loads;
  Material material;
  Layouts layouts = Layouts::kBoth;
};

/// Every problem with the inputs (field, value, expected range).
std::vector<Issue> validate(const Input& in);

/// A load along the chain line x, uniform over [begin, end] (begin == end: a point load).
struct Block {
  double begin = 0.0;  ///< [m]
  double end = 0.0;    ///< [m]
  double force = 0.0;  ///< [N] total, signed (+x toward the free span)
};

/// The roller as a free beam with self-equilibrated loads.
struct Beam {
  std::vector<Block> blocks;
  double start = 0.0;  ///< [m] lower end of the loaded length
  double stop = 0.0;   ///< [m] upper end
};

/// Signed forces of the four plates on the roller (x: +x toward the free span; y: normal to it
/// in the plane of the links), by Plate index, and the tooth's load, for layout 1 or 2.
struct LayoutLoads {
  int layout = 1;
  std::array<double, 4> plate_force{};    ///< [N] x components
  std::array<double, 4> plate_force_y{};  ///< [N] y components (0 when the links are collinear)
  Block tooth;                            ///< x component
  double tooth_y = 0.0;                   ///< [N] y component, over the same interval
};
LayoutLoads layout_loads(const Input& in, int layout);
/// The roller's loads in one direction: component 0 = x, 1 = y.
Beam beam(const Input& in, const LayoutLoads& loads, int component = 0);

/// Shear force Q(z) = Σ forces below z (the part of a block below z); `above` picks the limit
/// from above at a point load. Bending moment M(z) = Σ forces below z × arm to z. dM/dz = Q.
double shear(const Beam& b, double z, bool above = false);
double moment(const Beam& b, double z);

struct Diagram {
  std::vector<double> x, moment, shear;   ///< [m], [N·m], [N]; x repeated at a point load
  std::vector<double> moment_y, shear_y;  ///< the y components (filled by the two-beam form)
};
/// Samples every block boundary and `per_block` interior points of every distributed block.
Diagram diagram(const Beam& b, int per_block = 8);
/// Both components; `y` has the same blocks as `x` (beam(in, loads, 1)).
Diagram diagram(const Beam& x, const Beam& y, int per_block = 8);

struct Extremes {
  double moment = 0.0, moment_at = 0.0;  ///< [N·m] max |M| and where
  double shear = 0.0, shear_at = 0.0;    ///< [N] max |Q| and where
};
/// Exact: |M| peaks at a block boundary or where Q = 0 inside a block; |Q| at a boundary.
Extremes extremes(const Beam& b);
/// Of the resultants |M| = hypot(Mx, My), |Q| = hypot(Qx, Qy): |Q| is convex between boundaries
/// (max at one); |M|² has its stationary points where Mx·Qx + My·Qy = 0, found by a 64-point
/// scan and bisection inside each interval. Reduces to the exact form when y carries no load.
Extremes extremes(const Beam& x, const Beam& y);

/// [m] eq. (22): projection of a contact arc of angle γ on radius r onto the plane normal to N.
double projection(double radius, double angle);

/// [-] τ_max/(Q/A) at the neutral axis of a (hollow) circular section: 4/3 for a solid one.
double shear_factor(double outer, double inner);

struct Check {
  std::string name;            ///< e.g. "roller.bending"
  std::string section;         ///< where: layout, plate, height
  double stress = 0.0;         ///< [Pa]
  double allowable = 0.0;      ///< [Pa] the strength or allowable stress it is compared with
  double required = 0.0;       ///< [-] the safety factor it must reach
  double safety_factor = 0.0;  ///< [-] allowable/stress (∞ for zero stress)
  bool ok = true;
};

struct Contact {
  int layout = 1;
  int plate = 0;
  double force = 0.0;             ///< [N] |N| of the most loaded plate–roller contact
  double width = 0.0;             ///< [m] B of that plate
  double radius = 0.0;            ///< [m] r of eq. (22): d/2 (sliding) or R1 (rolling)
  double angle = 0.0;             ///< [rad] γ of the contact arc
  double c = 0.0;                 ///< [m] eq. (22)
  double area = 0.0;              ///< [m²] A = c·B
  double p = 0.0;                 ///< [Pa] eq. (23) p = N/A (rolling: the mean Hertz pressure)
  bool hertz = false;             ///< rolling hinge: the Hertz fields below are set
  double peak = 0.0;              ///< [Pa] Hertz p0
  double half_width = 0.0;        ///< [m] Hertz b
  double effective_radius = 0.0;  ///< [m] R* = R1 R2/(R2 − R1)
};

struct LayoutResult {
  LayoutLoads loads;
  Diagram diagram;
  Extremes extremes;
  bool planar = false;           ///< loads in y too (θ ≠ 0 and S2 ≠ 0)
  double force_residual = 0.0;   ///< [N] max |ΣF| of the roller over x and y
  double moment_residual = 0.0;  ///< [N·m] max |ΣM| about z = 0 over x and y
};

struct Result {
  std::vector<LayoutResult> layouts;
  std::vector<Check> checks;
  Contact contact;
  std::vector<Diagnostic> diagnostics;
};

/// Runs every check (named assess: catena::check is the namespace of input checks); throws
/// InputError on invalid input.
Result assess(const Input& in);

}  // namespace catena::strength
