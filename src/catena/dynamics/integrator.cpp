// The energy-conserving implicit midpoint step with Newton's method on the chain's block
// tridiagonal Jacobian (include/catena/dynamics/integrator.hpp; docs/models/dynamics.md).
#include "catena/dynamics/integrator.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace catena::dynamics {

std::vector<Issue> validate(const IntegratorOptions& options) {
  std::vector<Issue> out;
  check::finite_positive(out, "step", options.step, "s");
  if (options.max_iterations < 1 || options.max_iterations > 1000) {
    out.push_back(
        {"max_iterations", std::to_string(options.max_iterations), "an integer in [1, 1000]"});
  }
  if (!std::isfinite(options.tolerance) || !(options.tolerance >= 1e-15) ||
      !(options.tolerance <= 1e-2)) {
    out.push_back({"tolerance", check::format_si(options.tolerance, ""),
                   "a number in [1e-15, 1e-2] (a fraction of the pitch)"});
  }
  if (!std::isfinite(options.theta) || !(options.theta >= 0.5) || !(options.theta <= 1.0)) {
    out.push_back({"theta", check::format_si(options.theta, ""), "a number in [0.5, 1]"});
  }
  return out;
}

namespace {
// x −= c w, node by node: the bordered solve's δu₀ − W δx and the switch update's δ − W c
void subtract_scaled(std::span<Vec2> x, std::span<const Vec2> w, double c) {
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i].x -= w[i].x * c;
    x[i].y -= w[i].y * c;
  }
}
// e + v · x over a switched hinge's three nodes `at` (v: their x, y entries in turn): the switch
// update's Vᵀ y and Vᵀ W
double hinge_dot(const double* v, const std::size_t* at, std::span<const Vec2> x, double e) {
  for (int q = 0; q < 3; ++q) e += v[2 * q] * x[at[q]].x + v[2 * q + 1] * x[at[q]].y;
  return e;
}
std::size_t checked_nodes(const Model& model, const IntegratorOptions& options) {
  std::vector<Issue> issues = validate(model);
  std::vector<Issue> more = validate(options);
  issues.insert(issues.end(), more.begin(), more.end());
  throw_if_any(issues);
  return model.nodes();
}
// Whether node i can touch the guide on the step from x₀ (the state) to the iterate u, its θ
// point (qx, qy): the guide's bounds cull (exact: a roller outside them cannot touch it;
// guide_bounds). The contact acts at the θ point, or, with the discrete gradient
// (Guide::discrete_gradient), over the step: then it is culled only when its θ point, x₀ and u are
// all outside the bounds (a roller entering or leaving the rail on the step, or bouncing off it
// within a step or two, has a force while its θ point's gap is ≤ 0). Exact against the bounds;
// but the guide hint's lists (GuideHint) are made from the θ points: they reach 1.25 margins
// (p/4) past the box and a node moves at most a margin before they are made afresh, so a listed
// node's x₀ or u is covered only while it is within p/16 of the θ point in x and in y — θ|Δx|
// ≤ p/16 a step (1.2 mm on 12B); past that an x₀ or u inside the box can be missed (docs "Guides:
// the discrete gradient").
bool step_touch_possible(const Guide& guide, const GuideBounds& bounds, const State& s,
                         const std::vector<double>& ux, const std::vector<double>& uy,
                         std::size_t i, double qx, double qy) {
  if (guide_touch_possible(bounds, qx, qy)) return true;
  return guide.discrete_gradient && (guide_touch_possible(bounds, s.x[i], s.y[i]) ||
                                     guide_touch_possible(bounds, ux[i], uy[i]));
}
// Node i's contact with a guide at its θ point (qx, qy) of the step from x₀ (the state) to the
// iterate u, with the step's velocity (u − x₀)/h: the force the step applies. The guide's bounds
// cull first (step_touch_possible), so that a node far from a rail costs a few comparisons. With
// the discrete gradient (Guide::discrete_gradient) the elastic part is taken over the step from
// x₀ to u.
GuideContact guide_contact_at_theta(const Guide& guide, const GuideFrame& frame,
                                    const GuideBounds& bounds, const State& s,
                                    const std::vector<double>& ux, const std::vector<double>& uy,
                                    std::size_t i, double qx, double qy, double h,
                                    double anchor = NAN) {
  if (!step_touch_possible(guide, bounds, s, ux, uy, i, qx, qy)) return {};
  const double vx = (ux[i] - s.x[i]) / h, vy = (uy[i] - s.y[i]) / h;
  if (!guide.discrete_gradient) return guide_contact(guide, frame, qx, qy, vx, vy, anchor);
  const GuideStep step{s.x[i], s.y[i], ux[i], uy[i], h};
  return guide_contact(guide, frame, qx, qy, vx, vy, anchor, &step);
}
// The stick law's anchor of node i on the sticking guide `guide` (Guide::stick_stiffness) whose
// anchors are the state's slot `slot` (State::stick_anchor) for the step from the state s: the
// state's, or where the node starts the step if it was not in contact (a roller touching down
// sticks where it is). NaN for a guide without the stick law (slot < 0).
double step_anchor(const Guide& guide, const GuideFrame& frame, const State& s, std::ptrdiff_t slot,
                   std::size_t i) {
  if (slot < 0) return NAN;
  const std::size_t at = static_cast<std::size_t>(slot) * s.x.size() + i;
  const double a = at < s.stick_anchor.size() ? s.stick_anchor[at] : NAN;
  return std::isfinite(a) ? a : guide_position(guide, frame, s.x[i], s.y[i]);
}
// Loaded pieces with load_inertia of which two or more, one with a speed of its own, may overlap
// at a node: only then is a node's arriving material the pieces' increments'
// (Integrator::arrival).
bool load_speeds_mix(std::span<const Guide> guides) {
  int loaded = 0;
  bool speed = false;
  for (const Guide& g : guides) {
    if (!g.load_inertia || !(g.load_per_metre > 0.0)) continue;
    ++loaded;
    speed = speed || g.load_speed != 0.0;
  }
  return loaded >= 2 && speed;
}
std::size_t sticking_guides(const Model& model) {
  std::size_t k = 0;
  for (const Guide& g : model.guides)
    if (g.stick_stiffness > 0.0) ++k;
  return k;
}
// The chain's links and hinges in one order for every pass that walks them (the Newton system's
// assembly, the stick law's end of a step), n nodes. f(j, a, b) for link j from node a = j to
// node b (node 0 after the last on a loop); f(ha, i, hb) for the hinge at node i between links ha
// (ha → i) and i (i → hb), at every node of a loop (modulo n) and at an open chain's inner nodes
// (n ≥ 3).
template <class F>
void for_each_link(std::size_t n, std::size_t links, F&& f) {
  for (std::size_t j = 0; j < links; ++j) f(j, j, j + 1 == n ? 0 : j + 1);
}
template <class F>
void for_each_hinge(std::size_t n, bool closed, F&& f) {
  const std::size_t first = closed ? 0 : 1, last = closed ? n : n - 1;
  for (std::size_t i = first; i < last; ++i) f(i == 0 ? n - 1 : i - 1, i, i + 1 == n ? 0 : i + 1);
}
}  // namespace

Integrator::Integrator(const Model& model, IntegratorOptions options)
    : options_(options),
      solver_(checked_nodes(model, options), model.closed),
      pentadiagonal_(model.hinge.active() && model.nodes() >= 3),
      penta_(pentadiagonal_ ? model.nodes() : 1, pentadiagonal_ && model.closed),
      far_lower_(pentadiagonal_ ? model.nodes() : 0),
      far_upper_(pentadiagonal_ ? model.nodes() : 0),
      ux_(model.nodes()),
      uy_(model.nodes()),
      l0_(model.links()),
      l1_(model.links()),
      hinge_links_(model.hinge.active() ? model.links() : 0),
      trial_(model.hinge.sticks() ? model.nodes() : 0),
      trial_base_(trial_.size()),
      kept_branch_(trial_.size()),
      switch_u_(trial_.size()),
      switch_w_(trial_.empty() ? 0 : kMaxSwitches, std::vector<Vec2>(trial_.size())),
      delta_(model.nodes()),
      psi1_(model.sprockets.size()),
      slide1_(model.sprockets.size()),
      load_mass0_(model.nodes()),
      angle_of_(model.sprockets.size(), static_cast<std::size_t>(-1)),
      slide_of_(model.sprockets.size(), static_cast<std::size_t>(-1)),
      slide_force_(model.sprockets.size()),
      wheel_force_(model.sprockets.size()),
      torque_(model.sprockets.size()),
      dvx_(model.nodes()),
      dvy_(model.nodes()),
      dspeed_(model.sprockets.size()),
      dslide_speed_(model.sprockets.size()) {
  qx_.resize(model.nodes());
  qy_.resize(model.nodes());
  listed_x_.assign(model.nodes(), NAN);  // no lists yet: made at the first assembly
  listed_y_.assign(model.nodes(), NAN);
  candidates_.resize(model.sprockets.size());
  for (std::vector<std::size_t>& list : candidates_) list.reserve(model.nodes());
  for (std::size_t w = 0; w < model.sprockets.size(); ++w) {
    if (model.sprockets[w].driver) continue;
    angle_of_[w] = extra_.size();
    extra_.push_back({w, false});
  }
  for (std::size_t w = 0; w < model.sprockets.size(); ++w) {
    if (!model.sprockets[w].takeup) continue;
    slide_of_[w] = extra_.size();
    extra_.push_back({w, true});
  }
  const std::size_t m = extra_.size();
  xres_.assign(m, 0.0);
  xjac_.assign(m * m, 0.0);
  dx_.assign(m, 0.0);
  switch_wx_.assign(trial_.empty() ? 0 : kMaxSwitches * m, 0.0);
  schur_.assign(m * m, 0.0);
  bcol_.assign(m, std::vector<Vec2>(model.nodes()));
  brow_.assign(m, std::vector<Vec2>(model.nodes()));
  wsol_.assign(m, std::vector<Vec2>(model.nodes()));
  border_rows_.assign(m, {});
  for (std::vector<std::size_t>& rows : border_rows_) rows.reserve(model.nodes());
  // A quarter pitch: at a chain speed v a node crosses it in p/(4 v h) steps (over a hundred at
  // 1 m/s and h = 1e-4 s for 12B), while a rail's list grows by half a pitch's width of nodes.
  guide_hint_ = GuideHint(0.25 * model.pitch);
  all_nodes_.resize(model.nodes());
  for (std::size_t i = 0; i < model.nodes(); ++i) all_nodes_[i] = static_cast<std::uint32_t>(i);
}

void Integrator::theta_points(const State& s) {
  const std::size_t n = qx_.size();
  const double th = options_.theta;
  const double* sx = s.x.data();
  const double* sy = s.y.data();
  const double* ux = ux_.data();
  const double* uy = uy_.data();
  double* qx = qx_.data();
  double* qy = qy_.data();
  for (std::size_t i = 0; i < n; ++i) {
    qx[i] = (1.0 - th) * sx[i] + th * ux[i];
    qy[i] = (1.0 - th) * sy[i] + th * uy[i];
  }
}

void Integrator::refresh_guide_hint(const Model& model) {
  // the rails' frames, O(G): recomputed here so that a model whose guides changed since the last
  // step is still right
  guide_frame_.resize(model.guides.size());
  stick_slot_.resize(model.guides.size());
  std::ptrdiff_t sticking = 0;
  for (std::size_t g = 0; g < model.guides.size(); ++g) {
    guide_frame_[g] = guide_frame(model.guides[g]);
    stick_slot_[g] = model.guides[g].stick_stiffness > 0.0 ? sticking++ : -1;
  }
  if (model.guides.empty() || !options_.guide_hint) return;
  guide_hint_.update(model.guides, qx_, qy_);
}

void Integrator::prepare_links(const Model& model) {
  if (model.links_carry_compression || !model.links_discrete_gradient) return;
  link_start_.resize(model.links());
  for (std::size_t j = 0; j < model.links(); ++j)  // (a bilateral link reads no start)
    if (!model.bilateral(j))
      link_start_[j] = link_step_start(model, l0_[j] - model.rest_length(j), j);
}

void Integrator::prepare_seats(const Model& model) {
  const std::size_t wheels = model.sprockets.size();
  seat_geometry_.resize(wheels);
  seat_psi_.assign(wheels, NAN);
  seat_direction_.resize(wheels);
  pocket_start_.resize(wheels);
  seat_start_.resize(wheels);
  for (std::size_t w = 0; w < wheels; ++w) {
    const Sprocket& wheel = model.sprockets[w];
    if (wheel.pocket && wheel.discrete_gradient) pocket_start_[w].assign(model.nodes(), {});
    if (wheel.pocket) continue;
    if (wheel.discrete_gradient) seat_start_[w].assign(model.nodes(), {});
    seat_geometry_[w] = seat_geometry(wheel);
    seat_direction_[w].assign(static_cast<std::size_t>(std::max(wheel.teeth, 1)), SeatDirection{});
  }
}

