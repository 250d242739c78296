// Helpers shared by the test files.
#pragma once
#include <fenv.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/file_text.hpp"
#include "run/setup.hpp"
#include "integrate/erk_integrator.hpp"
#include "rhs/terms.hpp"

namespace arksph::testing {

// Floating-point traps (ARKSPH_FP_TRAPS=1, tests/doctest_main.cpp) off for a scope, on the calling
// thread only (use it around serial code): for a computation that is meant to make infinities or
// NaNs, or library code vectorised under -fno-trapping-math that converts every lane of a select
// and so raises FE_INVALID on lanes whose result it then discards. The flags raised inside are
// cleared, and the traps that were on are restored, at scope exit.
class FpTrapsOff {
 public:
  FpTrapsOff() : saved_(fedisableexcept(FE_ALL_EXCEPT)) {}
  ~FpTrapsOff() {
    feclearexcept(FE_ALL_EXCEPT);
    if (saved_ > 0) feenableexcept(saved_);
  }
  FpTrapsOff(const FpTrapsOff&) = delete;
  FpTrapsOff& operator=(const FpTrapsOff&) = delete;

 private:
  int saved_;  // the traps that were enabled (-1 if fedisableexcept failed)
};

// A fresh directory under the system temp dir, removed (permissions restored first) at scope exit.
struct ScratchDir {
  std::filesystem::path dir;
  explicit ScratchDir(const std::string& tag) {
    dir = std::filesystem::temp_directory_path() / ("arksph_test_" + tag + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::permissions(dir, std::filesystem::perms::owner_all, std::filesystem::perm_options::add, ec);
    std::filesystem::remove_all(dir, ec);
  }
  std::string operator/(const std::string& name) const { return (dir / name).string(); }
};

// The whole file as a string (empty if it cannot be read).
inline std::string slurp(const std::string& path) { return file_text(path); }

// The number of lines of a text (its newlines): one-line messages are a contract (exit codes).
inline int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

// The text of the scene file tests/scenes/<name> (scenes shared by several test files).
inline std::string test_scene(const std::string& name) {
  const std::string path = std::string(ARKSPH_SOURCE_DIR) + "/tests/scenes/" + name;
  std::string text = slurp(path);
  if (text.empty()) throw std::runtime_error("cannot read test scene " + path);
  return text;
}

// The scenes of tests/scenes shared by many tests (described in their files).
inline const std::string kIsphWalledBox = test_scene("isph_walled_box.toml");
inline const std::string kTaylorGreenBox = test_scene("taylor_green_box.toml");

// The model's fields at its initial state (a field refresh: the pair list is built and kept).
inline const FluidFields& fields_at_start(Model& model) {
  std::vector<double> y0(model.rhs->layout().size());
  model.rhs->initial_state(y0.data());
  model.rhs->eval(0.0, y0.data(), nullptr);
  return model.rhs->fields();
}

// The cells of a comma-separated file, row by row (no quoting: the files arksph writes need none).
inline std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(slurp(path));
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> row;
    std::istringstream ls(line);
    for (std::string cell; std::getline(ls, cell, ',');) row.push_back(cell);
    rows.push_back(row);
  }
  return rows;
}

// One fixed step of the scene's ERKStep table followed by the projection (the run loop's step for
// scheme isph), from the initial state y0 (filled here). Returns the state after the step.
inline std::vector<double> one_projected_step(const Scene& scene, Model& model, std::vector<double>& y0) {
  y0.assign(model.rhs->layout().size(), 0.0);
  model.rhs->initial_state(y0.data());
  ErkOptions o;
  o.table = scene.integrator;
  o.fixed_dt = scene.dt;
  Projection* proj = model.projection.get();
  o.postprocess = [proj](double t, double* y) { proj->project(t, y); };
  ErkIntegrator integ([&](double t, const double* y, double* yd) { model.rhs->eval(t, y, yd); }, y0, 0.0, o);
  proj->begin_step(0.0, y0.data());
  integ.step(scene.dt);
  return {integ.state(), integ.state() + integ.size()};
}

// Momentum rate of the scene's right-hand side on its lattice jittered by +-0.2 dx, with random
// velocities (and densities perturbed by 1 %, so that pressure terms are not trivially zero):
// px, py = sum_a m_a du_a/dt, dv_a/dt, and the scale sum_a m_a (|du_a/dt| + |dv_a/dt|).
struct MomentumRate {
  double px = 0, py = 0, scale = 0;
};
// The particles of `lattice` (a 2D scene's model) moved by up to +-0.2 dx, with velocities drawn from
// [-1, 1] per component: a disordered set on which every pair term has work to do.
inline ParticleSet jittered(const Scene& scene, ParticleSet ps, std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.2 * scene.spacing, 0.2 * scene.spacing), vel(-1, 1);
  for (std::size_t a = 0; a < ps.n; ++a) {
    ps.init_pos[0][a] += jitter(rng);
    ps.init_pos[1][a] += jitter(rng);
    ps.init_vel[0][a] = vel(rng);
    ps.init_vel[1][a] = vel(rng);
  }
  return ps;
}

inline MomentumRate momentum_rate(const Scene& scene, unsigned seed) {
  Model model = build_model(scene);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> vel(-1, 1);
  const ParticleSet ps = jittered(scene, model.particles, rng);
  RhsEvaluator rhs(scene, ps, make_kernel(scene.kernel, model.h, 2), terms_from_scene(scene, model.sound_speed));
  std::vector<double> y(rhs.layout().size()), ydot(y.size());
  rhs.initial_state(y.data());
  if (rhs.layout().has_density)
    for (std::size_t a = 0; a < ps.n; ++a) y[rhs.layout().rho() + a] *= 1.0 + 0.01 * vel(rng);
  rhs.eval(0.0, y.data(), ydot.data());
  MomentumRate m;
  for (std::size_t a = 0; a < ps.n; ++a) {
    const double ax = ydot[rhs.layout().vel(0) + a], ay = ydot[rhs.layout().vel(1) + a];
    m.px += ps.mass[a] * ax;
    m.py += ps.mass[a] * ay;
    m.scale += ps.mass[a] * (std::abs(ax) + std::abs(ay));
  }
  return m;
}

}  // namespace arksph::testing
