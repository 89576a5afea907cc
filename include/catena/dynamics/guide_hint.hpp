// The guides' node hint (docs/models/dynamics.md, "Guides: O(N) a step").
//
// Per guide, the nodes that may be inside its bounding box (guide_bounds): the nodes whose
// positions, when the hint was last built, lay within the box widened by a margin. While no node
// has moved more than the margin (in x or in y) from where it was then, every node inside a
// guide's box is on that guide's list, so the integrator tries only the listed nodes against each
// guide instead of every node against every guide. A node that moves further triggers a rebuild,
// which bins the nodes on a uniform grid laid over the guides' widened boxes: O(N + G + pairs).
// Checking the positions is O(N) and comparing the guides' boxes with the ones the hint was built
// for is O(G), so a step costs O(N + G + listed pairs) instead of O(N·G).
//
// Each guide's list is in increasing node order, so that a loop over a guide's listed nodes visits
// the pairs in the same order as a loop over all nodes: results are bit-identical.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "catena/dynamics/chain.hpp"

namespace catena::dynamics {

class GuideHint {
 public:
  /// `margin` [m] > 0: how far a node may move before the lists are rebuilt (larger: fewer
  /// rebuilds, longer lists).
  explicit GuideHint(double margin = 0.0) : margin_(margin >= 0.0 ? margin : 0.0) {}

  /// Makes the lists hold every node i with guide_touch_possible(guide_bounds(guides[g]), x[i],
  /// y[i]) for every g (and possibly more), rebuilding them when a node has moved more than the
  /// margin since the last build, when the guides' boxes changed, or when the node count changed.
  /// Returns true when it rebuilt. x and y have one entry per node.
  bool update(std::span<const Guide> guides, std::span<const double> x, std::span<const double> y);
  /// The same for any boxes (the wheels' reach in energy()): box g in place of
  /// guide_bounds(guides[g]); a box with a non-finite bound lists every node.
  bool update(std::span<const GuideBounds> boxes, std::span<const double> x,
              std::span<const double> y);

  /// Guide g's listed nodes, increasing. Valid after update.
  std::span<const std::uint32_t> nodes(std::size_t g) const {
    return {nodes_.data() + start_[g], nodes_.data() + start_[g + 1]};
  }
  /// Into `out`, increasing: the guides whose widened box may hold the point (x, y), from the grid
  /// of the last update (every g with guide_touch_possible(bounds()[g], x, y) is there, and
  /// possibly more). O(guides listed in the point's cell). Valid after update; the point may be
  /// anywhere (a non-finite one gets the guides without a finite box only).
  void guides_near(double x, double y, std::vector<std::uint32_t>& out) const;
  /// The guides' boxes as of the last update (guide_bounds of each).
  std::span<const GuideBounds> bounds() const { return bounds_; }
  double margin() const { return margin_; }
  std::size_t rebuilds() const { return rebuilds_; }

 private:
  template <class BoxOf>
  bool update_from(std::size_t count, BoxOf box_of, std::span<const double> x,
                   std::span<const double> y);
  void rebuild_grid();
  std::size_t cell_index(double v, double origin, std::size_t side) const;
  void rebuild_lists(std::span<const double> x, std::span<const double> y);

  double margin_;
  std::vector<GuideBounds> bounds_;             // per guide: guide_bounds
  std::vector<GuideBounds> wide_;               // per guide: the box widened by the list's reach
  std::vector<std::uint8_t> everywhere_;        // per guide: a non-finite box, every node listed
  std::vector<std::uint32_t> everywhere_list_;  // those guides, increasing
  // the grid over the finite widened boxes: cell (cx, cy) lists the guides whose widened box
  // overlaps it, in cell_guides_[cell_start_[c] .. cell_start_[c + 1])
  double grid_x0_ = 0.0, grid_y0_ = 0.0, cell_ = 1.0;
  std::size_t grid_nx_ = 0, grid_ny_ = 0;
  std::vector<std::size_t> cell_start_;
  std::vector<std::uint32_t> cell_guides_;
  std::vector<double> hint_x_, hint_y_;  // per node: where it was at the last build
  std::vector<std::size_t> start_;       // per guide + 1: its list in nodes_
  std::vector<std::uint32_t> nodes_;
  std::vector<std::size_t> fill_;  // scratch: per guide, the next free slot
  bool built_ = false;
  std::size_t rebuilds_ = 0;
};

/// What energy() keeps between calls when given it: the wheels' and the guides' node hints and the
/// wheels' boxes. A run that evaluates its energy at every sample (the guard on energy from
/// nothing, analysis.cpp) then rebuilds only the hints' node lists, not their grids, and allocates
/// nothing after the first call; the result is the same as energy(model, state)'s bit for bit (the
/// lists are the same nodes in node order).
struct EnergyScratch {
  GuideHint wheels{0.0};
  GuideHint guides{0.0};
  std::vector<GuideBounds> boxes;
};

Energy energy(const Model& model, const State& state, EnergyScratch& scratch);

/// Where the lift of a node by one guide disagrees with another (docs/models/dynamics.md, "Guides
/// against the starting path: several rails"): the node `node`, moved last by guide `first`, either
/// then pulled through a later guide `second` from behind its surface (it lay `depth` into the
/// second's contact, more than a roller radius, when the second lifted it) or left `depth` inside
/// an earlier guide `second`'s contact (deeper than its ramp ε) by the moves after it. `through`
/// when `depth` is more than the second's roller radius (behind its surface, whatever the order).
struct LiftConflict {
  std::size_t node = 0, first = 0, second = 0;
  bool through = false;
  double depth = 0.0;  ///< [m] the node's gap g in the second guide
};

/// Moves every node that starts inside a guide out along the rail's normal to touch it: for each
/// guide in order, each node it is active on (guide_contact at rest) moves by penetration · n. The
/// result is bit-identical to that loop over every guide and every node, in O(N + G + pairs): a
/// node's moves depend only on its own position and the guides in order, so each node is taken
/// through the guides near it (GuideHint's grid, asked again after each move). x and y have one
/// entry per node. Returns the nodes whose moves disagree (LiftConflict), in node order: a node
/// one guide moved and a later one then pulled through its surface, or one left inside an earlier
/// guide's contact; none where the lift leaves every node out of every contact but the last
/// mover's without crossing a surface.
std::vector<LiftConflict> lift_onto_guides(std::span<const Guide> guides, std::span<double> x,
                                           std::span<double> y);

}  // namespace catena::dynamics
