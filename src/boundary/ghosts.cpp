#include "boundary/ghosts.hpp"

#include <cmath>

namespace arksph {

namespace {
using Map = std::array<double, 4>;
constexpr Map identity{1, 1, 0, 0};

// Reflection across a wall whose normal is along `axis`.
Map wall_map(const SideSpec& s, int axis, bool force_free_slip) {
  if (s.slip == SlipKind::free_slip || force_free_slip) {
    Map m = identity;
    m[axis] = -1.0;  // normal component reversed, tangential kept
    return m;
  }
  return {-1, -1, 2 * s.velocity[0], 2 * s.velocity[1]};  // u' = 2w - u
}

// Composition: apply a then b.  u -> sb*(sa*u + ba) + bb
Map compose(const Map& a, const Map& b) {
  return {a[0] * b[0], a[1] * b[1], b[0] * a[2] + b[2], b[1] * a[3] + b[3]};
}
}  // namespace

GhostBuilder::GhostBuilder(const Scene& scene, double support_radius)
    : dim_(scene.dimension),
      radius_(support_radius),
      alpha_(scene.corner_alpha),
      free_slip_div_(scene.free_slip_divergence),
      lo_(scene.min),
      hi_(scene.max),
      sides_(scene.sides),
      wall_particles_(scene.wall_particles && scene.dimension == 2),
      wall_images_(scene.wall_ghosts),
      dx_(scene.spacing) {
  for (int k = 0; k < dim_; ++k) len_[k] = hi_[k] - lo_[k];
  any_side_ = true;
  for (int s = 0; s < 2 * dim_; ++s)
    if (sides_[s].kind == SideKind::wall) any_wall_ = true;
}

void GhostBuilder::build(const double* x, const double* y, std::size_t n, GhostSet& g, double skin) const {
  const double reach = radius_ + skin;
  g.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const double p[2] = {x[i], y ? y[i] : 0.0};
    // Candidate images along each axis: index 0 is "no image".
    struct Option {
      double coord;
      Map map, div_map;
      bool wall;
      int side;
      double a = 1.0, b = 0.0;  // coordinate map c' = a c + b
    };
    Option opts[2][3];
    int nopt[2] = {1, 1};
    for (int k = 0; k < 2; ++k) opts[k][0] = {p[k], identity, identity, false, -1, 1.0, 0.0};
    for (int k = 0; k < dim_; ++k) {
      for (int end = 0; end < 2; ++end) {
        const int side = 2 * k + end;  // left,right,bottom,top
        const double dist = end == 0 ? p[k] - lo_[k] : hi_[k] - p[k];
        if (dist >= reach) continue;
        const SideSpec& s = sides_[side];
        if (s.kind == SideKind::periodic && s.halo) continue;
        if (s.kind == SideKind::wall && !wall_images_) continue;
        Option o;
        o.side = side;
        if (s.kind == SideKind::periodic) {
          o.coord = end == 0 ? p[k] + len_[k] : p[k] - len_[k];
          o.a = 1.0;
          o.b = end == 0 ? len_[k] : -len_[k];
          o.map = o.div_map = identity;
          o.wall = false;
        } else {
          const double plane = end == 0 ? lo_[k] : hi_[k];
          o.coord = 2 * plane - p[k];
          o.a = -1.0;
          o.b = 2 * plane;
          o.map = wall_map(s, k, false);
          o.div_map = wall_map(s, k, free_slip_div_);
          o.wall = true;
        }
        opts[k][nopt[k]++] = o;
      }
    }
    for (int ix = 0; ix < nopt[0]; ++ix) {
      for (int iy = 0; iy < nopt[1]; ++iy) {
        if (ix == 0 && iy == 0) continue;
        const Option& ox = opts[0][ix];
        const Option& oy = opts[1][iy];
        Map m = compose(ox.map, oy.map);
        if (ox.wall && oy.wall && sides_[ox.side].slip == SlipKind::no_slip &&
            sides_[oy.side].slip == SlipKind::no_slip) {
          // Corner image of two no-slip walls, Szewc eq. 46: u''' = u + 2 alpha (w1 + w2).
          const auto& w1 = sides_[ox.side].velocity;
          const auto& w2 = sides_[oy.side].velocity;
          m = {1, 1, 2 * alpha_ * (w1[0] + w2[0]), 2 * alpha_ * (w1[1] + w2[1])};
        }
        const Map dm = free_slip_div_ ? compose(ox.div_map, oy.div_map) : m;
        g.source.push_back(static_cast<std::uint32_t>(i));
        g.x.push_back(ox.coord);
        g.y.push_back(oy.coord);
        g.map.push_back(m);
        g.div_map.push_back(dm);
        const bool one_wall = ox.wall != oy.wall;
        const Option& w = ox.wall ? ox : oy;
        g.place.push_back({ox.a, oy.a, ox.b, oy.b});
        g.wall_side.push_back(static_cast<std::int8_t>(one_wall ? w.side : -1));
        g.wall_dist.push_back(one_wall ? std::abs(p[w.side / 2] - (w.side % 2 ? hi_[w.side / 2] : lo_[w.side / 2])) : 0.0);
      }
    }
    if (wall_particles_) add_wall_particles(i, p, reach, g);
  }
}

