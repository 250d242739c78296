// The validated, fully resolved scene: every key of docs/scene-reference.md with its default filled in.
// Produced by io/scene_reader (TOML + --set overrides), consumed by setup and the run loop.
//
// Defaults are written once, in the key declarations (the scene catalog, io/scene_catalog.hpp):
// a member bound to a key (`.to(&Scene::member)`) has no initialiser here. A Scene is made by
// scene_defaults() (io/scene_defaults.hpp), which gives every key its declared default and every
// "auto" key its rule's value, as a scene file that sets only the required keys gives them; the
// reader starts from it and applies the file. A test that needs a scene takes scene_defaults() and
// sets what it changes. The default constructor is private, so a Scene with unset members cannot be
// made elsewhere. Members without a key (the box, the sides, the phases, the records the reader fills)
// keep their initialisers.
//
// A key with a closed list of values (an Option, core/option.hpp) is held as its enumerator
// (core/option_values.hpp, core/projection_method.hpp): parsed once by the reader, written back as
// its name; one with an "auto" rule (method.ppe_divergence, method.ppe_pressure_level,
// method.body_force_pressure) as a std::optional of it, empty while the rules run
// (io/scene_defaults.cpp). Text stays for the keys that select a registered part (open lists,
// resolved through their registry).
#pragma once
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/option_values.hpp"
#include "core/parameter.hpp"
#include "core/projection_method.hpp"

namespace arksph {

enum class SideKind { wall, periodic };
enum class SlipKind { no_slip, free_slip };

// The scene's names of the sides, in the order of Scene::sides.
inline constexpr const char* kSideNames[4] = {"left", "right", "bottom", "top"};

// One side of the box: left, right, bottom, top (index 0..3; 1D uses left, right only).
struct SideSpec {
  SideKind kind = SideKind::wall;
  SlipKind slip = SlipKind::no_slip;
  std::array<double, 2> velocity{0.0, 0.0};  // wall velocity w (moving lid)
  // A periodic side whose neighbours across arrive as halo copies at shifted positions: in the scene
  // of one rank of a decomposed run (distributed/halo_rhs.hpp). It gives no ghost images, and the
  // positions are not wrapped across it. No key: false in every scene that is read.
  bool halo = false;
};

struct PhaseSpec {
  std::string where;   // muParser expression in x, y; true (non-zero) selects the particle
  double density = 1;  // reference density of the phase (equal number density, other mass)
};

struct Scene {
  std::string source = "<embedded default>";  // file the scene came from (for messages)

  // [scene]
  std::string name;
  int dimension;

  // [domain]
  std::array<double, 2> min{0, 0}, max{1, 1};

  // [boundary] left, right, bottom, top (kSideNames)
  std::array<SideSpec, 4> sides{};
  double corner_alpha;  // Szewc et al. 2012 eq. 46, range [-1, 1]
  bool free_slip_divergence;  // Szewc §6: free-slip images for the velocity divergence only
  bool wall_particles;  // Basa et al. 2008 §6.1.2: particles on the wall carrying its velocity (2D)
  bool wall_ghosts;  // mirror images across the walls (false: wcsph with a wall force only)
  std::string wall_force;  // force of the walls on the fluid (rhs/term_registry.hpp)
  std::string wall_velocity;  // no-slip ghost tangential velocity, Basa et al. 2008 §6.1.2: "mirror" | "linear" | "quadratic"

  // [fluid]
  double spacing;
  std::string fluid_region;  // expression in x, y: non-zero where the domain holds fluid at t = 0; "": all of it
  double density;
  double viscosity;  // kinematic nu
  std::vector<std::string> body_force;
  bool shuffle_initial_order;  // particles in a fixed pseudo-random memory order at t = 0 (benchmarks)

  // [initial]
  std::vector<std::string> initial_velocity;
  std::vector<std::string> initial_offset;  // displacement added to the lattice positions
  bool initial_hydrostatic;  // wcsph: start at the Tait density of the hydrostatic pressure
  std::string initial_pressure;  // wcsph: pressure expression p(x, y) at t = 0 (Tait density)

  // [[phase]]
  std::vector<PhaseSpec> phases;