bool Integrator::update_candidates(const Model& model, double moved) {
  // A node off a wheel's list was farther than reach + margin from its centre where the list was
  // made; it has moved by at most √2 · moved since (its θ point's ∞-norm distance), so it is
  // still beyond reach while √2 · moved ≤ margin/2 (half: room for the reach test's roundings).
  const std::size_t n = model.nodes(), wheels = model.sprockets.size();
  candidates_.resize(wheels);
  listed_wheel_.resize(3 * wheels, NAN);
  bool valid = true;
  for (std::size_t w = 0; w < wheels && valid; ++w) {
    const Sprocket& wheel = model.sprockets[w];
    const double reach = contact_reach(wheel);
    valid = std::sqrt(2.0) * moved <= 0.5 * kCandidateMargin * reach &&
            listed_wheel_[3 * w] == wheel.centre_x && listed_wheel_[3 * w + 1] == wheel.centre_y &&
            listed_wheel_[3 * w + 2] == reach;
  }
  if (valid) return true;
  // made afresh at these θ points: every node that is not beyond reach + margin; none while a
  // θ point is not finite (every node is tested then, as the reach test lets NaN through)
  const double* qx = qx_.data();
  const double* qy = qy_.data();
  double check = 0.0;
  for (std::size_t i = 0; i < n; ++i) check += std::abs(qx[i]) + std::abs(qy[i]);
  if (!std::isfinite(check)) {
    std::fill(listed_x_.begin(), listed_x_.end(), NAN);
    return false;
  }
  for (std::size_t w = 0; w < wheels; ++w) {
    const Sprocket& wheel = model.sprockets[w];
    const double reach = contact_reach(wheel);
    const double wide = (1.0 + kCandidateMargin) * reach, wide2 = wide * wide;
    std::vector<std::size_t>& list = candidates_[w];
    list.clear();
    for (std::size_t i = 0; i < n; ++i) {
      const double rx = qx[i] - wheel.centre_x, ry = qy[i] - wheel.centre_y;
      if (!(rx * rx + ry * ry > wide2)) list.push_back(i);
    }
    listed_wheel_[3 * w] = wheel.centre_x;
    listed_wheel_[3 * w + 1] = wheel.centre_y;
    listed_wheel_[3 * w + 2] = reach;
  }
  listed_x_ = qx_;
  listed_y_ = qy_;
  return true;
}

