#include "catena/dynamics/guide_hint.hpp"

#include <algorithm>
#include <cmath>

namespace catena::dynamics {

namespace {
constexpr std::size_t kGridSide = 64;  // at most 64 × 64 cells

bool same_box(const GuideBounds& a, const GuideBounds& b) {
  return a.x_lo == b.x_lo && a.x_hi == b.x_hi && a.y_lo == b.y_lo && a.y_hi == b.y_hi;
}

bool inside(const GuideBounds& b, double x, double y) {
  return x >= b.x_lo && x <= b.x_hi && y >= b.y_lo && y <= b.y_hi;
}
}  // namespace

std::size_t GuideHint::cell_index(double v, double origin, std::size_t side) const {
  // monotone in v: the subtraction, the division by cell_ > 0, the floor and the clamps all are
  const double c = std::floor((v - origin) / cell_);
  if (!(c > 0.0)) return 0;  // below the grid, or NaN
  return std::min(side - 1, static_cast<std::size_t>(std::min(c, 1e9)));
}

bool GuideHint::update(std::span<const Guide> guides, std::span<const double> x,
                       std::span<const double> y) {
  return update_from(
      guides.size(), [&](std::size_t g) { return guide_bounds(guides[g]); }, x, y);
}

bool GuideHint::update(std::span<const GuideBounds> boxes, std::span<const double> x,
                       std::span<const double> y) {
  return update_from(
      boxes.size(), [&](std::size_t g) { return boxes[g]; }, x, y);
}

template <class BoxOf>
bool GuideHint::update_from(std::size_t count, BoxOf box_of, std::span<const double> x,
                            std::span<const double> y) {
  bool grid_stale = bounds_.size() != count;
  if (grid_stale) bounds_.resize(count);
  for (std::size_t g = 0; g < count; ++g) {
    const GuideBounds b = box_of(g);
    if (!same_box(b, bounds_[g])) {
      bounds_[g] = b;
      grid_stale = true;
    }
  }
  if (grid_stale) {
    rebuild_grid();
    built_ = false;
  }
  bool stale = !built_ || hint_x_.size() != x.size();
  // NaN-safe: a node whose move is not known to be within the margin forces the rebuild
  for (std::size_t i = 0; !stale && i < x.size(); ++i) {
    stale = !(std::abs(x[i] - hint_x_[i]) <= margin_) || !(std::abs(y[i] - hint_y_[i]) <= margin_);
  }
  if (!stale) return false;
  rebuild_lists(x, y);
  return true;
}

void GuideHint::rebuild_grid() {
  const std::size_t count = bounds_.size();
  // The lists reach 1.25 margins past each box: a node within the margin of where it was at the
  // build (as computed, rounded) is then inside the widened box whenever it is inside the box.
  const double reach = margin_ >= 0.0 ? 1.25 * margin_ : 0.0;
  wide_.resize(count);
  everywhere_.assign(count, 0);
  everywhere_list_.clear();
  double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
  for (std::size_t g = 0; g < count; ++g) {
    const GuideBounds& b = bounds_[g];
    const GuideBounds w{b.x_lo - reach, b.x_hi + reach, b.y_lo - reach, b.y_hi + reach};
    wide_[g] = w;
    if (!std::isfinite(w.x_lo) || !std::isfinite(w.x_hi) || !std::isfinite(w.y_lo) ||
        !std::isfinite(w.y_hi)) {
      everywhere_[g] = 1;  // no finite box (a non-finite guide): every node is listed
      everywhere_list_.push_back(static_cast<std::uint32_t>(g));
      continue;
    }
    lo_x = std::min(lo_x, w.x_lo);
    hi_x = std::max(hi_x, w.x_hi);
    lo_y = std::min(lo_y, w.y_lo);
    hi_y = std::max(hi_y, w.y_hi);
  }
  cell_start_.assign(1, 0);
  cell_guides_.clear();
  grid_nx_ = grid_ny_ = 0;
  if (!(lo_x <= hi_x)) return;  // no finite box
  const double extent = std::max(hi_x - lo_x, hi_y - lo_y);
  cell_ = extent > 0.0 && std::isfinite(extent) ? extent / static_cast<double>(kGridSide) : 1.0;
  grid_x0_ = lo_x;
  grid_y0_ = lo_y;
  const auto side = [&](double span) {
    const double cells = std::floor(span / cell_) + 1.0;
    return cells >= static_cast<double>(kGridSide) || !(cells >= 1.0)
               ? kGridSide
               : static_cast<std::size_t>(cells);
  };
  grid_nx_ = side(hi_x - lo_x);
  grid_ny_ = side(hi_y - lo_y);
  // A cell index is monotone in the coordinate (the subtraction, the division by cell_ > 0, the
  // floor and the clamp all are), so a point inside a widened box falls in one of the cells
  // between those of the box's corners.
  const auto cx = [&](double v) { return cell_index(v, grid_x0_, grid_nx_); };
  const auto cy = [&](double v) { return cell_index(v, grid_y0_, grid_ny_); };
  const std::size_t cells = grid_nx_ * grid_ny_;
  cell_start_.assign(cells + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t g = 0; g < count; ++g) {
      if (everywhere_[g] != 0) continue;
      const GuideBounds& w = wide_[g];
      for (std::size_t j = cy(w.y_lo); j <= cy(w.y_hi); ++j) {
        for (std::size_t i = cx(w.x_lo); i <= cx(w.x_hi); ++i) {
          const std::size_t c = j * grid_nx_ + i;
          if (pass == 0) {
            ++cell_start_[c + 1];
          } else {
            cell_guides_[fill_[c]++] = static_cast<std::uint32_t>(g);
          }
        }
      }
    }
    if (pass == 0) {
      for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
      cell_guides_.resize(cell_start_[cells]);
      fill_.assign(cell_start_.begin(), cell_start_.end() - 1);
    }
  }
}

