// Ghost particles (boundary/ghosts): mirror positions and velocity maps of no-slip, moving and
// free-slip walls (Szewc et al. 2012 eqs. 38-39), corners (eq. 46), the free-slip divergence option
// (eq. 53), periodic images combined with walls, the support-radius cut, and the SPH interpolation
// of velocity at a wall (eqs. 43-45) and at a corner (eq. 48).
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "boundary/ghosts.hpp"
#include "core/scene.hpp"
#include "io/scene_defaults.hpp"
#include "kernels/kernel.hpp"

using namespace arksph;

namespace {

using Map = std::array<double, 4>;

// A mirror coordinate is 2 * plane - p: one rounding of a number of size <= 2, i.e. <= 2.2e-16 for
// the unit box; a periodic image p +- L likewise. 1e-15 allows a couple of ulps.
constexpr double kPosTol = 1e-15;

Scene unit_box() {
  Scene s = scene_defaults();
  s.dimension = 2;
  s.min = {0, 0};
  s.max = {1, 1};
  for (auto& side : s.sides) side = SideSpec{};  // no-slip walls at rest
  return s;
}
enum Side { kLeft = 0, kRight = 1, kBottom = 2, kTop = 3 };

GhostSet build_one(const Scene& scene, double radius, double px, double py) {
  GhostBuilder gb(scene, radius);
  GhostSet g;
  gb.build(&px, &py, 1, g);
  REQUIRE(g.x.size() == g.size());
  REQUIRE(g.y.size() == g.size());
  REQUIRE(g.map.size() == g.size());
  REQUIRE(g.div_map.size() == g.size());
  return g;
}

// The ghost of g at (gx, gy), or -1.
int find_ghost(const GhostSet& g, double gx, double gy) {
  int found = -1;
  for (std::size_t q = 0; q < g.size(); ++q)
    if (std::abs(g.x[q] - gx) <= kPosTol && std::abs(g.y[q] - gy) <= kPosTol) {
      if (found >= 0) return -2;  // duplicate: also a failure
      found = static_cast<int>(q);
    }
  return found;
}

std::array<double, 2> apply(const Map& m, double u, double v) { return {m[0] * u + m[2], m[1] * v + m[3]}; }

}  // namespace

TEST_CASE("ghosts: a particle near the bottom no-slip wall has one mirror ghost") {
  const Scene scene = unit_box();
  const GhostSet g = build_one(scene, 0.1, 0.5, 0.03);
  REQUIRE(g.size() == 1);
  CHECK(g.source[0] == 0);
  CHECK(std::abs(g.x[0] - 0.5) <= kPosTol);
  CHECK(std::abs(g.y[0] + 0.03) <= kPosTol);  // r' = 2d + r (Szewc eq. 38), d = (0, -0.03)
  CHECK(g.map[0] == Map{-1, -1, 0, 0});        // u' = -u (eq. 39 with w = 0)
  CHECK(g.div_map[0] == g.map[0]);             // no free-slip divergence option
  GhostBuilder gb(scene, 0.1);
  CHECK(gb.has_walls());
}

TEST_CASE("ghosts: a moving top wall maps u' = 2w - u") {
  Scene scene = unit_box();
  scene.sides[kTop].velocity = {1.0, 0.0};
  const GhostSet g = build_one(scene, 0.1, 0.4, 0.95);
  REQUIRE(g.size() == 1);
  CHECK(std::abs(g.x[0] - 0.4) <= kPosTol);
  CHECK(std::abs(g.y[0] - 1.05) <= kPosTol);
  CHECK(g.map[0] == Map{-1, -1, 2, 0});
  const auto u = apply(g.map[0], 0.3, -0.2);
  CHECK(u[0] == doctest::Approx(1.7).epsilon(1e-15));  // 2 * 1 - 0.3
  CHECK(u[1] == doctest::Approx(0.2).epsilon(1e-15));  // 2 * 0 + 0.2
  // Oblique wall velocity too (not physical for a lid, but the map must be componentwise).
  scene.sides[kTop].velocity = {0.25, -0.5};
  const GhostSet g2 = build_one(scene, 0.1, 0.4, 0.95);
  REQUIRE(g2.size() == 1);
  CHECK(g2.map[0] == Map{-1, -1, 0.5, -1.0});
}