double Integrator::assemble(const Model& model, const State& s, bool jacobian, bool report_only) {
  forward_pending_ = false;  // the residual changes: a forward sweep of the old one is stale
  const std::size_t n = model.nodes();
  const double h = options_.step;
  const double th = options_.theta;
  const double k = model.axial_stiffness;
  const double c = model.axial_damping;
  // Residual R(u) = (m/hθ)(u − x₀ − h v₀) + α m (u − x₀) − h (Σ f + m g) and its Jacobian
  // J = (m/hθ + α m) I + h Σ A; the system is J δ = −R.
  // The dissipative works of this iterate (the step's report takes the last assembly's): the drag
  // impulse is −α m Δx, its work −α m |Δx|²/h; the link dampers' and contact dampers' below.
  damper_work_ = drag_work_ = contact_damping_work_ = seat_friction_work_ = 0.0;
  // The node and link loops read through local pointers: the stores into the solver's arrays
  // would otherwise make the compiler reload every vector's data pointer in every iteration.
  const double* sx = s.x.data();
  const double* sy = s.y.data();
  const double* svx = s.vx.data();
  const double* svy = s.vy.data();
  const double* ux = ux_.data();
  const double* uy = uy_.data();
  const double* mass = model.mass.data();
  Vec2* rhs = solver_.rhs.data();
  Mat2* diag = solver_.diag.data();
  const double drag = model.drag, grav_x = model.gravity_x, grav_y = model.gravity_y;
  double drag_work = 0.0;
  const bool open_chain = model.links() < n;
  // the drag's work, in a loop of its own (α = 0, the usual case: the sum stays +0 without it)
  for (std::size_t i = 0; drag != 0.0 && i < n; ++i) {
    const double m = mass[i];
    const double dx = ux[i] - sx[i], dy = uy[i] - sy[i];
    drag_work -= drag * m * (dx * dx + dy * dy) / h;
  }
  for (std::size_t i = 0; !report_only && i < n; ++i) {
    const double m = mass[i];
    const double dx = ux[i] - sx[i], dy = uy[i] - sy[i];
    const double inertia = m / (h * th);
    if (jacobian) {
      diag[i] = {inertia + drag * m, 0.0, 0.0, inertia + drag * m};
      // a closed loop's links set every lower and upper block below (an open chain's leave the
      // corners lower[0] and upper[n − 1])
      if (open_chain) solver_.lower[i] = solver_.upper[i] = {};
      if (pentadiagonal_) far_lower_[i] = far_upper_[i] = {};
    }
    rhs[i] = {-(inertia * (dx - h * svx[i]) + drag * m * dx - h * m * grav_x),
              -(inertia * (dy - h * svy[i]) + drag * m * dy - h * m * grav_y)};
  }
  drag_work_ = drag_work;
  for (const NodeLoad& f : model.loads) {  // constant: no Jacobian term
    if (report_only) break;
    solver_.rhs[f.node].x += h * f.fx;
    solver_.rhs[f.node].y += h * f.fy;
  }
  const std::size_t links = model.links();
  const double* len0 = l0_.data();
  double* len1 = l1_.data();
  Mat2* upper = solver_.upper.data();
  Mat2* lower = solver_.lower.data();
  double damper_work = 0.0;
  const bool hinges = !hinge_links_.empty();  // (read once: the stores below may alias it)
  const LinkStart* link_start = link_start_.data();
  const double bilateral_slope = k * th + c / h;  // a bilateral link's ∂T/∂l₁, every link's
  for_each_link(n, links, [&](std::size_t j, std::size_t a, std::size_t b) {
    const double d0x = sx[b] - sx[a], d0y = sy[b] - sy[a];
    const double d1x = ux[b] - ux[a], d1y = uy[b] - uy[a];
    const double l0 = len0[j];
    const double l1 = std::sqrt(
        d1x * d1x + d1y * d1y);  // sqrt, not hypot: no overflow at chain scales, and faster
    len1[j] = l1;
    const double lt = (1.0 - th) * l0 + th * l1;
    const double mx = (1.0 - th) * d0x + th * d1x, my = (1.0 - th) * d0y + th * d1y;
    const double p = model.rest_length(j);  // p ± a (round-link chain), else p
    // φ and ∂(φ l_θ)/∂l₁ = θ ∂T/∂s + (∂T/∂ṡ)/h of the link's law
    double phi = 0.0, dtension = 0.0;
    if (!model.bilateral(j)) {
      // A tension-only link (docs/models/dynamics.md, "Tension-only links"): link_force's T at the
      // θ point's stretch and the step's rate, or with Model::links_discrete_gradient T over the
      // step (link_step_force: at θ = ½ its spring's work is −ΔE, since d_θ·(d₁ − d₀)/l_θ =
      // l₁ − l₀ there); the damper's share T − T_e does the work −(T − T_e) d_θ·(d₁ − d₀)/l_θ
      // (−T_e there where T is clamped at 0, as the seats' damper).
      double tension = 0.0, elastic = 0.0;
      if (model.links_discrete_gradient) {
        const LinkStep law = link_step_force(model, l0 - p, l1 - p, h, j, link_start[j]);
        tension = law.tension;
        elastic = law.elastic;
        dtension = law.slope;  // ∂T/∂l₁ = ∂T/∂s₁; 0 on a slack link
      } else {
        const LinkForce law = tension_only_link_force(model, lt - p, (l1 - l0) / h, j);
        tension = law.tension;
        elastic = law.elastic;
        dtension = th * law.stiffness + law.damping / h;  // 0 on a slack link
      }
      damper_work -= (tension - elastic) * (mx * (d1x - d0x) + my * (d1y - d0y)) / lt;
      if (report_only) return;  // (no hinges: validated)
      phi = tension / lt;
    } else {
      // A bilateral link (every link with Model::links_carry_compression, or its parity's with
      // Model::link_bilateral: at θ = ½ its force is the discrete gradient link_step_force takes).
      // The damper's share of φ d_θ does the work −c (l₁ − l₀)/h · d_θ·(d₁ − d₀)/l_θ on the two
      // nodes (d_θ·(d₁ − d₀) = l̄ (l₁ − l₀) + (θ − ½)|d₁ − d₀|²: −c (l₁ − l₀)²/h at θ = ½)
      if (c > 0.0) {
        damper_work -= c * (l1 - l0) / h * (mx * (d1x - d0x) + my * (d1y - d0y)) / lt;
      }
      // report only: the force is not needed (but for the hinges' couples, which take it)
      if (report_only && !hinges) return;
      // φ = [k (l_θ − p) + c (l₁ − l₀)/h] / l_θ; the force on node a is φ d_θ, on node b −φ d_θ.
      // At θ = ½ the work over the step is exactly the change of ½ k (l − p)² plus the damper's
      // loss c (l₁ − l₀)²/h (Simo & Tarnow 1992).
      phi = (k * (lt - p) + c * (l1 - l0) / h) / lt;
      dtension = bilateral_slope;
    }
    const double fx = h * phi * mx, fy = h * phi * my;
    rhs[a].x += fx;
    rhs[a].y += fy;
    rhs[b].x -= fx;
    rhs[b].y -= fy;
    // the link's share of the couples of the hinges at its two ends (the hinge loop below)
    if (hinges) hinge_link(d0x, d0y, d1x, d1y, l0, l1, p, k, th, hinge_links_[j], jacobian);
    if (!jacobian) return;
    // A = ∂(φ d_θ)/∂d₁ = θ φ I + d_θ ⊗ (∂φ/∂l₁) d₁/l₁,  ∂φ/∂l₁ = [∂T/∂l₁ − θ φ] / l_θ
    // (∂T/∂l₁ = k θ + c/h for the bilateral link).
    const double dphi = (dtension - th * phi) / lt;
    const double gx = l1 > 0.0 ? dphi * d1x / l1 : 0.0;
    const double gy = l1 > 0.0 ? dphi * d1y / l1 : 0.0;
    const Mat2 hA{h * (th * phi + mx * gx), h * mx * gy, h * my * gx, h * (th * phi + my * gy)};
    Mat2& daa = diag[a];
    Mat2& dbb = diag[b];
    daa = {daa.a + hA.a, daa.b + hA.b, daa.c + hA.c, daa.d + hA.d};
    dbb = {dbb.a + hA.a, dbb.b + hA.b, dbb.c + hA.c, dbb.d + hA.d};
    // block (a, b) is upper[a] (the corner upper[n−1] when b = 0); block (b, a) is lower[b].
    upper[a] = {-hA.a, -hA.b, -hA.c, -hA.d};
    lower[b] = {-hA.a, -hA.b, -hA.c, -hA.d};
  });
  damper_work_ = damper_work;
  // Hinge friction (docs/models/dynamics.md, "Hinges"): the couple M g on nodes i − 1, i, i + 1.
  // The residual and the Jacobian are exact: −h ∂(M g)/∂u (rate, load and direction terms; not
  // symmetric) on the 3 × 3 node blocks, the blocks (i − 1, i + 1) and (i + 1, i − 1) in the
  // pentadiagonal band (far_upper_, far_lower_), solved by BlockPentadiagonalSolver.
  hinge_work_ = 0.0;
  if (model.hinge.active() && n >= 3) {
    const HingeLink* hinge_link_of = hinge_links_.data();
    Mat2* far_lower = far_lower_.data();
    Mat2* far_upper = far_upper_.data();
    double hinge_work = 0.0;
    HingeCouple hc;  // one for every hinge: each call writes every field read below
    // the stick law's deflections at the step's start (none sized: every hinge at its anchor)
    const double* deflection = model.hinge.sticks() && s.hinge_deflection.size() == n
                                   ? s.hinge_deflection.data()
                                   : nullptr;
    // where the stick law's trials go (the crossing cut's; none without the stick law)
    HingeTrial* const trials =
        deflection != nullptr && trial_.size() == n ? trial_.data() : nullptr;
    for_each_hinge(n, model.closed, [&](std::size_t ha, std::size_t i, std::size_t hb) {
      // links ha (ha → i) and i (i → hb), their terms from the links' loop above; −h × the
      // couple's Jacobian block (r, q) of the three nodes ha, i, hb into the band (node offsets
      // q − r in −2..2)
      Mat2* const slot[3][3] = {{&diag[ha], &upper[ha], &far_upper[ha]},
                                {&lower[i], &diag[i], &upper[i]},
                                {&far_lower[hb], &lower[hb], &diag[hb]}};
      hinge_couple_blocks(
          model.hinge, hinge_link_of[ha], hinge_link_of[i], h, hc, jacobian,
          [&](int r, int q, double ja, double jb, double jc, double jd) {
            Mat2& m = *slot[r][q];
            m = {m.a - h * ja, m.b - h * jb, m.c - h * jc, m.d - h * jd};
          },
          i, th, deflection != nullptr ? deflection[i] : 0.0);
      hinge_work += hc.work;
      if (trials != nullptr) trials[i] = {hc.trial, model.hinge.arm * hc.load};
      rhs[ha].x += h * hc.fx[0];
      rhs[ha].y += h * hc.fy[0];
      rhs[i].x += h * hc.fx[1];
      rhs[i].y += h * hc.fy[1];
      rhs[hb].x += h * hc.fx[2];
      rhs[hb].y += h * hc.fy[2];
    });
    hinge_work_ = hinge_work;
  }
  // The nodes' θ points, once for all wheels and guides, and how far they are from where the
  // wheels' candidate lists were made (∞-norm; NaN when a point is not finite)
  bool listed = false;  // the candidate lists hold every node within reach of its wheel
  if (model.sprockets.empty() && !model.guides.empty()) theta_points(s);
  if (!model.sprockets.empty()) {
    // theta_points' arithmetic, fused with the distance from the lists' points (one pass)
    double* qx = qx_.data();
    double* qy = qy_.data();
    const double* bx = listed_x_.data();
    const double* by = listed_y_.data();
    double moved = 0.0, check = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      qx[i] = (1.0 - th) * sx[i] + th * ux[i];
      qy[i] = (1.0 - th) * sy[i] + th * uy[i];
      const double mx = std::abs(qx[i] - bx[i]), my = std::abs(qy[i] - by[i]);
      moved = std::max(moved, std::max(mx, my));
      check += mx + my;  // NaN if any is
    }
    listed = update_candidates(model, std::isfinite(check) ? moved : INFINITY);
    // A wheel with the discrete gradient (Sprocket::discrete_gradient) tries a node whose x₀ or
    // iterate is in reach too: they are within max(θ, 1 − θ) |u − x₀| (∞-norm) of the θ point
    if (std::any_of(model.sprockets.begin(), model.sprockets.end(),
                    [](const Sprocket& w) { return w.discrete_gradient && !w.pocket; })) {
      double step_move = 0.0;
      for (std::size_t i = 0; i < n; ++i)
        step_move = std::max(step_move, std::max(std::abs(ux[i] - sx[i]), std::abs(uy[i] - sy[i])));
      seat_travel_ = std::max(th, 1.0 - th) * step_move;
    }
  }
  max_penetration_ = 0.0;
  takeup_damper_work_ = 0.0;
  double wheel_norm2 = 0.0;
  const std::size_t nx = extra_.size();
  if (jacobian) std::fill(xjac_.begin(), xjac_.end(), 0.0);
  for (std::size_t w = 0; w < model.sprockets.size(); ++w) {
    const Sprocket& fixed = model.sprockets[w];
    const double psi = (1.0 - th) * s.angle[w] + th * psi1_[w];
    const double omega = (psi1_[w] - s.angle[w]) / h;
    const bool driven = !fixed.driver;
    const std::size_t ia = angle_of_[w];
    // A take-up's wheel sits at its slide's θ point and moves at the step's slide speed: the
    // contacts see the roller relative to it (docs/models/dynamics.md, "Take-up")
    const bool slides = fixed.takeup;
    const std::size_t is = slide_of_[w];
    const double ex = fixed.takeup_dx, ey = fixed.takeup_dy;
    double slide_th = 0.0, slide_rate = 0.0;
    Sprocket moved;
    if (slides) {
      slide_th = (1.0 - th) * s.slide[w] + th * slide1_[w];
      slide_rate = (slide1_[w] - s.slide[w]) / h;
      moved = at_slide(fixed, slide_th);
    }
    const Sprocket& wheel = slides ? moved : fixed;
    double torque = 0.0;
    double wdiag = driven ? wheel.inertia / (h * th) : 0.0;
    double sdiag = 0.0, cross_ws = 0.0, cross_sw = 0.0;  // ∂R_s/∂s, ∂R_ψ/∂s, ∂R_s/∂ψ
    double pull_x = 0.0, pull_y = 0.0;  // Σ (f n − F_t): the chain's force on the wheel
    // the border's column and row: zero but in the rows the last Jacobian assembly set
    auto clear_border = [&](std::size_t x) {
      for (const std::size_t i : border_rows_[x]) bcol_[x][i] = brow_[x][i] = Vec2{};
      border_rows_[x].clear();
    };
    if (driven && jacobian) clear_border(ia);
    if (slides && jacobian) clear_border(is);
    // seat_contact's own first test, inline: most rollers are clear of a wheel, and the call
    // (its result zeroed, the velocity formed) cost more than the test.
    const double reach = contact_reach(wheel);
    // An ISO wheel's seat directions: kept while its θ-point angle is the same (a driver's, for
    // the whole step), else taken afresh as seat_contact takes them
    const SeatGeometry& geometry = seat_geometry_[w];
    std::vector<SeatDirection>& directions = seat_direction_[w];
    if (!wheel.pocket && !(seat_psi_[w] == psi)) {
      for (SeatDirection& d : directions) d.k = NAN;
      seat_psi_[w] = psi;
    }
    const double cx0 = wheel.centre_x, cy0 = wheel.centre_y, reach2 = reach * reach;
    const double* thx = qx_.data();
    const double* thy = qy_.data();
    // The seats' discrete gradient ("Sprockets: the discrete gradient"): the step's ends, the
    // wheel's angles and centres there (a take-up's slides)
    const bool stepped = wheel.discrete_gradient;  // the seats' or the pockets'
    SeatStep ends;
    if (stepped) {
      ends.h = h;
      ends.cx0 = ends.cx1 = fixed.centre_x;
      ends.cy0 = ends.cy1 = fixed.centre_y;
      if (slides) {  // as at_slide
        ends.cx0 += s.slide[w] * ex;
        ends.cy0 += s.slide[w] * ey;
        ends.cx1 += slide1_[w] * ex;
        ends.cy1 += slide1_[w] * ey;
      }
    }
    auto beyond = [&](double x, double y, double cx, double cy) {
      return (x - cx) * (x - cx) + (y - cy) * (y - cy) > reach2;
    };
    // every node, or only the wheel's candidates (the same nodes pass the test, in the same
    // order); a pocket wheel's held joints may be beyond its reach, so it tries every node. A
    // node off the list is beyond (1 + margin/2) reach at its θ point (update_candidates): its x₀
    // and iterate are still beyond reach while √2 times the travel is within a quarter margin.
    const bool short_list =
        listed && !slides && !wheel.pocket &&
        (!stepped || std::sqrt(2.0) * seat_travel_ <= 0.25 * kCandidateMargin * reach);
    const std::size_t count = short_list ? candidates_[w].size() : n;
    const std::size_t* list = candidates_[w].data();
    for (std::size_t slot_i = 0; slot_i < count; ++slot_i) {
      const std::size_t i = short_list ? list[slot_i] : slot_i;
      const double qx = thx[i], qy = thy[i];
      const double rx = qx - cx0, ry = qy - cy0;
      const int held = wheel.pocket ? held_pocket(s, i, w) : kNoPocket;
      if (rx * rx + ry * ry > reach2 && held == kNoPocket &&
          (!stepped || (beyond(s.x[i], s.y[i], ends.cx0, ends.cy0) &&
                        beyond(ux_[i], uy_[i], ends.cx1, ends.cy1))))
        continue;
      if (model.is_pinned(i)) continue;
      double vx = (ux_[i] - s.x[i]) / h, vy = (uy_[i] - s.y[i]) / h;
      if (slides) {  // relative to the sliding centre
        vx -= slide_rate * ex;
        vy -= slide_rate * ey;
      }
      // (assigned once: a default-constructed contact overwritten cost its zeroing per roller)
      const SeatContact sc = [&] {
        if (wheel.pocket && !stepped)
          return pocket_contact(wheel, qx, qy, vx, vy, psi, omega, held);
        if (wheel.pocket) {  // its discrete gradient ("Pocket wheel: the discrete gradient")
          const PocketStep e{.x0 = s.x[i],
                             .y0 = s.y[i],
                             .x1 = ux_[i],
                             .y1 = uy_[i],
                             .cx0 = ends.cx0,
                             .cy0 = ends.cy0,
                             .cx1 = ends.cx1,
                             .cy1 = ends.cy1,
                             .angle0 = s.angle[w],
                             .angle1 = psi1_[w],
                             .theta = th,
                             .start = i < pocket_start_[w].size() ? &pocket_start_[w][i] : nullptr,
                             .jacobian = jacobian};
          return pocket_step_contact(wheel, qx, qy, vx, vy, psi, omega, held, e);
        }
        // seat_contact, its seat's direction from the step's table when there
        const double kseat = nearest_seat(rx, ry, psi, geometry.tau);
        const double teeth = static_cast<double>(directions.size());
        const double slot = kseat - teeth * std::floor(kseat / teeth);  // k mod z, in [0, z)
        // (beyond 2⁵³ the subtraction may round outside [0, z): then seat_contact, no table slot)
        if (slot >= 0.0 && slot < teeth) {
          SeatDirection& d =
              directions[std::min(static_cast<std::size_t>(slot), directions.size() - 1)];
          if (!(d.k == kseat)) {
            const double sigma = psi + kseat * geometry.tau;
            d = {kseat, std::cos(sigma), std::sin(sigma)};
          }
          if (!stepped)
            return seat_contact_at(wheel, geometry, qx, qy, vx, vy, omega, kseat, d.cs, d.sn);
          // the step's ends, each measured in its own nearest seat at the wheel's angle there
          SeatStep e = ends;
          e.x0 = s.x[i];
          e.y0 = s.y[i];
          e.x1 = ux_[i];
          e.y1 = uy_[i];
          e.angle0 = s.angle[w];
          e.angle1 = psi1_[w];
          e.turn = psi1_[w] - s.angle[w];
          e.theta = th;
          e.start = i < seat_start_[w].size() ? &seat_start_[w][i] : nullptr;
          e.jacobian = jacobian;
          return seat_contact_at(wheel, geometry, qx, qy, vx, vy, omega, kseat, d.cs, d.sn, &e);
        }
        // a non-finite iterate: as seat_contact (no table slot)
        return seat_contact(wheel, geometry, qx, qy, vx, vy, psi, omega);
      }();
      if (!sc.active) continue;
      max_penetration_ = std::max(max_penetration_, sc.depth);
      contact_damping_work_ += h * sc.damping_power;
      torque += sc.torque;
      solver_.rhs[i].x -= h * sc.force * sc.nx;  // the force on the roller is −f n
      solver_.rhs[i].y -= h * sc.force * sc.ny;
      if (sc.skew != 0.0) {  // the discrete gradient's correction along the step, −S Δ
        solver_.rhs[i].x -= h * sc.skew * sc.skew_x;
        solver_.rhs[i].y -= h * sc.skew * sc.skew_y;
      }
      if (wheel.pocket && jacobian) {
        // the pocket's mouth ramp: the rest of the elastic ∂F/∂q on the diagonal block (its
        // coupling to a driven wheel's angle below, as the body's; the damping's is left out:
        // quasi-Newton, the residual is exact)
        const double* e = sc.dq_extra;
        if (e[0] != 0.0 || e[1] != 0.0 || e[2] != 0.0 || e[3] != 0.0) {
          const double hq = h * th;
          Mat2& d = solver_.diag[i];
          d = {d.a - hq * e[0], d.b - hq * e[1], d.c - hq * e[2], d.d - hq * e[3]};
        }
        // the release's: the rest of ∂F/∂v too (−∂(h F)/∂u gains −∂F/∂v, v = (u − x₀)/h)
        const double* ev = sc.dv_extra;
        if (ev[0] != 0.0 || ev[1] != 0.0 || ev[2] != 0.0 || ev[3] != 0.0) {
          Mat2& d = solver_.diag[i];
          d = {d.a - ev[0], d.b - ev[1], d.c - ev[2], d.d - ev[3]};
        }
      }
      // Seat friction (docs/models/dynamics.md, "Seat friction"): F(q, v, ψ, ω) on the roller at
      // the θ point with the step's velocities, its reaction's torque on the wheel
      // (on a pocket wheel's body between the pockets the pocket's, faded over the capture's blend
      // and none beyond it: friction_weight, "Pocket wheel: friction")
      const bool rubs = wheel.friction > 0.0 && sc.friction_weight > 0.0;
      const SeatFriction sf =
          rubs ? seat_friction(wheel, sc, qx, qy, vx, vy, omega) : SeatFriction{};
      if (rubs) {
        seat_friction_work_ += h * sf.power;
        torque += sf.torque;
        solver_.rhs[i].x += h * sf.fx;
        solver_.rhs[i].y += h * sf.fy;
      }
      if (slides) {
        pull_x += sc.force * sc.nx - sf.fx;
        pull_y += sc.force * sc.ny - sf.fy;
        if (sc.skew != 0.0) {
          pull_x += sc.skew * sc.skew_x;
          pull_y += sc.skew * sc.skew_y;
        }
      }
      // separating: no force, no stiffness, unless a discrete gradient's correction along the
      // step acts (a pocket's may without the θ point's force; a seat's is f cc, 0 with f)
      if (!jacobian || (sc.force <= 0.0 && sc.skew == 0.0)) continue;
      // D = ∂(h f n)/∂u = normal n nᵀ + tangent (I − n nᵀ), from
      // ∂(f n)/∂q = (∂f/∂g + c/(θh)) n nᵀ + (f/s)(I − n nᵀ), q = x_θ, ∂q/∂u = θ.
      // The damper's rate ġ = v_rel·n, v_rel = v − ω perp(q − c), also turns with the roller's
      // position: ∂ġ/∂q = (κ t·v_rel + ω) t, t = perp(n); its share c n (∂ġ/∂q)ᵀ is not
      // symmetric (without it Newton converges only linearly while a wheel turns). ISO seats and
      // pockets alike; a pocket with the release (Sprocket::pocket_release) has it in its exact
      // blocks (dq_extra) already. On the mouth's ramp (Sprocket::pocket_mouth > 0, no release) the
      // term is approximate and untested: it takes the ramp's scaled damping as c and the force's
      // direction as n (the ramp's damper acts along the seat's n), so a damped ramp's blocks are
      // quasi-Newton; its elastic blocks are exact (dq_extra, below and in the angle's coupling).
      const double normal = h * (th * sc.stiffness + sc.damping / h);
      const double tangent = h * th * sc.force * sc.curvature;
      const double rcx = qx - wheel.centre_x, rcy = qy - wheel.centre_y;
      const double tnx = -sc.ny, tny = sc.nx;
      const double slip = (vx + omega * rcy) * tnx + (vy - omega * rcx) * tny;
      const bool rotation = !(wheel.pocket && wheel.pocket_release);
      const double turn = rotation ? h * th * sc.damping * (sc.curvature * slip + omega) : 0.0;
      const Mat2 dc{normal * sc.nx * sc.nx + tangent * (1.0 - sc.nx * sc.nx) + turn * sc.nx * tnx,
                    (normal - tangent) * sc.nx * sc.ny + turn * sc.nx * tny,
                    (normal - tangent) * sc.nx * sc.ny + turn * sc.ny * tnx,
                    normal * sc.ny * sc.ny + tangent * (1.0 - sc.ny * sc.ny) + turn * sc.ny * tny};
      Mat2& d = solver_.diag[i];
      d = {d.a + dc.a, d.b + dc.b, d.c + dc.c, d.d + dc.d};
      // the discrete gradient's dependence on the iterate: ∂(h f n)/∂u = h (∂f/∂g₁) n n₁ᵀ
      const double hs = h * sc.gap_slope;
      Mat2 dgrad{hs * sc.nx * sc.step_nx, hs * sc.nx * sc.step_ny, hs * sc.ny * sc.step_nx,
                 hs * sc.ny * sc.step_ny};
      // and its correction's, ∂(h S Δ)/∂u = h (Δ ∂S/∂x₁ᵀ + S I)
      const bool skewed = sc.skew != 0.0;
      if (skewed) {
        dgrad = {dgrad.a + h * (sc.skew_x * sc.skew_dx + sc.skew),
                 dgrad.b + h * sc.skew_x * sc.skew_dy, dgrad.c + h * sc.skew_y * sc.skew_dx,
                 dgrad.d + h * (sc.skew_y * sc.skew_dy + sc.skew)};
      }
      if (hs != 0.0 || skewed) d = {d.a + dgrad.a, d.b + dgrad.b, d.c + dgrad.c, d.d + dgrad.d};
      const double ht = h * th;
      if (rubs) {  // −∂(h F)/∂u = −(hθ ∂F/∂q + ∂F/∂v), as a guide's
        d = {d.a - (ht * sf.dq[0] + sf.dv[0]), d.b - (ht * sf.dq[1] + sf.dv[1]),
             d.c - (ht * sf.dq[2] + sf.dv[2]), d.d - (ht * sf.dq[3] + sf.dv[3])};
      }
      if (!driven) continue;
      // Turning the wheel by dψ₁ (its θ point by θ dψ₁, its speed by dψ₁/h) is, for the
      // contact, turning the roller and its velocity the other way about the centre: with
      // t = perp(q − c), the coupling column is ∂R_i/∂ψ₁ = −D t + h θ f perp(n) − h θ c (n·perp v)
      // n, the wheel's row −Dᵀ t + h θ f perp(n), and the wheel's own derivative gains tᵀ D t − h θ
      // f (q − c)·n + h θ c (t·n)(n·perp v) (the law is invariant under turning q, v and ψ
      // together).
      const double cx = rcx, cy = rcy;
      const double tx = -cy, ty = cx;
      const Vec2 dt{dc.a * tx + dc.b * ty, dc.c * tx + dc.d * ty};
      const Vec2 dtt{dc.a * tx + dc.c * ty, dc.b * tx + dc.d * ty};
      const double hf = h * th * sc.force;
      const double spin =  // h θ c n·perp(v)
          rotation ? h * th * sc.damping * (sc.ny * vx - sc.nx * vy) : 0.0;
      border_rows_[ia].push_back(i);
      bcol_[ia][i] = {-dt.x - hf * sc.ny - spin * sc.nx, -dt.y + hf * sc.nx - spin * sc.ny};
      brow_[ia][i] = {-dtt.x - hf * sc.ny, -dtt.y + hf * sc.nx};
      wdiag +=
          tx * dt.x + ty * dt.y - hf * (sc.nx * cx + sc.ny * cy) + spin * (tx * sc.nx + ty * sc.ny);
      if (wheel.pocket && (sc.surface == 3 || wheel.pocket_mouth > 0.0)) {
        // the body between the pockets: its whole ∂F/∂q and ∂F/∂v are dq_extra = E_q and
        // dv_extra = E_v (the fields give none), so by F(Rq, Rv, ψ + δ) = R F(q, v, ψ) the column
        // gains hθ E_q t + E_v t + hθ E_v perp(v), the row hθ tᵀE_q + tᵀE_v, and the wheel's own
        // entry −hθ tᵀE_q t − hθ tᵀE_v perp(v) − tᵀE_v t. The mouth's ramp the same way: its
        // dq_extra is the rest of its elastic ∂F/∂q beyond the fields (which the column above
        // takes), and its law turns with the wheel too (no dv_extra; 0 within the mouth, where
        // its pockets' law is the fields'). Left out, the matrix missed 1.65e-3 of a column
        // (RampsNewtonMatrixOnADrivenWheelMatchesTheDifferences; docs/models/dynamics.md, "Pocket
        // wheel: the discrete gradient").
        const double* eq = sc.dq_extra;
        const double* ev = sc.dv_extra;
        const double hq = h * th, px = -vy, py = vx;
        const Vec2 qt{eq[0] * tx + eq[1] * ty, eq[2] * tx + eq[3] * ty};
        const Vec2 vt{ev[0] * tx + ev[1] * ty, ev[2] * tx + ev[3] * ty};
        const Vec2 vp{ev[0] * px + ev[1] * py, ev[2] * px + ev[3] * py};
        bcol_[ia][i].x += hq * qt.x + vt.x + hq * vp.x;
        bcol_[ia][i].y += hq * qt.y + vt.y + hq * vp.y;
        brow_[ia][i].x += hq * (tx * eq[0] + ty * eq[2]) + tx * ev[0] + ty * ev[2];
        brow_[ia][i].y += hq * (tx * eq[1] + ty * eq[3]) + tx * ev[1] + ty * ev[3];
        wdiag -=
            hq * (tx * qt.x + ty * qt.y) + hq * (tx * vp.x + ty * vp.y) + tx * vt.x + ty * vt.y;
      }
      if (hs != 0.0) {
        // the discrete gradient through g₁(x₁, ψ₁): the column h (∂f/∂g₁)(∂g₁/∂ψ₁) n, the row
        // −h (∂f/∂g₁)(n·t) n₁ (the torque f n·t), the wheel's own −h (∂f/∂g₁)(n·t)(∂g₁/∂ψ₁)
        const double arm = sc.nx * tx + sc.ny * ty;
        bcol_[ia][i].x += hs * sc.step_turn * sc.nx;
        bcol_[ia][i].y += hs * sc.step_turn * sc.ny;
        brow_[ia][i].x -= hs * arm * sc.step_nx;
        brow_[ia][i].y -= hs * arm * sc.step_ny;
        wdiag -= hs * arm * sc.step_turn;
      }
      if (skewed) {
        // the correction: R_i gains h S Δ, the wheel's residual h S R² Δψ (its torque −S R² Δψ)
        const double r2dpsi = wheel.pitch_radius * wheel.pitch_radius * (psi1_[w] - s.angle[w]);
        bcol_[ia][i].x += h * sc.skew_x * sc.skew_dpsi;
        bcol_[ia][i].y += h * sc.skew_y * sc.skew_dpsi;
        brow_[ia][i].x += h * r2dpsi * sc.skew_dx;
        brow_[ia][i].y += h * r2dpsi * sc.skew_dy;
        wdiag += h * (r2dpsi * sc.skew_dpsi + wheel.pitch_radius * wheel.pitch_radius * sc.skew);
      }
      if (rubs) {
        // the friction's part is not symmetric: the column −h(θ ∂F/∂ψ + ∂F/∂ω/h), the row
        // −h(θ ∂τ/∂q + ∂τ/∂v/h), and −h(θ ∂τ/∂ψ + ∂τ/∂ω/h) on the wheel's own entry
        bcol_[ia][i].x -= ht * sf.dpsi[0] + sf.domega[0];
        bcol_[ia][i].y -= ht * sf.dpsi[1] + sf.domega[1];
        brow_[ia][i].x -= ht * sf.torque_dq[0] + sf.torque_dv[0];
        brow_[ia][i].y -= ht * sf.torque_dq[1] + sf.torque_dv[1];
        wdiag -= ht * sf.torque_dpsi + sf.torque_domega;
      }
      if (!slides) continue;
      // Sliding the centre by ds₁ (its θ point by θ ds₁, its speed by ds₁/h) is, for every
      // contact, moving the roller by −e ds₁: with D_i the contact's whole block ∂R_i/∂u_i
      // (normal, tangent and friction), the column is −D_i e, the slide's row −D_iᵀ e, its own
      // entry gains eᵀ D_i e, and the wheel's angle couples by −(∂R_ψ/∂u_i)·e and −e·∂R_i/∂ψ₁.
      Mat2 dall = {dc.a + dgrad.a, dc.b + dgrad.b, dc.c + dgrad.c, dc.d + dgrad.d};
      if (rubs) {
        dall = {dall.a - (ht * sf.dq[0] + sf.dv[0]), dall.b - (ht * sf.dq[1] + sf.dv[1]),
                dall.c - (ht * sf.dq[2] + sf.dv[2]), dall.d - (ht * sf.dq[3] + sf.dv[3])};
      }
      if (wheel.pocket) {  // a pocket's own blocks, as on the diagonal (the body's whole ∂F/∂q)
        const double* e = sc.dq_extra;
        const double* ev = sc.dv_extra;
        dall = {dall.a - (ht * e[0] + ev[0]), dall.b - (ht * e[1] + ev[1]),
                dall.c - (ht * e[2] + ev[2]), dall.d - (ht * e[3] + ev[3])};
      }
      const Vec2 de{dall.a * ex + dall.b * ey, dall.c * ex + dall.d * ey};
      border_rows_[is].push_back(i);
      bcol_[is][i] = {-de.x, -de.y};
      brow_[is][i] = {-(dall.a * ex + dall.c * ey), -(dall.b * ex + dall.d * ey)};
      sdiag += ex * de.x + ey * de.y;
      cross_ws -= brow_[ia][i].x * ex + brow_[ia][i].y * ey;
      cross_sw -= ex * bcol_[ia][i].x + ey * bcol_[ia][i].y;
    }
    torque_[w] = torque;
    if (driven) {
      const double residual = wheel.inertia / (h * th) * (psi1_[w] - s.angle[w] - h * s.speed[w]) -
                              h * (torque - wheel.load_torque);
      xres_[ia] = -residual;
      if (jacobian) xjac_[ia * nx + ia] = wdiag;
      const double force_like = residual / wheel.pitch_radius;
      wheel_norm2 += force_like * force_like;
    }
    slide_force_[w] = slides ? pull_x * ex + pull_y * ey : 0.0;
    wheel_force_[w] = slides ? std::hypot(pull_x, pull_y) : 0.0;
    if (slides) {
      // m_t (s₁ − s₀ − h ṡ₀)/(hθ) = h [F₀ − k_t s_θ − c_t ṡ + m_t g·e + e·Σ(f n − F_t)]
      const double mt = wheel.takeup_mass;
      const double g_along = model.gravity_x * ex + model.gravity_y * ey;
      // the end stops (without a travel bound never active): their force at the θ point with
      // the step's slide speed, as a seat's on its roller
      const SlideStop stop = slide_stop(wheel, slide_th, slide_rate);
      contact_damping_work_ += h * stop.damping_power;
      const double push = wheel.takeup_force - wheel.takeup_stiffness * slide_th -
                          wheel.takeup_damping * slide_rate + mt * g_along + stop.force;
      const double residual = mt / (h * th) * (slide1_[w] - s.slide[w] - h * s.slide_speed[w]) -
                              h * (push + slide_force_[w]);
      xres_[is] = -residual;
      takeup_damper_work_ -= h * wheel.takeup_damping * slide_rate * slide_rate;
      wheel_norm2 += residual * residual;
      if (jacobian) {
        xjac_[is * nx + is] = mt / (h * th) + h * th * wheel.takeup_stiffness +
                              wheel.takeup_damping + sdiag + h * th * stop.stiffness + stop.damping;
        xjac_[ia * nx + is] = cross_ws;
        xjac_[is * nx + ia] = cross_sw;
      }
    }
  }
  // Guides: the force F(q, v) at the θ point with the step's velocity v = (u − x₀)/h; the
  // diagonal block gains −∂(h F)/∂u = −(hθ ∂F/∂q + ∂F/∂v). Node by node: the O(N) solve stays.
  // Each guide is tried against the nodes the hint lists near it, in node order (the pairs and
  // their order are those of the loop over every node: bit-identical; "Guides: O(N) a step").
  refresh_guide_hint(model);
  // report only: the guides' works are taken after the step, and the residual is not wanted
  if (report_only) return 0.0;
  for (std::size_t g = 0; g < model.guides.size(); ++g) {
    const Guide& guide = model.guides[g];
    const GuideBounds bounds = options_.guide_hint ? guide_hint_.bounds()[g] : guide_bounds(guide);
    for (const std::uint32_t i :
         options_.guide_hint ? guide_hint_.nodes(g) : std::span<const std::uint32_t>(all_nodes_)) {
      if (model.is_pinned(i)) continue;
      const GuideContact gc =
          guide_contact_at_theta(guide, guide_frame_[g], bounds, s, ux_, uy_, i, qx_[i], qy_[i], h,
                                 step_anchor(guide, guide_frame_[g], s, stick_slot_[g], i));
      if (!gc.active) continue;
      solver_.rhs[i].x += h * gc.fx;
      solver_.rhs[i].y += h * gc.fy;
      if (!jacobian) continue;
      const double ht = h * th;
      Mat2& d = solver_.diag[i];
      d = {d.a - (ht * gc.dq[0] + gc.dv[0]), d.b - (ht * gc.dq[1] + gc.dv[1]),
           d.c - (ht * gc.dq[2] + gc.dv[2]), d.d - (ht * gc.dq[3] + gc.dv[3])};
    }
  }
  // Rails' loads (Guide::load_per_metre; docs/models/dynamics.md, "A conveyed load"): the weight
  // share F(q) at the θ point; the diagonal block gains −hθ ∂F/∂q, the ramp's at the rail's ends.
  // Every node is tried against a loaded rail (a node carries it within a pitch of the rail,
  // farther than the guide hint's lists reach).
  for (std::size_t g = 0; g < model.guides.size(); ++g) {
    const Guide& guide = model.guides[g];
    if (!(guide.load_per_metre > 0.0)) continue;
    for (std::size_t i = 0; i < n; ++i) {
      if (model.is_pinned(i)) continue;
      const RailLoad load =
          rail_load(guide, guide_frame_[g], model.pitch, grav_x, grav_y, qx_[i], qy_[i]);
      if (!load.active) continue;
      rhs[i].x += h * load.fx;
      rhs[i].y += h * load.fy;
      if (!jacobian) continue;
      const double ht = h * th;
      Mat2& d = diag[i];
      d = {d.a - ht * load.dq[0], d.b - ht * load.dq[1], d.c - ht * load.dq[2],
           d.d - ht * load.dq[3]};
    }
  }
  // The conveyed load's inertia (Guide::load_inertia; docs/models/dynamics.md, "A conveyed load:
  // its inertia, loading and discharge"): node i's momentum is (m + m_L) v, m_L taken at the
  // step's ends (m_L0 at x₀, m_L1 at the iterate u), so that the momentum the steps exchange with
  // the load telescopes. R gains m_L1 (v₁ − v₀) + max(Δm_L, 0) v₀, Δm_L = m_L1 − m_L0: material
  // joining arrives at rest, (m + m_L1) v₁ − (m + m_L0) v₀ = h F; material leaving takes v₀ with
  // it, (m + m_L1)(v₁ − v₀) = h F. With v₁ − v₀ = (u − x₀ − h v₀)/hθ the diagonal block gains
  // m_L1/hθ I + a (∇m_L1)ᵀ, a = (v₁ − v₀) + [Δm_L > 0] v₀ (the mass's dependence on u through
  // the ramp w(s)). Material arriving with a speed of its own (Guide::load_speed) arrives with the
  // velocity w (arrival: its piece's u_g, or where pieces overlap their increments' velocity):
  // R gains −max(Δm_L, 0) w, a gains −[Δm_L > 0] w and the block −Δm_L ∂w/∂u = −f G.
  if (any_load_inertia(model.guides)) {
    const double ht = h * th;
    if (!load_mass0_set_) {
      load_mix_ = load_speeds_mix(model.guides);
      const std::size_t ng = model.guides.size();
      if (load_mix_) {
        // sized once for the model (its guides may be set after the build)
        if (pieces_.size() != ng) pieces_.resize(ng);
        if (piece_mass0_.size() != n * ng) piece_mass0_.resize(n * ng);
      }
      const std::span<LoadPiece> pieces =
          load_mix_ ? std::span<LoadPiece>(pieces_) : std::span<LoadPiece>();
      for (std::size_t i = 0; i < n; ++i) {
        load_mass0_[i] = load_mass(model, guide_frame_, sx[i], sy[i], pieces).mass;
        for (std::size_t g = 0; g < pieces.size(); ++g) piece_mass0_[i * ng + g] = pieces[g].mass;
      }
      load_mass0_set_ = true;
    }
    const std::span<LoadPiece> pieces =
        load_mix_ ? std::span<LoadPiece>(pieces_) : std::span<LoadPiece>();
    for (std::size_t i = 0; i < n; ++i) {
      if (model.is_pinned(i)) continue;
      const double m0 = load_mass0_[i];
      const LoadMass m1 = load_mass(model, guide_frame_, ux[i], uy[i], pieces);
      if (m0 == 0.0 && m1.mass == 0.0) continue;
      const double dm = m1.mass - m0, joins = dm > 0.0 ? dm : 0.0;
      const double dvx = (ux[i] - sx[i] - h * svx[i]) / ht, dvy = (uy[i] - sy[i] - h * svy[i]) / ht;
      // the arriving material's velocity w (0: at rest)
      const Arrival in = arrival(model, i, m1, dm);
      const double wx = in.wx, wy = in.wy;
      rhs[i].x -= m1.mass * dvx + joins * (svx[i] - wx);
      rhs[i].y -= m1.mass * dvy + joins * (svy[i] - wy);
      if (!jacobian) continue;
      const double ax = dvx + (dm > 0.0 ? svx[i] - wx : 0.0);
      const double ay = dvy + (dm > 0.0 ? svy[i] - wy : 0.0);
      const double mi = m1.mass / ht;
      Mat2& d = diag[i];
      d = {d.a + mi + ax * m1.dx, d.b + ax * m1.dy, d.c + ay * m1.dx, d.d + mi + ay * m1.dy};
      if (in.arrives) {
        const double f = in.f;
        d = {d.a - f * in.g[0], d.b - f * in.g[1], d.c - f * in.g[2], d.d - f * in.g[3]};
      }
    }
  }
  if (!model.pinned.empty()) {
    for (std::size_t i = 0; i < n; ++i) {
      if (!model.is_pinned(i)) continue;
      solver_.rhs[i] = {};
      if (!jacobian) continue;
      solver_.diag[i] = {1.0, 0.0, 0.0, 1.0};
      solver_.lower[i] = {};
      solver_.upper[i] = {};
      if (model.closed || i + 1 < n) solver_.lower[(i + 1) % n] = {};
      if (model.closed || i > 0) solver_.upper[(i + n - 1) % n] = {};
      if (pentadiagonal_) {
        far_lower_[i] = far_upper_[i] = {};
        if (model.closed || i + 2 < n) far_lower_[(i + 2) % n] = {};
        if (model.closed || i >= 2) far_upper_[(i + n - 2) % n] = {};
      }
    }
  }
  double norm2 = wheel_norm2;
  for (std::size_t i = 0; i < n; ++i) norm2 += rhs[i].x * rhs[i].x + rhs[i].y * rhs[i].y;
  return norm2;
}

