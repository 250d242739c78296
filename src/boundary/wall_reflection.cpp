#include "boundary/wall_reflection.hpp"

namespace arksph {

long WallReflection::apply(double* y) const {
  long reflected = 0;
  for (int k = 0; k < layout_.dim; ++k) {
    const SideSpec& lo = scene_.sides[2 * k];
    const SideSpec& hi = scene_.sides[2 * k + 1];
    double* pos = y + layout_.pos(k);
    double* vel = y + layout_.vel(k);
    for (std::size_t a = 0; a < layout_.n; ++a) {
      if (lo.kind == SideKind::wall && pos[a] < scene_.min[k]) {
        pos[a] = 2 * scene_.min[k] - pos[a];
        vel[a] = 2 * lo.velocity[k] - vel[a];
        ++reflected;
      } else if (hi.kind == SideKind::wall && pos[a] > scene_.max[k]) {
        pos[a] = 2 * scene_.max[k] - pos[a];
        vel[a] = 2 * hi.velocity[k] - vel[a];
        ++reflected;
      }
    }
  }
  return reflected;
}

}  // namespace arksph
