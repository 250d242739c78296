// `arksph study work-precision` without running a study: the error measures (analytic field,
// interpolated reference run) and the soonest-to-error interpolation. The real binary on a study:
// process/test_work_precision_study.cpp.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/errors.hpp"
#include "study/reference_error.hpp"
#include "study/work_precision.hpp"
#include "test_support.hpp"

using namespace arksph;
namespace fs = std::filesystem;

namespace {
// A lattice of n x n particles on the unit square with velocity (fu(x, y), fv(x, y)).
template <class Fu, class Fv>
ParticleVelocities lattice(int n, Fu fu, Fv fv) {
  ParticleVelocities p;
  const double dx = 1.0 / n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = (i + 0.5) * dx, y = (j + 0.5) * dx;
      p.x.push_back(x), p.y.push_back(y), p.u.push_back(fu(x, y)), p.v.push_back(fv(x, y));
      p.volume.push_back(dx * dx);
    }
  return p;
}

}  // namespace

TEST_CASE("work-precision: errors against an analytic field are the mean, r.m.s. and max of |u - u_exact|") {
  // Exact field u = x, v = 0 against a run holding u = x + 0.1 on half the particles: e_a = 0.1 or 0.
  ParticleVelocities run = lattice(4, [](double x, double) { return x; }, [](double, double) { return 0.0; });
  for (std::size_t a = 0; a < run.u.size(); a += 2) run.u[a] += 0.1;
  const AnalyticVelocity exact("x + 0*t", "0*y");
  const VelocityErrors e = errors_against_analytic(run, exact, 0.3);
  CHECK(e.l1 == doctest::Approx(0.05).epsilon(1e-12));
  CHECK(e.l2 == doctest::Approx(std::sqrt(0.005)).epsilon(1e-12));
  CHECK(e.linf == doctest::Approx(0.1).epsilon(1e-12));
  // The expressions see t: u = t gives |0.1 + x - 0.3| etc.; at the exact field itself the error is 0.
  const VelocityErrors zero = errors_against_analytic(lattice(5, [](double x, double) { return x; },
                                                              [](double, double y) { return -y; }),
                                                      AnalyticVelocity("x", "-y"), 1.0);
  CHECK(zero.linf == 0.0);
  CHECK_THROWS_AS(AnalyticVelocity("sin(", "0"), InputError);
}

TEST_CASE("work-precision: the Shepard interpolation of a reference run reproduces constant and interior linear fields") {
  // Shepard normalisation reproduces a constant exactly (rounding only: 1e-14). A linear field is
  // reproduced where the lattice is symmetric about the point (particle positions and cell corners of
  // the reference lattice, away from its edges): there the first kernel moment vanishes.
  const ParticleVelocities ref_const = lattice(40, [](double, double) { return 0.7; }, [](double, double) { return -0.2; });
  const ParticleVelocities coarse = lattice(10, [](double, double) { return 0.7; }, [](double, double) { return -0.2; });
  const VelocityErrors c = errors_against_reference(coarse, ref_const, "quartic_spline", 1.3 / 40);
  CHECK(c.linf < 1e-14);

  ParticleVelocities ref_lin = lattice(40, [](double x, double) { return x; }, [](double, double y) { return 2 * y; });
  ParticleVelocities inner;
  for (double x : {0.3, 0.5, 0.6125})  // 12/40, 20/40 (cell corners), 24.5/40 (a particle)
    for (double y : {0.35, 0.5, 0.7}) {
      inner.x.push_back(x), inner.y.push_back(y), inner.u.push_back(x), inner.v.push_back(2 * y), inner.volume.push_back(1);
    }
  const VelocityErrors l = errors_against_reference(inner, ref_lin, "quartic_spline", 1.3 / 40);
  CHECK(l.linf < 1e-12);  // exact up to rounding of sums of about 60 terms
  // A wrong reference is seen: the error is the offset.
  const VelocityErrors off = errors_against_reference(coarse, lattice(40, [](double, double) { return 0.8; },
                                                                         [](double, double) { return -0.2; }),
                                                      "quartic_spline", 1.3 / 40);
  CHECK(off.l1 == doctest::Approx(0.1).epsilon(1e-12));
}

TEST_CASE("work-precision: the wall time to a target error is interpolated log-log along a curve") {
  auto pt = [](double w, double e) {
    WorkPrecisionPoint p;
    p.wall_seconds = w, p.l2 = e, p.status = "ok";
    return p;
  };
  const std::vector<WorkPrecisionPoint> curve = {pt(1, 1e-2), pt(10, 1e-3), pt(100, 1e-4)};
  // error ~ 1e-2 / wall on this curve: error 3e-4 is reached at wall = 1e-2 / 3e-4 = 33.3 s.
  CHECK(time_to_error(curve, 3e-4) == doctest::Approx(1e-2 / 3e-4).epsilon(1e-12));
  CHECK(time_to_error(curve, 2e-2) == 1.0);   // the coarsest run is already below the target
  CHECK(time_to_error(curve, 1e-5) < 0);      // never reached
  std::vector<WorkPrecisionPoint> with_failure = curve;
  with_failure[1].status = "failed";  // failed runs are left out: interpolation between 1 s and 100 s
  CHECK(time_to_error(with_failure, 1e-3) == doctest::Approx(10.0).epsilon(1e-12));
}
