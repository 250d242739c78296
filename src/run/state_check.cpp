#include "run/state_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/errors.hpp"
#include "rhs/reference_speed.hpp"

namespace arksph {

namespace {
// A value in a diagnosis: 10 significant digits (a test or a user compares it with t), exponent form
// when large or small.
std::string precise(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", v);
  return text;
}
}  // namespace

StateChecker::StateChecker(const Scene& scene, const Model& model)
    : StateChecker(scene, model, model.rhs->max_acceleration()) {}

StateChecker::StateChecker(const Scene& scene, const Model& model, double max_acceleration)
    : scene_(scene), model_(model) {
  // Bound on the speed: time.blowup_speed, or 100 x the largest physical speed scale of the scene
  // (sound speed for wcsph, wall speeds, initial speeds, 10 sqrt(a L) with a the largest acceleration
  // at the start, 10 sqrt(|g| L) of the body force); a run beyond it has blown up.
  double u_ref = model.sound_speed;
  for (int s = 0; s < 2 * scene.dimension; ++s)
    u_ref = std::max(u_ref, std::hypot(scene.sides[s].velocity[0], scene.sides[s].velocity[1]));
  for (int k = 0; k < scene.dimension; ++k)
    for (double u : model.particles.init_vel[k]) u_ref = std::max(u_ref, std::abs(u));
  u_ref = std::max(u_ref, 10.0 * std::sqrt(max_acceleration * (scene.max[0] - scene.min[0])));
  // The body force too, which the projection schemes may carry in the pressure (rhs/pressure_gravity.hpp),
  // so that the acceleration at the start is zero: 10 sqrt(|g| L).
  u_ref = std::max(u_ref, 10.0 * reference_speed(scene, 0.0));
  speed_limit_ = scene.blowup_speed > 0 ? scene.blowup_speed : 100.0 * std::max(u_ref, 1e-6);
  margin_ = model.rhs->kernel().radius();
}

void StateChecker::check(double t, const double* y) const { check(t, y, model_.rhs->layout(), model_.particles.id); }

void StateChecker::check(double t, const double* y, const StateLayout& L, const std::vector<std::int64_t>& ids) const {
  auto fail = [&](std::size_t a, const std::string& what) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "t = %.9g, particle id %lld: ", t, static_cast<long long>(ids[a]));
    throw NumericalFailure(buf + what);
  };
  for (std::size_t a = 0; a < L.n; ++a) {
    double s2 = 0;
    for (int k = 0; k < L.dim; ++k) {
      const double x = y[L.pos(k) + a], u = y[L.vel(k) + a];
      if (!std::isfinite(x)) fail(a, std::string("position ") + "xy"[k] + " is not finite");
      if (!std::isfinite(u)) fail(a, std::string("velocity ") + "uv"[k] + " is not finite");
      s2 += u * u;
      const bool wall_lo = scene_.sides[2 * k].kind == SideKind::wall;
      const bool wall_hi = scene_.sides[2 * k + 1].kind == SideKind::wall;
      if ((wall_lo && x < scene_.min[k] - margin_) || (wall_hi && x > scene_.max[k] + margin_))
        fail(a, std::string("escaped through a wall (") + "xy"[k] + " = " + precise(x) + ")");
    }
    if (std::sqrt(s2) > speed_limit_)
      fail(a, "speed " + precise(std::sqrt(s2)) + " exceeds the blow-up bound " + precise(speed_limit_) +
                  (scene_.blowup_speed > 0 ? " (time.blowup_speed)" : ""));
    if (L.has_density) {
      const double rho = y[L.rho() + a];
      if (!std::isfinite(rho) || rho <= 0) fail(a, "density " + precise(rho) + " is not positive and finite");
    }
  }
}

// Adaptive mode: steps that t + dt can barely or no longer resolve, several in a row, mean the run
// will never reach time.end. One such step alone is not enough: ARKODE may end the approach to a
// stop time (an output or checkpoint time) with a sliver of a step. `tiny`: the count so far.
namespace {
constexpr int kTinyStepsInARow = 10;
}  // namespace

void check_step_size(double t, double dt, double end, int& tiny) {
  const double floor = 1e-12 * std::max(std::abs(t), end);
  tiny = (dt < floor || t + dt == t) ? tiny + 1 : 0;
  if (tiny >= kTinyStepsInARow) {
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "t = %.9g: the adaptive time step %.3g underflowed (below 1e-12 max(|t|, time.end) = %.3g, %d steps "
                  "in a row): the run cannot reach time.end",
                  t, dt, floor, kTinyStepsInARow);
    throw NumericalFailure(buf);
  }
}

std::string describe_rhs_entry(const StateLayout& L, const std::vector<std::int64_t>& ids, std::size_t i,
                               double value) {
  const std::size_t a = i % L.n, block = i / L.n;
  const int k = static_cast<int>(block % static_cast<std::size_t>(L.dim));
  std::string what;
  if (block < static_cast<std::size_t>(L.dim))
    what = std::string("velocity ") + "uv"[k] + " (dx/dt)";
  else if (block < 2 * static_cast<std::size_t>(L.dim))
    what = std::string("acceleration a") + "xy"[k];
  else if (L.has_density && i >= L.rho() && i < L.rho() + L.n)
    what = "density rate drho/dt";
  else
    what = "energy rate de/dt";
  char buf[64];
  std::snprintf(buf, sizeof buf, "particle id %lld: ", static_cast<long long>(a < ids.size() ? ids[a] : -1));
  return buf + what + " = " + message_number(value) + " in the right-hand side";
}

}  // namespace arksph