Integrator::Arrival Integrator::arrival(const Model& model, std::size_t i, const LoadMass& m1,
                                        double dm) const {
  Arrival out;
  if (!(dm > 0.0)) return out;
  // where loaded pieces overlap (pieces_ filled by load_mass at the iterate): each piece's
  // increment Δm_g = m_g(x₁) − m_g(x₀); the growing ones' material arrives with their u_g (as much
  // of it as the node's load grows by, Δm_L: what a shrinking piece hands over stays on the node)
  if (load_mix_) {
    const std::size_t ng = model.guides.size();
    const double* mass0 = piece_mass0_.data() + i * ng;
    int touching = 0;
    for (std::size_t g = 0; g < ng; ++g)
      if (pieces_[g].active || mass0[g] != 0.0) ++touching;
    if (touching >= 2) {
      // the growing pieces (Δm_g > 0), each with its increment and u_g
      const auto each_growing = [&](auto&& f) {
        for (std::size_t g = 0; g < ng; ++g) {
          const LoadPiece& p = pieces_[g];
          const double inc = p.mass - mass0[g];
          if (inc > 0.0) f(p, inc, model.guides[g].load_speed);
        }
      };
      double grown = 0.0, px = 0.0, py = 0.0, kinetic = 0.0;
      each_growing([&](const LoadPiece& p, double inc, double u) {
        grown += inc;
        px += inc * u * p.tx;
        py += inc * u * p.ty;
        kinetic += inc * u * u * (p.tx * p.tx + p.ty * p.ty);
      });
      if (!(grown > 0.0) || (px == 0.0 && py == 0.0 && kinetic == 0.0)) return out;
      out.arrives = true;
      out.wx = px / grown;
      out.wy = py / grown;
      out.energy = 0.5 * kinetic / grown;
      out.f = dm / grown;
      each_growing([&](const LoadPiece& p, double inc, double u) {
        const double rx = u * p.tx - out.wx, ry = u * p.ty - out.wy;
        out.g[0] += rx * p.dx + inc * u * p.dt[0];
        out.g[1] += rx * p.dy + inc * u * p.dt[1];
        out.g[2] += ry * p.dx + inc * u * p.dt[2];
        out.g[3] += ry * p.dy + inc * u * p.dt[3];
      });
      return out;
    }
  }
  // one loaded piece at the node: the velocity of the load it carries, that piece's u_g
  if (m1.px == 0.0 && m1.py == 0.0) return out;
  out.arrives = true;
  out.wx = m1.px / m1.mass;
  out.wy = m1.py / m1.mass;
  out.energy = 0.5 * (out.wx * out.wx + out.wy * out.wy);
  out.f = dm / m1.mass;
  out.g[0] = m1.dp[0] - out.wx * m1.dx;
  out.g[1] = m1.dp[1] - out.wx * m1.dy;
  out.g[2] = m1.dp[2] - out.wy * m1.dx;
  out.g[3] = m1.dp[3] - out.wy * m1.dy;
  return out;
}

