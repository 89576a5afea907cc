// Run-on of a round-link chain onto a pocket wheel: free, and forced through a straight guide.
//
// Source: 003 (Dolipiński et al.), eqs. (1)–(43), corrected as listed in
// docs/models/pocketwheel.md. Frame: the wheel axis O is the origin, the strand runs along +x
// towards the wheel on the upper side; a joint's angle θ is measured from the upward vertical,
// positive on the upstream (guide) side. The wheel turns by φ = ωτ (eq. 5); a seated joint's angle
// falls as θ = θ_c − φ. The guide is the line y = H ending at x = −l.
//
// Over one tooth period 2π/z the strand is carried by the last seated joint (the "crank"); a
// period has two or three such phases separated by seating events, at which the next joint of
// the strand lands on the pitch circle.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/pocketwheel/geometry.hpp"

namespace catena::pocketwheel {

enum class GuideKind {
  kNone,        ///< free run-on, eqs. (1)–(13)
  kChordal,     ///< straight guide at H = R cos(δ1/2), eqs. (14)–(25)
  kTangential,  ///< straight guide at H = R, eqs. (26)–(43)
  kHeight,      ///< straight guide at any H in [R cos(δ1/2), R]
};

/// How the free span between the last seated joint and the guide is modelled.
enum class SpanModel {
  /// The paper's: a rigid bar from the last seated joint to the material point of the chain
  /// that lay at the guide end at the start of the period; that point slides along the guide
  /// line (a slider-crank). After each seating the bar is the shorter span from the new joint.
  kSlider,
  /// Beyond the paper: the chain bends over the guide's edge E = (−l, H); the free span is the
  /// straight line from the last seated joint to E, and the chain in the guide moves by the
  /// change of that span's length.
  kPivot,
};

const char* to_string(GuideKind kind);
const char* to_string(SpanModel model);

/// The guide (constant model). Ignored fields may be left at their defaults.
struct Guide {
  GuideKind kind = GuideKind::kNone;
  double height = 0.0;        ///< [m] H, used only with kHeight
  double end_distance = 0.0;  ///< [m] l: abscissa of the guide end from the wheel axis (forced)
  SpanModel span_model = SpanModel::kSlider;
};

/// Problems with the guide alone and together with the wheel (H range, l outside the wheel).
std::vector<Issue> validate(const PocketWheel& wheel, const Guide& guide);

/// One phase of the period: the strand is carried by one seated joint, the crank.
struct Phase {
  double begin = 0.0;         ///< [rad] φ at which the phase starts
  double end = 0.0;           ///< [rad] φ at which it ends (a seating, or the period's end)
  double crank_angle0 = 0.0;  ///< [rad] θ_c: the crank joint is at θ = θ_c − φ
  double seating_link = 0.0;  ///< [m] length (t ± d) of the link that seats at the phase's end
  double span = 0.0;          ///< [m] slider: bar length from the crank to the guided point
  double travel0 = 0.0;       ///< [m] offset of x: free, x at the phase start; pivot, the links
                              ///< seated since φ = 0 less the span at φ = 0; slider, unused
};

/// The period resolved into phases: everything the pointwise closed forms need.
struct RunOnPlan {
  WheelGeometry geometry;
  Guide guide;
  double guide_height = 0.0;           ///< [m] H (0 for free run-on)
  std::vector<Phase> phases;           ///< cover [0, 2π/z] in order
  std::vector<double> seating_angles;  ///< [rad] seating events in [0, 2π/z)
  double first_link = 0.0;             ///< [m] length of the first link to seat after φ = 0
  double span0 = 0.0;                  ///< [m] slider bar length / pivot span at φ = 0
};

/// Kinematics at one φ, as derivatives with respect to φ (multiply by ω, ω² for time).
struct PointKinematics {
  double x = 0.0;    ///< [m] travel of the strand in the guide towards the wheel since φ = 0
  double dx = 0.0;   ///< [m/rad] dx/dφ
  double d2x = 0.0;  ///< [m/rad²] d²x/dφ²
  double y = 0.0;    ///< [m] free run-on: height of the strand (of the crank joint) above O
  double dy = 0.0;   ///< [m/rad] dy/dφ (free run-on)
  double d2y = 0.0;  ///< [m/rad²] d²y/dφ² (free run-on)
};

/// Resolves the period with the closed forms. Throws InputError for invalid or infeasible
/// input (the message states the limit, e.g. the smallest feasible guide end distance).
RunOnPlan plan_run_on(const PocketWheel& wheel, const Guide& guide);

/// Closed-form kinematics of phase `index` at φ (valid also slightly outside the phase: the
/// analytic continuation, used for one-sided limits).
PointKinematics evaluate_phase(const RunOnPlan& plan, std::size_t index, double phi);

/// Closed-form kinematics at φ ∈ [0, 2π/z]. At a seating event the right-hand limit; at
/// φ = 2π/z the start of the next period (x continues: x = 2t).
PointKinematics evaluate(const RunOnPlan& plan, double phi);

/// Sampling of one period.
struct Sampling {
  double omega = 0.0;                 ///< [rad/s] angular speed ω of the wheel
  int points = 721;                   ///< samples over [0, 2π/z], both ends included (≥ 2)
  std::optional<double> strand_mass;  ///< [kg] mass moving with the strand, for −M·a_x
};

std::vector<Issue> validate(const Sampling& sampling);

struct Extremes {
  double vx_min = 0.0;  ///< [m/s]
  double vx_max = 0.0;  ///< [m/s]
  double ax_min = 0.0;  ///< [m/s²]
  double ax_max = 0.0;  ///< [m/s²]
};

struct RunOnSeries {
  std::vector<double> phi;             ///< [rad]
  std::vector<double> time;            ///< [s] φ/ω
  std::vector<double> x;               ///< [m]
  std::vector<double> vx;              ///< [m/s]
  std::vector<double> ax;              ///< [m/s²]
  std::vector<double> vy;              ///< [m/s] free run-on only, else empty
  std::vector<double> ay;              ///< [m/s²] free run-on only, else empty
  std::vector<double> inertial_force;  ///< [N] −M·a_x, only with a strand mass
};

struct RunOnResult {
  RunOnPlan plan;
  double period = 0.0;  ///< [s] time of one tooth period 2π/(zω)
  Extremes extremes;    ///< over the closed period, both one-sided limits at every event
  RunOnSeries series;
  std::vector<Diagnostic> diagnostics;
};

/// Samples a plan with an evaluator of PointKinematics (closed form or numerical).
template <class Evaluate>
RunOnResult sample_run_on(const RunOnPlan& plan, const Sampling& sampling, Evaluate&& evaluate_at);

/// The closed-form analysis: plan, samples, extremes.
RunOnResult run_on(const PocketWheel& wheel, const Guide& guide, const Sampling& sampling);

/// Extremes of v_x and a_x over the period (grid per phase, refined by Brent's method).
Extremes extremes(const RunOnPlan& plan, double omega);

}  // namespace catena::pocketwheel

#include "catena/pocketwheel/run_on_sample.ipp"
