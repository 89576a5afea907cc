// The round-link chain on seed 003's pocket wheel as the pocket run-on validations, free and
// forced, set it up (tests/validation/dynamics_pocket*_test.cpp): one set of defaults for both.
#pragma once

namespace catena::dynamics::testing {

struct PocketRun {
  double pitch = 0.064;  // t
  double wire = 0.018;   // d
  int teeth = 8;
  double omega = 5.0;
  int strand_links = 40;
  int wrapped = 4;
  double node_mass = 0.42;  // one link of 6.6 kg/m
  double stiffness = 1e8;
  double damping = 2000.0;
  double force = 1000.0;
  double clearance = 1e-4;
  double contact_stiffness = 1e8;
  double contact_damping = 2000.0;
  double friction = 0.0;  // μ in the pockets (Sprocket::friction)
  double step = 1e-4;
  double theta = 0.6;
  int periods = 4;
  int skip_periods = 1;
  // round links carry no compression (Model::links_carry_compression; docs/models/dynamics.md,
  // "Tension-only links"): every link tension-only with no jam, unlike the command, whose flat
  // links are bilateral (Model::link_bilateral) and whose upright links jam at d
  bool tension_only = true;
  bool rails = true;  // the forced run-on's guide (false: the same strand, unguided)
  // [N] the forced run-on's slack side: the chain's downstream end pulled down (−y), so that it
  // leaves the wheel on its far side as into a locker (about 0.8 m of this chain hanging); 0
  // leaves it free, and the pockets, which hold a joint only against its links' pull, let the
  // wound-on chain fly off and lash back into the wheel
  double tail_force = 50.0;
};

}  // namespace catena::dynamics::testing
