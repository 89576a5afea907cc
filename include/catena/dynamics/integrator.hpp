// Time stepping for the chain (docs/models/dynamics.md, "Integrator").
//
// The energy-conserving implicit midpoint rule (the discrete energy–momentum method of Simo &
// Tarnow 1992, ZAMP 43): x₁ = x₀ + h (v₀ + v₁)/2 and M (v₁ − v₀) = h F, with each link's force
// taken along the midpoint chord d̄ = (d₀ + d₁)/2 with the discrete gradient of its energy,
// k (l̄ − p) / l̄, l̄ = (l₀ + l₁)/2, so that the work done over a step equals the change of
// elastic energy exactly; the damper's force c (l₁ − l₀)/h along the same direction dissipates
// c (l₁ − l₀)²/h ≥ 0. Unconditionally stable: the step is set by accuracy, not by k.
// Each step solves the nonlinear equations for x₁ by Newton's method with a backtracking line
// search on the residual; the Jacobian is the chain's block tridiagonal (cyclic for a loop)
// matrix, solved in O(N) by BlockTridiagonalSolver; with hinge friction the exact Jacobian is
// block pentadiagonal (a hinge couples nodes i − 1 and i + 1), solved in O(N) by
// BlockPentadiagonalSolver.
//
// Sprockets: contact forces are evaluated at the θ point like the links and add 2×2 blocks to the
// diagonal; a driver's angle is prescribed; a driven wheel's angle is one more unknown of the
// Newton system, which borders the chain's matrix with one row and column per driven wheel: one
// more O(N) substitution per wheel (same factors) and a Schur complement of the size of the number
// of driven wheels.
//
// Numerical damping (option theta > ½): the same scheme at the weighted point θ instead of the
// midpoint (x₁ = x₀ + h ((1 − θ) v₀ + θ v₁), chord and length interpolated at θ), the θ-method.
// Unconditionally stable, it damps the unresolved high-frequency (axial) modes — each step scales
// them by about −(1 − θ)/θ — but is only first order accurate and does not conserve energy: use it
// to settle a chain to equilibrium or to quiet stiff modes, not for the energy balance.
#pragma once

#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "catena/dynamics/block_pentadiagonal.hpp"
#include "catena/dynamics/block_tridiagonal.hpp"
#include "catena/dynamics/chain.hpp"
#include "catena/dynamics/guide_hint.hpp"
#include "catena/dynamics/small_lu.hpp"

