// The pressure Poisson system of a scene on one process (assemble_ppe, every rank builds it whole)
// and its rows on this rank of a decomposition (distributed_ppe::assemble_rows over the rank's
// particles and halo), on the scene's lattice jittered by up to 0.2 dx so that no two rows are alike.
#pragma once
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "distributed_ppe/ppe_rows.hpp"
#include "io/scene_reader.hpp"
#include "kernels/kernel.hpp"
#include "parallel/halo.hpp"
#include "projection/ppe_assembly.hpp"
#include "rhs/terms.hpp"
#include "run/setup.hpp"

namespace arksph::parallel::testing {

constexpr double kPpeDt = 1e-3;
// The halo of a decomposed run: two supports and the Verlet skin (distributed/halo_rhs.hpp).
constexpr double kPpeHaloSupports = 2.15;

// A 30 x 30 unit box, ISPH, Wendland kernel h = 2 dx, with a velocity field of non-zero divergence;
// walls on every side, or periodic on every side.
inline Scene ppe_scene(bool periodic, const std::string& spacing = "0.03333333333333333") {
  std::string text = R"toml(
[scene]
name = "ppe_box"
[domain]
min = [0.0, 0.0]
max = [1.0, 1.0]
)toml";
  if (periodic)
    text += "[boundary]\nleft = { kind = \"periodic\" }\nright = { kind = \"periodic\" }\n"
            "bottom = { kind = \"periodic\" }\ntop = { kind = \"periodic\" }\n";
  text += R"toml(
[fluid]
spacing = 0.1
viscosity = 0.01
[initial]
velocity = ["sin(2*pi*x)*cos(2*pi*y) + 0.3*sin(2*pi*x)", "0.2*sin(2*pi*(x+y))"]
[method]
scheme = "isph"
kernel = "wendland_quintic"
h_over_dx = 2.0
[time]
end = 0.01
dt = 0.001
)toml";
  std::ostringstream warnings;
  return read_scene_text(text, "<ppe test>", {"fluid.spacing=" + spacing}, warnings);
}

inline Domain ppe_domain(const Scene& scene) {
  Domain d;
  d.dim = 2;
  for (int k = 0; k < 2; ++k) {
    d.box.lo[static_cast<std::size_t>(k)] = scene.min[k];
    d.box.hi[static_cast<std::size_t>(k)] = scene.max[k];
    d.periodic[static_cast<std::size_t>(k)] = scene.sides[2 * static_cast<std::size_t>(k)].kind == SideKind::periodic;
  }
  return d;
}

// Rows of given P as a free surface gives them (projection/ppe_assembly.hpp), here a band at the
// top of the box, y > 0.75, with a P that varies along it, so that a column moved to the wrong row or
// a given value lost shows in the rows and the solution.
inline bool in_given_band(double y) { return y > 0.75; }
inline double given_value(double x, double y) { return 0.3 + 0.1 * std::cos(2 * M_PI * x) + 0.05 * y; }

// The whole system as one process builds it (every rank alike: the same seed); with `given`, the
// rows of the band above given.
struct OneProcessPpe {
  Scene scene;
  Model model;  // lattice, h
  ParticleSet particles;  // jittered, wrapped into the box
  std::unique_ptr<RhsEvaluator> rhs;
  DirichletRows given;  // per particle; empty without the band
  PoissonSystem sys;

  explicit OneProcessPpe(const Scene& s, bool with_given = false) : scene(s), model(build_model(s)), particles(model.particles) {
    const Domain domain = ppe_domain(scene);
    std::mt19937 rng(2024);
    std::uniform_real_distribution<double> jitter(-0.2 * scene.spacing, 0.2 * scene.spacing);
    for (std::size_t a = 0; a < particles.n; ++a) {
      double x[3] = {particles.init_pos[0][a] + jitter(rng), particles.init_pos[1][a] + jitter(rng), 0};
      domain.wrap(x);
      particles.init_pos[0][a] = x[0];
      particles.init_pos[1][a] = x[1];
    }
    rhs = std::make_unique<RhsEvaluator>(scene, particles, make_kernel(scene.kernel, model.h, 2),
                                         terms_from_scene(scene, model.sound_speed));
    std::vector<double> y(rhs->layout().size());
    rhs->initial_state(y.data());
    rhs->eval(0.0, y.data(), nullptr);
    const FluidFields& f = rhs->fields();
    if (with_given) {
      for (std::size_t a = 0; a < f.n_real; ++a) {
        given.fixed.push_back(in_given_band(f.y[a]) ? 1 : 0);
        given.value.push_back(given_value(f.x[a], f.y[a]));
      }
    }
    assemble_ppe(f, divergence_cummins_rudman(f), kPpeDt, given, sys);
  }
  double radius() const { return rhs->kernel().radius(); }
};

