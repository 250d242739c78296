// HDF5 checkpoint: everything an exact restart needs (layout: io/checkpoint_layout.md).
//   - the ODE state vector y, block by block as StateLayout lays it out (x, y, u, v, rho);
//   - the constant per-particle data (mass, rho0, id, phase);
//   - the resolved scene as TOML text, the time, the integrator counters and the output counters;
//   - the steady-state monitor's samples, when the run has one.
// The file is built in memory, written to a temporary beside `path` (temporary_path), synced and
// renamed onto `path`, so a reader sees either the previous checkpoint or the new one, never a
// partial file.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/particles.hpp"

namespace arksph {

constexpr int kCheckpointFormatVersion = 1;

struct Checkpoint {
  int format_version = kCheckpointFormatVersion;
  int dimension = 2;
  bool has_density = false;     // the state holds a density block (continuity equation)
  bool has_energy = false;      // the state holds an energy block (ideal-gas equation of state)
  std::size_t n = 0;            // particles
  double time = 0;              // simulated time of the state
  long steps = 0;               // accepted steps since t = 0 (over all restarts)
  long rhs_evals = 0;           // RHS evaluations by the integrator since t = 0
  long step_attempts = 0;
  long error_test_fails = 0;
  double last_step = 0;         // the last step size taken
  double next_step = 0;         // the step size the integrator would try next
  long output_frame = 0;        // output frames written so far (index of the next one)
  long checkpoint_index = 0;    // scheduled checkpoints written so far (output.checkpoint_every)
  long wall_reflections = 0;
  double cpu_seconds = 0;       // CPU time of the run up to this state, over all restarts (run/cpu_time.hpp);
                                // 0 in files that lack it
  // metrics.energy_budget: the viscous dissipation W_visc accumulated up to `time`
  // (diagnostics/viscous_dissipation.hpp); absent in files of runs without the budget.
  bool has_viscous_dissipation = false;
  double viscous_dissipation = 0;
  std::string scene_toml;       // Scene::resolved_toml of the run that wrote it
  std::string run_id;           // the run's id (run/output_folder.hpp); "" in files that lack it
  std::vector<double> state;    // y in StateLayout order, size layout().size()
  std::vector<double> mass, rho0;
  std::vector<std::int64_t> id;
  std::vector<std::int32_t> phase;
  // The steady-state monitor's samples (diagnostics/steady_state.hpp), so that a restart measures
  // the same windows as the run it continues: rows of (t, KE, centreline values...), row-major,
  // steady_columns values each. Empty without time.steady_tolerance (and in files that lack them).
  int steady_columns = 0;
  std::vector<double> steady_samples;

  StateLayout layout() const {
    StateLayout L;
    L.n = n;
    L.dim = dimension;
    L.has_density = has_density;
    L.has_energy = has_energy;
    return L;
  }
};

// Writes atomically (a temporary, then rename). Throws OutputError("cannot write <path>: reason")
// when the file cannot be written (disk full, size limit, unwritable folder).
void write_checkpoint(const std::string& path, const Checkpoint& c);

// Reads a checkpoint; ignores any `path.tmp` beside it. Throws InputError("<path>: ...") if the file
// is missing, not HDF5, truncated, of another format version or inconsistent.
Checkpoint read_checkpoint(const std::string& path);

// The values a run continues from, checked like scene values before they are used: times and steps
// finite and non-negative, counters at most 2^53, the frame and checkpoint numbers within the
// frames a scene may schedule (io/scene_limits.hpp), ids a permutation of 0..n-1, masses and
// densities positive and finite. InputError("<path>: <attribute> = value: reason") otherwise: a file
// edited by hand or damaged outside the reach of its checksums is refused (exit 2), not looped over.
void check_restart_values(const Checkpoint& c, const std::string& path);

}  // namespace arksph