namespace catena::dynamics {

struct IntegratorOptions {
  double step = 1e-3;        ///< [s] h
  int max_iterations = 25;   ///< Newton iterations per step
  double tolerance = 1e-10;  ///< converged when max |Δx| ≤ tolerance · pitch
  double theta = 0.5;        ///< θ in [½, 1]: ½ energy-conserving midpoint, > ½ damped
  /// Try each guide only against the nodes GuideHint lists near it (O(N + G + pairs) a step);
  /// false: every node against every guide (O(N·G)), for verification. Bit-identical results.
  bool guide_hint = true;
  /// The stick law's chord iterations take up to four hinges' stick–slip switches into their
  /// kept factors by a low-rank update (docs/models/dynamics.md, "Hinges: sticking"); false: the
  /// kept factors alone, as before the update (for verification: the same residual and stopping
  /// tests, with more factorisations). No effect without the stick law.
  bool switch_update = true;
};

std::vector<Issue> validate(const IntegratorOptions& options);

/// What one step did.
struct StepReport {
  bool converged = false;
  int iterations = 0;  ///< Newton iterations taken (over every start)
  /// Newton runs from a starting point: 2 when the first (the predictor that extrapolates the
  /// velocities, or the last step's factors with hinge friction) did not converge and Newton ran
  /// again from constant velocity with fresh factors; one more with the hinges' stick law when
  /// those failed after the line search's crossing cut acted (again from constant velocity, as the
  /// second, with the halvings alone); each run takes at most max_iterations
  int starts = 1;
  int factorizations = 0;  ///< fresh Newton matrices factored (over every start)
  /// the stick law's chord iterations corrected for hinges' stick–slip switches
  /// (IntegratorOptions::switch_update), and the times that correction's W = A⁻¹ U (a
  /// substitution per switched hinge) and I + Vᵀ W were made: where the switched hinges, their
  /// branches or the factors had changed since the last (over every start)
  int switch_updates = 0;
  int switch_builds = 0;
  double last_correction = 0.0;  ///< [m] max |Δx| of the last Newton iteration
  int backtracks = 0;            ///< line-search points taken (the crossing cut's and halvings')
  double max_penetration = 0.0;  ///< [m] deepest roller–seat penetration at the step's θ point
  double friction_work = 0.0;    ///< [J] the guides' friction work over the step (≤ 0)
  /// [J] the links' dampers' work over the step: −Σ c (l₁ − l₀)/h · d_θ·(d₁ − d₀)/l_θ, which is
  /// −Σ c (l₁ − l₀)²/h at θ = ½
  double damper_work = 0.0;
  double drag_work = 0.0;  ///< [J] the drag's work over the step, −Σ α m |x₁ − x₀|²/h (≤ 0)
  /// [J] the seats' and guides' contact dampers' work over the step (≤ 0)
  double contact_damping_work = 0.0;
  /// [J] the seats' friction work over the step, Σ h f_t v_t (≤ 0; roller and wheel together)
  double seat_friction_work = 0.0;
  /// [J] the hinges' friction work over the step, Σ M Δβ (≤ 0); with the stick law
  /// (HingeFriction::stick_stiffness) Σ M Δβ + the change of the springs' ½ k_t d² (minus what the
  /// spring–sliders dissipated), taken at the accepted iterate
  double hinge_work = 0.0;
  /// [J] the take-ups' dampers' work over the step, −Σ c_t (s₁ − s₀)²/h (≤ 0)
  double takeup_damper_work = 0.0;
  /// [J] the rails' loads' work over the step, Σ F(q_θ)·(x₁ − x₀) (Guide::load_per_metre)
  double load_work = 0.0;
  /// [J] the loading's catch over the step (Guide::load_inertia; State::load_catch_work: ≤ 0 for
  /// material arriving at rest)
  double load_catch_work = 0.0;
  /// [J] the arriving material's kinetic energy over the step (Guide::load_speed;
  /// State::load_arrival_work, part of load_catch_work): ½ Δm_L |u|² on one loaded piece; where
  /// loaded pieces overlap at the node, each growing piece's material its own,
  /// ½ Δm_L Σ⁺ Δm_g |u_g|² / Σ⁺ Δm_g (Σ⁺ over the pieces whose share grows;
  /// docs/models/dynamics.md, "A conveyed load: its inertia, loading and discharge")
  double load_arrival_work = 0.0;
  /// [J] the discharge over the step: minus the leaving material's kinetic energy (≤ 0)
  double load_discharge_work = 0.0;
  SolveStatus solve = SolveStatus::kSolved;
};

/// "N Newton iterations" for a step's report, saying what N counts when Newton ran from two
/// starting points ("50 Newton iterations in all, from 2 starting points with at most 25 from
/// each"): for the message of a step that did not converge.
std::string newton_iterations_text(const StepReport& report, int max_iterations);

/// The mutable work arrays of the integrator for one model (sized once; steps allocate nothing).
class Integrator {
 public:
  /// Validates model and options (throws InputError listing every problem).
  Integrator(const Model& model, IntegratorOptions options);

  /// Advances `state` by one step h. Throws InputError when the model is not the one the
  /// integrator was built for or the state's arrays have the wrong sizes (checked every step, in
  /// O(1)); the state's values are checked by validate(model, state), which the caller runs
  /// once. On a failed solve the state is left unchanged (but for the release's held flags,
  /// which are first brought up to date with the start state: update_held, a function of it) and
  /// the report says why.
  StepReport step(const Model& model, State& state);

  const IntegratorOptions& options() const { return options_; }

  /// Continues the predictor's history (and the factors kept with it) from the time `to` when
  /// the last accepted step ended at `from`: a caller that resets a state's time after a sequence
  /// of steps (a grid step taken as sub-steps, whose summed time may differ from the grid's by
  /// rounding) keeps the history it would otherwise lose. No change when it ended elsewhere.
  void retime(double from, double to) {
    if (history_time_ == from) history_time_ = to;
  }

  /// [N·m] per sprocket, counter-clockwise positive: the chain's contact torque on the wheel at
  /// the θ point of the last step — the torque the step applied (a driven wheel's step is
  /// J (ω₁ − ω₀) = h (τ − T_L)). Taken at the last assembled Newton iterate, whose distance to the
  /// accepted one is below `tolerance`·p. Zero before the first step.
  const std::vector<double>& applied_torque() const { return torque_; }

