// Plausibility of the values read from a checkpoint (io/checkpoint.hpp, check_restart_values).
#include <cmath>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "io/checkpoint.hpp"
#include "io/scene_limits.hpp"

namespace arksph {

namespace {

constexpr double kMaxCount = 9007199254740992.0;  // 2^53: counters beyond it are not exact in summary.json

[[noreturn]] void refuse(const std::string& path, const std::string& what, const std::string& value,
                         const std::string& reason) {
  throw InputError(path + ": " + what + " = " + value + ": " + reason + " (the checkpoint is damaged or was edited)");
}

void check_count(const std::string& path, const char* what, long value, double max) {
  if (value < 0 || static_cast<double>(value) > max)
    refuse(path, what, std::to_string(value), "outside [0, " + message_number(max) + "]");
}

void check_time(const std::string& path, const char* what, double value) {
  if (!std::isfinite(value) || value < 0) refuse(path, what, message_number(value), "not a finite, non-negative time");
}

}  // namespace

void check_restart_values(const Checkpoint& c, const std::string& path) {
  check_time(path, "time", c.time);
  check_time(path, "last_step", c.last_step);
  check_time(path, "next_step", c.next_step);
  check_time(path, "cpu_seconds", c.cpu_seconds);
  if (!std::isfinite(c.viscous_dissipation))  // may be negative: a moving wall's work enters it
    refuse(path, "viscous_dissipation", message_number(c.viscous_dissipation), "not finite");
  check_count(path, "steps", c.steps, kMaxCount);
  check_count(path, "rhs_evals", c.rhs_evals, kMaxCount);
  check_count(path, "step_attempts", c.step_attempts, kMaxCount);
  check_count(path, "error_test_fails", c.error_test_fails, kMaxCount);
  check_count(path, "wall_reflections", c.wall_reflections, kMaxCount);
  // One frame at t = 0 and at most kMaxScheduledWrites more up to any time.end; the same for checkpoints.
  check_count(path, "output_frame", c.output_frame, kMaxScheduledWrites + 1);
  check_count(path, "checkpoint_index", c.checkpoint_index, kMaxScheduledWrites + 1);
  std::vector<bool> seen(c.n, false);
  for (std::size_t a = 0; a < c.id.size(); ++a) {
    const std::int64_t id = c.id[a];
    if (id < 0 || static_cast<std::size_t>(id) >= c.n || seen[static_cast<std::size_t>(id)])
      refuse(path, "/particles/id[" + std::to_string(a) + "]", std::to_string(id),
             "the ids are not a permutation of 0.." + std::to_string(c.n - 1));
    seen[static_cast<std::size_t>(id)] = true;
  }
  for (std::size_t a = 0; a < c.mass.size(); ++a) {
    if (!(std::isfinite(c.mass[a]) && c.mass[a] > 0))
      refuse(path, "/particles/mass[" + std::to_string(a) + "]", message_number(c.mass[a]), "not positive and finite");
    if (!(std::isfinite(c.rho0[a]) && c.rho0[a] > 0))
      refuse(path, "/particles/rho0[" + std::to_string(a) + "]", message_number(c.rho0[a]), "not positive and finite");
  }
}

}  // namespace arksph
