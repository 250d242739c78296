// One output frame's diagnostics (the timeseries.csv columns and the per-frame CSV files of
// run/run_output.hpp) as sums over particles and sample points that add up across the ranks of a
// decomposed run, so that no process needs the whole model's fields:
//   1. each process add()s its own particles (whose neighbourhoods its fields hold complete) and
//      the sample points it owns (Ghia's centreline points, the phase indicator's grid nodes);
//   2. the processes sum sums() and take the largest of maxima() (one process: nothing to do);
//   3. each adds fluctuations(), its particles' squared density deviations about the total means
//      (Szewc eq. 56 needs the mean first; all particles, and the upper phase), and the processes
//      sum them;
//   4. finish() turns the totals into the figures.
// The figures are those of the whole-model functions (flow_metrics, divergence_rms, ghia_errors,
// poiseuille_epsilon, phase_interface, ExactVelocity::errors, nearest_neighbor_histogram) and the
// upper phase's density mean and r.m.s. (Szewc eqs. 55-56), which one process computes the same way.
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include "core/scene.hpp"
#include "diagnostics/energy_budget.hpp"
#include "diagnostics/exact_velocity.hpp"
#include "diagnostics/flow_metrics.hpp"
#include "diagnostics/ghia.hpp"
#include "diagnostics/nearest_neighbor.hpp"
#include "diagnostics/phase_interface.hpp"
#include "rhs/fluid_fields.hpp"

namespace arksph {

struct FrameDiagnostics {
  double t = 0;
  FlowMetrics metrics;
  double divergence_rms = 0;  // projection/divergence_operator.hpp, over the state's velocities
  GhiaErrors ghia;            // scene.ghia_re
  double poiseuille_eps = 0;  // scene.poiseuille (NaN at t = 0)
  std::vector<double> poiseuille_profile;  // (y, u) of every particle, pair after pair
  PhaseInterface interface;   // scene.interface
  PhaseDensity upper_density;
  ExactVelocityErrors exact;  // metrics.exact_velocity
  Histogram nearest;          // nearest-neighbour distances over dx
  // metrics.energy_budget (diagnostics/energy_budget.hpp): E_p and E_c of the particles.
  double potential_energy = 0, compressible_energy = 0;
};

// The particles a process adds: the first n real points of fresh fields f.
struct FrameParticles {
  const FluidFields* f = nullptr;
  std::size_t n = 0;
  const double* d0 = nullptr;            // number density at t = 0, per particle
  const std::int32_t* phase = nullptr;   // per real point of f (ghosts take their source's)
};

class FrameReduction {
 public:
  // sound_speed: the run's resolved WCSPH sound speed (the Tait energy of metrics.energy_budget).
  FrameReduction(const Scene& scene, double sound_speed);
  // Pass 1. owns(x, y): whether this process adds the sample point (x, y).
  void add(const FrameParticles& p, const std::function<bool(double, double)>& owns);
  std::vector<double>& sums() { return sums_; }
  std::vector<double>& maxima() { return max_; }
  // Pass 2, after the totals of pass 1.
  std::vector<double> fluctuations() const;
  // Number densities d of the added particles (pass 1), C&R eq. 25.
  const std::vector<double>& number_density() const { return d_; }
  // Poiseuille profile: (y, u) of the added particles, to be joined over the processes for finish.
  const std::vector<double>& profile() const { return profile_; }
  // The figures from the totals of both passes (fluctuations: the totals of pass 2).
  FrameDiagnostics finish(double t, const std::vector<double>& fluctuations) const;

 private:
  const Scene& scene_;
  Kernel ghia_kernel_;
  std::vector<std::array<double, 2>> ghia_points_;
  IndicatorGrid grid_;
  ExactVelocity exact_;
  EnergyBudget energy_;
  std::size_t bins_ = 0;
  // Offsets into sums_ of each diagnostic's block (see the constructor).
  std::size_t ghia_at_ = 0, poiseuille_at_ = 0, grid_at_ = 0, upper_at_ = 0, exact_at_ = 0, energy_at_ = 0,
              nearest_at_ = 0;
  std::vector<double> sums_, max_;
  std::vector<double> d_, mass_, profile_;
  std::vector<std::int32_t> phase_;  // of the added particles (scene.interface)
};

}  // namespace arksph