SolveStatus Integrator::factor() {
  switch_.count = 0;  // the switch update's W and I + Vᵀ W are of the factors being replaced
  if (!pentadiagonal_) {
    // A fresh iteration's first substitution is always of the residual (and, with a border, of
    // the first extra's column, beside it): its forward sweep rides along with the factorisation
    // and the substitution below only finishes it (the same arithmetic, one pass fewer).
    const std::span<const Vec2> second =
        extra_.empty() ? std::span<const Vec2>() : std::span<const Vec2>(bcol_[0]);
    const SolveStatus status = solver_.factor_forward(solver_.rhs, second);
    forward_pending_ = status == SolveStatus::kSolved;
    return status;
  }
  // the tridiagonal arrays' cyclic convention (lower[0] is block (0, n − 1), upper[n − 1] block
  // (n − 1, 0)) is the pentadiagonal bands' (column i + o modulo n)
  penta_.band[0] = far_lower_;
  penta_.band[1] = solver_.lower;
  penta_.band[2] = solver_.diag;
  penta_.band[3] = solver_.upper;
  penta_.band[4] = far_upper_;
  return penta_.factor();
}

void Integrator::substitute(std::span<const Vec2> b, std::span<Vec2> x) {
  const bool pending = forward_pending_;
  forward_pending_ = false;
  if (pentadiagonal_) {
    penta_.substitute(b, x);
  } else if (pending && extra_.empty() && b.data() == solver_.rhs.data()) {
    solver_.finish(x, {});
  } else {
    solver_.substitute(b, x);
  }
}

void Integrator::substitute(std::span<const Vec2> b, std::span<Vec2> x, std::span<const Vec2> b2,
                            std::span<Vec2> x2) {
  const bool pending = forward_pending_;
  forward_pending_ = false;
  if (pentadiagonal_) {
    penta_.substitute(b, x, b2, x2);
  } else if (pending && !extra_.empty() && b.data() == solver_.rhs.data() &&
             b2.data() == bcol_[0].data()) {
    solver_.finish(x, x2);
  } else {
    solver_.substitute(b, x, b2, x2);
  }
}

std::string newton_iterations_text(const StepReport& report, int max_iterations) {
  std::string text = std::to_string(report.iterations) + " Newton iterations";
  if (report.starts > 1) {
    text += " in all, from " + std::to_string(report.starts) + " starting points with at most " +
            std::to_string(max_iterations) + " from each";
  }
  return text;
}

