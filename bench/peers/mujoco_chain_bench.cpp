// Peer benchmarks (issue 21, docs/performance.md), two problems: the free loop (here) and the
// sprocket drive (BM_PeerSprocketDriveCatenaVsMuJoCo, below). The same free 200-link 12B loop as
// BM_DynamicsLoopStep/200 (p = 19.05 mm, 0.0238 kg a pin, running at 5 m/s on a circle under
// gravity in the plane, step 1e-4 s), stepped by Catena and by MuJoCo in the same run, CPU time
// per step of each side by side and their ratio as counters.
//
// What is compared, honestly: the same masses, pitch, speed, gravity and step, but not the same
// mechanics. Catena's links are stiff axial springs (5e7 N/m, 2 N·s/m) between point masses,
// integrated by the implicit midpoint rule with Newton's method on the cyclic block-tridiagonal
// Jacobian (the free loop: no sprockets, no contact). MuJoCo's chain is its natural model of one:
// rigid links in joint coordinates, four kinematic chains of 50 links (a planar floating root and
// 49 hinges each: MJCF cannot nest 200 bodies), the loop closed by four `connect` equality
// constraints handled by its soft-constraint solver (Newton solver and semi-implicit Euler,
// MuJoCo's defaults; the constraints' solref time constant 2 h, the stiffest MuJoCo advises: with
// the default 0.02 s the closure let go by more than a pitch within 0.6 s under the loop's
// tension). An axial spring of 5e7 N/m is not an option there: its explicit spring force at h =
// 1e-4 s is far beyond the stability limit (ω h ≈ 9 ≫ 2). Each pin's mass sits on its hinge axis as
// in Catena, with a small rotational inertia (1e-3 m p²) so that a chain's last hinge has a
// joint-space mass. No contacts on either side (no geoms in MuJoCo).
//
// Built only when MuJoCo's headers and library are found (libmujoco-dev); not installed by
// scripts/setup.sh.
#include <benchmark/benchmark.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <ctime>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "catena/dynamics/integrator.hpp"

namespace {

using namespace catena::dynamics;

constexpr double kPitch = 0.01905;    // [m]
constexpr double kNodeMass = 0.0238;  // [kg] 1.25 kg/m × p
constexpr double kStiffness = 5e7;    // [N/m]
constexpr double kSpeed = 5.0;        // [m/s]
constexpr double kStep = 1e-4;        // [s]
constexpr int kBatch = 50;            // steps timed together (the CPU clock is a system call)

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The MJCF of a closed planar loop of n rigid links of pitch p: at qpos0 the links form the
// regular n-gon of side p through (R, 0), counter-clockwise; body i sits on pin i with its hinge
// there and its link along its local x axis. MJCF's parser refuses elements nested more than
// about 100 deep, so the loop is kSegments kinematic chains of n / kSegments links, each with
// its own planar floating root, and kSegments `connect` constraints tie each chain's far end to
// the next chain's root pin.
constexpr int kSegments = 4;

double pin_angle(int i, int n) { return 2.0 * std::numbers::pi * i / n; }
double link_direction(int i, int n) {  // pin i → pin i + 1
  return std::numbers::pi / 2.0 + std::numbers::pi * (2 * i + 1) / n;
}

std::string loop_mjcf(int n) {
  const double pi = std::numbers::pi;
  const double radius = kPitch / (2.0 * std::sin(pi / n));
  const double inertia = 1e-3 * kNodeMass * kPitch * kPitch;
  const int per = n / kSegments;
  std::ostringstream x;
  x.precision(17);
  x << "<mujoco model=\"chain_loop\">\n"
    << "  <compiler angle=\"radian\"/>\n"
    << "  <option timestep=\"" << kStep << "\" gravity=\"0 -9.81 0\"/>\n"
    << "  <worldbody>\n";
  std::ostringstream in;
  in.precision(17);
  in << "<inertial pos=\"0 0 0\" mass=\"" << kNodeMass << "\" diaginertia=\"" << inertia << " "
     << inertia << " " << inertia << "\"/>";
  for (int sgm = 0; sgm < kSegments; ++sgm) {
    const int r = sgm * per;
    x << "<body name=\"b" << r << "\" pos=\"" << radius * std::cos(pin_angle(r, n)) << " "
      << radius * std::sin(pin_angle(r, n)) << " 0\" euler=\"0 0 " << link_direction(r, n)
      << "\"><joint type=\"slide\" axis=\"1 0 0\"/><joint type=\"slide\" axis=\"0 1 0\"/>"
      << "<joint type=\"hinge\" axis=\"0 0 1\"/>" << in.str() << "\n";
    for (int i = r + 1; i < r + per; ++i) {
      x << "<body name=\"b" << i << "\" pos=\"" << kPitch << " 0 0\" euler=\"0 0 " << 2.0 * pi / n
        << "\"><joint type=\"hinge\" axis=\"0 0 1\"/>" << in.str() << "\n";
    }
    for (int i = 0; i < per; ++i) x << "</body>";
    x << "\n";
  }
  x << "  </worldbody>\n  <equality>\n";
  for (int sgm = 0; sgm < kSegments; ++sgm) {
    x << "    <connect body1=\"b" << (sgm + 1) * per - 1 << "\" body2=\"b" << ((sgm + 1) * per) % n
      << "\" anchor=\"" << kPitch << " 0 0\" solref=\"" << 2.0 * kStep << " 1\"/>\n";
  }
  x << "  </equality>\n</mujoco>\n";
  return x.str();
}

struct MjDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
  void operator()(mjData* d) const { mj_deleteData(d); }
};

