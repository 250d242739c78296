// The general scene keys (those not declared by a registered part), in the order of the scene file,
// and their assembly with the families' keys into the scene catalog.
#include <algorithm>
#include <stdexcept>

#include "boundary/wall_velocity_rules.hpp"
#include "boundary/walled_flow.hpp"
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
#include "rhs/neighbor_cache.hpp"
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
  FamilyInfo info{"kernel", "method.kernel", {}, {}, {}};
  for (const auto& [name, summary] : kernel_summaries()) info.entries.push_back({name, summary, {}, {}});
  return info;
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
        free_slip_divergence_param(),
        choice("boundary.wall_velocity", "auto").family("wall_velocity")
            .doc("tangential velocity of no-slip ghosts")
            .to(&Scene::wall_velocity),
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
        choice("method.viscosity_model", "auto").family("viscosity_model")
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
            .doc("how the density is obtained").to(&Scene::density_mode),
        choice("method.pressure_gradient", "colagrossi").family("pressure_gradient")
            .doc("symmetric form of the pressure gradient (wcsph)").to(&Scene::pressure_gradient),
        choice("method.density_correction", "none").family("density_correction")
            .doc("position correction after the projection (projection schemes)").to(&Scene::density_correction),
        choice("method.regularisation", "auto").family("regularisation")
            .doc("particle regularisation: a velocity added to dr/dt inside f(t, y)").to(&Scene::regularisation),
        choice("method.density_diffusion", "auto").family("density_diffusion")
            .doc("diffusive term in the continuity equation (wcsph)").to(&Scene::density_diffusion)},
       ""},
      {projection_params(), "isph"},
      {{choice("method.neighbor_storage", "pairs").choices(neighbor_storages().names())
            .doc("kernel values stored per pair (fast), or only the candidates stored and the kernel recomputed by every term (less memory)")
            .to(&Scene::neighbor_storage, neighbor_storages()),
        flag("method.force_sweep", true)
            .doc("force terms share one neighbour gather per particle (no pair storage); same results")
            .to(&Scene::force_sweep),
        choice("method.ppe_solver", "auto").family("ppe_solver").doc("Poisson solver of the projection schemes")
            .to(&Scene::ppe_solver),
        choice("method.rank_ppe_solver", "auto").choices({"auto", "amg", "hypre"})
            .doc("Poisson solver of the projection schemes over MPI ranks: amg (CG with cg_amg's V-cycle, distributed), "
                 "hypre (PCG with BoomerAMG); auto: amg")
            .to(&Scene::rank_ppe_solver)},
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

// The parts a scene selects, read from its family keys; a key at "auto" is answered by its family's
// rule, so a rule may ask for a family whose key is resolved after its own.
class CatalogParts final : public SelectedParts {
 public:
  explicit CatalogParts(const Scene& s) : s_(s) {}
  std::string name(const std::string& family) const override {
    const FamilyInfo& f = known_family(family);
    for (const CatalogKey& k : scene_catalog())
      if (k.param.key == f.key) {
        const std::string value = std::get<std::string>(k.param.load(s_));
        return value == "auto" && f.automatic ? f.automatic.choose(s_, *this) : value;
      }
    throw std::logic_error("family " + family + ": its key " + f.key + " is not in the scene catalog");
  }
  const PartTraits& traits(const std::string& family) const override {
    const FamilyInfo& f = known_family(family);
    const std::string selected = name(family);
    for (const auto& e : f.entries)
      if (e.name == selected) return e.traits;
    throw std::out_of_range("unknown " + family + " '" + selected + "'");
  }

 private:
  static const FamilyInfo& known_family(const std::string& family) {
    if (const FamilyInfo* f = find_family(family)) return *f;
    throw std::logic_error("automatic rule: no family " + family);
  }
  const Scene& s_;
};

// A key that selects a part of a family with an automatic rule takes "auto" (its default) and the
// rule, whose description ends the key's.
CatalogKey catalog_key(Param p, std::string owner) {
  const FamilyInfo* f = p.family.empty() ? nullptr : find_family(p.family);
  if (f && f->automatic && p.key == f->key) {
    p.fallback = std::string("auto");
    p.doc += "; auto: " + f->automatic.doc;
    p.automatic = [f](const Scene& s) { return f->automatic.choose(s, CatalogParts(s)); };
  }
  return {std::move(p), std::move(owner)};
}

std::vector<CatalogKey> build_catalog() {
  std::vector<CatalogKey> out;
  for (const Group& g : general_keys()) {
    for (const Param& p : g.keys) {
      out.push_back(catalog_key(p, g.owner));
      if (p.family.empty()) continue;
      const FamilyInfo* f = find_family(p.family);
      if (!f) continue;
      for (const Param& fp : f->params) out.push_back(catalog_key(fp, f->family));
      for (const auto& e : f->entries)
        for (const Param& ep : e.params) out.push_back(catalog_key(ep, f->family + ": " + e.name));
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
