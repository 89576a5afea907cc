// The start of a chain loop over any number of sprockets (docs/models/dynamics.md, "Command"): the
// belt path round the wheels' pitch circles (the convex hull of the circles: arcs on the wheels,
// outer common tangents between them, counter-clockwise; or, with wheels on the back of the chain,
// a serpentine path through the wheels in their given order, crossed tangents between a wheel
// inside the loop and one outside it) and N nodes placed along it at one spacing so that the loop
// closes, each wheel turned so that its seats sit under its wrapped rollers.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "catena/dynamics/chain.hpp"

namespace catena::dynamics {

/// A pitch circle: centre and radius [m]; `back`: the wheel is on the back of the chain (outside
/// the loop, the chain wrapping it clockwise while the loop runs counter-clockwise).
struct Circle {
  double x = 0.0, y = 0.0, radius = 0.0;
  bool back = false;
};

/// One piece of the belt path: an arc on wheel `wheel` from the angle `from` to `to` of the chain's
/// point about the wheel's centre (counter-clockwise, to > from, on a wheel inside the loop;
/// clockwise, to < from, on a wheel on its back), or a straight span from (x0, y0) to (x1, y1).
struct PathPiece {
  bool arc = false;
  std::size_t wheel = 0;        ///< arc: the wheel; span: the wheel it leaves
  std::size_t next = 0;         ///< span: the wheel it arrives on
  double from = 0.0, to = 0.0;  ///< arc: [rad] the chain's angles about the centre
  double sense = 1.0;           ///< arc: +1 wrapped counter-clockwise, −1 on the back (clockwise)
  /// a span laid sagging (the start with slack, `sag_span`): not straight but a circular arc from
  /// (x0, y0) to (x1, y1) about (cx, cy) of `radius`, from the angle `from` (`sense` +1); still a
  /// span (arc false)
  bool sag = false;
  /// a sag beyond a half circle (`sag_span`): not a circular arc but the catenary of its length
  /// hanging down (−y) from (x0, y0) to (x1, y1), x1 > x0: y = y0 + a (cosh((x − x0 − u)/a) −
  /// cosh(u/a)), `hang_a` = a [m], `hang_u` = u [m] (its lowest point's x from x0); `sag` true too
  bool catenary = false;
  double hang_a = 0.0, hang_u = 0.0;
  double cx = 0.0, cy = 0.0;  ///< arc: [m] the wheel's centre
  double radius = 0.0;        ///< arc: [m] its pitch radius
  double x0 = 0.0, y0 = 0.0;  ///< [m] start point
  double x1 = 0.0, y1 = 0.0;  ///< [m] end point
  double length = 0.0;        ///< [m]
  double start = 0.0;         ///< [m] arc length along the path at its start
};

/// The belt path: pieces in order counter-clockwise, starting with the arc on wheel `first` (the
/// point where the chain arrives on it), alternating arc, span, arc, span...
struct BeltPath {
  std::vector<PathPiece> pieces;
  std::vector<std::size_t> order;  ///< the wheels in the order the chain meets them
  double length = 0.0;             ///< [m] the path's length
  /// wheels the hull does not wrap exactly once (inside the hull, touching it at a point, or met
  /// twice): empty when the path is usable
  std::vector<std::size_t> unwrapped;
  /// a serpentine path's faults (wheel: the one named, or the count of circles for the path as a
  /// whole; why: what is wrong); empty when the path is usable
  struct Fault {
    std::size_t wheel = 0;
    std::string why;
  };
  std::vector<Fault> faults;
};

/// Whether the segments p0p1 and q0q1 cross (a proper crossing or a touch). Two segments on one
/// line (every end within 1e-12 of the longer one's length of the other's line, where the side
/// tests' signs are rounding) cross only if they overlap along it.
bool segments_cross(double px0, double py0, double px1, double py1, double qx0, double qy0,
                    double qx1, double qy1);

/// The distance from (x, y) to the segment from (x0, y0) to (x1, y1).
double segment_distance(double x, double y, double x0, double y0, double x1, double y1);

/// The belt path round the circles (at least two; no circle may contain another), starting at the
/// point where it arrives on circle `first`. Without a circle on the back: the hull of the circles
/// (gift wrapping). With one: the serpentine path through the circles in their given order,
/// counter-clockwise round the loop, each wheel on the side `back` says — its faults (a wheel not
/// wrapped, a span crossing another or running through a wheel, the loop not turning once
/// counter-clockwise) in `faults`, with no pieces.
BeltPath belt_path(const std::vector<Circle>& circles, std::size_t first);

/// The point at arc length `s` along the path (taken modulo its length) and the unit tangent.
struct PathPoint {
  double x = 0.0, y = 0.0, tx = 0.0, ty = 0.0;
  std::size_t piece = 0;
};
PathPoint path_point(const BeltPath& path, double s);

/// The path's length in links of chord `spacing`: how many nodes at that chord fit round it (the
/// chord walk's step count where it reaches the start again, with its fraction).
double path_links(const BeltPath& path, double spacing);

/// N nodes on the path, node 0 at its start, each the next point forward at chord `spacing` from
/// the one before, with the spacing solved so that node N − 1 is one spacing from node 0.
struct LoopPlacement {
  std::vector<double> s;  ///< [m] each node's arc length along the path
  double spacing = 0.0;   ///< [m] the chord that closes the loop
  /// per wheel: its angle ψ (seat 0's angle) set so that the seats straddle the wrapped rollers
  /// evenly, the wrapped rollers' count, and the largest distance of one from its seat centre
  std::vector<double> angle;
  std::vector<int> wrapped;
  std::vector<double> seat_offset;  ///< [m]
};
/// `teeth` per wheel (for the seats' spacing 2π/z). Returns an empty placement (no nodes) if the
/// spacing cannot be solved.
LoopPlacement place_loop(const BeltPath& path, const std::vector<Circle>& circles,
                         const std::vector<int>& teeth, int nodes, double pitch);

/// The span of the path a slack chain sags in: the straight piece whose outward normal (the
/// right of the travel) points most nearly down (−y), among the spans between two wheels wrapped
/// on their outside (a span touching a wheel on the back of the chain would sag into it); the
/// path's piece count if it has none.
std::size_t slack_span(const BeltPath& path);

/// What the sagging piece `piece` of `laid` (a path from `sag_span`) runs into, as a name; empty
/// when it is clear. Sampled along the arc (at least 512 samples, at most half a roller radius
/// apart): a wheel other than its two closer than `tip[w]` + `roller`/2 (its teeth), a guide
/// closer than `roller`/2 (its surface: the rollers would start through the rail), another
/// straight span closer than `roller` (two rollers side by side), the points within one `pitch`
/// of the arc's ends left out of the last (they sit on the end wheels by the spans leaving them);
/// another sagging span's arc (but for a pitch at either of its ends) closer than `roller` too;
/// and any of those inside the circular segment the sag sweeps between its chord and its arc (a
/// wheel's centre, 257 points of a guide, 255 of a span or of another sag's arc), where the chain
/// would enclose it. A catenary whose lowest curvature radius a is below `roller`/2 is named as
/// "its own other strand (…)" (its two strands there within a roller's diameter of each other).
std::string sag_obstacle(const BeltPath& laid, std::size_t piece,
                         const std::vector<Circle>& circles, const std::vector<double>& tip,
                         const std::vector<Guide>& guides, double roller, double pitch);

/// The largest extra length [m] span `piece` of the taut `path` can sag by with no obstacle
/// (`sag_obstacle`): up to the half circle's (π/2 − 1) c (c the span's length) as a circular arc
/// (`sag_span`), beyond it, where the span hangs, as the lay a start lays there (`tangent_span`,
/// else, where that is refused, the catenary between the tangent points; where the tangent lay
/// keeps less than a pitch of either wrap, both, a start there may find no roller on the wheel
/// and lay the other), up to the longest
/// catenary's kCatenaryMostExtra c; less where an obstacle is met, found by bisection to 1e-6 of c
/// (taking the clear extras as an interval from 0). 0 if the span cannot sag at all.
double sag_limit(const BeltPath& path, std::size_t piece, const std::vector<Circle>& circles,
                 const std::vector<double>& tip, const std::vector<Guide>& guides, double roller,
                 double pitch);

/// The largest total extra length [m] the spans `pieces` of the taut `path` can share in
/// proportion to their lengths (`sag_spans`) with no obstacle (`sag_obstacle`) for any of them,
/// the other sagging spans included: `sag_limit` for one span; for more, by bisection on the total
/// to 1e-6 of the spans' length, as `sag_limit` with every span laid and checked together: up to
/// (π/2 − 1) of it (every share a half circle) the arcs, beyond it, where the spans hang, the lay a
/// start lays (`tangent_spans`, else the catenaries between the tangent points; where a wrap of
/// the tangent lay keeps less than a pitch, both), up to kCatenaryMostExtra of it. 0 if none can
/// sag.
double sag_spans_limit(const BeltPath& path, const std::vector<std::size_t>& pieces,
                       const std::vector<Circle>& circles, const std::vector<double>& tip,
                       const std::vector<Guide>& guides, double roller, double pitch);

/// [m] The most path beyond its chord a link of chord `pitch` across a kink turning by `turn` [rad]
/// takes (docs/models/dynamics.md, "The band below the half circle"): with its ends a before and b
/// after the kink, (a + b) cos(φ/2) <= p, equal at a = b = p / (2 cos(φ/2)), p (sec(φ/2) − 1) more
/// than its chord up to φ = 120°, where a = b = p; beyond, the last joint before the kink lies a
/// pitch from it at most (a <= p), and the most is at a = p: −2 p cos φ, up to 2 p as φ → 180°.
double kink_link_extra(double turn, double pitch);

/// [m] How far below the half circle ((π/2 − 1) of the chords) a count of the spans `pieces` may be
/// laid tangent (`tangent_spans`), from their kinks there (docs/models/dynamics.md, "The band below
/// the half circle"): a link across a kink takes at most `kink_link_extra` more path than its
/// chord, so a count's lay between the tangent points closes with an e up to that much per kink
/// above its N p less the path's length. Each span's two kinks are the larger of the half circle's
/// (90°, its arc meeting the chord square) and those of the lay just beyond it (`sag_spans` a hair
/// past the half circle: the catenary's ends, `sag_point`, against the chord): Σ_k of both kinks'
/// `kink_link_extra`, at most 4 p a span.
double sag_spans_band(const BeltPath& path, const std::vector<std::size_t>& pieces, double pitch);

/// The largest extra length up to the half circle ((π/2 − 1) of the chords, a hair inside) with
/// `pieces` laid as circular arcs (`sag_spans`) clear of everything, the other sags included: the
/// most a count laid as arcs may take. Above `sag_spans_limit` only where that limit is cut within
/// the band below the half circle (`sag_spans_band`), where a count may be laid tangent
/// (`tangent_spans`) or as arcs and both are checked. 0 if none can sag.
double sag_spans_arcs_limit(const BeltPath& path, const std::vector<std::size_t>& pieces,
                            const std::vector<Circle>& circles, const std::vector<double>& tip,
                            const std::vector<Guide>& guides, double roller, double pitch);

/// The chords of the spans `pieces` summed [m] (what their shares of an extra length are in
/// proportion to); 0 if any is not a span of `path` or none is given.
double span_chords(const BeltPath& path, const std::vector<std::size_t>& pieces);

/// What the lead-in arc `arc` laid at an end of the guide `rail` (`lead_in_arcs`) runs
/// into, as a name; empty when clear (docs/models/dynamics.md, "Lead-ins"). Sampled along the
/// arc's surface (at least 512 samples, at most a quarter roller apart): the chain's path `path`
/// closer than `roller`/2 (a roller's centre on it would be in the arc's contact), a wheel's wrap
/// named "the chain on sprocket[w]", a span "the span sprocket[a] -> sprocket[b]", but for the
/// spans the rail carries (a point within `roller` of its segment or arc: the lead-in bends away
/// from them); where the rail's end itself is nearer a piece than `roller`/2 (a rail that runs to a
/// wheel's tangent point), the arc may come no closer to that piece than the rail's end is; and a
/// guide of `guides` closer than `roller`/2 ("guide[g]"), but for those whose index is in `skip`
/// (the rail and its own arcs). Only the pieces and guides whose bounding box comes within
/// `roller`/2 of the samples' are measured (the same verdict, less work).
std::string lead_in_obstacle(const BeltPath& path, const Guide& rail, const Guide& arc,
                             const std::vector<Guide>& guides, const std::vector<std::size_t>& skip,
                             double roller);

/// How the chain's starting path `path` lies in the contact of the guide `rail` (docs/models/
/// dynamics.md, "Guides against the starting path"): sampled along the path (an eighth of a roller
/// radius apart, at least 512 and at most 1e6 samples), a point in the rail's contact
/// (`guide_contact`: between its ends, 0 < g < 2r) deeper than its surface, g > r (the roller's
/// centre past the surface: the path crosses the rail or lies in it, not on it), is a cut. The
/// deepest cut's piece ("the chain on sprocket[w]", "the span sprocket[a] -> sprocket[b]"; empty
/// when there is none), its depth g and point, where it is along the rail (from `start_angle`
/// round an arc's centre [rad], from (x0, y0) along a straight rail [m]). With a cut also: the
/// longest part of the rail over no cut, and over no point in its contact at all (the same
/// measure, a sample's reach inside the samples; NaN when none), and the least moves of the
/// rail's surface away from its rollers' side (a straight rail along −n, an arc's radius smaller
/// outside, larger inside) that leave no cut, within a roller's diameter, and that leave no point
/// in its contact (the surface just touching the rollers, g ≤ 0), within kRailCutReach roller
/// radii (NaN when none does). A move lowers every sample's gap by itself and keeps the rail's
/// ends, so the least is exact from the samples' gaps (each widened by their spacing, for the
/// path between them): one pass over the samples.
struct RailCut {
  std::string piece;
  double depth = 0.0;       ///< [m]
  double x = 0.0, y = 0.0;  ///< [m]
  double along = 0.0;
  double clear_from = NAN, clear_to = NAN;
  double touch_from = NAN, touch_to = NAN;
  double shift = NAN;     ///< [m] the least move that leaves no cut
  double touching = NAN;  ///< [m] the least move that leaves no point in the contact
};
RailCut rail_cut(const BeltPath& path, const Guide& rail);
/// [roller radii] the largest move rail_cut names (to touching).
inline constexpr double kRailCutReach = 4.0;
/// The samples rail_cut visits for `rail` (those of the pieces whose box meets the rail's, over
/// its moves): the work of one check.
double rail_cut_work(const BeltPath& path, const Guide& rail);

/// A rail's end with no guide laid on from it (a lead-in's arc, a hand-laid arc or rail whose end
/// lies within the contact's ramp ε of it; a full ring's own other end) is square: a roller
/// crossing it below the rail's surface takes the contact force of its whole depth at once
/// (docs/models/dynamics.md, "Guides against the starting path: the square ends"). For each
/// square end of the rails `rails` (indices into `guides`): how deep the chain's starting path
/// crosses it where the chain runs onto the rail (along the path's direction, counter-clockwise,
/// whichever side the driver is on), its g in [0, square_end_reach) (0: not crossing its
/// contact); the path sampled as rail_cut samples it, as a polyline, against the end's normal
/// from the roller line to the face's reach (r behind the surface, where the contact is off).
/// An end joined tangentially to an arc with the rollers outside whose face reaches less deep
/// (square_end_reach: an arc of radius ρ < r, a lead-in smaller than the roller) is square below
/// that arc's reach only: there the face passes under the arc's centre, ρ behind the joint along
/// −n, where the arc has no contact (its sweep lies on the other side); its g from ρ + r on.
struct SquareEnd {
  std::size_t rail = 0;  ///< index into `rails`
  bool at_start = true;
  double x = 0.0, y = 0.0;       ///< [m] the end of the rail's surface
  double depth = 0.0;            ///< [m] the deepest crossing's g
  double nx = 0.0, ny = 0.0;     ///< the surface's unit normal there (towards its free side)
  double tx = 0.0, ty = 0.0;     ///< the rail's unit direction there, from the end into the rail
  double from = 0.0;             ///< [m] the g its face is square beyond (0; ρ + r under an arc)
  std::size_t under = SIZE_MAX;  ///< the arc it is joined to (index into `guides`); none: bare
};
std::vector<SquareEnd> square_ends(const BeltPath& path, const std::vector<Guide>& guides,
                                   const std::vector<std::size_t>& rails);
/// [m] How deep below the roller line a square end's face reaches into `rail`'s contact: 2r, where
/// the contact is off (guide_contact), but on an arc with the rollers outside at most ρ + r, where
/// the face passes the arc's centre (deeper it lies on the opposite radius, outside the sweep, with
/// no contact: a lead-in smaller than the roller).
double square_end_reach(const Guide& rail);

/// A roller striking a square end in a step (docs/models/dynamics.md, "Guides against the starting
/// path: the square ends", the run's diagnostic): of the square ends `ends` (square_ends' of the
/// rails `rails`, indices into `guides`), the deepest crossing of an end's face, from outside the
/// rail into it, by a node's straight move from (x, y) to (x + h vx, y + h vy) (the step's start
/// and its constant-velocity predictor) more than the rail's contact ramp ε below the roller line
/// (g in (ε, square_end_reach), and past the end's `from`): the end (index into `ends`), the
/// node and that g. None: no such.
struct EndStrike {
  std::size_t end = 0;   ///< index into `ends`
  std::size_t node = 0;  ///< the roller's node
  double depth = 0.0;    ///< [m] its g where it crosses the end's face
};
std::optional<EndStrike> square_end_strike(const std::vector<SquareEnd>& ends,
                                           const std::vector<Guide>& guides,
                                           const std::vector<std::size_t>& rails,
                                           std::span<const double> x, std::span<const double> y,
                                           std::span<const double> vx, std::span<const double> vy,
                                           double h);

/// A lead-in arc's own far end (`lead_in_arcs`, radius R, sweep α, at a rail's end, its centre R
/// behind the end along the end's normal) is square too: a roller crossing its face (the radial
/// line at α) g into the arc's contact lies (R + r) − (R + r − g) cos α below the rail's roller
/// line's tangent at the end (docs/models/dynamics.md, "Lead-ins", the far end). A roller running
/// parallel to that tangent at that depth G meets the arc's roller line within its sweep, and so
/// clears its far end, exactly when (R + r)(1 − cos α) >= G: at a sweep α from the radius
/// G / (1 − cos α) − r on, at a radius R from the sweep acos(1 − G / (R + r)) on (NaN when
/// G > R + r, which a strike within the face's reach R + r does not give).
double lead_in_rail_depth(double radius, double angle, double roller, double g);
double lead_in_clear_radius(double angle, double roller, double depth);
double lead_in_clear_angle(double radius, double roller, double depth);
/// Whether a roller running parallel to the end's tangent can cross that far face g into the
/// arc's contact: G exceeds the clearance (R + r)(1 − cos α) by g cos α, so it can unless the
/// sweep is a quarter turn, where the face runs parallel to the rail (G = R + r for every g) and
/// the clearance's radius and sweep are the lead-in's own; a roller struck there moved across
/// the rail, and the parallel rule names no remedy for it.
bool lead_in_parallel_strike(double radius, double angle, double roller, double g);

/// The distances `lead_in_obstacle` measures for `arc` (its samples times the pieces and guides
/// its prefilter keeps): the work of one check, which `lead_in_limit`'s bisections repeat at most
/// kLeadInPasses times in all (their arcs lie within the given arc's bounding box).
double lead_in_work(const BeltPath& path, const Guide& rail, const Guide& arc,
                    const std::vector<Guide>& guides, const std::vector<std::size_t>& skip,
                    double roller);
inline constexpr double kLeadInPasses = 43.0;  // the check, then two bisections of ≤ 21 steps

/// The largest lead-in radius at `lead`'s sweep, and the largest sweep at its radius, whose arcs
/// (`lead_in_arcs`) are all clear (`lead_in_obstacle`): `lead`'s own values when they are, else
/// by bisection to 1e-6 of them from 0 (0: none clears).
struct LeadInLimit {
  double radius = 0.0;  ///< [m]
  double angle = 0.0;   ///< [rad]
};
LeadInLimit lead_in_limit(const BeltPath& path, const Guide& rail, const LeadIn& lead,
                          const std::vector<Guide>& guides, const std::vector<std::size_t>& skip,
                          double roller);

/// The path with span `piece` laid as a circular arc of its chord plus `extra` (> 0), bulging
/// outward (to the right of the travel), between the same tangent points; the other pieces and the
/// wheels unchanged. Beyond a half circle (extra > (π/2 − 1) c), up to kCatenaryMostExtra c: the
/// catenary of that length through the same points (`catenary`), for a span whose outward side
/// is down (travelling towards +x, so that the catenary, which hangs below its chord, bulges
/// outward). Empty (no pieces) if `piece` is not a span or neither curve is laid.
BeltPath sag_span(const BeltPath& path, std::size_t piece, double extra);

/// The most extra length a sag is laid with, in its chord c: a catenary of 11 c.
inline constexpr double kCatenaryMostExtra = 10.0;

/// The path with span `piece` (between two wheels wrapped counter-clockwise, travelling towards
/// +x) laid as the catenary tangent to both wheels' pitch circles, hanging below them (the free
/// chain leaving a wheel where its slope is the wheel's tangent): each wrap shortened to its
/// tangent point, the path `extra` [m] longer than `path`. The tangent points' slope parameters
/// t0, t1 and the catenary's a from the two tangency conditions and the length condition,
/// bracketed and bisected (docs/models/dynamics.md, "The fold at the far wheel: the tangent
/// lay"). Empty when it cannot be laid: no tangent catenary of that extra within the longest
/// scan, the chain more curved where it leaves a wheel than the wheel, a wrap used up, or the
/// curve cutting into its own wheels.
BeltPath tangent_span(const BeltPath& path, std::size_t piece, double extra);

/// The path with each span of `pieces` laid tangent to its wheels (`tangent_span`) with its share
/// of `extra` in proportion to its chord (as `sag_spans` shares it; one span: the whole extra,
/// exactly), one after another: a wrap between two slack spans is cut at both ends, and refused
/// where the two cuts use it up. Empty where any span's tangent lay is refused.
BeltPath tangent_spans(const BeltPath& path, const std::vector<std::size_t>& pieces, double extra);

/// The catenary through two points a horizontal distance h > 0 and a height v apart, of length
/// `length` (more than the chord): its parameter a [m] (from √(S² − v²) = 2 a sinh(h / 2a), by
/// bisection on h / 2a) and its lowest point's horizontal distance u [m] from the first point
/// (h/2 − a atanh(v/S)). NAN both if not defined (h not positive, length not beyond the chord).
struct Catenary {
  double a = NAN, u = NAN;
};
Catenary catenary_through(double h, double v, double length);

/// The point at arc length `along` [m] of a sagging piece (arc or catenary) and its unit tangent.
PathPoint sag_point(const PathPiece& q, double along);

/// A start with slack: N nodes at chord exactly `pitch` (so the chain is N·pitch long) on the path
/// with its slack span (`slack_span`) sagging by the extra length that closes the loop
/// (`slack_extra`). `laid` gets that path: the span sagging between its tangent points
/// (`sag_spans`) where that closes on circular arcs (up to the half circle), but where it would
/// be a catenary or closes for no e, the slack span tangent to its wheels (`tangent_span`; with
/// more spans every one so, `tangent_spans`) when that closes and is laid (else the lay between
/// the tangent points as it is). Node 0 is at
/// the path's start but where neither closes from there (a node passing a fold of the path): then
/// at the phase over the first link that closes it at the e where the walk's end jumps over the
/// closure, or at the longest catenary where the walk still overshoots. Empty placement if N·pitch
/// does not exceed the path's length, the sag cannot be solved, any link's chord (the closing one
/// too) is off `pitch` by more than 1e-9 of it, or a wheel is left without a roller on it.
LoopPlacement place_slack_loop(const BeltPath& path, const std::vector<Circle>& circles,
                               const std::vector<int>& teeth, int nodes, double pitch,
                               BeltPath& laid);

/// Every span a slack chain may sag in (between two wheels wrapped on their outside), in the
/// path's order.
std::vector<std::size_t> sagging_spans(const BeltPath& path);

/// The path with each span of `pieces` sagging (`sag_span`) by its share of `extra`, in
/// proportion to its length. Empty if any cannot (not a span, beyond a half circle).
BeltPath sag_spans(const BeltPath& path, const std::vector<std::size_t>& pieces, double extra);

/// The extra length e (the sagging arcs' length beyond their chords, shared by `pieces` as
/// `sag_spans` shares it) at which N nodes walked at chord exactly `pitch` close the loop: by
/// secant on the walk's miss, and where the secant does not converge (the miss, continuous and
/// falling in e, bends sharply where a node passes a sag's kink at a wheel, and the secant can
/// cycle) by bisection between N·pitch less the path's length (where the miss is not negative: a
/// chord spans at least its own length of the path) and every span's half circle (beyond it, for
/// spans that hang, the longest catenary, kCatenaryMostExtra chords). Where the bisection closes
/// on a jump of the miss over 0 (a node passing a fold of the path), that e when node 0's phase
/// over the first link closes the walk there (`place_slack_loop`); where the walk from the
/// path's start still overshoots at the longest catenary, that catenary's e when a phase closes
/// it there. INFINITY when the walk overshoots at the most e the spans take, at the longest
/// catenary at every phase of node 0 the phase search tries (the count needs more), NAN when no e
/// is found (or N·pitch does not exceed the path's length). Where that lay is a catenary or closes
/// for no e, the tangent lay's e (`tangent_spans`: the path's extra over the taut path)
/// when that closes, bisected up to the longest catenary (given also where `place_slack_loop` lays
/// the other).
double slack_extra(const BeltPath& path, const std::vector<std::size_t>& pieces, int nodes,
                   double pitch);

/// A start with slack shared by the spans `pieces` in proportion to their lengths
/// (`sag_spans`), solved as `place_slack_loop` solves one span's.
LoopPlacement place_slack_loop(const BeltPath& path, const std::vector<Circle>& circles,
                               const std::vector<int>& teeth, int nodes, double pitch,
                               BeltPath& laid, const std::vector<std::size_t>& pieces);

/// The extra length e of the lay `place_slack_loop` lays for N = `nodes` (with `pieces`): the
/// tangent lay's, or where that is not laid the lay between the tangent points' it lays instead;
/// `slack_extra` where it lays none.
double laid_slack_extra(const BeltPath& path, const std::vector<Circle>& circles,
                        const std::vector<int>& teeth, int nodes, double pitch,
                        const std::vector<std::size_t>& pieces);

/// How many counts the search for the most links that start tries one by one before it bisects
/// (`longest_count`'s and `links_that_start_phrase`'s default, one number for the search and the
/// message that tells it).
inline constexpr int kLongestCountScan = 100;

/// The most links that start with slack among the counts lo + 1 .. hi (`starts` says whether a
/// count does): tried downwards from hi, the first that starts taken (`scanned`: none above it
/// starts). The counts that start need not be an interval, so they are tried one by one; after
/// `scan` counts without a start the rest is bisected as if they were (bounded work): the count
/// found then starts but a larger one may (`scanned` false). `links` 0 when none is found.
struct LongestCount {
  int links = 0;
  bool scanned = false;
};
LongestCount longest_count(int lo, int hi, const std::function<bool(int)>& starts,
                           int scan = kLongestCountScan);

/// The end of a refusal of a chain too long for its slack: the most links that start
/// (`longest`, found among the counts below the limit, `scan` of them tried one by one), and,
/// when the count given (`given`) is not above it, that no start was found at exactly that count.
std::string links_that_start_phrase(const LongestCount& longest, int given,
                                    int scan = kLongestCountScan);

/// The loop's start state from a placement: nodes at the placement, moving along the path at
/// `chain_speed`; every wheel at its placement angle, turning at chain_speed / its radius.
State loop_state(const BeltPath& path, const std::vector<Circle>& circles,
                 const LoopPlacement& placement, double chain_speed);

}  // namespace catena::dynamics