// An MJCF text loaded through a one-file virtual file system (null and `error` set on failure).
std::unique_ptr<mjModel, MjDeleter> load_mjcf(const std::string& xml, std::string& error) {
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  if (mj_makeEmptyFileVFS(vfs.get(), "model.xml", static_cast<int>(xml.size())) != 0) {
    error = "VFS";
    return nullptr;
  }
  std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), "model.xml")], xml.data(), xml.size());
  char message[1000] = "";
  std::unique_ptr<mjModel, MjDeleter> m(
      mj_loadXML("model.xml", vfs.get(), message, sizeof message));
  mj_deleteVFS(vfs.get());
  error = message;
  return m;
}

// The loop's closure: the largest gap between a chain's far end and the next chain's root [m].
double closure_gap(const mjModel* m, mjData* d, int n) {
  mj_kinematics(m, d);
  const int per = n / kSegments;
  double worst = 0.0;
  for (int sgm = 0; sgm < kSegments; ++sgm) {
    const int last = (sgm + 1) * per, root = ((sgm + 1) * per) % n + 1;  // body 0 is the world
    const double* xm = d->xmat + 9 * last;
    const double* xp = d->xpos + 3 * last;
    const double ex = xp[0] + xm[0] * kPitch - d->xpos[3 * root];
    const double ey = xp[1] + xm[3] * kPitch - d->xpos[3 * root + 1];
    const double ez = xp[2] + xm[6] * kPitch - d->xpos[3 * root + 2];
    worst = std::max(worst, std::sqrt(ex * ex + ey * ey + ez * ez));
  }
  return worst;
}

