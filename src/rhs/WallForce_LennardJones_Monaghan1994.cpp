// Repulsive boundary particles of Lennard-Jones type (Monaghan 1994, "Simulating free surface flows
// with SPH", J. Comput. Phys. 110, §3; the wall model of Cummins & Rudman 1999 §3.1.1 for WCSPH).
//
// Each wall carries a row of fixed boundary particles on its line, spaced r0 apart. A fluid particle
// a closer than r0 to a boundary particle k feels the central force per unit mass
//   f_ak = D ((r0/r)^p1 - (r0/r)^p2) r_ak / r^2,   r = |r_ak| < r0,   p1 = 12, p2 = 4,
// and none beyond r0, so a lattice whose first row lies r0 from the wall starts in equilibrium.
// D = boundary.wall_force_strength, or the square of the scene's reference speed when 0 (Monaghan
// chooses D of the order of the largest velocity squared); r0 = boundary.wall_force_range dx (0.5:
// the distance of the first row of the cell-centred lattice). A corner point belongs to the vertical
// wall only, so it pushes once; along a periodic tangential side the row wraps around.
//
// The force is added on top of whatever the walls do otherwise: with `boundary.wall_ghosts = false`
// (WCSPH) it is the only wall model, as in Monaghan 1994 and Cummins & Rudman's WCSPH runs.
#include <algorithm>
#include <cmath>

#include "core/param_builder.hpp"
#include "rhs/reference_speed.hpp"
#include "rhs/term_registry.hpp"
#include "rhs/terms.hpp"

namespace arksph {
namespace {

// Distances below this fraction of r0 count as this fraction: a particle pushed onto a boundary
// particle gets a large finite force (the run's wall reflection returns escapes), never inf.
constexpr double kClosest = 0.25;

class LennardJonesWall final : public Term {
 public:
  LennardJonesWall(const Scene& s, double strength, double range)
      : dim_(s.dimension), strength_(strength), r0_(range), sides_(s.sides), lo_(s.min), hi_(s.max) {}
  std::string name() const override { return "wall_force:lennard_jones"; }
  Stage stage() const override { return Stage::force; }
  bool uses_neighbors() const override { return false; }
  void apply(FluidFields& f) const override {
    double* out[2] = {f.dudt.data(), f.dvdt.data()};
    for (std::size_t a = 0; a < f.n_real; ++a) {
      const double p[2] = {f.x[a], dim_ == 2 ? f.y[a] : 0.0};
      double acc[2] = {0.0, 0.0};
      for (int side = 0; side < 2 * dim_; ++side)
        if (sides_[side].kind == SideKind::wall) add_wall(side, p, acc);
      for (int k = 0; k < dim_; ++k) out[k][a] += acc[k];
    }
  }

 private:
  // D ((r0/r)^12 - (r0/r)^4) / r^2, the factor of r_ak.
  double magnitude(double r2) const {
    const double s2 = r0_ * r0_ / std::max(r2, kClosest * kClosest * r0_ * r0_);  // (r0/r)^2
    const double s4 = s2 * s2;
    return strength_ * (s4 * s4 * s4 - s4) / std::max(r2, kClosest * kClosest * r0_ * r0_);
  }
  // The boundary particles of one wall near p: along the tangential axis t at lo_t + j r0.
  void add_wall(int side, const double p[2], double acc[2]) const {
    const int k = side / 2;
    const double plane = side % 2 ? hi_[k] : lo_[k];
    const double dn = p[k] - plane;  // signed normal offset from the wall line
    if (std::abs(dn) >= r0_) return;
    if (dim_ == 1) {
      acc[0] += magnitude(dn * dn) * dn;
      return;
    }
    const int t = 1 - k;
    const double length = hi_[t] - lo_[t];
    const long n = std::lround(length / r0_);  // boundary particles lo_t + j r0, j = 0..n
    const bool periodic = sides_[2 * t].kind == SideKind::periodic;
    // Corner points: kept by the vertical walls (k = 0) only, where the adjoining side is a wall.
    const long first = (k == 1 && !periodic && sides_[2 * t].kind == SideKind::wall) ? 1 : 0;
    const long last = periodic ? n - 1 : ((k == 1 && sides_[2 * t + 1].kind == SideKind::wall) ? n - 1 : n);
    const long j0 = static_cast<long>(std::ceil((p[t] - r0_ - lo_[t]) / r0_));
    const long j1 = static_cast<long>(std::floor((p[t] + r0_ - lo_[t]) / r0_));
    for (long j = j0; j <= j1; ++j) {
      if (!periodic && (j < first || j > last)) continue;
      const double dt = p[t] - (lo_[t] + static_cast<double>(j) * length / static_cast<double>(n));
      const double r2 = dn * dn + dt * dt;
      if (r2 >= r0_ * r0_) continue;
      const double m = magnitude(r2);
      acc[k] += m * dn;
      acc[t] += m * dt;
    }
  }

  int dim_;
  double strength_, r0_;
  std::array<SideSpec, 4> sides_;
  std::array<double, 2> lo_, hi_;
};

}  // namespace

Part<TermFactory> wall_force_none() {
  return {"none", "no wall force: the walls act through their ghost particles only"};
}

Part<TermFactory> wall_force_lennard_jones() {
  return {"lennard_jones",
          "repulsive Lennard-Jones boundary particles on the walls, (r0/r)^12 - (r0/r)^4 (Monaghan 1994 §3)",
          [](const Scene& s) -> std::unique_ptr<Term> {
            double strength = part_param<double>(s, "boundary.wall_force_strength");
            if (strength <= 0) {
              const double u = reference_speed(s);
              strength = u * u;
            }
            return std::make_unique<LennardJonesWall>(s, strength,
                                                      part_param<double>(s, "boundary.wall_force_range") * s.spacing);
          },
          {number("boundary.wall_force_strength", 0.0).in(at_least(0)).unit("m^2/s^2")
               .doc("D of the Lennard-Jones wall force (0: the square of the reference speed)"),
           number("boundary.wall_force_range", 0.5).in(above(0))
               .doc("r0 / dx: range of the force and spacing of the boundary particles (0.5: the first lattice row)")}};
}

}  // namespace arksph
