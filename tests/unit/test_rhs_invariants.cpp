// Invariants of the fast right-hand side: the OpenMP gather loops give bit-identical
// results for 1 and 2 threads (no atomics, no reduction order that depends on the thread count),
// and f(t, y) allocates nothing between neighbour rebuilds.
#include <omp.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <new>

#include "doctest/doctest.h"
#include "io/scene_reader.hpp"
#include "test_support.hpp"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

// Counting global allocator for this test binary. Not under AddressSanitizer, which owns operator
// new/delete itself (a replacement there mixes its allocations with our free: alloc-dealloc
// mismatch); the allocation test then reports itself skipped and runs in the normal build.
#if defined(__SANITIZE_ADDRESS__)
#define ARKSPH_COUNTING_ALLOCATOR 0
#else
#define ARKSPH_COUNTING_ALLOCATOR 1
void* operator new(std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
#endif

using namespace arksph;

namespace {
// The Taylor-Green box, and a walled variant with a moving lid, body force and the linear
// wall velocity (ghost images, corners, every WCSPH term on).
Scene scene_variant(bool walls) {
  std::string text = testing::kTaylorGreenBox + "[time]\nend = 0.1\n";
  std::vector<std::string> sets;
  if (walls) {
    sets = {"boundary.left.kind=wall", "boundary.right.kind=wall", "boundary.bottom.kind=wall",
            "boundary.top.kind=wall", "boundary.top.velocity=[1,0]", "fluid.body_force=[0,-1]",
            "boundary.wall_velocity=linear"};
  }
  std::ostringstream warn;
  return read_scene_text(text, "<test>", sets, warn);
}

// A state a little off the lattice, so that no pair sum is symmetric by accident.
std::vector<double> disturbed_state(Model& model) {
  std::vector<double> y(model.rhs->layout().size());
  model.rhs->initial_state(y.data());
  const std::size_t n = model.rhs->layout().n;
  for (std::size_t a = 0; a < n; ++a) {
    y[a] += 1e-3 * std::sin(12.9898 * a);
    y[n + a] += 1e-3 * std::cos(78.233 * a);
  }
  // Densities off rho0 too, so that the pressure (0 at rho0 without a background) is not zero and the
  // pressure-gradient terms contribute.
  const StateLayout& layout = model.rhs->layout();
  if (layout.has_density)
    for (std::size_t a = 0; a < n; ++a) y[layout.rho() + a] *= 1.0 + 1e-3 * std::sin(3.7 * a);
  return y;
}
}  // namespace

TEST_CASE("rhs: 1 and 2 OpenMP threads give bit-identical derivatives") {
  for (int variant : {0, 1, 2, 3}) {  // periodic, walled; both again with shifting and delta-SPH
    const bool walls = variant % 2 == 1;
    CAPTURE(variant);
    Scene scene = scene_variant(walls);
    if (variant >= 2)
      scene = read_scene_text(scene.resolved_toml, "<test>",
                              {"method.regularisation=shifting", "method.density_diffusion=delta_sph"}, std::cerr);
    std::vector<double> ydot[2];
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      Model model = build_model(scene);
      std::vector<double> y = disturbed_state(model);
      ydot[threads - 1].assign(y.size(), 0.0);
      model.rhs->eval(0.0, y.data(), ydot[threads - 1].data());
    }
    omp_set_num_threads(omp_get_num_procs());
    REQUIRE(ydot[0].size() == ydot[1].size());
    // Exact equality: a gather loop sums each particle's pairs in one thread in list order.
    CHECK(std::memcmp(ydot[0].data(), ydot[1].data(), ydot[0].size() * sizeof(double)) == 0);
  }
}

// method.neighbor_storage = "candidates" evaluates the kernel in every term instead of storing W and
// F per pair: the same pairs in the same order with the same kernel arithmetic, so the derivatives
// must agree bit for bit with the stored list (periodic box and walled box with every WCSPH term;
// also ISPH's projection, which walks the pairs in the Poisson assembly and eq. 11).
TEST_CASE("rhs: lean neighbour storage gives bit-identical derivatives and projections") {
  for (int variant : {0, 1, 2}) {  // periodic wcsph; walled wcsph; walled isph (one projected step)
    CAPTURE(variant);
    const Scene base = scene_variant(variant > 0);
    std::vector<double> out[2];
    for (int lean : {0, 1}) {
      std::vector<std::string> sets = {std::string("method.neighbor_storage=") + (lean ? "candidates" : "pairs")};
      if (variant == 2) sets.insert(sets.end(), {"method.scheme=isph", "method.ppe_solver=klu", "time.dt=1e-3"});
      const Scene scene = read_scene_text(base.resolved_toml, "<test>", sets, std::cerr);
      Model model = build_model(scene);
      std::vector<double> y = disturbed_state(model);
      out[lean].assign(y.size(), 0.0);
      if (variant < 2) {
        model.rhs->eval(0.0, y.data(), out[lean].data());
      } else {
        model.rhs->eval(0.0, y.data(), nullptr);
        model.projection->begin_step(0.0, y.data());
        model.projection->project(1e-3, y.data());
        out[lean] = y;
      }
    }
    CHECK(std::memcmp(out[0].data(), out[1].data(), out[0].size() * sizeof(double)) == 0);
  }
}