StepReport Integrator::step(const Model& model, State& s) {
  // O(1) guards: a model or state of another size would index out of bounds.
  if (model.nodes() != solver_.size() || model.closed != solver_.cyclic() ||
      model.sprockets.size() != psi1_.size()) {
    throw InputError({{"model", std::to_string(model.nodes()) + " nodes",
                       "the model this integrator was built for (" +
                           std::to_string(solver_.size()) + " nodes)"}});
  }
  // hinge friction switched on or off since the build: its couples' arrays and the band's far
  // blocks are sized (or not) by the model the integrator was built for
  if ((model.hinge.active() && model.nodes() >= 3) != pentadiagonal_) {
    throw InputError({{"model.hinge", model.hinge.active() ? "active" : "inactive",
                       std::string("the model this integrator was built for (hinge friction ") +
                           (pentadiagonal_ ? "active" : "inactive") + ")"}});
  }
  if (s.x.size() != model.nodes() || s.y.size() != model.nodes() || s.vx.size() != model.nodes() ||
      s.vy.size() != model.nodes() || s.angle.size() != model.sprockets.size() ||
      s.speed.size() != model.sprockets.size() || s.slide.size() != model.sprockets.size() ||
      s.slide_speed.size() != model.sprockets.size()) {
    throw_if_any(validate(model, s));
  }
  // The release's held flags (Sprocket::pocket_release) of the state the step starts from: a
  // function of that state, so after a step (which sets them at its end) this changes nothing,
  // but a state that no step has ended in (t = 0, or one set by hand) gets them too — else a
  // joint within a mouth there that leaves it in this step would meet the sharp mouth.
  update_held(model, s);
  // the stick law's anchors (Guide::stick_stiffness): sized once, none in contact yet
  if (const std::size_t k = sticking_guides(model);
      k > 0 && s.stick_anchor.size() != k * model.nodes())
    s.stick_anchor.assign(k * model.nodes(), NAN);
  // the hinges' stick law's deflections (HingeFriction::stick_stiffness): sized once, every hinge
  // anchored where it is
  if (model.hinge.sticks() && s.hinge_deflection.size() != model.nodes())
    s.hinge_deflection.assign(model.nodes(), 0.0);
  const std::size_t n = model.nodes();
  const double h = options_.step;
  const double th = options_.theta;
  const double tol = options_.tolerance * model.pitch;
  constexpr int kMaxBacktracks = 12;
  const std::size_t nd = extra_.size();

  for (std::size_t j = 0; j < model.links(); ++j) {
    const std::size_t b = (j + 1) % n;
    const double dx = s.x[b] - s.x[j], dy = s.y[b] - s.y[j];
    l0_[j] = std::sqrt(dx * dx + dy * dy);
  }
  prepare_links(model);
  load_mass0_set_ = false;
  prepare_seats(model);
  // Newton from the predictor x₁ = x₀ + h v₀ + ht Δv: with ht = hθ, the velocities (and wheel
  // speeds) change over this step as over the last one (Δv the last accepted step's change, when
  // this integrator's last step ended at this state's time); with ht = 0, constant velocity. Only
  // Newton's starting point: the converged step is the same to the tolerance either way.
  bool estimated = false;  // converged on the error estimate, not on |Δ| ≤ tolerance
  bool checked = false;    // the residual was assembled at the accepted iterate
  // x ← x − λ Δ: the chain's nodes and the extra unknowns back along the last correction
  auto retreat = [&](double lambda) {
    for (std::size_t i = 0; i < n; ++i) {
      ux_[i] -= lambda * delta_[i].x;
      uy_[i] -= lambda * delta_[i].y;
    }
    for (std::size_t a = 0; a < nd; ++a)
      (extra_[a].slide ? slide1_ : psi1_)[extra_[a].wheel] -= lambda * dx_[a];
  };
  // The hinges' stick law's crossing cut. A hinge that slid at the correction's start and slides
  // the other way at its full step has crossed its whole stick band (its trial torque changed
  // sign and left the band): the correction took it as free (the slide's tangent has no spring)
  // and the spring's trial moved k_t θ Δβ past the band, so the next correction, free again,
  // sends it back past the band the other way: Newton cycles between the two slides and never
  // lands where it sticks (a node of inertia a on a spring k_t θ ≫ a cycles so exactly). The cut
  // retreats along the correction to where the first such hinge's trial, linear in the step to
  // first order, is 0 (its band's middle: it sticks there, and the next correction has its
  // spring), whether or not the residual rose. Returns the fraction of the correction kept,
  // 1 with no crossing (or without the stick law).
  bool cut_crossings = !trial_.empty();  // off for the last start (below)
  bool cut_acted = false;                // a crossing cut shortened a correction in this step
  auto crossing_cut = [&] {
    double cut = 1.0;
    for (std::size_t i = 0; i < trial_.size(); ++i) {
      const HingeTrial a = trial_base_[i], b = trial_[i];
      if (std::abs(a.trial) > a.limit && std::abs(b.trial) > b.limit &&
          (a.trial > 0.0) != (b.trial > 0.0))
        cut = std::min(cut, a.trial / (a.trial - b.trial));  // in (0, 1): the signs differ
    }
    return std::max(cut, std::ldexp(1.0, -kMaxBacktracks));
  };
  // Backtracking: from the full step (its residual `next`), first the crossing cut where a hinge
  // crossed its stick band, then halve the step while the residual grows past `norm2`,
  // assembling the residual (and with `jacobian` the Newton matrix) at each point; returns the
  // accepted point's residual.
  auto backtrack = [&](double next, double norm2, bool jacobian, StepReport& report) {
    double lambda = 1.0;
    if (const double cut = cut_crossings ? crossing_cut() : 1.0; cut < 1.0) {
      retreat(1.0 - cut);
      lambda = cut;
      next = assemble(model, s, jacobian);
      ++report.backtracks;
      cut_acted = true;
    }
    for (int b = 0; b < kMaxBacktracks && !(next < norm2); ++b) {
      lambda *= 0.5;
      retreat(lambda);
      next = assemble(model, s, jacobian);
      ++report.backtracks;
    }
    return next;
  };
  auto newton = [&](double ht, bool stale) {
    for (std::size_t i = 0; i < n; ++i) {
      ux_[i] = s.x[i] + h * s.vx[i] + ht * dvx_[i];
      uy_[i] = s.y[i] + h * s.vy[i] + ht * dvy_[i];
    }
    for (std::size_t w = 0; w < model.sprockets.size(); ++w) {
      const Sprocket& wheel = model.sprockets[w];
      psi1_[w] = s.angle[w] + (wheel.driver ? h * wheel.speed : h * s.speed[w] + ht * dspeed_[w]);
      slide1_[w] = wheel.takeup ? s.slide[w] + h * s.slide_speed[w] + ht * dslide_speed_[w] : 0.0;
    }
    std::fill(dx_.begin(), dx_.end(), 0.0);

    StepReport report;
    // With hinge friction the Newton matrix is the exact pentadiagonal one, whose assembly (the
    // 6×6 couple Jacobians) and factorisation (with the loop closure's four columns) are most of
    // a step: there, once a fresh Newton iteration has cut the correction to kNewtonContraction
    // of the one before, the next ones reuse its factors (the chord, or modified, Newton method;
    // Kelley, Iterative Methods for Linear and Nonlinear Equations, §5.4) and assemble the
    // residual alone, as long as each correction is at most kChordContraction of the one before
    // and the residual falls; otherwise the next iteration assembles and factors afresh (and a
    // chord step that raised the residual is undone first). The convergence tests (the
    // correction, and the error estimate, which Hairer & Wanner derive for simplified Newton)
    // are the same. Without hinge friction every iteration is a fresh Newton iteration.
    const bool chord = pentadiagonal_;
    constexpr double kNewtonContraction = 0.05, kChordContraction = 0.25, kStaleContraction = 0.1;
    bool fresh = !stale;  // this iteration's factors are of the Jacobian at the current iterate
    // the chord's test (0: no reuse after the next step; infinite: the first iteration with the
    // last step's factors is followed by a chord iteration, which tests its contraction)
    double previous_correction = stale ? INFINITY : 0.0;
    bool stale_seq = stale;
    estimated = false;
    checked = false;
    double previous = INFINITY;  // the last correction (Newton's contraction)
    double norm2 = assemble(model, s, !stale);
    for (int iter = 1; iter <= options_.max_iterations; ++iter) {
      report.iterations = iter;
      if (fresh) {
        stale_seq = false;
        factors_kept_ = false;
        ++report.factorizations;
        report.solve = factor();
        if (report.solve != SolveStatus::kSolved) return report;
        keep_branches();
      }
      if (nd == 0) {
        substitute(solver_.rhs, delta_);
      } else if (fresh) {
        report.solve = solve_fresh();
        if (report.solve != SolveStatus::kSolved) return report;
      } else {
        // a chord iteration: the same bordered solve with the kept W = A⁻¹ B and the Schur
        // complement's factors, for the new right-hand sides
        chord_solve(solver_.rhs, xres_.data(), delta_, dx_.data());
      }
      if (!fresh && !trial_.empty() && options_.switch_update)
        correct_for_switches(model, s, report, kSwitchPivotFloor);
      double correction = 0.0;
      // the stick law's trials where this correction starts (crossing_cut); a swap, as every
      // assembly rewrites each hinge's entry of trial_ (and the others stay {0, 0} in both)
      std::swap(trial_base_, trial_);
      for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(delta_[i].x) || !std::isfinite(delta_[i].y)) {
          report.solve = SolveStatus::kSingularPivot;
          return report;
        }
        ux_[i] += delta_[i].x;
        uy_[i] += delta_[i].y;
        correction = std::max({correction, std::abs(delta_[i].x), std::abs(delta_[i].y)});
      }
      for (std::size_t a = 0; a < nd; ++a) {
        const Extra& x = extra_[a];
        if (x.slide) {
          slide1_[x.wheel] += dx_[a];
          correction = std::max(correction, std::abs(dx_[a]));
        } else {
          psi1_[x.wheel] += dx_[a];
          correction =
              std::max(correction, std::abs(dx_[a]) * model.sprockets[x.wheel].pitch_radius);
        }
      }
      report.last_correction = correction;
      // Converged when this correction is within tolerance, or when the error it leaves,
      // estimated from the contraction ϑ = |Δ_k|/|Δ_{k−1}| as ϑ/(1 − ϑ)·|Δ_k| (Hairer & Wanner,
      // Solving ODEs II, §IV.8), is: near the solution Newton's error falls quadratically and the
      // correction that would only confirm it is skipped. With guides too: the conveyor's
      // validation (6b) resolves its tension means to ±0.1 % and shows no bias from it or the
      // predictor (docs/models/dynamics.md, "The predictor and the estimate with guides").
      // No estimate before two corrections of one sequence (previous is infinite until then, and
      // again after a backtracked step).
      const double rate = correction / previous;
      const double before = previous;  // restored if this step is undone
      previous = correction;
      // Undoes a chord step that raised the residual: back to the iterate before it (whose
      // residual fell) and a fresh iteration there, rather than halving along a correction of
      // stale factors; that iteration's correction is not a contraction of this sequence, so the
      // estimate compares the next one with the correction that led to the iterate.
      auto undo_chord_step = [&] {
        retreat(1.0);
        norm2 = assemble(model, s, true);
        fresh = true;
        previous_correction = 0.0;
        previous = before;
      };
      if (correction <= tol ||
          (std::isfinite(before) && rate < 0.5 && rate / (1.0 - rate) * correction <= tol)) {
        if (chord && !fresh && correction > tol) {
          // A chord step accepted on the estimate: the estimate assumes the chord iteration
          // contracts, which a chord step that raised the residual did not. Its residual (which
          // the step's works are taken from anyway) first; if it rose, back to the iterate
          // before it and a fresh iteration, as below.
          const double next = assemble(model, s, false);
          if (!(next < norm2)) {
            undo_chord_step();
            continue;
          }
          checked = true;
        }
        report.converged = true;
        estimated = correction > tol;
        break;
      }
      if (!chord) {
        // Backtracking: halve the step while the residual grows (far from the solution, a whip
        // of the chain turns links by large angles within a step and the full Newton step
        // overshoots). A damped step's correction is not Newton's contraction: no estimate
        // until two more full corrections.
        const int backtracks = report.backtracks;
        norm2 = backtrack(assemble(model, s, true), norm2, true, report);
        if (report.backtracks > backtracks) previous = INFINITY;
        continue;
      }
      // Hinge friction. A chord iteration with the factors of the Jacobian at x_k contracts the
      // error by about K |x_k − x*| (K the Jacobian's relative rate of change), which is what the
      // fresh Newton step from x_k contracted it by: the factors are kept once a fresh step has
      // contracted the correction by kNewtonContraction, and as long as each chord step
      // contracts it by kChordContraction.
      const bool reuse = fresh ? correction <= kNewtonContraction * previous_correction
                               : correction <= (stale_seq ? kStaleContraction : kChordContraction) *
                                                   previous_correction;
      previous_correction = correction;
      if (!reuse) {
        const double next = assemble(model, s, true);
        if (!fresh && !(next < norm2)) {
          undo_chord_step();
          continue;
        }
        // the line search's points on the residual alone, and the Jacobian once at the point it
        // accepts (the residual is the same either way, bit for bit)
        const int backtracks = report.backtracks;
        norm2 = backtrack(next, norm2, false, report);
        if (report.backtracks > backtracks) {
          previous = INFINITY;
          assemble(model, s, true);
        }
        fresh = true;
        continue;
      }
      // The residual alone at the new iterate (the couple Jacobians are not needed for a chord
      // step, nor at the line search's rejected points).
      double next = assemble(model, s, false);
      if (!fresh && !(next < norm2)) {
        undo_chord_step();
        continue;
      }
      // after a fresh (Newton) step: backtrack as above, on the residual alone
      const int backtracks = report.backtracks;
      norm2 = backtrack(next, norm2, false, report);
      const bool backtracked = report.backtracks > backtracks;
      // a damped step is far from the solution: the next iteration is a fresh Newton one, with
      // the Jacobian at the accepted point (the residual is the same)
      if (backtracked) {
        norm2 = assemble(model, s, true);
        fresh = true;
        previous_correction = 0.0;
        previous = INFINITY;
      } else {
        fresh = false;
      }
    }
    return report;
  };
  // with guides too (above; docs/models/dynamics.md, "The predictor and the estimate with guides")
  const double extrapolate = s.time == history_time_ ? h * th : 0.0;
  // the last step's factors: hinge friction only, and not with guides (no validation has hinge
  // friction and guides together)
  const bool stale =
      pentadiagonal_ && factors_kept_ && s.time == history_time_ && model.guides.empty();
  // Newton again from constant velocity with fresh factors, the iterations, factorisations,
  // backtracks and switch updates of the starts before (`before`) counted with its own
  auto restart = [&](const StepReport& before) {
    StepReport again = newton(0.0, false);
    again.iterations += before.iterations;
    again.starts = before.starts + 1;
    again.factorizations += before.factorizations;
    again.backtracks += before.backtracks;
    again.switch_updates += before.switch_updates;
    again.switch_builds += before.switch_builds;
    return again;
  };
  StepReport report = newton(extrapolate, stale);
  // the extrapolation can start Newton worse off than constant velocity (a large step, a whip)
  if (!report.converged && (extrapolate > 0.0 || stale)) report = restart(report);
  if (!report.converged && cut_acted) {
    // The crossing cut lands each crossing hinge in its band, which can cost more iterations
    // than the plain halvings where many hinges cross at once (larger steps): again with the
    // halvings alone. Only where a cut acted: otherwise this run would repeat the last one.
    cut_crossings = false;
    report = restart(report);
  }
  // Converged on the estimate, the last assembly is one correction (≤ √tolerance·p or so) off the
  // accepted iterate: the step's works and torques are taken there again (residual only).
  if (report.converged && estimated && !checked) assemble(model, s, false, true);
  report.max_penetration = max_penetration_;
  if (!report.converged) return report;
  // The guides' friction work over the step: the friction force the step applied (at the θ point,
  // with the step's velocity) times the step's displacement along the rail, h f_t v_t ≤ 0.
  // Likewise the guides' contact dampers; the links', the drag's and the seats' dissipation are
  // those of the last assembly's iterate (within tolerance·p of the accepted one).
  report.damper_work = damper_work_;
  report.drag_work = drag_work_;
  report.contact_damping_work = contact_damping_work_;
  report.seat_friction_work = seat_friction_work_;
  report.hinge_work = hinge_work_;
  report.takeup_damper_work = takeup_damper_work_;
  // the θ points of the accepted iterate (the last assembly's may be one correction before it;
  // the next assembly makes them afresh)
  if (!model.guides.empty()) theta_points(s);
  refresh_guide_hint(model);
  // one contact's friction work over the step, h f_t v_t (0 off the rail), its damper's booked
  auto contact_work = [&](const GuideContact& gc) {
    if (!gc.active) return 0.0;
    report.contact_damping_work += h * gc.damping_power;
    return h * gc.friction_force * gc.slip;
  };
  for (std::size_t g = 0; g < model.guides.size(); ++g) {
    const Guide& guide = model.guides[g];
    if (guide.stick_stiffness > 0.0) {
      // The stick law (Guide::stick_stiffness): every node's anchor moves on from the contact at
      // the θ point (the force the step applied, its reach μ f/k_t) and the step's end s₁ — kept
      // while |s₁ − a| is within the reach, dragged to s₁ ∓ reach where it slid (the spring left
      // at most at its reach), released off the rail or lifting. The springs' energy
      // ½ k_t (s − a)² is in energy(); the friction work is minus what the spring–slider
      // dissipated over the step: the friction force's work on the roller, h f_t v_t, plus the
      // change of the spring's energy from (s₀, a₀) to (s₁, a₁) — −μ f |Δa| while sliding
      // steadily, −k_t (θ − ½) Δs² while sticking (the θ-method's damping of the spring; 0 at
      // θ = ½), minus the spring's whole energy where it is released.
      const GuideBounds bounds = guide_bounds(guide);
      const double kt = guide.stick_stiffness;
      // a node neither on the hint's list (in increasing order) nor anchored stays free: skipped
      const auto near =
          options_.guide_hint ? guide_hint_.nodes(g) : std::span<const std::uint32_t>(all_nodes_);
      std::size_t listed = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const bool on_list = listed < near.size() && near[listed] == i;
        listed += on_list ? 1 : 0;
        if (model.is_pinned(i)) continue;
        const std::size_t at = static_cast<std::size_t>(stick_slot_[g]) * n + i;
        const double was = s.stick_anchor[at];
        // not anchored, and neither on the hint's list nor within the guide's reach on the step
        // (as the Newton assembly's test: with the discrete gradient x₀ and u besides the θ point):
        // it stays unanchored, nothing to book (and no position to take: on an arc that is an
        // atan2 a node)
        if (!std::isfinite(was) &&
            (!on_list || !step_touch_possible(guide, bounds, s, ux_, uy_, i, qx_[i], qy_[i])))
          continue;
        const double a = step_anchor(guide, guide_frame_[g], s, stick_slot_[g], i);
        const GuideContact gc = guide_contact_at_theta(guide, guide_frame_[g], bounds, s, ux_, uy_,
                                                       i, qx_[i], qy_[i], h, a);
        const double end = guide_position(guide, guide_frame_[g], ux_[i], uy_[i]);
        const double next = stick_anchor_after(guide, gc, a, end);
        s.stick_anchor[at] = next;
        if (!std::isfinite(was) && !std::isfinite(next) && !gc.active) continue;
        const double d0 =
            std::isfinite(was)
                ? stick_stretch(guide, guide_position(guide, guide_frame_[g], s.x[i], s.y[i]), was)
                : 0.0;
        const double d1 = std::isfinite(next) ? stick_stretch(guide, end, next) : 0.0;
        report.friction_work += contact_work(gc) + 0.5 * kt * (d1 * d1 - d0 * d0);
      }
      continue;
    }
    if (!(guide.friction > 0.0) && !(guide.contact_damping > 0.0)) continue;
    const GuideBounds bounds = options_.guide_hint ? guide_hint_.bounds()[g] : guide_bounds(guide);
    for (const std::uint32_t i :
         options_.guide_hint ? guide_hint_.nodes(g) : std::span<const std::uint32_t>(all_nodes_)) {
      if (model.is_pinned(i)) continue;
      const GuideContact gc =
          guide_contact_at_theta(guide, guide_frame_[g], bounds, s, ux_, uy_, i, qx_[i], qy_[i], h);
      report.friction_work += contact_work(gc);
    }
  }
  // The hinges' stick law (HingeFriction::stick_stiffness): each hinge's couple at the accepted
  // iterate (the links' terms taken there afresh), its deflection moved on from d₀ to
  // d₁ = d₀ + Δβ, kept while |d₁| is within the spring's reach e F/k_t (F the θ point's load),
  // else left at ±e F/k_t (the anchor dragged: the slip). The hinge work is minus what the
  // spring–sliders dissipated: the couple's work M Δβ plus the change of the springs' energy
  // ½ k_t (d₁² − d₀²) — 0 a step while sticking at θ = ½ without the damper, −e F |Δa| sliding.
  if (model.hinge.sticks() && n >= 3) {
    for_each_link(n, model.links(), [&](std::size_t j, std::size_t a, std::size_t b) {
      const double d1x = ux_[b] - ux_[a], d1y = uy_[b] - uy_[a];
      hinge_link(s.x[b] - s.x[a], s.y[b] - s.y[a], d1x, d1y, l0_[j],
                 std::sqrt(d1x * d1x + d1y * d1y), model.rest_length(j), model.axial_stiffness, th,
                 hinge_links_[j], false);
    });
    const double kt = model.hinge.stick_stiffness;
    double work = 0.0;
    HingeCouple hc;
    for_each_hinge(n, model.closed, [&](std::size_t ha, std::size_t i, std::size_t) {
      const double d0 = s.hinge_deflection[i];
      hinge_couple(model.hinge, hinge_links_[ha], hinge_links_[i], h, hc, false, i, th, d0);
      const double reach = model.hinge.arm * hc.load / kt;
      const double d1 = d0 + hc.turn;
      const double next = std::abs(d1) <= reach ? d1 : std::copysign(reach, d1);
      s.hinge_deflection[i] = next;
      work += hc.work + 0.5 * kt * (next * next - d0 * d0);
    });
    report.hinge_work = work;
  }
  // The rails' loads' work over the step: the force the step applied (at the θ point) times the
  // step's displacement.
  for (std::size_t g = 0; g < model.guides.size(); ++g) {
    const Guide& guide = model.guides[g];
    if (!(guide.load_per_metre > 0.0)) continue;
    for (std::size_t i = 0; i < n; ++i) {
      if (model.is_pinned(i)) continue;
      const RailLoad load = rail_load(guide, guide_frame_[g], model.pitch, model.gravity_x,
                                      model.gravity_y, qx_[i], qy_[i]);
      if (load.active)
        report.load_work += load.fx * (ux_[i] - s.x[i]) + load.fy * (uy_[i] - s.y[i]);
    }
  }
  // The load's catch and discharge over the step (Guide::load_inertia): the step's momentum
  // balance dotted with the displacement Δx = h ((1 − θ) v₀ + θ v₁). A node whose load grows
  // (Δm_L > 0) loses Δm_L ((½ − θ) |v₀|² + θ v₀·v₁) besides the load's kinetic energy gained
  // (½ Δm_L v² at a steady speed: the inelastic catch); one whose load shrinks hands the leaving
  // material ½ |Δm_L| |v₀|² (the discharge). What is left of the balance is the θ-method's own
  // (θ − ½)(m + m_L1) |v₁ − v₀|². Material arriving at w (Guide::load_speed) adds its reaction's
  // work Δm_L w·Δx/h to the catch: the catch is −Δm_L ((½ − θ) |v₀|² + θ v₀·v₁ − w·Δx/h), of
  // which the arriving material's kinetic energy is the input part (load_arrival_work, arrival()):
  // ½ Δm_L |w|² on one loaded piece; where loaded pieces overlap, each growing piece's material its
  // own, ½ Δm_L Σ⁺ Δm_g |u_g|² / Σ⁺ Δm_g (Σ⁺ over the growing pieces), which exceeds ½ Δm_L |w|²
  // when their speeds differ (docs/models/dynamics.md, "A conveyed load: its inertia, loading and
  // discharge"). The rest is the catch's loss: −½ Δm_L |v − w|² at a steady speed on one piece,
  // less that excess where pieces overlap.
  if (any_load_inertia(model.guides)) {
    const std::span<LoadPiece> pieces =
        load_mix_ ? std::span<LoadPiece>(pieces_) : std::span<LoadPiece>();
    for (std::size_t i = 0; i < n; ++i) {
      if (model.is_pinned(i)) continue;
      const LoadMass m1 = load_mass(model, guide_frame_, ux_[i], uy_[i], pieces);
      const double dm = m1.mass - load_mass0_[i];
      const double v0x = s.vx[i], v0y = s.vy[i];
      const double v1x = (ux_[i] - s.x[i] - h * (1.0 - th) * v0x) / (h * th);
      const double v1y = (uy_[i] - s.y[i] - h * (1.0 - th) * v0y) / (h * th);
      const double v00 = v0x * v0x + v0y * v0y;
      if (dm > 0.0) {
        report.load_catch_work -= dm * ((0.5 - th) * v00 + th * (v0x * v1x + v0y * v1y));
        if (const Arrival in = arrival(model, i, m1, dm); in.arrives) {
          const double wx = in.wx, wy = in.wy;
          report.load_catch_work +=
              dm * (wx * ((1.0 - th) * v0x + th * v1x) + wy * ((1.0 - th) * v0y + th * v1y));
          report.load_arrival_work += dm * in.energy;
        }
      } else {
        report.load_discharge_work += 0.5 * dm * v00;
      }
    }
  }
  s.friction_work += report.friction_work;
  s.load_work += report.load_work;
  s.load_catch_work += report.load_catch_work;
  s.load_arrival_work += report.load_arrival_work;
  s.load_discharge_work += report.load_discharge_work;
  s.damper_work += report.damper_work;
  s.drag_work += report.drag_work;
  s.contact_damping_work += report.contact_damping_work;
  s.seat_friction_work += report.seat_friction_work;
  s.hinge_work += report.hinge_work;
  s.takeup_damper_work += report.takeup_damper_work;
  for (std::size_t i = 0; i < n; ++i) {
    if (model.is_pinned(i)) continue;
    // x₁ = x₀ + h ((1 − θ) v₀ + θ v₁)
    const double vx = (ux_[i] - s.x[i] - h * (1.0 - th) * s.vx[i]) / (h * th);
    const double vy = (uy_[i] - s.y[i] - h * (1.0 - th) * s.vy[i]) / (h * th);
    s.x[i] = ux_[i];
    s.y[i] = uy_[i];
    dvx_[i] = vx - s.vx[i];
    dvy_[i] = vy - s.vy[i];
    s.vx[i] = vx;
    s.vy[i] = vy;
  }
  for (std::size_t w = 0; w < model.sprockets.size(); ++w) {
    const Sprocket& wheel = model.sprockets[w];
    const double speed = wheel.driver
                             ? wheel.speed
                             : (psi1_[w] - s.angle[w] - h * (1.0 - th) * s.speed[w]) / (h * th);
    dspeed_[w] = speed - s.speed[w];
    s.speed[w] = speed;
    s.angle[w] = psi1_[w];
    if (wheel.takeup) {
      const double rate = (slide1_[w] - s.slide[w] - h * (1.0 - th) * s.slide_speed[w]) / (h * th);
      dslide_speed_[w] = rate - s.slide_speed[w];
      s.slide_speed[w] = rate;
      s.slide[w] = slide1_[w];
    }
  }
  update_held(model, s);
  s.time += h;
  history_time_ = s.time;
  factors_kept_ = pentadiagonal_;
  return report;
}

