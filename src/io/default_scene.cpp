// The embedded default scene: 2D lid-driven cavity at Re = U L / nu = 1 * 1 / 0.01 = 100, compared with
// Ghia, Ghia & Shin 1982 (Table I, Re = 100). It is also the commented reference of every scene key.
#include "io/scene_reader.hpp"

namespace arksph {

const char* default_scene_toml() {
  return R"toml(# arksph scene: lid-driven cavity, Re = 100 (Ghia, Ghia & Shin 1982).
# Every key is shown; all but domain.min, domain.max, fluid.spacing and time.end have defaults.
# Any key can be overridden on the command line: arksph run --set time.end=2 --set method.scheme=isph

[scene]
name = "cavity_re100"          # label for messages, summary.json and the default output directory
dimension = 2                  # 1 or 2

[domain]
min = [0.0, 0.0]               # lower corner of the fluid box (one number per dimension)
max = [1.0, 1.0]               # upper corner (max > min in every component)

[boundary]                     # one entry per side: left, right, bottom, top (1D: left, right only)
# kind = "wall" | "periodic" (a periodic side needs its opposite periodic too)
# velocity = wall velocity (walls only; default 0), slip = "no_slip" | "free_slip" (walls only)
left   = { kind = "wall" }
right  = { kind = "wall" }
bottom = { kind = "wall" }
top    = { kind = "wall", velocity = [1.0, 0.0], slip = "no_slip" }   # the moving lid
corner_alpha = 0.0             # corner ghost weighting, Szewc et al. 2012 eq. 46, in [-1, 1]
free_slip_divergence = true    # free-slip images for the velocity divergence only (Szewc §6; needed at the lid corners)
wall_velocity = "mirror"       # no-slip ghosts: "mirror" (2w - u) | "linear" (near-wall shear extrapolated, Basa §6.1.2) | "quadratic" (two rows)
wall_particles = false         # true: particles on the no-slip walls with the wall velocity, one per fluid particle within dx (Basa §6.1.2)

[fluid]
spacing = 0.03333333333333333  # initial lattice spacing dx = 1/30 (must divide each domain length)
density = 1.0                  # reference density rho0 (> 0)
viscosity = 0.01               # kinematic viscosity nu (>= 0): Re = 1 * 1 / 0.01 = 100
body_force = ["0", "0"]        # acceleration g(x, y, t), one expression per dimension
shuffle_initial_order = false  # true: particles stored in a fixed pseudo-random order (ids kept): benchmarks of a mixed run

[initial]
velocity = ["0", "0"]          # initial velocity u(x, y), one expression per dimension
offset = ["0", "0"]            # displacement of each lattice point (x, y) at t = 0, e.g. to perturb one particle

# Further phases, by region (same number density, other mass); expressions in x, y and pi:
# [[phase]]
# where = "y > 1 - 0.15*sin(2*pi*x)"   # non-zero selects the particle; must select at least one
# density = 1.8                        # reference density of the phase (> 0)

[method]
scheme = "wcsph"               # "wcsph" | "isph" | "isph-gpps"  (arksph list)
kernel = "wendland_quintic"    # "cubic_spline" | "quartic_spline" | "wendland_quintic" | "quintic_spline"
h_over_dx = 2.0                # smoothing length h / dx, in [0.5, 4]
viscosity_model = "morris"     # Basa models "direct" (A) | "two_pass" (B) | "violeau" (C) | "cleary" (D) | "morris" (E); or "monaghan"
cleary_xi = 4.96333            # model D calibration constant xi (Basa eq. 34; > 0)
kernel_correction = "none"     # "none" | "shepard" (Basa eqs. 21-23) | "bonet_lok" (Basa eqs. 24-26): corrected gradients
pressure_reduction = false     # subtract the local average pressure in the pressure gradient (Basa eq. 20)
equation_of_state = "tait"     # "tait" (Basa eq. 13) | "ideal_gas" (Basa eq. 12, energy equation 14 in the state; wcsph only)
gas_gamma = 1.4                # ideal_gas: p = (gamma - 1) rho e, e(0) such that the sound speed is sound_speed (> 1)
sound_speed = 10.0             # WCSPH sound speed c0 (>= 0; 0: the documented default); wcsph only
tait_gamma = 7.0               # exponent of the Tait equation of state (>= 1), Cummins & Rudman eq. 7
background_pressure = 1.0      # constant added to the Tait pressure (>= 0; Morris et al. 1997); keeps p > 0 at the walls
density_mode = "continuity"    # "continuity" (Szewc eq. 19) | "summation" (Szewc eq. 21)
pressure_gradient = "colagrossi"   # "colagrossi" (Szewc eq. 23) | "monaghan" (C&R eq. 1)
density_correction = "none"    # "none" | "pozorski_wawrenczuk" (projection schemes only)
ppe_operator = "approximate"   # isph: "approximate" (C&R eq. 19) | "exact" (C&R eq. 18: odd-even decoupling; klu only)
ppe_divergence = "cummins_rudman"  # isph: PPE source, "cummins_rudman" (C&R eq. 17, ghosts out) | "difference" (ghosts in; stable at lid corners)
ppe_pressure_level = "zero_mean"  # isph: free level of P, "zero_mean" | "zero_min" (P >= 0, so eq. 11 never attracts)
ppe_pressure_offset = 0.0        # isph: constant added to P after the level (a background pressure)
neighbor_storage = "pairs"       # "pairs": kernel values stored per pair (fast) | "candidates": recomputed by every term (less memory)
force_sweep = true               # force terms share one neighbour gather per particle (no pair storage); same results
ppe_solver = "auto"            # isph: Poisson solver, "klu" (direct) | "cg" (Jacobi CG) | "cg_ic" (incomplete-Cholesky CG) | "cg_amg" (CG + aggregation AMG) | "auto" (KLU up to 400 particles, else cg_amg); CG warm-started
ppe_tolerance = 1e-10          # isph with cg: relative residual
gpps_spacing = 0              # isph-gpps: cell size of the auxiliary Poisson grid (Szewc §4.2); 0: fluid.spacing; must divide the box
gpps_volume_relaxation = 0     # isph-gpps: beta in [0, 1] of the source term -beta (phi - 1)/dt^2, phi = particle volume per cell / cell volume (0: off)
centre_positions = true        # isph: positions centred in time, Cummins & Rudman eq. 12
projection_points = "step"     # isph: project after each "step" (C&R) | "stages": also after every ERK stage
reorder_every = 100            # re-sort the particles by cell (grid of side = kernel support) at t = 0 and every this many steps (>= 0; 0: never)
correction_threshold = 1e-3    # pozorski_wawrenczuk: r.m.s. relative density error that triggers it (>= 0)
correction_max_iterations = 1  # pozorski_wawrenczuk: correction solves per step at most (Szewc: 1)
correction_solver = "fixed_point"  # pozorski_wawrenczuk: "fixed_point" (linear solves) | "kinsol" (Newton, KLU) | "newton" (exact Jacobian)

[time]
end = 2.0                      # final simulated time (> 0); a coarse start-up, a few seconds on 2 cores
integrator = "ARKODE_HEUN_EULER_2_1_2"   # ARKODE explicit Butcher table (arksph list)
dt = 0.0                       # 0: adaptive, limited by the stability bounds; > 0: fixed step
cfl = 0.25                     # coefficient of the stability limits, Szewc eqs. 34-35, in (0, 1]
rtol = 1e-2                    # relative tolerance (adaptive mode only, > 0; loose: the stability limits govern)
atol = 1e-4                    # absolute tolerance (adaptive mode only, > 0)
max_steps = 100000000          # abort after this many steps (>= 1)
imex = false                   # true: ARKStep IMEX, viscous term implicit (Newton + KLU), no viscous step limit (wcsph)
imex_pair = "ARK324L2SA"       # imex: ARKODE additive pair ARK324L2SA | ARK436L2SA | ARK437L2SA | ARK548L2SA | ARK548L2SAb
imex_linear = false            # imex: true: ARKStepSetLinear, exact J at every stage, one Newton iteration (slow); false: Newton, J reused

[output]
directory = "runs/default"     # output folder (--out overrides; default runs/<scene.name>)
every = 0.5                    # simulated time between VTP frames (0: first and last only)
checkpoint_every = 0.0         # simulated time between checkpoint.h5 writes (>= 0; 0: only at the end)

[metrics]
ghia_re = 100                  # Ghia et al. 1982 centreline errors: 0 (off), 100 or 1000
poiseuille = false             # Poiseuille error of Basa et al. 2008 eqs. 36-39
interface = false              # two phases: interface_NNNNNN.csv (0.5 contour of the smoothed phase), bubble/spike tips
)toml";
}

}  // namespace arksph
