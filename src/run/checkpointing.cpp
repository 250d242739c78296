#include "run/checkpointing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "core/errors.hpp"
#include "io/scene_reader.hpp"
#include "io/scene_schema.hpp"
#include "run/cpu_time.hpp"
#include "run/restart_keys.hpp"

namespace arksph {

namespace {

double tol(double t) { return 1e-12 * std::max(1.0, std::abs(t)); }

// The smallest k >= 1 with k * every > t. `hint` (the counter the checkpointed run had) is kept when
// it fits, so that a restart computes the same stop times k * every as the run it continues.
long next_index(double t, double every, long hint) {
  if (every <= 0) return std::max(hint, 1L);
  const auto time_of = [every](long k) { return scheduled_time(k, every); };
  if (hint >= 1 && time_of(hint) > t + tol(t) && time_of(hint - 1) <= t + tol(t)) return hint;
  long k = std::max(1L, static_cast<long>(std::floor(t / every)));
  while (time_of(k) <= t + tol(t)) ++k;
  while (k > 1 && time_of(k - 1) > t + tol(t)) --k;
  return k;
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

}  // namespace

double scheduled_time(long k, double every) {
  char text[40];
  std::snprintf(text, sizeof text, "%.15g", static_cast<double>(k) * every);
  return std::strtod(text, nullptr);
}

Checkpointer::Checkpointer(const Scene& scene, const Model& model, const Checkpoint* restart, std::string restart_path)
    : scene_(scene),
      model_(model),
      restart_(restart),
      path_(scene.directory + "/checkpoint.h5"),
      every_(scene.checkpoint_every) {
  if (!restart_) return;
  const std::string& src = restart_path;
  {
    std::ostringstream ignored;  // warnings were given when the checkpointed run started
    check_restart_keys(read_scene_text(restart_->scene_toml, src + " [scene_toml]", {}, ignored), scene, src);
  }
  const StateLayout& L = model.rhs->layout();
  const auto describe = [](std::size_t n, int dim, bool rho) {
    return std::to_string(n) + " particles in " + std::to_string(dim) + "D " + (rho ? "with" : "without") +
           " a density block";
  };
  if (restart_->has_energy != L.has_energy)
    throw InputError(src + ": the checkpoint " + (restart_->has_energy ? "holds" : "lacks") +
                     " an energy block; the scene's method.equation_of_state does not match");
  if (restart_->dimension != L.dim || restart_->n != L.n || restart_->has_density != L.has_density)
    throw InputError(src + ": the checkpoint holds " + describe(restart_->n, restart_->dimension, restart_->has_density) +
                     ", the scene with the --set overrides has " + describe(L.n, L.dim, L.has_density));
  const ParticleSet& p = model.particles;
  const std::pair<const char*, bool> constants[] = {{"mass", same_bits(p.mass, restart_->mass)},
                                                    {"rho0", same_bits(p.rho0, restart_->rho0)},
                                                    {"id", same_bits(p.id, restart_->id)},
                                                    {"phase", same_bits(p.phase, restart_->phase)}};
  for (const auto& [name, same] : constants)
    if (!same)
      throw InputError(src + ": particles/" + name +
                       " differs from the scene's: a restart may only change keys that keep the particle set");
  if (!(scene.end > restart_->time + tol(restart_->time)))
    throw InputError(src + ": time.end = " + scene_schema::format_number(scene.end) +
                     " is not after the checkpoint time " + scene_schema::format_number(restart_->time) +
                     " (continue with --set time.end=...)");
  if (scene.energy_budget && !restart_->has_viscous_dissipation)
    throw InputError(src + ": metrics.energy_budget: the checkpoint holds no viscous_dissipation (its run had no "
                     "energy budget), so the budget cannot continue; restart with --set metrics.energy_budget=false");
  next_ = next_index(restart_->time, every_, restart_->checkpoint_index);
}

double Checkpointer::earlier_viscous_dissipation() const {
  return restart_ ? restart_->viscous_dissipation : 0.0;
}

int Checkpointer::first_frame() const {
  if (!restart_) return 1;
  return static_cast<int>(next_index(restart_->time, scene_.every, restart_->output_frame));
}

StepStats Checkpointer::counters() const {
  StepStats s;
  if (!restart_) return s;
  s.steps = restart_->steps;
  s.rhs_evals = restart_->rhs_evals;
  s.attempts = restart_->step_attempts;
  s.error_test_fails = restart_->error_test_fails;
  s.last_step = restart_->last_step;
  return s;
}

// Due once the integrator has reached its stop time (an adaptive step can end a round-off short of
// it; the loop then takes one more step), and that stop is the checkpoint time up to round-off
// (k * checkpoint_every and an output time j * every may differ in the last bit).
bool Checkpointer::due(double t) const {
  return every_ > 0 && t >= stop_ && t >= next_time() - tol(next_time());
}

double Checkpointer::limit(double t_stop) {
  stop_ = every_ > 0 && next_time() < t_stop - tol(t_stop) ? next_time() : t_stop;
  return stop_;
}

bool Checkpointer::take_due(double t) {
  if (!due(t)) return false;
  while (due(t)) ++next_;
  return true;
}

std::string Checkpointer::write_state(double t, const double* y, const StepStats& st, double next_step, long frames,
                                      long reflections, double segment_cpu) {
  const StateLayout& L = model_.rhs->layout();
  Checkpoint c;
  c.dimension = L.dim;
  c.has_density = L.has_density;
  c.has_energy = L.has_energy;
  c.n = L.n;
  c.time = t;
  c.steps = st.steps;
  c.rhs_evals = st.rhs_evals;
  c.step_attempts = st.attempts;
  c.error_test_fails = st.error_test_fails;
  c.last_step = st.last_step;
  c.next_step = next_step;
  c.output_frame = frames;
  c.checkpoint_index = next_;
  c.wall_reflections = reflections;
  c.cpu_seconds = earlier_cpu_seconds() + segment_cpu;
  c.scene_toml = scene_.resolved_toml;
  c.run_id = run_id_;
  if (dissipation_) {
    c.has_viscous_dissipation = true;
    c.viscous_dissipation = dissipation_->total();
  }
  c.state.assign(y, y + L.size());
  const ParticleSet& p = model_.particles;
  c.mass = p.mass;
  c.rho0 = p.rho0;
  c.id = p.id;
  c.phase = p.phase;
  if (steady_ && steady_->enabled() && !steady_->samples().empty()) {
    const auto& samples = steady_->samples();
    c.steady_columns = 2 + static_cast<int>(samples.front().centreline.size());
    for (const SteadySample& s : samples) {
      c.steady_samples.push_back(s.t);
      c.steady_samples.push_back(s.kinetic_energy);
      c.steady_samples.insert(c.steady_samples.end(), s.centreline.begin(), s.centreline.end());
    }
  }
  write_checkpoint(path_, c);
  return path_;
}

}  // namespace arksph