void GuideHint::rebuild_lists(std::span<const double> x, std::span<const double> y) {
  const std::size_t count = bounds_.size();
  const std::size_t n = x.size();
  hint_x_.assign(x.begin(), x.end());
  hint_y_.assign(y.begin(), y.end());
  start_.assign(count + 1, 0);
  const auto cell_of = [&](double px, double py) {
    return cell_index(py, grid_y0_, grid_ny_) * grid_nx_ + cell_index(px, grid_x0_, grid_nx_);
  };
  const bool grid = grid_nx_ > 0;
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t i = 0; grid && i < n; ++i) {
      // a non-finite position is inside no finite box (and cannot be binned)
      if (!std::isfinite(x[i]) || !std::isfinite(y[i])) continue;
      const std::size_t c = cell_of(x[i], y[i]);
      for (std::size_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
        const std::uint32_t g = cell_guides_[k];
        if (!inside(wide_[g], x[i], y[i])) continue;
        if (pass == 0) {
          ++start_[g + 1];
        } else {
          nodes_[fill_[g]++] = static_cast<std::uint32_t>(i);
        }
      }
    }
    if (pass == 0) {
      for (std::size_t g = 0; g < count; ++g) {
        if (everywhere_[g] != 0) start_[g + 1] = n;
        start_[g + 1] += start_[g];
      }
      nodes_.resize(start_[count]);
      fill_.assign(start_.begin(), start_.end() - 1);
    }
  }
  for (std::size_t g = 0; g < count; ++g) {
    if (everywhere_[g] == 0) continue;
    for (std::size_t i = 0; i < n; ++i) nodes_[start_[g] + i] = static_cast<std::uint32_t>(i);
  }
  built_ = true;
  ++rebuilds_;
}

void GuideHint::guides_near(double x, double y, std::vector<std::uint32_t>& out) const {
  out.clear();
  // a non-finite point is inside no finite box (and cannot be binned)
  if (grid_nx_ > 0 && std::isfinite(x) && std::isfinite(y)) {
    const std::size_t c =
        cell_index(y, grid_y0_, grid_ny_) * grid_nx_ + cell_index(x, grid_x0_, grid_nx_);
    out.assign(cell_guides_.begin() + static_cast<std::ptrdiff_t>(cell_start_[c]),
               cell_guides_.begin() + static_cast<std::ptrdiff_t>(cell_start_[c + 1]));
  }
  if (everywhere_list_.empty()) return;
  const std::size_t mid = out.size();
  out.insert(out.end(), everywhere_list_.begin(), everywhere_list_.end());
  // both parts increasing (the cell's guides were binned in guide order), and disjoint
  std::inplace_merge(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(mid), out.end());
}

std::vector<LiftConflict> lift_onto_guides(std::span<const Guide> guides, std::span<double> x,
                                           std::span<double> y) {
  std::vector<LiftConflict> conflicts;
  if (guides.empty()) return conflicts;
  GuideHint hint(0.0);  // the boxes themselves: nothing moves while the grid is in use
  hint.update(guides, x, y);
  std::vector<std::uint32_t> near;
  near.reserve(guides.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    // the guides before `next` are done with this node; of the others, the first active one at
    // the node's current position moves it (the guides between were not active there, as in the
    // loop over every guide), and the guides near its new position are asked again
    std::size_t next = 0;
    bool lifted = false;
    std::size_t last = 0;  // the guide that moved it last (when lifted)
    for (bool moved = true; moved;) {
      moved = false;
      hint.guides_near(x[i], y[i], near);
      for (const std::uint32_t g : near) {
        if (g < next) continue;
        const GuideContact c = guide_contact(guides[g], x[i], y[i], 0.0, 0.0);
        if (!c.active) continue;
        // a node another guide moved, now behind this one's surface: pulled through it
        if (lifted && c.penetration > guides[g].roller_radius)
          conflicts.push_back({i, last, g, true, c.penetration});
        x[i] += c.penetration * c.nx;
        y[i] += c.penetration * c.ny;
        next = static_cast<std::size_t>(g) + 1;
        lifted = true;
        last = g;
        moved = true;
        break;
      }
    }
    if (!lifted) continue;
    // an earlier guide the later moves left it inside (beyond the contact's ramp): behind its
    // surface (deeper than a roller radius, pulled through it) or in front of it, by depth
    // whatever the guides' order
    hint.guides_near(x[i], y[i], near);
    for (const std::uint32_t g : near) {
      if (g >= last) break;
      const GuideContact c = guide_contact(guides[g], x[i], y[i], 0.0, 0.0);
      if (c.active && c.penetration > guides[g].contact_smoothing)
        conflicts.push_back({i, last, g, c.penetration > guides[g].roller_radius, c.penetration});
    }
  }
  return conflicts;
}

}  // namespace catena::dynamics