// Basa et al. 2008 §6.1.2, "particles on the wall": for a fluid particle closer than dx to a no-slip
// wall, a particle at the nearest point of the wall carrying the wall velocity (map u' = w, no
// dependence on the source), plus its periodic images along the wall. Mass, density and pressure are
// the source's, as for every ghost. Not a mirror image: wall_side = -1, so the wall-velocity
// extrapolations leave it alone.
void GhostBuilder::add_wall_particles(std::size_t i, const double p[2], double reach, GhostSet& g) const {
  for (int side = 0; side < 4; ++side) {
    const SideSpec& s = sides_[side];
    if (s.kind != SideKind::wall || s.slip != SlipKind::no_slip) continue;
    const int k = side / 2, t = 1 - k;
    const double plane = side % 2 ? hi_[k] : lo_[k];
    if (std::abs(p[k] - plane) >= dx_) continue;
    double shifts[3] = {0.0, 0.0, 0.0};
    int nshift = 1;
    if (sides_[2 * t].kind == SideKind::periodic) {  // images across the periodic tangential sides
      if (p[t] - lo_[t] < reach) shifts[nshift++] = len_[t];
      if (hi_[t] - p[t] < reach) shifts[nshift++] = -len_[t];
    }
    for (int j = 0; j < nshift; ++j) {
      std::array<double, 4> place{};
      place[k] = 0.0, place[2 + k] = plane;    // normal coordinate: on the wall
      place[t] = 1.0, place[2 + t] = shifts[j];  // tangential: the source's (shifted)
      g.source.push_back(static_cast<std::uint32_t>(i));
      g.x.push_back(place[0] * p[0] + place[2]);
      g.y.push_back(place[1] * p[1] + place[3]);
      const Map m{0, 0, s.velocity[0], s.velocity[1]};
      g.map.push_back(m);
      g.div_map.push_back(m);
      g.place.push_back(place);
      g.wall_side.push_back(-1);
      g.wall_dist.push_back(0.0);
    }
  }
}

}  // namespace arksph

namespace arksph {

void GhostBuilder::update(const double* x, const double* y, GhostSet& g) const {
  for (std::size_t i = 0; i < g.size(); ++i) {
    const auto& pl = g.place[i];
    const std::uint32_t s = g.source[i];
    g.x[i] = pl[0] * x[s] + pl[2];
    g.y[i] = y ? pl[1] * y[s] + pl[3] : 0.0;
    const int side = g.wall_side[i];
    if (side >= 0) {
      const int k = side / 2;
      const double c = k == 0 ? x[s] : y[s];
      g.wall_dist[i] = std::abs(c - (side % 2 ? hi_[k] : lo_[k]));
    }
  }
}

}  // namespace arksph