TEST_CASE("ghosts: free-slip walls reverse the normal component and keep the tangential one") {
  Scene scene = unit_box();
  for (auto& s : scene.sides) s.slip = SlipKind::free_slip;
  SUBCASE("left wall: normal is x") {
    const GhostSet g = build_one(scene, 0.1, 0.04, 0.5);
    REQUIRE(g.size() == 1);
    CHECK(std::abs(g.x[0] + 0.04) <= kPosTol);
    CHECK(std::abs(g.y[0] - 0.5) <= kPosTol);
    CHECK(g.map[0] == Map{-1, 1, 0, 0});
    const auto u = apply(g.map[0], 0.3, -0.2);
    CHECK(u[0] == -0.3);
    CHECK(u[1] == -0.2);
  }
  SUBCASE("top wall: normal is y") {
    const GhostSet g = build_one(scene, 0.1, 0.5, 0.97);
    REQUIRE(g.size() == 1);
    CHECK(std::abs(g.y[0] - 1.03) <= kPosTol);
    CHECK(g.map[0] == Map{1, -1, 0, 0});
    const auto u = apply(g.map[0], 0.3, -0.2);
    CHECK(u[0] == 0.3);
    CHECK(u[1] == 0.2);
  }
  SUBCASE("two free-slip walls at a corner: the diagonal image is the composition") {
    const GhostSet g = build_one(scene, 0.1, 0.02, 0.05);
    REQUIRE(g.size() == 3);
    const int d = find_ghost(g, -0.02, -0.05);
    REQUIRE(d >= 0);
    CHECK(g.map[d] == Map{-1, -1, 0, 0});  // Szewc eq. 53: both components reversed
  }
}

TEST_CASE("ghosts: corner of two no-slip walls, Szewc eq. 46") {
  // Top-left corner: left wall at rest (w1 = 0), top wall moving (w2 = (1, 0)).
  for (double alpha : {0.0, 0.5, -1.0}) {
    CAPTURE(alpha);
    Scene scene = unit_box();
    scene.sides[kTop].velocity = {1.0, 0.0};
    scene.corner_alpha = alpha;
    const GhostSet g = build_one(scene, 0.1, 0.03, 0.96);
    REQUIRE(g.size() == 3);
    const int left = find_ghost(g, -0.03, 0.96), top = find_ghost(g, 0.03, 1.04), diag = find_ghost(g, -0.03, 1.04);
    REQUIRE(left >= 0);
    REQUIRE(top >= 0);
    REQUIRE(diag >= 0);
    for (std::size_t q = 0; q < 3; ++q) CHECK(g.source[q] == 0);
    CHECK(g.map[left] == Map{-1, -1, 0, 0});  // u'' = -u
    CHECK(g.map[top] == Map{-1, -1, 2, 0});   // u'  = 2 w - u
    // u''' = u + 2 alpha (w1 + w2)
    CHECK(g.map[diag][0] == 1.0);
    CHECK(g.map[diag][1] == 1.0);
    CHECK(g.map[diag][2] == doctest::Approx(2 * alpha * 1.0).epsilon(1e-15));
    CHECK(g.map[diag][3] == 0.0);
    const auto u = apply(g.map[diag], 0.3, -0.2);
    CHECK(u[0] == doctest::Approx(0.3 + 2 * alpha).epsilon(1e-15));
    CHECK(u[1] == doctest::Approx(-0.2).epsilon(1e-15));
    // Without the free-slip divergence option, the divergence uses the same maps.
    for (std::size_t q = 0; q < 3; ++q) CHECK(g.div_map[q] == g.map[q]);
  }
}

