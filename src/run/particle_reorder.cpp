#include "run/particle_reorder.hpp"

#include <chrono>
#include <cmath>

namespace arksph {

void permute_model(Model& model, const Permutation& from) {
  permute(model.particles, from);
  model.rhs->permute_particles(from);
  if (model.projection) model.projection->permute_particles(from);
}

Permutation adopt_particle_order(Model& model, const std::vector<std::int64_t>& ids) {
  if (ids == model.particles.id) return {};
  Permutation from = permutation_to(model.particles.id, ids);
  if (!from.empty()) permute_model(model, from);
  return from;
}

ParticleReorder::ParticleReorder(const Scene& scene, Model& model)
    : scene_(scene), model_(model), every_(scene.reorder_every), side_(model.rhs->kernel().radius()) {}

Permutation ParticleReorder::order_of(const double* y) const {
  const StateLayout& L = model_.rhs->layout();
  const std::size_t n = L.n;
  std::vector<double> c[2];
  for (int k = 0; k < L.dim; ++k) {
    c[k].assign(y + L.pos(k), y + L.pos(k) + n);
    if (scene_.sides[2 * k].kind != SideKind::periodic) continue;
    const double lo = scene_.min[k], len = scene_.max[k] - scene_.min[k];
    for (double& v : c[k]) v = lo + (v - lo) - len * std::floor((v - lo) / len);  // as the fields see it
  }
  return cell_order(c[0].data(), L.dim == 2 ? c[1].data() : nullptr, n, scene_.min[0], scene_.min[1], side_);
}

bool ParticleReorder::sort(double* y, std::vector<double>& d0) {
  const auto t0 = std::chrono::steady_clock::now();
  const Permutation from = order_of(y);
  bool identity = true;
  for (std::size_t i = 0; i < from.size() && identity; ++i) identity = from[i] == i;
  if (!identity) {
    permute_model(model_, from);  // first: it frees the neighbour lists before any temporary is made
    permute_state(model_.rhs->layout(), y, from);
    permute(d0, from);
    ++count_;
  }
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return !identity;
}

void ParticleReorder::apply(double t, TimeIntegrator& integrator, std::vector<double>& d0, ViscousSplit* split) {
  const double h = integrator.next_step();
  if (!sort(integrator.state(), d0)) return;  // already in cell order: the integrator keeps its state
  const auto t0 = std::chrono::steady_clock::now();
  if (split) split->forget();
  integrator.restart_at(t, h);
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace arksph