void Integrator::check_unknowns(const Model& model, std::size_t count) const {
  const std::size_t size = 2 * model.nodes() + extra_.size();
  if (count != size || model.nodes() != solver_.size() || model.sprockets.size() != psi1_.size() ||
      (model.hinge.active() && model.nodes() >= 3) != pentadiagonal_) {
    throw InputError({{"unknowns", std::to_string(count),
                       std::to_string(size) + " values for this integrator's model"}});
  }
}

void Integrator::newton_system(const Model& model, const State& s, std::span<const double> unknowns,
                               std::vector<double>& residual, std::vector<double>* jacobian) {
  const std::size_t n = model.nodes(), m = extra_.size(), size = 2 * n + m;
  check_unknowns(model, unknowns.size());
  throw_if_any(validate(model, s));
  // this assembly overwrites the bordered solve's rows and columns: the next step factors afresh
  factors_kept_ = false;
  load_iterate(model, s, unknowns);
  assemble(model, s, jacobian != nullptr);
  residual.assign(size, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    residual[2 * i] = -solver_.rhs[i].x;
    residual[2 * i + 1] = -solver_.rhs[i].y;
  }
  for (std::size_t a = 0; a < m; ++a) residual[2 * n + a] = -xres_[a];
  if (jacobian == nullptr) return;
  std::vector<double>& J = *jacobian;
  J.assign(size * size, 0.0);
  auto put = [&](std::size_t r, std::size_t c, const Mat2& b) {
    J[(2 * r) * size + 2 * c] += b.a;
    J[(2 * r) * size + 2 * c + 1] += b.b;
    J[(2 * r + 1) * size + 2 * c] += b.c;
    J[(2 * r + 1) * size + 2 * c + 1] += b.d;
  };
  for (std::size_t i = 0; i < n; ++i) {
    put(i, i, solver_.diag[i]);
    if (i > 0) put(i, i - 1, solver_.lower[i]);
    if (i + 1 < n) put(i, i + 1, solver_.upper[i]);
  }
  if (model.closed) {
    put(0, n - 1, solver_.lower[0]);
    put(n - 1, 0, solver_.upper[n - 1]);
  }
  // hinge friction: the blocks (i, i − 2) and (i, i + 2), modulo n on a loop (where two offsets
  // name one column, at n = 3 or 4, they add up, as BlockPentadiagonalSolver takes them)
  for (std::size_t i = 0; pentadiagonal_ && i < n; ++i) {
    if (model.closed || i >= 2) put(i, (i + n - 2) % n, far_lower_[i]);
    if (model.closed || i + 2 < n) put(i, (i + 2) % n, far_upper_[i]);
  }
  for (std::size_t a = 0; a < m; ++a) {
    for (std::size_t i = 0; i < n; ++i) {
      J[(2 * i) * size + 2 * n + a] = bcol_[a][i].x;
      J[(2 * i + 1) * size + 2 * n + a] = bcol_[a][i].y;
      J[(2 * n + a) * size + 2 * i] = brow_[a][i].x;
      J[(2 * n + a) * size + 2 * i + 1] = brow_[a][i].y;
    }
    for (std::size_t b = 0; b < m; ++b) J[(2 * n + a) * size + 2 * n + b] = xjac_[a * m + b];
  }
}