TEST_CASE("ghosts: free_slip_divergence uses free-slip maps for the divergence only (Szewc eq. 53)") {
  Scene scene = unit_box();
  scene.free_slip_divergence = true;
  scene.sides[kBottom].velocity = {0.7, 0.0};  // a moving no-slip wall: the viscous map keeps 2w
  scene.corner_alpha = 0.5;
  SUBCASE("single walls") {
    const GhostSet gl = build_one(scene, 0.1, 0.05, 0.5);
    REQUIRE(gl.size() == 1);
    CHECK(gl.map[0] == Map{-1, -1, 0, 0});
    CHECK(gl.div_map[0] == Map{-1, 1, 0, 0});
    const GhostSet gb = build_one(scene, 0.1, 0.5, 0.05);
    REQUIRE(gb.size() == 1);
    CHECK(gb.map[0] == Map{-1, -1, 1.4, 0});
    CHECK(gb.div_map[0] == Map{1, -1, 0, 0});  // the wall velocity does not enter the divergence map
  }
  SUBCASE("bottom-left corner") {
    const GhostSet g = build_one(scene, 0.1, 0.02, 0.06);
    REQUIRE(g.size() == 3);
    const int left = find_ghost(g, -0.02, 0.06), bottom = find_ghost(g, 0.02, -0.06),
              diag = find_ghost(g, -0.02, -0.06);
    REQUIRE(left >= 0);
    REQUIRE(bottom >= 0);
    REQUIRE(diag >= 0);
    CHECK(g.div_map[left] == Map{-1, 1, 0, 0});
    CHECK(g.div_map[bottom] == Map{1, -1, 0, 0});
    CHECK(g.div_map[diag] == Map{-1, -1, 0, 0});
    // The viscous maps stay no-slip, eq. 39 and 46.
    CHECK(g.map[left] == Map{-1, -1, 0, 0});
    CHECK(g.map[bottom] == Map{-1, -1, 1.4, 0});
    CHECK(g.map[diag][0] == 1.0);
    CHECK(g.map[diag][1] == 1.0);
    CHECK(g.map[diag][2] == doctest::Approx(2 * 0.5 * 0.7).epsilon(1e-15));
    CHECK(g.map[diag][3] == 0.0);
  }
}

TEST_CASE("ghosts: periodic in x, walls in y (channel) near the bottom-left corner") {
  Scene scene = unit_box();
  scene.sides[kLeft].kind = SideKind::periodic;
  scene.sides[kRight].kind = SideKind::periodic;
  scene.sides[kBottom].velocity = {0.5, 0.0};
  scene.corner_alpha = 0.5;  // must not matter: only one of the two sides is a wall
  const GhostSet g = build_one(scene, 0.1, 0.02, 0.03);
  REQUIRE(g.size() == 3);
  const int periodic = find_ghost(g, 1.02, 0.03), mirror = find_ghost(g, 0.02, -0.03),
            both = find_ghost(g, 1.02, -0.03);
  REQUIRE(periodic >= 0);
  REQUIRE(mirror >= 0);
  REQUIRE(both >= 0);
  CHECK(g.map[periodic] == Map{1, 1, 0, 0});
  CHECK(g.map[mirror] == Map{-1, -1, 1, 0});
  CHECK(g.map[both] == Map{-1, -1, 1, 0});  // the product image carries the wall's map
  for (std::size_t q = 0; q < 3; ++q) CHECK(g.div_map[q] == g.map[q]);
  // Near the right end, the periodic image goes to the left.
  const GhostSet g2 = build_one(scene, 0.1, 0.97, 0.5);
  REQUIRE(g2.size() == 1);
  CHECK(std::abs(g2.x[0] + 0.03) <= kPosTol);
  CHECK(g2.map[0] == Map{1, 1, 0, 0});
  GhostBuilder gb(scene, 0.1);
  CHECK(gb.has_walls());
}

