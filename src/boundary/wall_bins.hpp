// Tangential bins of width dx along one wall side: the wall-velocity extrapolations of Basa et al.
// 2008 §6.1.2 pick, per bin, the fluid particles nearest to the wall and extrapolate their velocity
// to the ghosts of that stretch of wall.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "core/scene.hpp"

namespace arksph {

struct WallBins {
  int k = 0, t = 1;    // normal and tangential axes
  double plane = 0;    // wall position on axis k
  double lo_t = 0, dx = 1;
  long bins = 1;
  bool periodic_t = false;

  // True when the side is a no-slip wall (the only sides these extrapolations act on).
  static bool applies(const Scene& scene, int side) {
    const SideSpec& s = scene.sides[side];
    return s.kind == SideKind::wall && s.slip == SlipKind::no_slip;
  }
  WallBins(const Scene& scene, int side, double spacing)
      : k(side / 2), t(1 - side / 2), plane(side % 2 ? scene.max[side / 2] : scene.min[side / 2]),
        lo_t(scene.min[1 - side / 2]), dx(spacing),
        bins(std::max(1L, std::lround((scene.max[1 - side / 2] - scene.min[1 - side / 2]) / spacing))),
        periodic_t(scene.sides[2 * (1 - side / 2)].kind == SideKind::periodic) {}
  std::size_t count() const { return static_cast<std::size_t>(bins); }
  // The bin of tangential coordinate c (wrapped on a periodic tangential axis, else clamped).
  std::size_t of(double c) const {
    long b = static_cast<long>(std::floor((c - lo_t) / dx));
    if (periodic_t) b = ((b % bins) + bins) % bins;
    return static_cast<std::size_t>(std::clamp(b, 0L, bins - 1));
  }
};

// Calls side_fn(side, bins, w_t) for each no-slip wall side, w_t the wall's tangential velocity.
template <class SideFn>
void for_each_no_slip_wall(const Scene& scene, double spacing, SideFn&& side_fn) {
  for (int side = 0; side < 4; ++side) {
    if (!WallBins::applies(scene, side)) continue;
    const WallBins wb(scene, side, spacing);
    side_fn(side, wb, scene.sides[side].velocity[wb.t]);
  }
}

}  // namespace arksph