void BM_PeerChainLoopCatenaVsMuJoCo(benchmark::State& bs) {
  const int n = static_cast<int>(bs.range(0));
  if (n % kSegments != 0) {
    bs.SkipWithError("the number of links must be a multiple of kSegments");
    return;
  }
  const auto nn = static_cast<std::size_t>(n);
  const double pi = std::numbers::pi;

  // Catena: as BM_DynamicsLoopStep (links 5e-4 longer than p at the start: a little tension).
  Model cm = uniform_chain(nn, true, kPitch, kNodeMass, kStiffness, 2.0, false);
  cm.gravity_y = -9.81;
  const double cr = 1.0005 * kPitch / (2.0 * std::sin(pi / n));
  State cs(nn);
  for (std::size_t i = 0; i < nn; ++i) {
    const double a = 2.0 * pi * static_cast<double>(i) / n;
    cs.x[i] = cr * std::cos(a);
    cs.y[i] = cr * std::sin(a);
    cs.vx[i] = -kSpeed * std::sin(a);
    cs.vy[i] = kSpeed * std::cos(a);
  }
  Integrator integ(cm, {.step = kStep});

  // MuJoCo: the MJCF through a one-file virtual file system.
  std::string error;
  std::unique_ptr<mjModel, MjDeleter> mm = load_mjcf(loop_mjcf(n), error);
  if (!mm) {
    bs.SkipWithError(("MuJoCo could not load the loop: " + error).c_str());
    return;
  }
  std::unique_ptr<mjData, MjDeleter> md(mj_makeData(mm.get()));
  // Rigid rotation at ω = v / R: each chain's root pin moves at v along the circle; its slides
  // act along its reference axes (turned by its first link's direction), so the velocity goes in
  // that frame; each root's hinge turns at ω, the relative hinges are still.
  const double radius = kPitch / (2.0 * std::sin(pi / n));
  const int per = n / kSegments;
  for (int sgm = 0; sgm < kSegments; ++sgm) {
    const int r = sgm * per;
    const double a = pin_angle(r, n), phi = link_direction(r, n);
    const double vx = -kSpeed * std::sin(a), vy = kSpeed * std::cos(a);
    const int dof = sgm * (per + 2);  // 3 root dofs and per − 1 hinges a chain
    md->qvel[dof] = std::cos(phi) * vx + std::sin(phi) * vy;
    md->qvel[dof + 1] = -std::sin(phi) * vx + std::cos(phi) * vy;
    md->qvel[dof + 2] = kSpeed / radius;
  }
  const double gap0 = closure_gap(mm.get(), md.get(), n);

  double catena_cpu = 0.0, mujoco_cpu = 0.0;
  long steps = 0;
  for (auto _ : bs) {
    const double t0 = cpu_seconds();
    for (int k = 0; k < kBatch; ++k) {
      if (!integ.step(cm, cs).converged) {
        bs.SkipWithError("Catena: a step did not converge");
        return;
      }
    }
    const double t1 = cpu_seconds();
    for (int k = 0; k < kBatch; ++k) mj_step(mm.get(), md.get());
    const double t2 = cpu_seconds();
    catena_cpu += t1 - t0;
    mujoco_cpu += t2 - t1;
    steps += kBatch;
    benchmark::DoNotOptimize(cs.x.data());
    benchmark::DoNotOptimize(md->qpos);
  }

  // Both stable: every coordinate finite; Catena's links within 1 % of the pitch, MuJoCo's loop
  // closed to within 1 % of the pitch (its links are rigid by construction).
  double strain = 0.0;
  for (std::size_t j = 0; j < nn; ++j) {
    const std::size_t b = (j + 1) % nn;
    const double l = std::hypot(cs.x[b] - cs.x[j], cs.y[b] - cs.y[j]);
    strain = std::isfinite(l) ? std::max(strain, std::abs(l / kPitch - 1.0)) : INFINITY;
  }
  bool mj_finite = true;
  for (int i = 0; i < mm->nq; ++i) mj_finite = mj_finite && std::isfinite(md->qpos[i]);
  const double gap = mj_finite ? closure_gap(mm.get(), md.get(), n) : INFINITY;
  if (!(strain < 0.01)) bs.SkipWithError("Catena's loop is not stable (link strain > 1 %)");
  if (!(gap < 0.01 * kPitch)) bs.SkipWithError("MuJoCo's loop is not stable (closure gap > 1 % p)");

  // and both still carry the loop's motion: kinetic energy ½ Σ m v² (Catena) and ½ q̇ᵀ M q̇
  // (MuJoCo), about 59.5 J at the start (200 × 0.0238 kg at 5 m/s)
  double catena_kinetic = 0.0;
  for (std::size_t i = 0; i < nn; ++i) {
    catena_kinetic += 0.5 * kNodeMass * (cs.vx[i] * cs.vx[i] + cs.vy[i] * cs.vy[i]);
  }
  std::vector<mjtNum> mv(static_cast<std::size_t>(mm->nv));
  mj_forward(mm.get(), md.get());
  mj_mulM(mm.get(), md.get(), mv.data(), md->qvel);
  double mujoco_kinetic = 0.0;
  for (int i = 0; i < mm->nv; ++i)
    mujoco_kinetic += 0.5 * md->qvel[i] * mv[static_cast<std::size_t>(i)];
  bs.counters["catena_kinetic_J"] = catena_kinetic;
  bs.counters["mujoco_kinetic_J"] = mujoco_kinetic;
  const double us_per_step = 1e6 / static_cast<double>(steps);
  bs.counters["catena_us_per_step"] = catena_cpu * us_per_step;
  bs.counters["mujoco_us_per_step"] = mujoco_cpu * us_per_step;
  bs.counters["mujoco_over_catena"] = mujoco_cpu / catena_cpu;
  bs.counters["simulated_s"] = kStep * static_cast<double>(steps);
  bs.counters["catena_max_strain"] = strain;
  bs.counters["mujoco_gap_um"] = 1e6 * gap;
  bs.counters["mujoco_gap0_um"] = 1e6 * gap0;
  bs.counters["mujoco_constraint_rows"] = md->nefc;
  bs.SetLabel(std::string("MuJoCo ") + mj_versionString());
}
BENCHMARK(BM_PeerChainLoopCatenaVsMuJoCo)->Arg(200)->Unit(benchmark::kMicrosecond)->MinTime(4.0);