  /// [N] per sprocket: the chain's force on a take-up's wheel along its slide, e·Σ(f n − F_t),
  /// at the θ point of the last step (0 on a wheel without a take-up).
  const std::vector<double>& applied_slide_force() const { return slide_force_; }
  /// [N] per sprocket: the magnitude of the chain's whole force on a take-up's wheel,
  /// |Σ(f n − F_t)|, at the θ point of the last step (0 when no roller touches it, and on a wheel
  /// without a take-up).
  const std::vector<double>& applied_wheel_force() const { return wheel_force_; }

  /// The Newton system's size: 2N (the nodes' x₁, y₁) + one per driven wheel (its ψ₁) + one per
  /// take-up (its s₁).
  std::size_t unknowns() const { return 2 * ux_.size() + extra_.size(); }
  /// For verification only (O(N²) memory): the step's residual R at the iterate `unknowns` —
  /// the nodes' (x₁, y₁) interleaved, then the driven wheels' ψ₁ in wheel order, then the
  /// take-ups' s₁ in wheel order — and, when `jacobian` is given, the Jacobian the step's Newton
  /// iteration uses there, dense and row-major, assembled from its blocks (hinge friction's far
  /// blocks too) and borders. Pinned nodes are not supported here.
  void newton_system(const Model& model, const State& state, std::span<const double> unknowns,
                     std::vector<double>& residual, std::vector<double>* jacobian);
  /// For verification only: a stick-law chord iteration's Newton correction after its hinges
  /// switched branch. Factors the Newton matrix at `unknowns` of the state `kept` (as a step's
  /// fresh iteration, the bordered solve's elimination and the hinges' branches included), then
  /// solves with those factors for the residual at the same unknowns of `now` (the chord solve)
  /// and, with `update`, corrects that solve for the hinges that switched branch between the two
  /// (IntegratorOptions::switch_update's correction). `delta` is laid out as `unknowns`
  /// (newton_system's); the correction solves J δ = −R. False where the factorisation failed. The
  /// next step factors afresh.
  /// `pivot_floor`: the update's guard, its I + Vᵀ W taken as singular (and the kept factors'
  /// solve left alone) where a pivot is at most this fraction of the size of the terms its
  /// entries were summed from (SmallLu::factor); the step's is kSwitchPivotFloor.
  /// Throws InputError where `pivot_floor` is not in [0, 1).
  bool chord_solve_after_switch(const Model& model, const State& kept, const State& now,
                                std::span<const double> unknowns, bool update,
                                std::vector<double>& delta, double pivot_floor = kSwitchPivotFloor);
  /// chord_solve_after_switch for a sequence of states `now`, each solved with the one
  /// factorisation at `kept` (as a step's successive chord iterations are): the update's parts
  /// are kept from one state to the next while the same hinges stay switched to the same
  /// branches, made afresh where they change. `deltas[k]` is now[k]'s correction.
  bool chord_solves_after_switch(const Model& model, const State& kept, std::span<const State> now,
                                 std::span<const double> unknowns, bool update,
                                 std::vector<std::vector<double>>& deltas,
                                 double pivot_floor = kSwitchPivotFloor);
  /// The stick law's switch update's guard (above, and Integrator::step's): a pivot of I + Vᵀ W
  /// at most 1e-12 of its terms' size, where 12 of a double's 16 digits have cancelled
  static constexpr double kSwitchPivotFloor = 1e-12;

 private:
  // Fills the solver's rhs with −R(u) (and its blocks with J(u) when `jacobian`); returns |R|².
  // `report_only`: only what a step reports of its iterate (the works, the wheels' torques and
  // forces, the deepest penetration), by the same arithmetic; the rhs is left unusable and 0
  // returned (the assembly at an iterate accepted on the error estimate).
  double assemble(const Model& model, const State& s, bool jacobian, bool report_only = false);

