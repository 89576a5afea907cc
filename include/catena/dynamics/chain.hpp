// A planar chain of N links as a constant Model and a mutable State (docs/models/dynamics.md).
//
// The chain is N nodes (the roller or pin centres) joined by axial spring–dampers of rest length
// p, the pitch: link j joins node j to node j + 1, and in a closed loop link N − 1 joins node
// N − 1 back to node 0. Each node carries the mass of one link. Pinned nodes stay where the state
// puts them. State is a structure of arrays (x, y, vx, vy).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "catena/core/error.hpp"

namespace catena::dynamics {

struct Model {
  bool closed = false;               ///< closed loop (link N − 1 joins node N − 1 to node 0)
  double pitch = 0.0;                ///< [m] p, the unstretched length of one link
  double axial_stiffness = 0.0;      ///< [N/m] k of one link: tension = k (l − p) + c l̇
  double axial_damping = 0.0;        ///< [N·s/m] c of one link
  double drag = 0.0;                 ///< [1/s] α: a force −α m v on each node (to settle)
  double gravity_x = 0.0;            ///< [m/s²] g, x component
  double gravity_y = 0.0;            ///< [m/s²] g, y component
  std::vector<double> mass;          ///< [kg] per node; its size is N
  std::vector<std::uint8_t> pinned;  ///< per node, 1 = held fixed; empty = none pinned

  std::size_t nodes() const { return mass.size(); }
  /// Links: N in a closed loop, N − 1 in an open chain.
  std::size_t links() const { return closed ? mass.size() : mass.size() - 1; }
  bool is_pinned(std::size_t i) const { return !pinned.empty() && pinned[i] != 0; }
};

/// Every problem with the model, fields "nodes", "pitch", "axial_stiffness", "axial_damping",
/// "drag", "gravity", "mass", "pinned".
std::vector<Issue> validate(const Model& model);

/// N nodes of equal mass; an open chain gets its two end nodes pinned when `pin_ends`.
Model uniform_chain(std::size_t nodes, bool closed, double pitch, double node_mass,
                    double axial_stiffness, double axial_damping, bool pin_ends);

struct State {
  double time = 0.0;           ///< [s]
  std::vector<double> x, y;    ///< [m] node positions
  std::vector<double> vx, vy;  ///< [m/s] node velocities
  explicit State(std::size_t nodes = 0) : x(nodes), y(nodes), vx(nodes), vy(nodes) {}
  std::size_t nodes() const { return x.size(); }
};

/// Every problem with a state for this model (sizes, finite values, pinned nodes at rest,
/// no link of zero length), fields "state.x", "state.v", "state.link".
std::vector<Issue> validate(const Model& model, const State& state);

struct Energy {
  double kinetic = 0.0;    ///< [J] Σ ½ m v²
  double elastic = 0.0;    ///< [J] Σ ½ k (l − p)²
  double potential = 0.0;  ///< [J] −Σ m g·x
  double total() const { return kinetic + elastic + potential; }
};

Energy energy(const Model& model, const State& state);

/// [N] the tension of each link, k (l − p) + c l̇ (size links()).
void link_tensions(const Model& model, const State& state, std::span<double> tension);

}  // namespace catena::dynamics
