// The smallest scene a process test runs (shared by the tests that start the binary).
#pragma once

namespace arksph::testing {

// The minimal scene of the hostile-input tests: 10 x 10 particles in a resting box without a lid,
// 0.01 s; particle ids are the lattice order, row by row from (0.05, 0.05), so the particle at
// (0.95, 0.95) has id 99.
inline constexpr const char* kMinimalScene = R"(
[domain]
min = [0.0, 0.0]
max = [1.0, 1.0]
[fluid]
spacing = 0.1
[time]
end = 0.01
)";

}  // namespace arksph::testing
