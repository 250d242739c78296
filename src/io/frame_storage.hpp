// Rows of a frame held by value (io/frame.hpp is a view): for frames built rather than viewed,
// such as the wall points of output.walls (run/wall_frame.hpp) and their join over MPI ranks.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "io/frame.hpp"

namespace arksph {

struct FrameStorage {
  std::vector<double> x, y, u, v, pressure, density, summation_density, mass;
  std::vector<std::int64_t> id;
  std::vector<std::int32_t> phase, kind;
  // Every array sized to n rows (kind filled with `kind_value`).
  void resize(std::size_t n, std::int32_t kind_value);
  // The view of the rows (y and v left out in 1D).
  Frame view(int dimension, double time, double smoothing_length) const;
};

}  // namespace arksph