// The bordered solve's end: back substitution on the Schur complement's upper factor (its
// right-hand side in xx, already forward-eliminated), then δu = δu₀ − W δx (δu₀ in x).
void Integrator::finish_bordered(std::vector<Vec2>& x, double* xx) {
  const std::size_t nd = extra_.size();
  for (std::size_t c = nd; c-- > 0;) {
    double v = xx[c];
    for (std::size_t k = c + 1; k < nd; ++k) v -= schur_[c * nd + k] * xx[k];
    xx[c] = v / schur_[c * nd + c];
  }
  for (std::size_t a = 0; a < nd; ++a) subtract_scaled(x, wsol_[a], xx[a]);
}
// The bordered solve with the kept factors (a chord iteration's): the chain's part of the
// right-hand side `b`, the extras' `bx` (null: zero), into x and xx. The unknown's row over
// border_rows_ alone: brow_ and border_rows_ are written together, only by a Jacobian assembly
// (its clear_border zeroes the rows it listed, +0.0, before it lists the new ones), and a chord
// iteration assembles the residual alone — so the rows outside border_rows_[a] are +0.0 here,
// and the rows inside it are visited in the same ascending order as the loop over every row
// visited them. The terms left out are (+0)·δ + (+0)·δ = ±0, and g − (±0) = g but for g = −0
// exactly (then +0): at most the sign of an exactly zero correction (a non-finite δ is refused
// below either way).
void Integrator::chord_solve(std::span<const Vec2> b, const double* bx, std::vector<Vec2>& x,
                             double* xx) {
  const std::size_t nd = extra_.size();
  substitute(b, x);
  for (std::size_t a = 0; a < nd; ++a) {
    const std::vector<Vec2>& ba = brow_[a];
    double g = bx != nullptr ? bx[a] : 0.0;
    for (const std::size_t i : border_rows_[a]) g -= ba[i].x * x[i].x + ba[i].y * x[i].y;
    xx[a] = g;
  }
  for (std::size_t c = 0; c < nd; ++c) {
    for (std::size_t r = c + 1; r < nd; ++r) xx[r] -= schur_[r * nd + c] * xx[c];
  }
  finish_bordered(x, xx);
}
// The stick law's hinges that switched branch (sticking, sliding either way) since the kept
// factors were taken: each changes the Newton matrix by −h g ⊗ ΔM' (g = ∂β/∂x at the θ point,
// ΔM' the change of ∂M/∂x₁ between the two branches: hinge_branch_moment_gradient), a rank-1
// change U Vᵀ that the chord iteration's solve y = A⁻¹ r takes in by the Sherman–Morrison–
// Woodbury formula (Golub & Van Loan, §2.1): δ = y − W (I + Vᵀ W)⁻¹ Vᵀ y, W = A⁻¹ U (one
// substitution a switched hinge). Up to kMaxSwitches hinges; with more (or a near-singular
// I + Vᵀ W) the kept factors alone, as before. U, V (the links' terms at the iterate where
// these hinges' switches first appeared), W and I + Vᵀ W's factors are kept (switch_) while
// the same hinges stay switched to the same branches with the same factors, as the chord
// iteration keeps A: each further iteration costs Vᵀ y, the small solve and δ −= W c.
// Without a switch nothing is done: the chord iteration is the same, bit for bit.
bool Integrator::correct_for_switches(const Model& model, const State& s, StepReport& report,
                                      double pivot_floor) {
  const std::size_t nd = extra_.size();
  std::size_t nodes[kMaxSwitches];
  int now[kMaxSwitches];
  std::size_t r = 0;
  for (std::size_t i = 0; i < trial_.size(); ++i) {
    const int branch = branch_of(trial_[i]);
    if (branch == kept_branch_[i]) continue;
    if (r == kMaxSwitches) return false;
    nodes[r] = i;
    now[r] = branch;
    ++r;
  }
  if (r == 0) return false;
  bool same = r == switch_.count;
  for (std::size_t k = 0; k < r && same; ++k)
    same = nodes[k] == switch_.node[k] && now[k] == switch_.branch[k];
  if (!same) {
    build_switch_update(model, s, nodes, now, r, pivot_floor);
    ++report.switch_builds;
  }
  if (!switch_.usable) return false;
  // the coefficients (I + Vᵀ W)⁻¹ Vᵀ y with the kept factors
  double z[SmallLu::kMax];
  for (std::size_t k = 0; k < r; ++k) z[k] = hinge_dot(switch_.v[k], switch_.at[k], delta_, 0.0);
  switch_.capacitance.solve(z);
  for (std::size_t k = 0; k < r; ++k)
    if (!std::isfinite(z[k])) return false;
  for (std::size_t k = 0; k < r; ++k) {
    const double c = z[k];
    subtract_scaled(delta_, switch_w_[k], c);
    for (std::size_t e = 0; e < nd; ++e) dx_[e] -= switch_wx_[k * nd + e] * c;
  }
  ++report.switch_updates;
  return true;
}

void Integrator::build_switch_update(const Model& model, const State& s, const std::size_t* nodes,
                                     const int* branches, std::size_t count, double pivot_floor) {
  const std::size_t n = ux_.size(), nd = extra_.size(), r = count;
  const double h = options_.step, th = options_.theta;
  switch_.count = r;
  switch_.usable = false;
  for (std::size_t k = 0; k < r; ++k) {
    const std::size_t i = nodes[k];
    switch_.node[k] = i;
    switch_.branch[k] = branches[k];
    const std::size_t ha = i == 0 ? n - 1 : i - 1, hb = i + 1 == n ? 0 : i + 1;
    HingeLink link[2];
    const std::size_t ends[3] = {ha, i, hb};
    for (int e = 0; e < 2; ++e) {
      const std::size_t j = ends[e], a = ends[e], b = ends[e + 1];
      hinge_link(s.x[b] - s.x[a], s.y[b] - s.y[a], ux_[b] - ux_[a], uy_[b] - uy_[a], l0_[j], l1_[j],
                 model.rest_length(j), model.axial_stiffness, th, link[e], true);
    }
    double mx[3], my[3], kx[3], ky[3];
    hinge_branch_moment_gradient(model.hinge, link[0], link[1], h, i, th, branches[k], mx, my);
    hinge_branch_moment_gradient(model.hinge, link[0], link[1], h, i, th, kept_branch_[i], kx, ky);
    const double gx[3] = {link[0].px, -link[0].px - link[1].px, link[1].px};
    const double gy[3] = {link[0].py, -link[0].py - link[1].py, link[1].py};
    // a pinned node's row and column are the identity's (assemble): no term there
    for (int q = 0; q < 3; ++q) {
      const double keep = model.is_pinned(ends[q]) ? 0.0 : 1.0;
      switch_.at[k][q] = ends[q];
      switch_.v[k][2 * q] = keep * (mx[q] - kx[q]);
      switch_.v[k][2 * q + 1] = keep * (my[q] - ky[q]);
      switch_u_[ends[q]] = {-h * gx[q] * keep, -h * gy[q] * keep};
    }
    chord_solve(switch_u_, nullptr, switch_w_[k], switch_wx_.data() + k * nd);
    for (int q = 0; q < 3; ++q) switch_u_[ends[q]] = Vec2{};
  }
  // I + Vᵀ W, and the size of its terms before they cancel (|I| + |V|ᵀ |W| entry by entry:
  // where the two differ by orders, I + Vᵀ W's entries are mostly their rounding)
  SmallLu& a = switch_.capacitance;
  double terms = 0.0;
  for (std::size_t k = 0; k < r; ++k) {
    const double* v = switch_.v[k];
    const std::size_t* at = switch_.at[k];
    double row = 0.0;
    for (std::size_t c = 0; c < r; ++c) {
      const std::vector<Vec2>& w = switch_w_[c];
      double size = k == c ? 1.0 : 0.0;
      for (int q = 0; q < 3; ++q)
        size += std::abs(v[2 * q] * w[at[q]].x) + std::abs(v[2 * q + 1] * w[at[q]].y);
      a.lu[k][c] = hinge_dot(v, at, w, k == c ? 1.0 : 0.0);
      row += size;
    }
    terms = std::max(terms, row);
  }
  // A pivot at most pivot_floor of the terms: I + Vᵀ W is singular to rounding (and so
  // the switched Newton matrix: det(A + U Vᵀ) = det A det(I + Vᵀ W)), and the solve's
  // coefficients would be noise (or overflow).
  switch_.usable = a.factor(r, terms, pivot_floor);
}

void Integrator::load_iterate(const Model& model, const State& s,
                              std::span<const double> unknowns) {
  const std::size_t n = model.nodes(), m = extra_.size();
  const double h = options_.step;
  for (std::size_t j = 0; j < model.links(); ++j) {
    const std::size_t b = (j + 1) % n;
    l0_[j] = std::hypot(s.x[b] - s.x[j], s.y[b] - s.y[j]);
  }
  prepare_links(model);
  load_mass0_set_ = false;
  prepare_seats(model);
  for (std::size_t i = 0; i < n; ++i) {
    ux_[i] = unknowns[2 * i];
    uy_[i] = unknowns[2 * i + 1];
  }
  for (std::size_t w = 0; w < model.sprockets.size(); ++w) {
    psi1_[w] = s.angle[w] + h * model.sprockets[w].speed;  // a driver's; the others set below
    slide1_[w] = 0.0;
  }
  for (std::size_t a = 0; a < m; ++a)
    (extra_[a].slide ? slide1_ : psi1_)[extra_[a].wheel] = unknowns[2 * n + a];
}

bool Integrator::chord_solve_after_switch(const Model& model, const State& kept, const State& now,
                                          std::span<const double> unknowns, bool update,
                                          std::vector<double>& delta, double pivot_floor) {
  std::vector<std::vector<double>> deltas;
  const bool solved = chord_solves_after_switch(model, kept, std::span<const State>(&now, 1),
                                                unknowns, update, deltas, pivot_floor);
  delta = std::move(deltas[0]);
  return solved;
}

bool Integrator::chord_solves_after_switch(const Model& model, const State& kept,
                                           std::span<const State> now,
                                           std::span<const double> unknowns, bool update,
                                           std::vector<std::vector<double>>& deltas,
                                           double pivot_floor) {
  const std::size_t n = model.nodes(), m = extra_.size(), size = 2 * n + m;
  check_unknowns(model, unknowns.size());
  std::vector<Issue> issues = validate(model, kept);
  for (const State& s : now) {
    std::vector<Issue> more = validate(model, s);
    issues.insert(issues.end(), more.begin(), more.end());
  }
  if (!std::isfinite(pivot_floor) || !(pivot_floor >= 0.0) || !(pivot_floor < 1.0))
    issues.push_back({"pivot_floor", check::format_si(pivot_floor, ""), "a number in [0, 1)"});
  throw_if_any(issues);
  deltas.assign(now.size(), std::vector<double>(size, 0.0));
  factors_kept_ = false;  // the next step factors afresh
  load_iterate(model, kept, unknowns);
  assemble(model, kept, true);
  if (factor() != SolveStatus::kSolved) return false;
  keep_branches();
  if (m == 0) {
    substitute(solver_.rhs, delta_);
  } else if (solve_fresh() != SolveStatus::kSolved) {
    return false;
  }
  StepReport counts;
  for (std::size_t k = 0; k < now.size(); ++k) {
    load_iterate(model, now[k], unknowns);
    assemble(model, now[k], false);
    if (m == 0)
      substitute(solver_.rhs, delta_);
    else
      chord_solve(solver_.rhs, xres_.data(), delta_, dx_.data());
    if (update && !trial_.empty()) correct_for_switches(model, now[k], counts, pivot_floor);
    std::vector<double>& delta = deltas[k];
    for (std::size_t i = 0; i < n; ++i) {
      delta[2 * i] = delta_[i].x;
      delta[2 * i + 1] = delta_[i].y;
    }
    for (std::size_t a = 0; a < m; ++a) delta[2 * n + a] = dx_[a];
  }
  return true;
}

void Integrator::keep_branches() {
  for (std::size_t i = 0; i < trial_.size(); ++i)
    kept_branch_[i] = static_cast<signed char>(branch_of(trial_[i]));
}

SolveStatus Integrator::solve_fresh() {
  const std::size_t nd = extra_.size();
  // The driven wheels' angles and the take-ups' slides border the chain's matrix:
  // [A B; Cᵀ D] [δu; δx] = [r; r_x]. Solve A W = B (one more O(N) substitution per extra
  // unknown, same factors; the first rides along with δu₀'s), then the small Schur
  // complement (D − Cᵀ W) δx = r_x − Cᵀ δu₀, and δu = δu₀ − W δx.
  substitute(solver_.rhs, delta_, bcol_[0], wsol_[0]);
  for (std::size_t a = 1; a < nd; ++a) substitute(bcol_[a], wsol_[a]);
  for (std::size_t a = 0; a < nd; ++a) {
    // the unknown's row, over the rows where it is not zero (in the same order: the same
    // sums, the zero terms left out)
    const std::vector<Vec2>& ba = brow_[a];
    const std::vector<std::size_t>& rows = border_rows_[a];
    double g = xres_[a];
    for (const std::size_t i : rows) g -= ba[i].x * delta_[i].x + ba[i].y * delta_[i].y;
    dx_[a] = g;
    for (std::size_t b = 0; b < nd; ++b) {
      const std::vector<Vec2>& wb = wsol_[b];
      double sab = xjac_[a * nd + b];
      for (const std::size_t i : rows) sab -= ba[i].x * wb[i].x + ba[i].y * wb[i].y;
      schur_[a * nd + b] = sab;
    }
  }
  // Gaussian elimination on the nd × nd Schur complement (nd is the number of driven
  // wheels and take-ups: small), right-hand side in dx_; the multipliers are kept below
  // the diagonal for the chord iterations (they are not read again here).
  for (std::size_t c = 0; c < nd; ++c) {
    const double piv = schur_[c * nd + c];
    if (!(std::abs(piv) > 0.0) || !std::isfinite(piv)) {
      return SolveStatus::kSingularPivot;
    }
    for (std::size_t r = c + 1; r < nd; ++r) {
      const double f = schur_[r * nd + c] / piv;
      for (std::size_t k = c; k < nd; ++k) schur_[r * nd + k] -= f * schur_[c * nd + k];
      schur_[r * nd + c] = f;
      dx_[r] -= f * dx_[c];
    }
  }
  finish_bordered(delta_, dx_.data());
  return SolveStatus::kSolved;
}

}  // namespace catena::dynamics
