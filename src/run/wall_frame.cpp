#include "run/wall_frame.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/output_fields.hpp"

namespace arksph {

namespace {
// c brought into [lo, lo + len) along a periodic axis.
double wrapped(double c, double lo, double len) {
  const double r = std::fmod(c - lo, len);
  return lo + (r < 0 ? r + len : r);
}
}  // namespace

bool is_written_wall_point(const Scene& scene, double x, double y, double support) {
  const double c[2] = {x, y};
  for (int k = 0; k < scene.dimension; ++k) {
    const double lo = scene.min[k], hi = scene.max[k];
    if (c[k] >= lo && c[k] <= hi) continue;
    const SideSpec& side = scene.sides[2 * k + (c[k] > hi ? 1 : 0)];
    const double beyond = c[k] > hi ? c[k] - hi : lo - c[k];
    if (side.kind != SideKind::wall || beyond >= support) return false;
  }
  return true;
}

WallFrame::WallFrame(const Scene& scene, const FluidFields& f, const Frame& particles, double support, bool wrap) {
  const bool two_d = f.dim == 2;
  struct Point {
    std::size_t i;  // index into f
    double x, y;    // position (wrapped along the periodic axes with `wrap`)
  };
  std::vector<Point> points;
  for (std::size_t i = f.n_real; i < f.n_all; ++i) {
    if (f.src[i] >= particles.n) continue;  // an image of a halo copy: its owner writes it
    double c[2] = {f.x[i], two_d ? f.y[i] : 0.0};
    for (int k = 0; wrap && k < f.dim; ++k)
      if (scene.sides[2 * k].kind == SideKind::periodic)
        c[k] = wrapped(c[k], scene.min[k], scene.max[k] - scene.min[k]);
    if (is_written_wall_point(scene, c[0], c[1], support)) points.push_back({i, c[0], c[1]});
  }
  // Rows by the id of the particle imaged; a particle's images keep the evaluator's order.
  std::stable_sort(points.begin(), points.end(), [&](const Point& a, const Point& b) {
    return particles.id[f.src[a.i]] < particles.id[f.src[b.i]];
  });
  rows_.resize(points.size(), static_cast<std::int32_t>(ParticleKind::wall));
  for (std::size_t k = 0; k < points.size(); ++k) {
    const std::size_t i = points[k].i, s = f.src[i];
    rows_.x[k] = points[k].x;
    rows_.y[k] = points[k].y;
    rows_.u[k] = f.u[i];
    rows_.v[k] = two_d ? f.v[i] : 0.0;
    rows_.pressure[k] = particles.pressure[s] + (f.p[i] - f.p[s]);  // the hydrostatic step of the wall point
    rows_.density[k] = f.rho[i];
    rows_.summation_density[k] = particles.summation_density[s];
    rows_.mass[k] = f.m[i];
    rows_.id[k] = particles.id[s];
    rows_.phase[k] = particles.phase ? particles.phase[s] : 0;
  }
  frame_ = rows_.view(f.dim, particles.time, particles.smoothing_length);
}

std::string wall_file_name(int frame) {
  char name[64];
  std::snprintf(name, sizeof name, "walls_%06d.vtp", frame);
  return name;
}

}  // namespace arksph
