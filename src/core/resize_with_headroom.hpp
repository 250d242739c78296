// Per-point arrays whose length creeps up by a few points between evaluations (wall ghosts as
// particles near walls, halo copies at an exchange). std::vector::resize reallocates them to twice
// their size when it must grow (libstdc++), which would double their memory for a few points;
// resize_with_headroom grows them to 1/32 beyond the new length instead. Values are unaffected.
#pragma once
#include <cstddef>
#include <vector>

namespace arksph {

template <class T>
void resize_with_headroom(std::vector<T>& v, std::size_t n) {
  if (n > v.capacity()) v.reserve(n + n / 32);
  v.resize(n);
}

}  // namespace arksph
