// The particle set: constant per-particle data (mass, id, phase, reference density) and the initial
// state. The evolving state (positions, velocities, densities) lives in the integrator's N_Vector,
// laid out as structure-of-arrays blocks (see StateLayout).
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include "core/scene.hpp"

namespace arksph {

// y = [ x (N) | y (N) | u (N) | v (N) | rho (N, only with the continuity equation) ]  (2D)
// y = [ x (N) | u (N) | rho (N) ]                                                       (1D)
// followed by e (N), the specific internal energy, only with the ideal-gas equation of state.
struct StateLayout {
  std::size_t n = 0;
  int dim = 2;
  bool has_density = false;
  bool has_energy = false;
  std::size_t energy() const { return static_cast<std::size_t>(2 * dim + (has_density ? 1 : 0)) * n; }
  std::size_t pos(int k) const { return static_cast<std::size_t>(k) * n; }
  std::size_t vel(int k) const { return static_cast<std::size_t>(dim + k) * n; }
  std::size_t rho() const { return static_cast<std::size_t>(2 * dim) * n; }
  std::size_t size() const {
    return (2 * static_cast<std::size_t>(dim) + (has_density ? 1 : 0) + (has_energy ? 1 : 0)) * n;
  }
};

struct ParticleSet {
  int dim = 2;
  std::size_t n = 0;
  double dx = 0;
  std::vector<double> mass;       // m = rho_phase * dx^d
  std::vector<double> rho0;       // reference density of the particle's phase
  std::vector<std::int64_t> id;   // stable identifier
  std::vector<std::int32_t> phase;
  std::vector<double> init_pos[2], init_vel[2];
  std::vector<double> init_rho;   // density at t = 0 when not rho0 (initial.hydrostatic); empty: rho0
  double init_energy = 0;         // specific internal energy at t = 0 (ideal-gas equation of state)
};

// Fills the domain (or the part fluid.region selects) with a square lattice, spacing dx, particles
// at min + (i + 1/2) dx; assigns phases by the [[phase]] regions (the last matching region wins)
// and the initial velocity field.
// A NaN or infinite initial velocity is bad input (InputError naming the key and the particle).
// `each_row`, if given, is called before each row of particles (it may throw: the set-up polls for
// a signal this way).
ParticleSet make_lattice(const Scene& scene, const std::function<void()>& each_row = {});

}  // namespace arksph