  // The Newton matrix's factorisation and substitutions: block tridiagonal without hinge
  // friction; with it, the exact block-pentadiagonal matrix (the tridiagonal arrays plus the
  // hinges' blocks two nodes apart, far_lower_/far_upper_) in penta_.
  SolveStatus factor();
  // The θ points x_θ = (1 − θ) x₀ + θ u of the state s and the iterate ux_, uy_ into qx_, qy_
  // (assemble's with guides but no wheels, and the accepted iterate's after a step; with wheels
  // assemble forms them by the same arithmetic in its candidate lists' pass).
  void theta_points(const State& s);
  // Brings the guide hint up to date with the θ points qx_, qy_ (those of the iterate ux_, uy_:
  // the caller has filled them), O(N) + a rebuild when a node has moved more than its margin.
  void refresh_guide_hint(const Model& model);
  void substitute(std::span<const Vec2> b, std::span<Vec2> x);
  // newton_system's and chord_solve_after_switch's check of their unknowns against this
  // integrator's model (an InputError naming the count the model needs)
  void check_unknowns(const Model& model, std::size_t count) const;
  // newton_system's and chord_solve_after_switch's setup: the links at the state s, and the
  // iterate (nodes, then the driven wheels' angles and the take-ups' slides) from `unknowns`.
  void load_iterate(const Model& model, const State& s, std::span<const double> unknowns);
  // The Newton correction with fresh factors into delta_ (and dx_ with bordering unknowns): the
  // bordered solve's elimination, whose W = A⁻¹ B and Schur factors the chord iterations keep.
  SolveStatus solve_fresh();
  // kept_branch_ from trial_ (the assembly the factors were taken from)
  void keep_branches();
  // The bordered solve's end: back substitution on the Schur complement's upper factor (its
  // right-hand side in xx, already forward-eliminated), then δu = δu₀ − W δx (δu₀ in x).
  void finish_bordered(std::vector<Vec2>& x, double* xx);
  // The bordered solve with the kept factors (a chord iteration's): the chain's part of the
  // right-hand side `b`, the extras' `bx` (null: zero), into x and xx.
  void chord_solve(std::span<const Vec2> b, const double* bx, std::vector<Vec2>& x, double* xx);
  // The stick law's chord iteration corrected for the hinges that switched branch since the
  // kept factors were taken (delta_ and dx_ in place); false where it left them as they were.
  // The report counts the corrections (switch_updates) and the makings of their parts
  // (switch_builds).
  // `pivot_floor`: the guard's (kSwitchPivotFloor in a step).
  bool correct_for_switches(const Model& model, const State& s, StepReport& report,
                            double pivot_floor);
  // correct_for_switches' parts for the `count` switched hinges `nodes` (now on `branches`),
  // at the iterate: into switch_ and switch_w_, switch_wx_
  void build_switch_update(const Model& model, const State& s, const std::size_t* nodes,
                           const int* branches, std::size_t count, double pivot_floor);
  void substitute(std::span<const Vec2> b, std::span<Vec2> x, std::span<const Vec2> b2,
                  std::span<Vec2> x2);

