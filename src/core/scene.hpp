// The validated, fully resolved scene: every key of docs/scene-reference.md with its default filled in.
// Produced by io/scene_reader (TOML + --set overrides), consumed by setup and the run loop.
#pragma once
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "core/parameter.hpp"

namespace arksph {

enum class SideKind { wall, periodic };
enum class SlipKind { no_slip, free_slip };

// One side of the box: left, right, bottom, top (index 0..3; 1D uses left, right only).
struct SideSpec {
  SideKind kind = SideKind::wall;
  SlipKind slip = SlipKind::no_slip;
  std::array<double, 2> velocity{0.0, 0.0};  // wall velocity w (moving lid)
};

struct PhaseSpec {
  std::string where;   // muParser expression in x, y; true (non-zero) selects the particle
  double density = 1;  // reference density of the phase (equal number density, other mass)
};

struct Scene {
  std::string source = "<embedded default>";  // file the scene came from (for messages)

  // [scene]
  std::string name = "unnamed";
  int dimension = 2;

  // [domain]
  std::array<double, 2> min{0, 0}, max{1, 1};

  // [boundary] left, right, bottom, top
  std::array<SideSpec, 4> sides{};
  double corner_alpha = 0.0;          // Szewc et al. 2012 eq. 46, range [-1, 1]
  bool free_slip_divergence = false;  // Szewc §6: free-slip images for the velocity divergence only
  bool wall_particles = false;  // Basa et al. 2008 §6.1.2: particles on the wall carrying its velocity (2D)
  bool wall_ghosts = true;      // mirror images across the walls (false: wcsph with a wall force only)
  std::string wall_force = "none";  // force of the walls on the fluid (rhs/term_registry.hpp)
  std::string wall_velocity = "mirror";  // no-slip ghost tangential velocity, Basa et al. 2008 §6.1.2: "mirror" | "linear" | "quadratic"

  // [fluid]
  double spacing = 0.02;
  double density = 1.0;
  double viscosity = 0.01;  // kinematic nu
  std::vector<std::string> body_force{"0", "0"};
  bool shuffle_initial_order = false;  // particles in a fixed pseudo-random memory order at t = 0 (benchmarks)

  // [initial]
  std::vector<std::string> initial_velocity{"0", "0"};
  std::vector<std::string> initial_offset{"0", "0"};  // displacement added to the lattice positions
  bool initial_hydrostatic = false;  // wcsph: start at the Tait density of the hydrostatic pressure
  std::string initial_pressure = "0";  // wcsph: pressure expression p(x, y) at t = 0 (Tait density)

  // [[phase]]
  std::vector<PhaseSpec> phases;

