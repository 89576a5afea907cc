// The chain model and state: validation, energy and link tensions (docs/models/dynamics.md).
#include "catena/dynamics/chain.hpp"

#include <cmath>
#include <string>

namespace catena::dynamics {
namespace {
constexpr std::size_t kMaxNodes = 10'000'000;
}

std::vector<Issue> validate(const Model& model) {
  std::vector<Issue> out;
  const std::size_t n = model.nodes();
  const std::size_t min_nodes = model.closed ? 3 : 2;
  if (n < min_nodes || n > kMaxNodes) {
    out.push_back({"nodes", std::to_string(n),
                   std::string("an integer in [") + std::to_string(min_nodes) + ", " +
                       std::to_string(kMaxNodes) + "] (" +
                       (model.closed ? "closed loop" : "open chain") + ")"});
  }
  check::finite_positive(out, "pitch", model.pitch, "m");
  check::finite_positive(out, "axial_stiffness", model.axial_stiffness, "N/m");
  if (!std::isfinite(model.axial_damping) || model.axial_damping < 0.0) {
    out.push_back({"axial_damping", check::format_si(model.axial_damping, "N*s/m"),
                   "a finite value >= 0 N*s/m"});
  }
  if (!std::isfinite(model.drag) || model.drag < 0.0) {
    out.push_back({"drag", check::format_si(model.drag, "1/s"), "a finite value >= 0 1/s"});
  }
  if (!std::isfinite(model.gravity_x) || !std::isfinite(model.gravity_y)) {
    out.push_back(
        {"gravity",
         check::format_si(model.gravity_x, "") + ", " + check::format_si(model.gravity_y, "m/s^2"),
         "finite components"});
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(model.mass[i]) || model.mass[i] <= 0.0) {
      out.push_back({"mass[" + std::to_string(i) + "]", check::format_si(model.mass[i], "kg"),
                     "a finite value > 0 kg"});
      break;  // one line for a whole bad array is enough to name it
    }
  }
  if (!model.pinned.empty() && model.pinned.size() != n) {
    out.push_back({"pinned", std::to_string(model.pinned.size()) + " entries",
                   "empty or one entry per node (" + std::to_string(n) + ")"});
  }
  return out;
}

Model uniform_chain(std::size_t nodes, bool closed, double pitch, double node_mass,
                    double axial_stiffness, double axial_damping, bool pin_ends) {
  Model m;
  m.closed = closed;
  m.pitch = pitch;
  m.axial_stiffness = axial_stiffness;
  m.axial_damping = axial_damping;
  m.mass.assign(nodes, node_mass);
  if (pin_ends && !closed && nodes >= 2) {
    m.pinned.assign(nodes, 0);
    m.pinned.front() = 1;
    m.pinned.back() = 1;
  }
  return m;
}

std::vector<Issue> validate(const Model& model, const State& state) {
  std::vector<Issue> out;
  const std::size_t n = model.nodes();
  if (state.x.size() != n || state.y.size() != n || state.vx.size() != n || state.vy.size() != n) {
    out.push_back({"state.x", std::to_string(state.x.size()) + " nodes",
                   "x, y, vx, vy of " + std::to_string(n) + " nodes each"});
    return out;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(state.x[i]) || !std::isfinite(state.y[i])) {
      out.push_back({"state.x[" + std::to_string(i) + "]", "not finite", "finite positions"});
      break;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(state.vx[i]) || !std::isfinite(state.vy[i])) {
      out.push_back({"state.v[" + std::to_string(i) + "]", "not finite", "finite velocities"});
      break;
    }
    if (model.is_pinned(i) && (state.vx[i] != 0.0 || state.vy[i] != 0.0)) {
      out.push_back(
          {"state.v[" + std::to_string(i) + "]", "moving", "zero velocity at a pinned node"});
      break;
    }
  }
  for (std::size_t j = 0; j < model.links() && n >= 2; ++j) {
    const std::size_t b = (j + 1) % n;
    if (!(std::hypot(state.x[b] - state.x[j], state.y[b] - state.y[j]) > 0.0)) {
      out.push_back({"state.link[" + std::to_string(j) + "]", "length 0",
                     "nodes of a link at distinct positions"});
      break;
    }
  }
  return out;
}

Energy energy(const Model& model, const State& state) {
  Energy e;
  const std::size_t n = model.nodes();
  for (std::size_t i = 0; i < n; ++i) {
    const double m = model.mass[i];
    e.kinetic += 0.5 * m * (state.vx[i] * state.vx[i] + state.vy[i] * state.vy[i]);
    e.potential -= m * (model.gravity_x * state.x[i] + model.gravity_y * state.y[i]);
  }
  for (std::size_t j = 0; j < model.links(); ++j) {
    const std::size_t b = (j + 1) % n;
    const double stretch =
        std::hypot(state.x[b] - state.x[j], state.y[b] - state.y[j]) - model.pitch;
    e.elastic += 0.5 * model.axial_stiffness * stretch * stretch;
  }
  return e;
}

void link_tensions(const Model& model, const State& state, std::span<double> tension) {
  const std::size_t n = model.nodes();
  for (std::size_t j = 0; j < model.links() && j < tension.size(); ++j) {
    const std::size_t b = (j + 1) % n;
    const double dx = state.x[b] - state.x[j], dy = state.y[b] - state.y[j];
    const double l = std::hypot(dx, dy);
    const double rate = (dx * (state.vx[b] - state.vx[j]) + dy * (state.vy[b] - state.vy[j])) / l;
    tension[j] = model.axial_stiffness * (l - model.pitch) + model.axial_damping * rate;
  }
}

}  // namespace catena::dynamics