// ---------------------------------------------------------------------------------------------
// The sprocket drive: BM_DynamicsTwoSprocketDrive's problem (bench/dynamics_bench.cpp) — a
// 200-link 12B loop over two sprockets z = 20, 90 pitches apart, the driver at 30 rad/s, the driven
// wheel J = 0.05 kg·m² against a 20 N·m load, gravity in the plane, h = 1e-4 s — in both engines.
//
// MuJoCo's drive: the chain as above (rigid links, four kinematic chains closed by `connect`),
// each pin carrying its roller as a sphere of d1/2 (contacts in the plane: every body moves in it);
// each wheel a body on a hinge at its centre whose seats are contact geometry — a root capsule
// (along z) of radius R − d1/2, on which a seated roller's centre lies on the pitch circle, and a
// capsule tooth half-way between seats on the pitch circle, its radius leaving 0.1 mm to a
// seated roller (the roller swinging in about the previous one's pin, at p, clears it by 0.04 mm).
// Frictionless contacts (condim 1) as Catena's seats in this benchmark, their solref time constant
// 2 h as the loop's closure (the stiffest MuJoCo advises; the default 0.02 s was not tried).
// The driver is held at its prescribed angle and speed by setting its joint's position and velocity
// before each step; the driven wheel's load is a constant applied joint torque. Catena's contact is
// the ISO 606 seat (k_c = 2e8 N/m, c_c = 800 N·s/m), its links elastic (5e7 N/m, 100 N·s/m) and
// pretensioned by 1e-3 of the pitch; MuJoCo's links are rigid and not pretensioned: the same drive,
// not the same mechanics (docs/performance.md).
constexpr int kDriveTeeth = 20, kDriveSpan = 90;
constexpr double kDriveOmega = 30.0;        // [rad/s]
constexpr double kDriveInertia = 0.05;      // [kg·m²] driven wheel
constexpr double kDriveLoad = 20.0;         // [N·m] against counter-clockwise turning
constexpr double kRollerRadius = 0.006035;  // [m] d1/2, 12B
constexpr double kToothClearance = 1e-4;    // [m]
constexpr long kSettle = 500;               // steps before the driven speed is averaged