  // [method]
  std::string scheme;
  std::string kernel;
  double h_over_dx;
  std::string viscosity_model;
  std::string kernel_correction;  // Basa et al. 2008 §4: "none" | "shepard" (eqs. 21-23) | "bonet_lok" (eqs. 24-26)
  bool pressure_reduction;  // Basa et al. 2008 eq. 20: local average pressure subtracted in the pressure gradient
  double sound_speed;  // 0: default 10 * reference speed (docs/scene-reference.md)
  double tait_gamma;  // C&R eq. 7
  std::string equation_of_state;  // "tait" (Basa eq. 13) | "ideal_gas" (Basa eq. 12 with the energy equation 14)
  double gas_gamma;  // ideal_gas: p = (gamma - 1) rho e; e(0) chosen so that sqrt(gamma p / rho) = c
  double background_pressure;  // added to the Tait pressure (Morris et al. 1997); keeps p > 0 near walls
  std::string density_mode;  // "continuity" (Szewc eq. 19) | "summation" (Szewc eq. 21)
  std::string pressure_gradient;  // "colagrossi" (Szewc eq. 23) | "monaghan" (C&R eq. 1)
  std::string density_correction;
  std::string regularisation;  // particle regularisation in dr/dt (rhs/term_registry.hpp)
  std::string density_diffusion;  // delta-SPH in the continuity equation (wcsph)
  ProjectionMethod projection;  // isph: "cummins_rudman" (after each step) | "constrained" | "orthogonal" (pressure in f)
  double orthogonal_spacing;  // orthogonal projection: pressure node spacing / fluid.spacing
  double orthogonal_relaxation;  // orthogonal projection: beta of its relaxation rate
  bool pressure_in_f() const { return projection != ProjectionMethod::cummins_rudman; }
  double constraint_relaxation;  // constrained projection: alpha = this x U/h, the decay rate of D u
  PpeOperator ppe_operator;  // isph: "approximate" (C&R eq. 19) | "exact" (C&R eq. 18)
  std::optional<PpeDivergence> ppe_divergence;  // isph source: "cummins_rudman" (C&R eq. 17) | "difference"
  std::optional<PressureLevel> ppe_pressure_level;  // isph: "zero_mean" | "zero_min" (P >= 0, no tensile pairs)
  bool force_sweep;  // the per-particle force terms share one neighbourhood gather
  NeighborStorage neighbor_storage;  // "pairs" (W, F stored) | "candidates" (kernel on the fly)
  double ppe_pressure_offset;  // isph: constant added to P after the level (background pressure)
  std::optional<BodyForcePressure> body_force_pressure;  // isph: "modified" (P = p - rho0 g . r) | "split" (rhs/pressure_gravity.hpp)
  std::string ppe_solver;  // isph: "klu" | "cg" | "cg_ic" | "cg_amg" | "auto" (docs/methods/isph.md)
  std::string rank_ppe_solver;  // isph over MPI ranks: "amg" | "hypre" | "auto" (distributed_ppe/rank_poisson_solver.hpp)
  double ppe_tolerance;  // isph, cg: relative residual
  double gpps_spacing;  // isph-gpps: auxiliary grid cell size (Szewc §4.2); 0: fluid.spacing
  double gpps_volume_relaxation;  // isph-gpps: beta of the cell-volume source term (0: off, Szewc's GPPS)
  bool centre_positions;  // isph: positions centred in time (C&R eq. 12)
  long reorder_every;  // re-sort particles by cell at t = 0 and every this many steps (0: never)
  ProjectionPoints projection_points;  // isph: project after each "step" (C&R) | after each "stages" too
  double correction_threshold;  // pozorski_wawrenczuk: r.m.s. relative density error that triggers it
  int correction_max_iterations;  // pozorski_wawrenczuk: Poisson solves per step at most
  std::string correction_solver;  // pozorski_wawrenczuk: "fixed_point" | "kinsol" | "newton"
  double correction_relaxation;  // pozorski_wawrenczuk with the constrained projection: kappa = this x U/h

  // [time]
  double end;
  double steady_tolerance;  // > 0: stop at steady state (diagnostics/steady_state.hpp)
  double steady_window;  // simulated time the steady-state rate is taken over (0: one output interval)
  SteadyMeasure steady_measure;  // how the steady-state rate is taken (diagnostics/steady_state.hpp)
  std::string integrator;
  double dt;  // 0: adaptive, limited by the stability function; > 0: fixed step
  double cfl;  // coefficient of Szewc eqs. 34-35
  double rtol, atol;  // adaptive mode only: loose, so that the stability limits govern
  long max_steps;
  double blowup_speed;  // a particle faster than this stops the run (run/state_check.hpp); 0: automatic
  bool imex;  // ARKStep IMEX: viscous term implicit (Newton, KLU), the rest explicit
  std::string imex_pair;  // time.imex: ARKODE additive pair (arksph list: imex_pair)
  bool imex_linear;  // time.imex: true: ARKStepSetLinear, J re-probed at every stage, one Newton iteration

  // [output]
  std::string directory;
  double every;  // 0: only first and last frame
  double checkpoint_every;  // simulated time between checkpoint.h5 writes; 0: only at the end
  bool pieces;  // several MPI ranks: one VTP piece per rank and a PVTP per frame
  bool walls;   // the wall points of each frame as walls_NNNNNN.vtp, listed in walls.pvd

  // [metrics]
  int ghia_re;  // 0: off; 100 or 1000: Ghia et al. 1982 centreline errors
  bool poiseuille;  // Basa et al. 2008 eqs. 36-39
  bool interface;  // two phases: 0.5 contour of the smoothed phase indicator, tip heights
  std::vector<std::string> exact_velocity;  // u(x, y, t) per dimension; all "0": off
  bool energy_budget;  // kinetic, potential, compressible energy and viscous dissipation (diagnostics/energy_budget.hpp)

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

 private:
  Scene() = default;  // members bound to keys unset: only scene_defaults() makes a Scene
  friend Scene scene_defaults();
};

}  // namespace arksph
