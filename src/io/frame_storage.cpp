#include "io/frame_storage.hpp"

namespace arksph {

void FrameStorage::resize(std::size_t n, std::int32_t kind_value) {
  for (auto* field : {&x, &y, &u, &v, &pressure, &density, &summation_density, &mass}) field->resize(n);
  id.resize(n);
  phase.resize(n);
  kind.assign(n, kind_value);
}

Frame FrameStorage::view(int dimension, double time, double smoothing_length) const {
  const bool two_d = dimension == 2;
  Frame f;
  f.dimension = dimension;
  f.n = x.size();
  f.time = time;
  f.x = x.data();
  f.y = two_d ? y.data() : nullptr;
  f.u = u.data();
  f.v = two_d ? v.data() : nullptr;
  f.pressure = pressure.data();
  f.density = density.data();
  f.summation_density = summation_density.data();
  f.mass = mass.data();
  f.id = id.data();
  f.phase = phase.data();
  f.smoothing_length = smoothing_length;
  f.kind = kind.data();
  return f;
}

}  // namespace arksph
