// A checkpoint with awkward values and a field-by-field, bit-for-bit comparison: shared by the
// checkpoint file tests (unit/) and the SIGKILL test (process/).
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "io/checkpoint.hpp"

namespace arksph::testing {

// A checkpoint with awkward values: signed zero, subnormals, infinities, extreme ids.
inline Checkpoint sample_checkpoint(std::size_t n, int dim, bool has_density) {
  Checkpoint c;
  c.dimension = dim;
  c.has_density = has_density;
  c.n = n;
  c.time = 0.1 + 0.2;  // 0.30000000000000004: not a short decimal
  c.steps = 123456789012L;
  c.rhs_evals = 987654321098L;
  c.step_attempts = 7;
  c.error_test_fails = 3;
  c.last_step = std::nextafter(1e-3, 1.0);
  c.next_step = 1.0 / 3.0;
  c.output_frame = 42;
  c.checkpoint_index = 5;
  c.wall_reflections = 11;
  c.scene_toml = "[scene]\nname = \"caf\xC3\xA9 \\\"quoted\\\"\"\n# long line " + std::string(70000, 'x') + "\n";
  c.state.resize(c.layout().size());
  for (std::size_t i = 0; i < c.state.size(); ++i) c.state[i] = std::sin(1.0 + static_cast<double>(i)) * 1e3 / 7.0;
  c.state[0] = -0.0;
  c.state[1] = std::numeric_limits<double>::denorm_min();
  c.state[2] = -std::numeric_limits<double>::infinity();
  c.state[3] = std::numeric_limits<double>::max();
  for (std::size_t a = 0; a < n; ++a) {
    c.mass.push_back(1.0 / (3.0 + static_cast<double>(a)));
    c.rho0.push_back(a % 2 ? 1.8 : 1.0);
    c.id.push_back(static_cast<std::int64_t>(a) * 4000000000LL - 7);
    c.phase.push_back(static_cast<std::int32_t>(a % 3) - 1);
  }
  return c;
}

template <class T>
inline bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

inline void check_equal(const Checkpoint& a, const Checkpoint& b) {
  CHECK(a.format_version == b.format_version);
  CHECK(a.dimension == b.dimension);
  CHECK(a.has_density == b.has_density);
  CHECK(a.n == b.n);
  CHECK(std::memcmp(&a.time, &b.time, sizeof a.time) == 0);
  CHECK(a.steps == b.steps);
  CHECK(a.rhs_evals == b.rhs_evals);
  CHECK(a.step_attempts == b.step_attempts);
  CHECK(a.error_test_fails == b.error_test_fails);
  CHECK(std::memcmp(&a.last_step, &b.last_step, sizeof a.last_step) == 0);
  CHECK(std::memcmp(&a.next_step, &b.next_step, sizeof a.next_step) == 0);
  CHECK(a.output_frame == b.output_frame);
  CHECK(a.checkpoint_index == b.checkpoint_index);
  CHECK(a.wall_reflections == b.wall_reflections);
  CHECK(a.scene_toml == b.scene_toml);
  CHECK(same_bits(a.state, b.state));
  CHECK(same_bits(a.mass, b.mass));
  CHECK(same_bits(a.rho0, b.rho0));
  CHECK(same_bits(a.id, b.id));
  CHECK(same_bits(a.phase, b.phase));
}

}  // namespace arksph::testing