// method.force_sweep (the default) runs the per-particle force terms from one gathered neighbourhood
// per particle instead of each term walking the stored pair list: the same pairs, kernel values and
// sums in the same order, so the derivatives must agree bit for bit, for every sweep-capable term and
// for a mix with terms that still walk the pair list (a kernel correction, pressure reduction), and
// with the regularisation (shifting, with and without Lind's weight, and delta-SPH).
TEST_CASE("rhs: the force sweep gives the term-by-term derivatives bit for bit") {
  const std::vector<std::vector<std::string>> variants = {
      {},
      {"method.pressure_gradient=monaghan", "method.viscosity_model=cleary"},
      {"method.viscosity_model=violeau"},
      {"method.viscosity_model=direct", "method.kernel_correction=shepard"},
      {"method.kernel_correction=bonet_lok", "method.pressure_reduction=true"},
      {"method.equation_of_state=ideal_gas"},
      {"method.regularisation=shifting", "method.density_diffusion=delta_sph"},
      {"method.regularisation=shifting", "method.shifting_anti_clumping=0"},
  };
  for (bool walls : {false, true}) {
    for (std::size_t v = 0; v < variants.size(); ++v) {
      CAPTURE(walls);
      CAPTURE(v);
      const Scene base = scene_variant(walls);
      std::vector<double> out[2];
      for (int sweep : {0, 1}) {
        std::vector<std::string> sets = variants[v];
        sets.push_back(std::string("method.force_sweep=") + (sweep ? "true" : "false"));
        const Scene scene = read_scene_text(base.resolved_toml, "<test>", sets, std::cerr);
        Model model = build_model(scene);
        std::vector<double> y = disturbed_state(model);
        out[sweep].assign(y.size(), 0.0);
        model.rhs->eval(0.0, y.data(), out[sweep].data());
        if (v == 0 && sweep) CHECK(model.rhs->fields().pairs.n_real == 0);  // no pair list was stored
      }
      REQUIRE(out[0].size() == out[1].size());
      CHECK(std::memcmp(out[0].data(), out[1].data(), out[0].size() * sizeof(double)) == 0);
    }
  }
}

// The plain pair loops (2D, no kernel correction, no pressure reduction known at compile time:
// rhs/particle_term.hpp) against the general ones that test these per pair: the same bits.
// With and without the regularisation (shifting and delta-SPH, whose plain loops are separate code).
TEST_CASE("rhs: the plain pair loops give the general loops' derivatives bit for bit") {
  for (bool walls : {false, true}) {
    for (bool sweep : {false, true}) {
      for (bool regularised : {false, true}) {
        CAPTURE(walls);
        CAPTURE(sweep);
        CAPTURE(regularised);
        std::vector<std::string> sets = {std::string("method.force_sweep=") + (sweep ? "true" : "false")};
        if (regularised)
          sets.insert(sets.end(), {"method.regularisation=shifting", "method.density_diffusion=delta_sph"});
        const Scene scene = read_scene_text(scene_variant(walls).resolved_toml, "<test>", sets, std::cerr);
        std::vector<double> out[2];
        for (int plain : {0, 1}) {
          Model model = build_model(scene);
          model.rhs->set_options({.plain_pair_loops = plain == 1});
          std::vector<double> y = disturbed_state(model);
          out[plain].assign(y.size(), 0.0);
          model.rhs->eval(0.0, y.data(), out[plain].data());
        }
        CHECK(std::memcmp(out[0].data(), out[1].data(), out[0].size() * sizeof(double)) == 0);
      }
    }
  }
}

TEST_CASE("rhs: f(t, y) allocates nothing between neighbour rebuilds") {
  if (!ARKSPH_COUNTING_ALLOCATOR) {
    MESSAGE("skipped: AddressSanitizer replaces operator new");
    return;
  }
  for (int variant : {0, 1, 2}) {  // periodic; walls, linear wall velocity; walls, quadratic
    CAPTURE(variant);
    Scene scene = scene_variant(variant > 0);
    if (variant == 2) scene = read_scene_text(scene.resolved_toml, "<test>", {"boundary.wall_velocity=quadratic"}, std::cerr);
    Model model = build_model(scene);
    std::vector<double> y = disturbed_state(model), ydot(y.size());
    model.rhs->eval(0.0, y.data(), ydot.data());  // first call: lists built, buffers sized
    const long rebuilds = model.rhs->neighbor_rebuilds();
    for (double& v : y) v += 1e-9;  // moved, but far less than the Verlet skin
    const long before = g_allocations.load();
    model.rhs->eval(1e-3, y.data(), ydot.data());
    model.rhs->eval(2e-3, y.data(), ydot.data());
    const long allocated = g_allocations.load() - before;
    CHECK(model.rhs->neighbor_rebuilds() == rebuilds);
    CHECK(allocated == 0);
  }
}
