// The general scene keys (those not declared by a registered part), in the order of the scene file,
// and their assembly with the families' keys into the scene catalog.
#include <algorithm>

#include "boundary/wall_velocity_rules.hpp"
#include "core/param_builder.hpp"
#include "core/scheme.hpp"
#include "diagnostics/steady_state.hpp"
#include "integrate/time_params.hpp"
#include "io/scene_catalog.hpp"
#include "kernels/kernel.hpp"
#include "projection/correction/DensityCorrection_PozorskiWawrenczuk.hpp"
#include "projection/grid/ProjectionGrid_Szewc2012.hpp"
#include "projection/poisson/poisson_solver.hpp"
#include "projection/projection.hpp"
#include "rhs/density/initial_density.hpp"
#include "rhs/reference_speed.hpp"
#include "rhs/term_registry.hpp"

namespace arksph {

namespace {

ParamBuilder numbers(std::string key) {
  return ParamBuilder(std::move(key), Param::Type::numbers, std::vector<double>{});
}
ParamBuilder expressions(std::string key, std::vector<std::string> variables) {
  ParamBuilder b(std::move(key), Param::Type::expressions, std::vector<std::string>{"0", "0"});
  b.variables(std::move(variables));
  return b;
}
// A sub-table read by the scene reader's own code (a side of the box); listed for the reference.
ParamBuilder table(std::string key, std::string doc) {
  ParamBuilder b(std::move(key), Param::Type::table, std::string());
  b.doc(std::move(doc)).custom();
  return b;
}

FamilyInfo kernel_family() {
  FamilyInfo info{"kernel", "method.kernel", {}, {}};
  for (const auto& [name, summary] : kernel_summaries()) info.entries.push_back({name, summary, {}, {}});
  return info;
}

// method.density_mode = "auto". wcsph with phases: the summation density (Szewc eq. 21); with the
// continuity equation the Rayleigh-Taylor case blows up at t ~ 0.85. One phase, and the projection
// schemes (whose density is not in the state): continuity (Szewc eq. 19), the setting of the cavity
// and Poiseuille cases.
std::string automatic_density_mode(const Scene& s) {
  return scheme_traits(s.scheme).weakly_compressible && !s.phases.empty() ? "summation" : "continuity";
}

// True for isph (C&R's projection after each step) with the P-W correction, in a walled box with a
// flow (a wall or initial speed): the scenes whose automatic regularisation is the transport velocity.
bool corrected_walled_flow(const Scene& s) {
  bool wall = false;
  for (int i = 0; i < 2 * s.dimension; ++i) wall |= s.sides[i].kind == SideKind::wall;
  return wall && scheme_traits(s.scheme).particle_poisson() && !s.pressure_in_f() &&
         s.density_correction == "pozorski_wawrenczuk" && flow_speed(s) > 0;
}

// method.regularisation = "auto". Particle shifting for every scheme: on the Taylor-Green vortex
// (Re = 100, 50 x 50, t = 1) it brings the relative L1 velocity error from 0.42 to 0.003 (isph,
// constrained projection), 0.51 to 0.05 (isph-gpps) and 0.73 to 0.003 (wcsph, with delta-SPH), and
// it keeps the walled spin-down's density error at a fiftieth (docs/methods/regularisation.md).
// Where the P-W correction already holds the particles at the reference density in a walled flow,
// Adami's transport velocity: it dissipates less than shifting and imposes no step limit. Cavity at
// Re = 1000, 60 x 60, t = 60, with the quadratic wall velocity that comes with it: Ghia r.m.s.
// 0.026 / 0.038 in 8,041 steps, against shifting's 0.055 / 0.077 in 42,600 (cases/cavity_re1000).
std::string automatic_regularisation(const Scene& s) {
  return corrected_walled_flow(s) ? "transport_velocity" : "shifting";
}

// boundary.wall_velocity = "auto". Mirrored ghosts (Szewc's walls), except beside the transport
// velocity of isph with the P-W correction: there the walls' dissipation is the larger error left,
// and Basa's quadratic extrapolation takes it out (cavity at Re = 1000: Ghia v r.m.s. 0.040 against
// 0.056 mirrored, kinetic energy at t = 60 0.037 against 0.034).
std::string automatic_wall_velocity(const Scene& s) {
  const std::string regularisation = s.regularisation == "auto" ? automatic_regularisation(s) : s.regularisation;
  return corrected_walled_flow(s) && regularisation == "transport_velocity" && s.dimension == 2 ? "quadratic"
                                                                                                 : "mirror";
}

// method.density_diffusion = "auto". delta-SPH damps WCSPH's pressure noise where the density is a
// state (the continuity equation); nothing to diffuse otherwise.
std::string automatic_density_diffusion(const Scene& s) {
  const std::string mode = s.density_mode == "auto" ? automatic_density_mode(s) : s.density_mode;
  return scheme_traits(s.scheme).weakly_compressible && mode == "continuity" ? "delta_sph" : "none";
}

// boundary.free_slip_divergence = "auto". The cavity (Re = 1000) needs the free-slip images for
// isph-gpps (the run blows up by t ~ 0.8 without them) and for wcsph, where the no-slip divergence
// at the lid corners gives a negative density by t ~ 0.07 (Re = 100: the same). isph with C&R eq. 17
// does not read them; walls at rest under wcsph keep the no-slip images (Poiseuille, Basa's setting),
// except below a free surface: in the dam break (a column a x 2a, 40 x 80 particles, up to its
// impact on the far wall) the floor's no-slip images behind the surge's tip, their tangential
// velocity reversed, put a false compression of order 2 U into the tip's continuity equation; the
// floor particles at the tip then reach 2-3 times the front speed with pressures of -40 to +50
// rho g a. With the free-slip images the largest speed is the tip's (within 7 %) and the pressure
// stays within [-0.7, 1.9] rho g a.
std::string automatic_free_slip_divergence(const Scene& s) {
  bool wall = false, moving = false;
  for (int i = 0; i < 2 * s.dimension; ++i) {
    if (s.sides[i].kind != SideKind::wall) continue;
    wall = true;
    moving |= s.sides[i].velocity[0] != 0 || s.sides[i].velocity[1] != 0;
  }
  const SchemeTraits& scheme = scheme_traits(s.scheme);
  const bool surface = !s.fluid_region.empty();
  return wall && (scheme.grid || (scheme.weakly_compressible && (moving || surface))) ? "true" : "false";
}

// One entry per key; a family selector pulls in the family's keys right after itself.
struct Group {
  std::vector<Param> keys;
  std::string owner;
};

std::vector<Group> general_keys() {
  const std::string side_doc =
      "{ kind = \"wall\" | \"periodic\", velocity = [wall velocity], slip = \"no_slip\" | \"free_slip\" }; "
      "a periodic side needs its opposite periodic too";
  return {
      {{text("scene.name", "unnamed").doc("label for messages, summary.json and the default output directory")
            .to(&Scene::name),
        integer("scene.dimension", 2).allowed({1, 2}).doc("1 or 2").to(&Scene::dimension),
        numbers("domain.min").required().custom().unit("m").doc("lower corner of the fluid box, one number per dimension"),
        numbers("domain.max").required().custom().unit("m").doc("upper corner (max > min in every component)"),
        table("boundary.left", side_doc),
        table("boundary.right", side_doc),
        table("boundary.bottom", side_doc + " (2D only)"),
        table("boundary.top", side_doc + " (2D only)"),
        number("boundary.corner_alpha", 0.0).in(between(-1, 1))
            .doc("corner ghost weighting alpha (Szewc et al. 2012 eq. 46)").to(&Scene::corner_alpha),
        flag("boundary.free_slip_divergence", false)
            .doc("free-slip images for the velocity divergence only (Szewc et al. 2012 §6); auto: true with walls for isph-gpps, and for wcsph when a wall moves or the fluid has a free surface (fluid.region); else false")
            .automatic(automatic_free_slip_divergence).to(&Scene::free_slip_divergence),
        choice("boundary.wall_velocity", "auto").family("wall_velocity")
            .doc("tangential velocity of no-slip ghosts; auto: quadratic beside the transport velocity that isph with "
                 "the P-W correction takes in a walled flow, else mirror")
            .automatic(automatic_wall_velocity).to(&Scene::wall_velocity),
        flag("boundary.wall_ghosts", true)
            .doc("mirror images of the fluid across the walls (Szewc et al. 2012 §6); false: none, the walls act "
                 "through boundary.wall_force only (wcsph)")
            .to(&Scene::wall_ghosts),
        choice("boundary.wall_force", "none").family("wall_force")
            .doc("force of the walls on the fluid particles, added to the ghosts' action").to(&Scene::wall_force),
        flag("boundary.wall_particles", false)
            .doc("particles on the no-slip walls with the wall velocity, one per fluid particle within dx "
                 "(Basa et al. 2008 §6.1.2; 2D)")
            .to(&Scene::wall_particles),
        number("fluid.spacing", 0.02).required().in(above(0)).unit("m")
            .doc("initial lattice spacing dx; must divide each domain length").to(&Scene::spacing),
        text("fluid.region", "")
            .doc("where the domain holds fluid at t = 0: an expression in x, y, non-zero selects a lattice "
                 "point (e.g. \"x < 1 && y < 2\"); empty: the whole domain. The rest is empty, and the "
                 "fluid has a free surface where it meets the empty part")
            .to(&Scene::fluid_region),
        number("fluid.density", 1.0).in(above(0)).unit("kg/m^d").doc("reference density rho0").to(&Scene::density),
        number("fluid.viscosity", 0.01).in(at_least(0)).unit("m^2/s").doc("kinematic viscosity nu")
            .to(&Scene::viscosity),
        expressions("fluid.body_force", {"x", "y", "t"}).unit("m/s^2")
            .doc("acceleration g(x, y, t), one expression per dimension").to(&Scene::body_force),
        flag("fluid.shuffle_initial_order", false)
            .doc("particles stored in a fixed pseudo-random order at t = 0 (ids kept): benchmarks of a mixed run")
            .to(&Scene::shuffle_initial_order),
        expressions("initial.velocity", {"x", "y"}).unit("m/s")
            .doc("initial velocity u(x, y), one expression per dimension").to(&Scene::initial_velocity),
        expressions("initial.offset", {"x", "y"}).unit("m")
            .doc("displacement of each lattice point (x, y) at t = 0").to(&Scene::initial_offset)},
       ""},
      {initial_density_params(), "wcsph"},
      {{
        ParamBuilder("phase.where", Param::Type::text, std::string()).required().custom()
            .doc("[[phase]]: region of a further phase, an expression in x, y; non-zero selects; must select a particle"),
        ParamBuilder("phase.density", Param::Type::number, 1.0).required().custom().in(above(0))
            .doc("[[phase]]: reference density of the phase (same number density, other mass)"),
        choice("method.scheme", "wcsph").family("scheme").doc("time-stepping scheme").to(&Scene::scheme),
        choice("method.kernel", "wendland_quintic").family("kernel").doc("smoothing kernel").to(&Scene::kernel),
        number("method.h_over_dx", 2.0).in(between(0.5, 4)).doc("smoothing length h / dx; the kernel radius (support x h) must exceed dx").to(&Scene::h_over_dx),
        choice("method.viscosity_model", "morris").family("viscosity_model")
            .doc("viscous term (Basa et al. 2008 models A-E)").to(&Scene::viscosity_model),
        choice("method.kernel_correction", "none").family("kernel_correction")
            .doc("corrected kernel gradients in the pressure and viscous terms (Basa et al. 2008 §4)")
            .to(&Scene::kernel_correction),
        flag("method.pressure_reduction", false)
            .doc("local average pressure subtracted in the pressure gradient (Basa et al. 2008 eq. 20)")
            .to(&Scene::pressure_reduction),
        choice("method.equation_of_state", "tait").family("equation_of_state")
            .doc("equation of state of wcsph").to(&Scene::equation_of_state),
        choice("method.density_mode", "auto").family("density_mode")
            .doc("how the density is obtained; auto: summation for wcsph with a [[phase]], else continuity")
            .automatic(automatic_density_mode).to(&Scene::density_mode),
        choice("method.pressure_gradient", "colagrossi").family("pressure_gradient")
            .doc("symmetric form of the pressure gradient (wcsph)").to(&Scene::pressure_gradient),
        choice("method.density_correction", "none").family("density_correction")
            .doc("position correction after the projection (projection schemes)").to(&Scene::density_correction),
        choice("method.regularisation", "auto").family("regularisation")
            .doc("particle regularisation: a velocity added to dr/dt inside f(t, y); auto: transport_velocity for isph "
                 "with the P-W correction in a walled flow, else shifting")
            .automatic(automatic_regularisation).to(&Scene::regularisation),
        choice("method.density_diffusion", "auto").family("density_diffusion")
            .doc("diffusive term in the continuity equation (wcsph); auto: delta_sph for wcsph with the continuity equation, else none")
            .automatic(automatic_density_diffusion).to(&Scene::density_diffusion)},
       ""},
      {projection_params(), "isph"},
      {{choice("method.neighbor_storage", "pairs").choices({"pairs", "candidates"})
            .doc("kernel values stored per pair (fast), or only the candidates stored and the kernel recomputed by every term (less memory)")
            .to(&Scene::neighbor_storage),
        flag("method.force_sweep", true)
            .doc("force terms share one neighbour gather per particle (no pair storage); same results")
            .to(&Scene::force_sweep),
        choice("method.ppe_solver", "auto").family("ppe_solver").doc("Poisson solver of the projection schemes")
            .to(&Scene::ppe_solver)},
       ""},
      {grid_projection_params(), "isph-gpps"},
      {projection_time_params(), "isph"},
      {{integer("method.reorder_every", 100).in(at_least(0))
            .doc("re-sort the particles by cell at t = 0 and every this many steps (0: never)")
            .to(&Scene::reorder_every),
        number("time.end", 1.0).required().in(above(0)).unit("s").doc("final simulated time (at least 1e-150)").to(&Scene::end)},
       ""},
      {steady_state_params(), ""},
      {time_params(), "time integration"},
      {imex_params(), "imex"},
      {{text("output.directory", "").doc("output folder (--out overrides); default runs/<scene.name>")
            .to(&Scene::directory),
        number("output.every", 0.0).in(at_least(0)).unit("s")
            .doc("simulated time between VTP frames (0: first and last only); at most 100,000 frames up to time.end").to(&Scene::every),
        number("output.checkpoint_every", 0.0).in(at_least(0)).unit("s")
            .doc("simulated time between checkpoint.h5 writes (0: only at the end); at most 100,000 up to time.end").to(&Scene::checkpoint_every),
        flag("output.pieces", false)
            .doc("runs over several MPI ranks: each rank writes its particles of a frame as particles_NNNNNN_rR.vtp and rank 0 "
                 "particles_NNNNNN.pvtp, listed in particles.pvd; one process: ignored")
            .to(&Scene::pieces),
        flag("output.walls", false)
            .doc("the wall points (mirror images within one kernel support beyond each wall, and boundary.wall_particles) "
                 "of each frame as walls_NNNNNN.vtp (kind 1, id of the particle imaged), listed in walls.pvd; with "
                 "output.pieces, walls_NNNNNN_rR.vtp and walls_NNNNNN.pvtp")
            .to(&Scene::walls),
        integer("metrics.ghia_re", 0).allowed({0, 100, 1000, 10000})
            .doc("Ghia et al. 1982 centreline errors at this Reynolds number (100, 1000 or 10000; 0: off); 2D lid-driven cavity only").to(&Scene::ghia_re),
        flag("metrics.poiseuille", false).doc("Poiseuille error of Basa et al. 2008 eqs. 36-39; 2D channel only (periodic in x, resting walls, force along x)")
            .to(&Scene::poiseuille),
        flag("metrics.interface", false)
            .doc("two phases: interface_NNNNNN.csv (0.5 contour of the smoothed phase), bubble and spike tips")
            .to(&Scene::interface),
        expressions("metrics.exact_velocity", {"x", "y", "t"}).unit("m/s")
            .doc("exact velocity u(x, y, t), one expression per dimension (all 0: off): relative L1 velocity "
                 "error, peak-speed error and amplitude error (the fitted multiple of the exact field, minus 1) in "
                 "timeseries.csv and summary.json")
            .to(&Scene::exact_velocity),
        flag("metrics.energy_budget", false)
            .doc("energy budget in timeseries.csv and summary.json: potential energy -sum m g . r, the compressible "
                 "energy of the equation of state (wcsph; 0 for the projection schemes), the viscous dissipation "
                 "integrated over the steps and the total with the kinetic energy, which stays constant up to the "
                 "time-integration error and the terms that are not conservative (docs/methods/energy-budget.md); "
                 "needs a constant body force with no component along a periodic axis; costs one field refresh per step")
            .to(&Scene::energy_budget)},
       ""},
  };
}

std::vector<CatalogKey> build_catalog() {
  std::vector<CatalogKey> out;
  for (const Group& g : general_keys()) {
    for (const Param& p : g.keys) {
      out.push_back({p, g.owner});
      if (p.family.empty()) continue;
      const FamilyInfo* f = find_family(p.family);
      if (!f) continue;
      for (const Param& fp : f->params) out.push_back({fp, f->family});
      for (const auto& e : f->entries)
        for (const Param& ep : e.params) out.push_back({ep, f->family + ": " + e.name});
    }
  }
  return out;
}

}  // namespace

const std::vector<FamilyInfo>& scene_families() {
  static const std::vector<FamilyInfo> families = {
      describe(scheme_registry()),       kernel_family(),
      describe(viscosity_models()),      describe(pressure_gradients()),
      describe(density_modes()),         describe(kernel_corrections()),
      describe(equations_of_state()),    describe(density_corrections()),
      describe(correction_solvers()),    describe(poisson_solvers()),
      describe(wall_velocity_rules()),   describe(erk_tables()),
      describe(imex_pairs()),            describe(regularisations()),
      describe(density_diffusions()),       describe(wall_forces()),
  };
  return families;
}

const FamilyInfo* find_family(const std::string& family) {
  for (const auto& f : scene_families())
    if (f.family == family) return &f;
  return nullptr;
}

const std::vector<CatalogKey>& scene_catalog() {
  static const std::vector<CatalogKey> catalog = build_catalog();
  return catalog;
}

std::vector<std::string> scene_tables() {
  std::vector<std::string> tables;
  for (const auto& k : scene_catalog()) {
    const std::string t = k.param.key.substr(0, k.param.key.find('.'));
    if (std::find(tables.begin(), tables.end(), t) == tables.end()) tables.push_back(t);
  }
  return tables;
}

std::vector<std::string> keys_of_table(const std::string& table) {
  std::vector<std::string> keys;
  for (const auto& k : scene_catalog())
    if (k.param.key.compare(0, table.size() + 1, table + ".") == 0) keys.push_back(k.param.key.substr(table.size() + 1));
  return keys;
}

}  // namespace arksph
