// A read-only view of the particle fields that output writers need (real particles only).
#pragma once
#include <cstddef>
#include <cstdint>

namespace arksph {

struct Frame {
  int dimension = 2;
  std::size_t n = 0;
  double time = 0;
  const double* x = nullptr;  // positions (y may be null in 1D)
  const double* y = nullptr;
  const double* u = nullptr;  // velocity components (v may be null in 1D)
  const double* v = nullptr;
  const double* pressure = nullptr;
  const double* density = nullptr;
  const double* summation_density = nullptr;  // m_a sum_b W_ab (Szewc eq. 21)
  const double* mass = nullptr;
  const std::int64_t* id = nullptr;
  const std::int32_t* phase = nullptr;
  double smoothing_length = 0;           // h, the same for every particle of a run
  const std::int32_t* kind = nullptr;    // ParticleKind (io/output_fields.hpp); null: every particle is fluid
  // 1 on the free-surface particles (fluid.region); null: no free_surface array in the file.
  const std::uint8_t* free_surface = nullptr;
};

}  // namespace arksph