std::string drive_mjcf(const State& s, double pitch_radius) {
  const double pi = std::numbers::pi;
  const auto n = static_cast<int>(s.nodes());
  const int per = n / kSegments;
  const double inertia = 1e-3 * kNodeMass * kPitch * kPitch;
  auto direction = [&](int i) {  // pin i → pin i + 1
    const auto a = static_cast<std::size_t>(i), b = static_cast<std::size_t>((i + 1) % n);
    return std::atan2(s.y[b] - s.y[a], s.x[b] - s.x[a]);
  };
  std::ostringstream x;
  x.precision(17);
  x << "<mujoco model=\"chain_drive\">\n"
    << "  <compiler angle=\"radian\"/>\n"
    << "  <option timestep=\"" << kStep << "\" gravity=\"0 -9.81 0\"/>\n"
    << "  <default><geom condim=\"1\" solref=\"" << 2.0 * kStep << " 1\"/></default>\n"
    << "  <worldbody>\n";
  std::ostringstream in;
  in.precision(17);
  in << "<inertial pos=\"0 0 0\" mass=\"" << kNodeMass << "\" diaginertia=\"" << inertia << " "
     << inertia << " " << inertia << "\"/><geom type=\"sphere\" size=\"" << kRollerRadius
     << "\" contype=\"1\" conaffinity=\"0\"/>";
  for (int sgm = 0; sgm < kSegments; ++sgm) {
    const int r = sgm * per;
    const auto rr = static_cast<std::size_t>(r);
    x << "<body name=\"b" << r << "\" pos=\"" << s.x[rr] << " " << s.y[rr] << " 0\" euler=\"0 0 "
      << direction(r) << "\"><joint type=\"slide\" axis=\"1 0 0\"/>"
      << "<joint type=\"slide\" axis=\"0 1 0\"/><joint type=\"hinge\" axis=\"0 0 1\"/>" << in.str()
      << "\n";
    for (int i = r + 1; i < r + per; ++i) {
      x << "<body name=\"b" << i << "\" pos=\"" << kPitch << " 0 0\" euler=\"0 0 "
        << std::remainder(direction(i) - direction(i - 1), 2.0 * pi)
        << "\"><joint type=\"hinge\" axis=\"0 0 1\"/>" << in.str() << "\n";
    }
    for (int i = 0; i < per; ++i) x << "</body>";
    x << "\n";
  }
  // the wheels, seat 0 at their State angles (π/2 and −π/2) at qpos = 0
  const double root = pitch_radius - kRollerRadius;
  const double tooth =
      2.0 * pitch_radius * std::sin(pi / (2.0 * kDriveTeeth)) - kRollerRadius - kToothClearance;
  const double centres[2] = {0.0, kDriveSpan * kPitch};
  for (int w = 0; w < 2; ++w) {
    x << "<body name=\"wheel" << w << "\" pos=\"" << centres[w] << " 0 0\"><joint name=\"wheel" << w
      << "\" type=\"hinge\" axis=\"0 0 1\"/><inertial pos=\"0 0 0\" mass=\"1\" "
      << "diaginertia=\"" << kDriveInertia << " " << kDriveInertia << " " << kDriveInertia
      << "\"/><geom type=\"capsule\" size=\"" << root
      << " 0.01\" contype=\"0\" conaffinity=\"1\"/>\n";
    for (int k = 0; k < kDriveTeeth; ++k) {
      const double a = s.angle[static_cast<std::size_t>(w)] + 2.0 * pi * (k + 0.5) / kDriveTeeth;
      x << "<geom type=\"capsule\" size=\"" << tooth << " 0.01\" pos=\""
        << pitch_radius * std::cos(a) << " " << pitch_radius * std::sin(a)
        << " 0\" contype=\"0\" conaffinity=\"1\"/>\n";
    }
    x << "</body>\n";
  }
  x << "  </worldbody>\n  <equality>\n";
  for (int sgm = 0; sgm < kSegments; ++sgm) {
    x << "    <connect body1=\"b" << (sgm + 1) * per - 1 << "\" body2=\"b" << ((sgm + 1) * per) % n
      << "\" anchor=\"" << kPitch << " 0 0\" solref=\"" << 2.0 * kStep << " 1\"/>\n";
  }
  x << "  </equality>\n</mujoco>\n";
  return x.str();
}