  IntegratorOptions options_;
  BlockTridiagonalSolver solver_;
  bool pentadiagonal_;                       // hinge friction on: the exact pentadiagonal solve
  BlockPentadiagonalSolver penta_;           // sized 1 when not used
  std::vector<Mat2> far_lower_, far_upper_;  // blocks (i, i − 2) and (i, i + 2) (hinge friction)
  std::vector<double> ux_, uy_;              // the Newton iterate x₁
  std::vector<double> l0_;                   // link lengths at the start of the step
  std::vector<double> l1_;                   // link lengths at the iterate (assemble's)
  std::vector<HingeLink> hinge_links_;       // each link's share of its hinges' couples
  // The stick law's hinges (HingeFriction::sticks) per node: the trial torque and the limit e F
  // at the last assembly's iterate (trial_), and at the iterate a Newton correction started from
  // (trial_base_): the line search's crossing cut (Integrator::step)
  struct HingeTrial {
    double trial = 0.0, limit = 0.0;
  };
  std::vector<HingeTrial> trial_, trial_base_;
  // a hinge's branch at its trial: 0 sticking, ±1 sliding that way
  static int branch_of(const HingeTrial& t) {
    return std::abs(t.trial) <= t.limit ? 0 : (t.trial > 0.0 ? 1 : -1);
  }
  // The stick law's chord iterations across a stick–slip switch (Integrator::step): each hinge's
  // branch where the kept factors were taken (0 sticking, ±1 sliding that way), and per switched
  // hinge (at most kMaxSwitches) the update's column U = −h g, its solve W = A⁻¹ U with the
  // kept factors (the nodes' part, then the extras' nd values each) and the small matrix
  // I + Vᵀ W, V the switch's change of ∂M/∂x₁
  static constexpr std::size_t kMaxSwitches = 4;
  std::vector<signed char> kept_branch_;
  std::vector<Vec2> switch_u_;
  std::vector<std::vector<Vec2>> switch_w_;
  std::vector<double> switch_wx_;
  // The update's parts kept across chord iterations while the switched hinges, their branches
  // and the factors stay (a chord iteration's Newton matrix is the kept one, and its update is
  // taken where the switches first appeared): the hinges (count 0: none kept; factor() clears
  // it), V on their nodes `at`, and I + Vᵀ W's LU factors; `usable` false where I + Vᵀ W was
  // near-singular (then the kept factors alone)
  struct SwitchUpdate {
    std::size_t count = 0;
    std::size_t node[kMaxSwitches] = {};
    int branch[kMaxSwitches] = {};
    double v[kMaxSwitches][6] = {};
    std::size_t at[kMaxSwitches][3] = {};
    SmallLu capacitance;  // I + Vᵀ W
    bool usable = false;
  };
  static_assert(kMaxSwitches <= SmallLu::kMax);
  SwitchUpdate switch_;
  std::vector<Vec2> delta_;     // Newton correction
  std::vector<double> psi1_;    // sprocket angles at the end of the step (iterate)
  std::vector<double> slide1_;  // take-ups' slides at the end of the step (iterate), per wheel
  // per node: the conveyed load's mass m_L at x₀ (Guide::load_inertia), fixed for the step: taken
  // at the step's first assembly (its guides' frames then current), unset with l0_
  std::vector<double> load_mass0_;
  bool load_mass0_set_ = false;
  // Where loaded pieces with their own arriving speeds may overlap (load_speeds_mix): per node and
  // guide, the piece's m_L,g at x₀ (node-major, taken with load_mass0_), and the pieces at the
  // iterate of the node at hand (load_mass's)
  bool load_mix_ = false;
  std::vector<double> piece_mass0_;
  std::vector<LoadPiece> pieces_;
  // The material joining node i over the step (Guide::load_speed): it arrives with the velocity w,
  // and −Δm_L ∂w/∂x₁ = −f G; `energy`: its kinetic energy per kg. With one loaded piece at the
  // node w = p/m_L1 (LoadMass::p; f = Δm_L/m_L1, G = ∂p/∂x₁ − w (∇m_L1)ᵀ); with more (pieces_
  // filled at the iterate) the growing pieces' increments' w = Σ⁺ Δm_g u_g / Σ⁺ Δm_g
  // (f = Δm_L/Σ⁺ Δm_g, G = Σ⁺ ((u_g − w) (∇m_g)ᵀ + Δm_g ∂u_g/∂x₁)).
  struct Arrival {
    bool arrives = false;
    double wx = 0.0, wy = 0.0, f = 0.0, energy = 0.0;
    double g[4] = {0.0, 0.0, 0.0, 0.0};
  };
  Arrival arrival(const Model& model, std::size_t i, const LoadMass& m1, double dm) const;
  // The unknowns that border the chain's matrix: the driven wheels' angles in wheel order, then
  // the take-ups' slides in wheel order (docs/models/dynamics.md, "Take-up").
  struct Extra {
    std::size_t wheel = 0;
    bool slide = false;
  };
  std::vector<Extra> extra_;
  std::vector<std::size_t> angle_of_, slide_of_;  // per wheel: its extras' index, or npos
  std::vector<double> xres_;                      // per extra: −R
  std::vector<double> xjac_;                      // m × m: ∂R_a/∂x_b among the extras
  std::vector<double> dx_;                        // per extra: the Newton correction
  std::vector<std::vector<Vec2>> bcol_;           // per extra: the coupling column ∂R/∂x_a
  // per extra: its row ∂R_a/∂u (the column's transpose but for seat friction)
  std::vector<std::vector<Vec2>> brow_;
  std::vector<std::vector<Vec2>> wsol_;  // per extra: A⁻¹ times that column
  // the solver's forward sweep of the residual (and bcol_[0]) was done by the last factor() and
  // the next substitution of them only finishes it
  bool forward_pending_ = false;
  // per extra: the rows of bcol_ and brow_ the last Jacobian assembly set, ascending (the others
  // are zero)
  std::vector<std::vector<std::size_t>> border_rows_;
  std::vector<double> schur_;        // the extras' Schur complement
  std::vector<double> slide_force_;  // per wheel: the chain's force along the slide
  std::vector<double> wheel_force_;  // per wheel: |the chain's force| on a take-up's wheel
  std::vector<double> torque_;       // per wheel: the θ-point contact torque (last assembly)
  // The seat contacts' step constants (docs/models/dynamics.md, "Solver"): each ISO wheel's tooth
  // geometry (seat_geometry, set at the start of a step), and the directions (cos σ, sin σ) of its
  // seats σ = ψ_θ + k τ at the θ-point angle ψ_θ they were taken at — a driver's ψ_θ is the same
  // in every Newton iteration of a step, so its seats' sines and cosines are taken once a step.
  struct SeatDirection {
    double k = NAN;  // the seat index it is for (NaN: none)
    double cs = 0.0, sn = 0.0;
  };
  void prepare_seats(const Model& model);
  // The tension-only links' step starts (Model::links_discrete_gradient): link_step_start of
  // each link's stretch l0_ − p, taken once a step when l0_ is (link_step_force reads them in
  // every Newton iteration)
  void prepare_links(const Model& model);
  std::vector<LinkStart> link_start_;
  std::vector<SeatGeometry> seat_geometry_;
  std::vector<double> seat_psi_;  // per wheel: the angle of its directions
  // [m] max(θ, 1 − θ) max |u − x₀| (∞-norm) over the nodes: how far a node's x₀ or iterate is from
  // its θ point, for the reach test of the seats' discrete gradient (set by assemble when a wheel
  // has it)
  double seat_travel_ = 0.0;
  std::vector<std::vector<SeatDirection>> seat_direction_;  // per wheel: by k mod z
  // per pocket wheel with the discrete gradient, per node: the memo of the step's start
  // (PocketStart: its energy is taken once a step, not in every Newton iteration)
  std::vector<std::vector<PocketStart>> pocket_start_;
  // per ISO wheel with the discrete gradient, per node: the memo of the step's start (SeatStart:
  // its gap, taken once a step, not in every Newton iteration)
  std::vector<std::vector<SeatStart>> seat_start_;
  // the nodes' θ points x_θ of the iterate (assemble's; the wheels' and the guides' one set)
  std::vector<double> qx_, qy_;
  // Each wheel's candidates: the nodes within (1 + kCandidateMargin) · reach of its centre at
  // the θ points listed_x_, listed_y_ where the lists were made (in node order; the reach test
  // then runs on these alone), and the wheel's centre and reach then. Kept while no θ point has
  // moved far enough since to come within reach from outside the list (update_candidates).
  // Not used for a take-up's wheel (its centre moves within the step).
  static constexpr double kCandidateMargin = 0.1;
  bool update_candidates(const Model& model, double moved);
  std::vector<std::vector<std::size_t>> candidates_;
  std::vector<double> listed_x_, listed_y_;
  std::vector<double> listed_wheel_;  // per wheel: centre x, y and reach at the lists' making
  // The predictor's history: the last accepted step's change of each node's velocity and each
  // wheel's speed and slide speed, and the time it ended at (NaN: none; a state at another time
  // starts from the constant-velocity predictor).
  std::vector<double> dvx_, dvy_, dspeed_, dslide_speed_;
  double history_time_ = NAN;
  // the factors in penta_ (and the bordered solve's W and Schur factors) are those of a Newton
  // matrix of the step that ended at history_time_ (hinge friction: the next step's first
  // iterations may reuse them)
  bool factors_kept_ = false;
  double max_penetration_ = 0.0;
  std::vector<GuideFrame> guide_frame_;  // per guide: guide_frame, refreshed with the hint
  // per guide: its slot in State::stick_anchor (−1: not sticking), refreshed with the frames
  std::vector<std::ptrdiff_t> stick_slot_;
  GuideHint guide_hint_;                  // per guide: the nodes near it
  std::vector<std::uint32_t> all_nodes_;  // 0 … N − 1 (the guide loops without the hint)
  // the dissipative works of the last assembly's iterate (StepReport's fields)
  double damper_work_ = 0.0, drag_work_ = 0.0, contact_damping_work_ = 0.0;
  double seat_friction_work_ = 0.0;
  double hinge_work_ = 0.0;
  double takeup_damper_work_ = 0.0;
};

}  // namespace catena::dynamics