TEST_CASE("ghosts: particles at or beyond the support radius from every side get none") {
  const Scene scene = unit_box();
  CHECK(build_one(scene, 0.1, 0.5, 0.5).size() == 0);
  CHECK(build_one(scene, 0.1, 0.11, 0.89).size() == 0);
  // Exactly at the support radius (binary-exact numbers): the neighbour search uses r < radius, so a
  // particle at distance R from the wall would have its image at 2R from itself and R from the wall:
  // no fluid particle could see it. None is made.
  CHECK(build_one(scene, 0.125, 0.125, 0.5).size() == 0);
  CHECK(build_one(scene, 0.125, 0.875, 0.5).size() == 0);
  CHECK(build_one(scene, 0.125, 0.5, 0.125).size() == 0);
  CHECK(build_one(scene, 0.125, 0.5, 0.875).size() == 0);
  CHECK(build_one(scene, 0.125, 0.124, 0.5).size() == 1);
  // Several particles at once: sources are indexed correctly.
  const double x[3] = {0.5, 0.05, 0.5}, y[3] = {0.5, 0.5, 0.95};
  GhostBuilder gb(scene, 0.1);
  GhostSet g;
  gb.build(x, y, 3, g);
  REQUIRE(g.size() == 2);
  CHECK(g.source[0] == 1);
  CHECK(g.source[1] == 2);
  // Rebuilding clears the previous ghosts.
  const double far[1] = {0.5};
  gb.build(far, far, 1, g);
  CHECK(g.size() == 0);
  CHECK(g.map.empty());
}

TEST_CASE("ghosts: 1D walls (y = nullptr)") {
  Scene scene = scene_defaults();
  scene.dimension = 1;
  scene.min = {0, 0};
  scene.max = {2, 0};
  scene.sides[kRight].velocity = {0.5, 0.0};
  const double x[3] = {0.05, 1.0, 1.97};
  GhostBuilder gb(scene, 0.1);
  GhostSet g;
  gb.build(x, nullptr, 3, g);
  REQUIRE(g.size() == 2);
  CHECK(g.source[0] == 0);
  CHECK(std::abs(g.x[0] + 0.05) <= kPosTol);
  CHECK(g.map[0][0] == -1.0);
  CHECK(g.map[0][2] == 0.0);
  CHECK(g.source[1] == 2);
  CHECK(std::abs(g.x[1] - 2.03) <= 2 * kPosTol);  // 2 * 2 - 1.97: one rounding of a number ~ 4
  CHECK(g.map[1][0] == -1.0);
  CHECK(g.map[1][2] == 1.0);
}

namespace {
// Fluid lattice (i + 1/2) dx in the unit box plus its ghosts; Shepard-weighted and plain SPH
// interpolation of velocity at a point, with particle velocities u (fluid) and their ghost maps.
struct Interp {
  double shepard[2], plain[2];
};
Interp interpolate(const Kernel& k, const std::vector<double>& x, const std::vector<double>& y,
                   const std::vector<double>& u, const std::vector<double>& v, const GhostSet& g, double V,
                   double px, double py) {
  double num[2] = {0, 0}, den = 0;
  auto add = [&](double bx, double by, double ub, double vb) {
    const double r = std::hypot(px - bx, py - by);
    const double w = k.W(r);
    num[0] += V * ub * w;
    num[1] += V * vb * w;
    den += V * w;
  };
  for (std::size_t b = 0; b < x.size(); ++b) add(x[b], y[b], u[b], v[b]);
  for (std::size_t q = 0; q < g.size(); ++q) {
    const auto s = g.source[q];
    const auto ug = apply(g.map[q], u[s], v[s]);
    add(g.x[q], g.y[q], ug[0], ug[1]);
  }
  return {{num[0] / den, num[1] / den}, {num[0], num[1]}};
}
}  // namespace