// This rank's particles and halo of the one-process particle set, and its rows.
struct RankPpe {
  enum Field : int { X = 0, Y, U, V, MASS, RHO0, PHASE, ROW, INDEX, N_FIELDS };
  ParticleFields owned, halo;
  distributed_ppe::RowRange range;
  std::vector<distributed_ppe::GlobalRow> row_of;  // owned, then halo
  std::vector<std::size_t> index_of;               // one-process index of owned, then halo
  distributed_ppe::GlobalRow pinned = -1;
  Scene scene;  // one.scene, its periodic sides bringing halo copies (SideSpec::halo): walls only
  std::unique_ptr<RhsEvaluator> rhs;
  distributed_ppe::LocalRows rows;

  DirichletRows given;  // one's given rows, owned then halo; empty without them

  // keep_halo < 1: only that leading fraction of the received halo copies is kept (a test of the
  // test: a rank that misses copies must assemble other rows). halo_flags false: the halo copies
  // are not given rows whatever their owners are (a test of the test for the given rows).
  RankPpe(const Communicator& comm, const OneProcessPpe& one, double keep_halo = 1.0, bool halo_flags = true)
      : owned(2, N_FIELDS), halo(2, N_FIELDS), scene(one.scene) {
    for (SideSpec& side : scene.sides) side.halo = side.kind == SideKind::periodic;
    const ParticleSet& ps = one.particles;
    const CellGrid grid(ppe_domain(one.scene), one.radius());
    ParticleFields positions(2, 2);
    positions.resize(ps.n);
    for (std::size_t a = 0; a < ps.n; ++a) {
      positions.field[0][a] = ps.init_pos[0][a];
      positions.field[1][a] = ps.init_pos[1][a];
    }
    const Decomposition dec = Decomposition::rcb(grid, count_per_cell(grid, positions), comm.size());
    for (std::size_t a = 0; a < ps.n; ++a) {
      const double x[2] = {ps.init_pos[0][a], ps.init_pos[1][a]};
      if (dec.owner(x) != comm.rank()) continue;
      owned.id.push_back(static_cast<std::uint64_t>(ps.id[a]));
      const double values[N_FIELDS] = {x[0], x[1], ps.init_vel[0][a], ps.init_vel[1][a], ps.mass[a], ps.rho0[a],
                                       static_cast<double>(ps.phase[a]), 0.0, static_cast<double>(a)};
      for (int k = 0; k < N_FIELDS; ++k) owned.field[static_cast<std::size_t>(k)].push_back(values[k]);
    }
    HaloExchange exchange;
    exchange.exchange(comm, dec, owned, kPpeHaloSupports * one.radius(), halo);
    range = distributed_ppe::global_rows(comm, owned.size());
    for (std::size_t i = 0; i < owned.size(); ++i) owned.field[ROW][i] = static_cast<double>(range.first + static_cast<std::int64_t>(i));
    exchange.update(comm, owned, {ROW}, halo);
    halo.resize(static_cast<std::size_t>(keep_halo * static_cast<double>(halo.size())));
    std::vector<std::int64_t> ids;
    for (std::uint64_t id : owned.id) ids.push_back(static_cast<std::int64_t>(id));
    pinned = distributed_ppe::row_of_id(comm, ids, range, ps.id[0]);  // one process pins its particle 0

    ParticleSet set;
    set.dim = 2;
    set.n = owned.size() + halo.size();
    set.dx = ps.dx;
    set.init_energy = ps.init_energy;
    for (const ParticleFields* p : {&owned, &halo}) {
      for (std::size_t i = 0; i < p->size(); ++i) {
        set.id.push_back(static_cast<std::int64_t>(p->id[i]));
        set.mass.push_back(p->field[MASS][i]);
        set.rho0.push_back(p->field[RHO0][i]);
        set.phase.push_back(static_cast<std::int32_t>(p->field[PHASE][i]));
        for (int k = 0; k < 2; ++k) {
          set.init_pos[k].push_back(p->field[static_cast<std::size_t>(X + k)][i]);
          set.init_vel[k].push_back(p->field[static_cast<std::size_t>(U + k)][i]);
        }
        row_of.push_back(static_cast<distributed_ppe::GlobalRow>(p->field[ROW][i]));
        index_of.push_back(static_cast<std::size_t>(p->field[INDEX][i]));
      }
    }
    rhs = std::make_unique<RhsEvaluator>(scene, set, make_kernel(scene.kernel, one.model.h, 2),
                                         terms_from_scene(scene, one.model.sound_speed));
    std::vector<double> y(rhs->layout().size());
    rhs->initial_state(y.data());
    rhs->eval(0.0, y.data(), nullptr);
    const FluidFields& f = rhs->fields();
    if (!one.given.empty()) {
      for (std::size_t s = 0; s < f.n_real; ++s) {
        const std::size_t i = index_of[s];
        given.fixed.push_back(s < owned.size() || halo_flags ? one.given.fixed[i] : 0);
        given.value.push_back(one.given.value[i]);
      }
    }
    distributed_ppe::assemble_rows(comm, f, owned.size(), row_of, range, pinned, divergence_cummins_rudman(f), kPpeDt, rows,
                                   given);
  }
};

}  // namespace arksph::parallel::testing