void BM_PeerSprocketDriveCatenaVsMuJoCo(benchmark::State& bs) {
  // Catena: exactly BM_DynamicsTwoSprocketDrive's set-up
  const auto n = static_cast<std::size_t>(kDriveTeeth + 2 * kDriveSpan);
  Model cm = uniform_chain(n, true, kPitch * (1.0 - 1e-3), kNodeMass, kStiffness, 100.0, false);
  cm.gravity_y = -9.81;
  Sprocket a = iso606_sprocket(kPitch, 0.01207, 0.01168, kDriveTeeth, 0.0, 0.0, 2e8, 800.0);
  a.driver = true;
  a.speed = kDriveOmega;
  Sprocket b =
      iso606_sprocket(kPitch, 0.01207, 0.01168, kDriveTeeth, kDriveSpan * kPitch, 0.0, 2e8, 800.0);
  b.inertia = kDriveInertia;
  b.load_torque = kDriveLoad;
  cm.sprockets = {a, b};
  const State start =
      two_sprocket_loop(kDriveTeeth, kDriveSpan, kPitch, a.pitch_radius, kDriveOmega);
  State cs = start;
  Integrator integ(cm, {.step = kStep, .theta = 0.6});

  // MuJoCo: the same start, the chain's velocities in joint coordinates
  std::string error;
  std::unique_ptr<mjModel, MjDeleter> mm = load_mjcf(drive_mjcf(start, a.pitch_radius), error);
  if (!mm) {
    bs.SkipWithError(("MuJoCo could not load the drive: " + error).c_str());
    return;
  }
  std::unique_ptr<mjData, MjDeleter> md(mj_makeData(mm.get()));
  const int nn = static_cast<int>(n), per = nn / kSegments;
  auto link_rate = [&](int i) {  // the angular speed of link i → i + 1
    const auto p = static_cast<std::size_t>(i), q = static_cast<std::size_t>((i + 1) % nn);
    const double dx = start.x[q] - start.x[p], dy = start.y[q] - start.y[p];
    const double dvx = start.vx[q] - start.vx[p], dvy = start.vy[q] - start.vy[p];
    return (dx * dvy - dy * dvx) / (dx * dx + dy * dy);
  };
  for (int sgm = 0; sgm < kSegments; ++sgm) {
    const int r = sgm * per;
    const auto rr = static_cast<std::size_t>(r), r1 = static_cast<std::size_t>(r + 1);
    const double phi = std::atan2(start.y[r1] - start.y[rr], start.x[r1] - start.x[rr]);
    const int dof = sgm * (per + 2);  // 3 root dofs and per − 1 hinges a chain
    md->qvel[dof] = std::cos(phi) * start.vx[rr] + std::sin(phi) * start.vy[rr];
    md->qvel[dof + 1] = -std::sin(phi) * start.vx[rr] + std::cos(phi) * start.vy[rr];
    md->qvel[dof + 2] = link_rate(r);
    for (int i = r + 1; i < r + per; ++i)
      md->qvel[dof + 2 + i - r] = link_rate(i) - link_rate(i - 1);
  }
  const int driver = mm->jnt_dofadr[mj_name2id(mm.get(), mjOBJ_JOINT, "wheel0")];
  const int driven = mm->jnt_dofadr[mj_name2id(mm.get(), mjOBJ_JOINT, "wheel1")];
  const int driver_q = mm->jnt_qposadr[mj_name2id(mm.get(), mjOBJ_JOINT, "wheel0")];
  md->qvel[driver] = kDriveOmega;
  md->qvel[driven] = kDriveOmega;
  md->qfrc_applied[driven] = -kDriveLoad;
  const double gap0 = closure_gap(mm.get(), md.get(), nn);

  double catena_cpu = 0.0, mujoco_cpu = 0.0;
  double catena_penetration = 0.0, mujoco_penetration = 0.0;
  // Σ, least and largest of the driven wheel's speed over the steps after the first kSettle
  double catena_speed = 0.0, mujoco_speed = 0.0;
  double catena_range[2] = {INFINITY, -INFINITY}, mujoco_range[2] = {INFINITY, -INFINITY};
  long steps = 0;
  int most_contacts = 0;
  for (auto _ : bs) {
    // kBatch steps of each engine timed together (a read of the CPU clock costs about 1.4 µs,
    // 2 % of Catena's step); the bookkeeping of the checks inside is a few comparisons a step
    const double t0 = cpu_seconds();
    for (int k = 0; k < kBatch; ++k) {
      const StepReport rep = integ.step(cm, cs);
      if (!rep.converged) {
        bs.SkipWithError("Catena: a step did not converge");
        return;
      }
      catena_penetration = std::max(catena_penetration, rep.max_penetration);
      if (steps + k >= kSettle) {
        catena_speed += cs.speed[1];
        catena_range[0] = std::min(catena_range[0], cs.speed[1]);
        catena_range[1] = std::max(catena_range[1], cs.speed[1]);
      }
    }
    const double t1 = cpu_seconds();
    for (int k = 0; k < kBatch; ++k) {
      md->qpos[driver_q] = kDriveOmega * md->time;  // the driver: prescribed angle and speed
      md->qvel[driver] = kDriveOmega;
      mj_step(mm.get(), md.get());
      for (int c = 0; c < md->ncon; ++c)
        mujoco_penetration = std::max(mujoco_penetration, -md->contact[c].dist);
      most_contacts = std::max(most_contacts, md->ncon);
      if (steps + k >= kSettle) {
        mujoco_speed += md->qvel[driven];
        mujoco_range[0] = std::min(mujoco_range[0], md->qvel[driven]);
        mujoco_range[1] = std::max(mujoco_range[1], md->qvel[driven]);
      }
    }
    const double t2 = cpu_seconds();
    catena_cpu += t1 - t0;
    mujoco_cpu += t2 - t1;
    steps += kBatch;
    benchmark::DoNotOptimize(cs.x.data());
    benchmark::DoNotOptimize(md->qpos);
  }

  bool mj_finite = true;
  for (int i = 0; i < mm->nq; ++i) mj_finite = mj_finite && std::isfinite(md->qpos[i]);
  const double gap = mj_finite ? closure_gap(mm.get(), md.get(), nn) : INFINITY;
  const double steps_d = static_cast<double>(steps);
  const double averaged = static_cast<double>(steps - kSettle);
  const double catena_mean = catena_speed / averaged, mujoco_mean = mujoco_speed / averaged;
  // Both stable: no roller deeper than 0.5 mm in a wheel over the whole run (Catena's seats: a few
  // µm; 0.5 mm is 2.6 % of the pitch), the driven wheel's mean speed after the first 0.05 s within
  // 2 % of the driver's (equal wheels), MuJoCo's closure within 1 % of the pitch
  constexpr double kMaxPenetration = 5e-4;
  if (!(catena_penetration < kMaxPenetration)) bs.SkipWithError("Catena: penetration > 0.5 mm");
  if (!(mujoco_penetration < kMaxPenetration)) bs.SkipWithError("MuJoCo: penetration > 0.5 mm");
  if (!(std::abs(catena_mean / kDriveOmega - 1.0) < 0.02))
    bs.SkipWithError("Catena: the driven wheel's mean speed is off the driver's by > 2 %");
  if (!(std::abs(mujoco_mean / kDriveOmega - 1.0) < 0.02))
    bs.SkipWithError("MuJoCo: the driven wheel's mean speed is off the driver's by > 2 %");
  if (!(gap < 0.01 * kPitch)) bs.SkipWithError("MuJoCo's loop is not closed (gap > 1 % p)");

  const double us_per_step = 1e6 / steps_d;
  bs.counters["catena_us_per_step"] = catena_cpu * us_per_step;
  bs.counters["mujoco_us_per_step"] = mujoco_cpu * us_per_step;
  bs.counters["mujoco_over_catena"] = mujoco_cpu / catena_cpu;
  bs.counters["simulated_s"] = kStep * steps_d;
  bs.counters["catena_penetration_um"] = 1e6 * catena_penetration;
  bs.counters["mujoco_penetration_um"] = 1e6 * mujoco_penetration;
  bs.counters["catena_driven_speed"] = catena_mean;
  bs.counters["mujoco_driven_speed"] = mujoco_mean;
  bs.counters["catena_driven_min"] = catena_range[0];
  bs.counters["catena_driven_max"] = catena_range[1];
  bs.counters["mujoco_driven_min"] = mujoco_range[0];
  bs.counters["mujoco_driven_max"] = mujoco_range[1];
  bs.counters["mujoco_gap_um"] = 1e6 * gap;
  bs.counters["mujoco_gap0_um"] = 1e6 * gap0;
  bs.counters["mujoco_most_contacts"] = most_contacts;
  bs.SetLabel(std::string("MuJoCo ") + mj_versionString() + ", " + std::to_string(steps) +
              " steps");
}
// a fixed 3000 steps (0.3 s, 1.4 turns of the wheels): the checks need more than the single batch
// a benchmark's first trial would run
BENCHMARK(BM_PeerSprocketDriveCatenaVsMuJoCo)->Unit(benchmark::kMicrosecond)->Iterations(60);

}  // namespace
