#include "catena/pocketwheel/layout.hpp"

#include <cmath>

namespace catena::pocketwheel {

ChainLayout chain_layout(const PocketWheel& wheel, const RunOnPlan& plan, double wrap) {
  const WheelGeometry& g = plan.geometry;
  const double r = g.pitch_radius;
  auto at = [&](double theta) { return std::pair{-r * std::sin(theta), r * std::cos(theta)}; };
  ChainLayout out;
  // The link just downstream of the crank is the other kind than the first to seat next
  // (the kinds alternate along the chain): t + d spans δ1, t − d spans δ2 (eqs. 7–8).
  const double crank = plan.phases.front().crank_angle0;
  const bool first_is_long = plan.first_link > wheel.pitch;
  double step = first_is_long ? g.delta2 : g.delta1;
  for (double theta = crank; theta >= crank - wrap - 1e-12;) {
    out.seated.push_back(at(theta));
    theta -= step;
    step = step == g.delta1 ? g.delta2 : g.delta1;
  }
  const auto [cx, cy] = out.seated.front();
  const double run = 3.0 * wheel.pitch;  // how much straight strand to show
  if (plan.guide.kind == GuideKind::kNone) {
    out.strand = {{cx, cy}, {cx - run, cy}};
  } else {
    const double l = plan.guide.end_distance, h = plan.guide_height;
    out.strand = {{cx, cy}, {-l, h}, {-l - run, h}};
  }
  return out;
}

}  // namespace catena::pocketwheel