TEST_CASE("ghosts: SPH velocity at a moving no-slip wall is the wall velocity (Szewc eqs. 43-45, 48)") {
  const int nside = 40;
  const double dx = 1.0 / nside, V = dx * dx;
  const Kernel k = make_kernel("wendland_quintic", 2 * dx, 2);
  std::vector<double> x, y;
  for (int j = 0; j < nside; ++j)
    for (int i = 0; i < nside; ++i) {
      x.push_back((i + 0.5) * dx);
      y.push_back((j + 0.5) * dx);
    }
  const std::size_t n = x.size();
  std::vector<double> zero(n, 0.0), ur(n), vr(n);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> dist(-1.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    ur[i] = dist(rng);
    vr[i] = dist(rng);
  }

  // Tolerances.
  // Shepard-weighted: the lattice is mirror-symmetric about every wall, so each fluid particle and
  // its mirror have the same W at a wall point and eq. 43 holds term by term: u_a + (2w - u_a) = 2w
  // over twice the weight. What remains is round-off in the mirror positions (2 - y) and in ~100
  // terms of the sums: 1e-12.
  constexpr double kShepardTol = 1e-12;
  // Plain sum (eq. 43 as written): <u> = 2 w sum_fluid V W, and sum_fluid V W = 1/2 only up to the
  // lattice-sum error of the half-space (eq. 44). Observed for Wendland, h = 2 dx, at the three wall
  // points: |<u> - w| / |w| between 3.6e-4 and 7.7e-4 (same order as this kernel's whole-plane
  // Shepard error at h = 2 dx, 1.2e-3, see test_kernels). Tolerance 5e-3, relative to each
  // component of w; an error in the map (e.g. u' = w - u) would give an O(1) miss.
  constexpr double kPlainTol = 5e-3;

  SUBCASE("straight wall (bottom, moving with w), eqs. 43-45") {
    Scene scene = unit_box();
    const std::array<double, 2> w = {1.0, -0.25};  // a normal component too: the map is componentwise
    scene.sides[kBottom].velocity = w;
    GhostBuilder gb(scene, k.radius());
    GhostSet g;
    gb.build(x.data(), y.data(), n, g);
    for (double px : {0.5, 0.5 + 0.3 * dx, 0.37}) {  // at and between lattice columns, far from corners
      CAPTURE(px);
      const Interp a = interpolate(k, x, y, zero, zero, g, V, px, 0.0);
      CHECK(std::abs(a.shepard[0] - w[0]) < kShepardTol);
      CHECK(std::abs(a.shepard[1] - w[1]) < kShepardTol);
      CAPTURE(a.plain[0]);
      CAPTURE(a.plain[1]);
      CHECK(std::abs(a.plain[0] - w[0]) < kPlainTol * std::abs(w[0]));
      CHECK(std::abs(a.plain[1] - w[1]) < kPlainTol * std::abs(w[1]));
      // The fluid velocity cancels exactly against its mirror (eq. 43): any u_a gives the same.
      const Interp b = interpolate(k, x, y, ur, vr, g, V, px, 0.0);
      CHECK(std::abs(b.shepard[0] - w[0]) < kShepardTol);
      CHECK(std::abs(b.shepard[1] - w[1]) < kShepardTol);
    }
  }
  SUBCASE("corner of a resting wall and a moving lid: u = w (1 + alpha) / 2, eq. 48") {
    for (double alpha : {-1.0, 0.0, 0.5, 1.0}) {
      CAPTURE(alpha);
      Scene scene = unit_box();
      const std::array<double, 2> w = {1.0, 0.0};
      scene.sides[kTop].velocity = w;
      scene.corner_alpha = alpha;
      GhostBuilder gb(scene, k.radius());
      GhostSet g;
      gb.build(x.data(), y.data(), n, g);
      // At the corner, the four images of each particle have the same W; with Shepard weights the
      // result is exact up to round-off, whatever the fluid velocity.
      for (const auto* uv : {&zero, &ur}) {
        const Interp a = interpolate(k, x, y, *uv, uv == &zero ? zero : vr, g, V, 0.0, 1.0);
        CHECK(std::abs(a.shepard[0] - 0.5 * w[0] * (1 + alpha)) < kShepardTol);
        CHECK(std::abs(a.shepard[1]) < kShepardTol);
      }
    }
  }
}