  // [method]
  std::string scheme = "wcsph";
  std::string kernel = "wendland_quintic";
  double h_over_dx = 2.0;
  std::string viscosity_model = "morris";
  std::string kernel_correction = "none";  // Basa et al. 2008 §4: "none" | "shepard" (eqs. 21-23) | "bonet_lok" (eqs. 24-26)
  bool pressure_reduction = false;     // Basa et al. 2008 eq. 20: local average pressure subtracted in the pressure gradient
  double sound_speed = 0.0;            // 0: default 10 * reference speed (docs/scene-reference.md)
  double tait_gamma = 7.0;             // C&R eq. 7
  std::string equation_of_state = "tait";  // "tait" (Basa eq. 13) | "ideal_gas" (Basa eq. 12 with the energy equation 14)
  double gas_gamma = 1.4;              // ideal_gas: p = (gamma - 1) rho e; e(0) chosen so that sqrt(gamma p / rho) = c
  double background_pressure = 0.0;    // added to the Tait pressure (Morris et al. 1997); keeps p > 0 near walls
  std::string density_mode = "continuity";      // "continuity" (Szewc eq. 19) | "summation" (Szewc eq. 21)
  std::string pressure_gradient = "colagrossi"; // "colagrossi" (Szewc eq. 23) | "monaghan" (C&R eq. 1)
  std::string density_correction = "none";
  std::string regularisation = "none";     // particle regularisation in dr/dt (rhs/term_registry.hpp)
  std::string density_diffusion = "none";  // delta-SPH in the continuity equation (wcsph)
  std::string projection = "cummins_rudman";  // isph: "cummins_rudman" (after each step) | "constrained" | "orthogonal" (pressure in f)
  double orthogonal_spacing = 3.0;            // orthogonal projection: pressure node spacing / fluid.spacing
  double orthogonal_relaxation = 0.1;         // orthogonal projection: beta of its relaxation rate
  bool pressure_in_f() const { return projection == "constrained" || projection == "orthogonal"; }
  double constraint_relaxation = 1.0;  // constrained projection: alpha = this x U/h, the decay rate of D u
  std::string ppe_operator = "approximate";  // isph: "approximate" (C&R eq. 19) | "exact" (C&R eq. 18)
  std::string ppe_divergence = "cummins_rudman";  // isph source: "cummins_rudman" (C&R eq. 17) | "difference"
  std::string ppe_pressure_level = "zero_mean";  // isph: "zero_mean" | "zero_min" (P >= 0, no tensile pairs)
  bool force_sweep = true;  // the per-particle force terms share one neighbourhood gather
  std::string neighbor_storage = "pairs";        // "pairs" (W, F stored) | "candidates" (kernel on the fly)
  double ppe_pressure_offset = 0.0;              // isph: constant added to P after the level (background pressure)
  std::string ppe_solver = "auto";     // isph: "klu" | "cg" | "cg_ic" | "cg_amg" | "auto" (docs/methods/isph.md)
  double ppe_tolerance = 1e-10;        // isph, cg: relative residual
  double gpps_spacing = 0.0;           // isph-gpps: auxiliary grid cell size (Szewc §4.2); 0: fluid.spacing
  double gpps_volume_relaxation = 0.0; // isph-gpps: beta of the cell-volume source term (0: off, Szewc's GPPS)
  bool centre_positions = true;        // isph: positions centred in time (C&R eq. 12)
  long reorder_every = 100;  // re-sort particles by cell at t = 0 and every this many steps (0: never)
  std::string projection_points = "step";  // isph: project after each "step" (C&R) | after each "stages" too
  double correction_threshold = 1e-3;  // pozorski_wawrenczuk: r.m.s. relative density error that triggers it
  int correction_max_iterations = 1;   // pozorski_wawrenczuk: Poisson solves per step at most
  std::string correction_solver = "fixed_point";  // pozorski_wawrenczuk: "fixed_point" | "kinsol" | "newton"
  double correction_relaxation = 1.0;  // pozorski_wawrenczuk with the constrained projection: kappa = this x U/h

  // [time]
  double end = 1.0;
  double steady_tolerance = 0.0;  // > 0: stop at steady state (diagnostics/steady_state.hpp)
  double steady_window = 0.0;     // simulated time the steady-state rate is taken over (0: one output interval)
  std::string steady_measure = "window_means";  // how the steady-state rate is taken (diagnostics/steady_state.hpp)
  std::string integrator = "ARKODE_HEUN_EULER_2_1_2";
  double dt = 0.0;        // 0: adaptive, limited by the stability function; > 0: fixed step
  double cfl = 0.25;      // coefficient of Szewc eqs. 34-35
  double rtol = 1e-2, atol = 1e-4;  // adaptive mode only: loose, so that the stability limits govern
  long max_steps = 100000000;
  double blowup_speed = 0.0;  // a particle faster than this stops the run (run/state_check.hpp); 0: automatic
  bool imex = false;                     // ARKStep IMEX: viscous term implicit (Newton, KLU), the rest explicit
  std::string imex_pair = "ARK324L2SA";  // time.imex: ARKODE additive pair (arksph list: imex_pair)
  bool imex_linear = false;              // time.imex: true: ARKStepSetLinear, J re-probed at every stage, one Newton iteration

  // [output]
  std::string directory = "runs/unnamed";
  double every = 0.0;  // 0: only first and last frame
  double checkpoint_every = 0.0;  // simulated time between checkpoint.h5 writes; 0: only at the end
  bool pieces = false;            // several MPI ranks: one VTP piece per rank and a PVTP per frame

  // [metrics]
  int ghia_re = 0;          // 0: off; 100 or 1000: Ghia et al. 1982 centreline errors
  bool poiseuille = false;  // Basa et al. 2008 eqs. 36-39
  bool interface = false;   // two phases: 0.5 contour of the smoothed phase indicator, tip heights
  std::vector<std::string> exact_velocity;  // u(x, y, t) per dimension; all "0": off

  // Parameters that parts declare without a member here (core/param_builder.hpp), by dotted key.
  ParamTable part_params;

  // The keys read as "auto" and the values their rules chose (Param::automatic), in catalog order:
  // printed in the run header and written into summary.json ("resolved").
  std::vector<std::pair<std::string, std::string>> automatic;
  // Those of them this run does not use (a part not selected, another scheme's key: io/key_use.hpp);
  // the run header leaves them out.
  std::vector<std::string> automatic_unused;

  // The resolved scene as TOML text (all keys, "auto" replaced), written into summary.json.
  std::string resolved_toml;
};

}  // namespace arksph
