// Roller warp (seed 000 §1.4): every problem with the inputs, reported at once.
#include <cmath>
#include <string>

#include "catena/warp/warp.hpp"
#include "internal.hpp"

namespace catena::warp {

using detail::kJointName;

std::vector<Issue> validate(const Warp& w, const Load& load) {
  std::vector<Issue> out;
  for (std::size_t i = 0; i < 4; ++i) {
    const Support& s = w.supports[i];
    const std::string name = std::string("joint ") + kJointName[i];
    check::finite(out, (name + " height").c_str(), s.height, "m");
    if (!(std::isfinite(s.clearance) && s.clearance >= 0 && s.clearance <= kMaxClearance))
      out.push_back({name + " clearance", check::format_si(s.clearance, "m"),
                     "a clearance 0 … " + check::format_si(kMaxClearance, "m")});
    check::finite_positive(out, (name + " stiffness").c_str(), s.stiffness, "N/m^n");
    check::finite_positive(out, (name + " width").c_str(), s.width, "m");
    if (i > 0 && std::isfinite(s.height) && std::isfinite(w.supports[i - 1].height) &&
        !(s.height > w.supports[i - 1].height))
      out.push_back({name + " height", check::format_si(s.height, "m"),
                     std::string("above joint ") + kJointName[i - 1] + " (" +
                         check::format_si(w.supports[i - 1].height, "m") +
                         "): order lower outer < lower inner < upper inner < upper outer"});
  }
  if (!(w.exponent >= 1 && w.exponent <= 3))
    out.push_back({"exponent", check::format_si(w.exponent, ""), "n of R = k·g^n in [1, 3]"});
  check::finite_positive(out, "roller_diameter", w.roller_diameter, "m");
  check::finite_positive(out, "modulus", w.modulus, "Pa");
  if (!(w.poisson >= 0 && w.poisson < 0.5))
    out.push_back({"poisson", check::format_si(w.poisson, ""), "0 ≤ ν < 0.5"});
  if (w.kind == HingeKind::kRolling) {
    check::finite_positive(out, "r1", w.r1, "m");
    if (!(std::isfinite(w.r2) && w.r2 > w.r1))
      out.push_back({"r2", check::format_si(w.r2, "m"), "R2 > R1 (the roller's concave face)"});
  }
  if (!(std::isfinite(load.force) && load.force > 0 && load.force <= kMaxForce))
    out.push_back({"force", check::format_si(load.force, "N"),
                   "a tooth load 0 < F ≤ " + check::format_si(kMaxForce, "N")});
  const double lo = w.supports[0].height, hi = w.supports[3].height;
  if (!std::isfinite(load.height)) {
    out.push_back({"load_height", check::format_si(load.height, "m"), "a finite height L1"});
  } else if (std::isfinite(lo) && std::isfinite(hi) && !(load.height >= lo && load.height <= hi)) {
    out.push_back({"load_height", check::format_si(load.height, "m"),
                   "L1 between the outer joints [" + check::format_si(lo, "m") + ", " +
                       check::format_si(hi, "m") +
                       "] (outside, unilateral joints cannot balance the moment)"});
  }
  return out;
}

}  // namespace catena::warp
