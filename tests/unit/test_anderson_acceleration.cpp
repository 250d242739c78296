// Anderson acceleration (projection/anderson_acceleration.hpp) on a linear fixed point
// x = M x + b whose exact solution is known: x* = (I - M)^-1 b. M is diagonal with a spectrum that
// a plain iteration is slow on (three modes contracting by 0.95, 0.9 and -0.85 a step, the others by
// 0.1), so that the test tells acceleration from none.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "projection/anderson_acceleration.hpp"

using namespace arksph;

namespace {

constexpr std::size_t kSize = 40;

double eigenvalue(std::size_t i) {
  if (i == 3) return 0.95;
  if (i == 17) return 0.9;
  if (i == 29) return -0.85;
  return 0.1 * std::cos(static_cast<double>(i));
}

// Iterations until |G(x) - x| <= 1e-12 max|x*| (at most `limit`), and the error max|x - x*| then.
struct Outcome {
  int iterations = 0;
  double error = 0;
};

Outcome iterate(int depth, int limit) {
  std::vector<double> b(kSize), exact(kSize), x(kSize, 0.0), g(kSize);
  double scale = 0;
  for (std::size_t i = 0; i < kSize; ++i) {
    b[i] = 1.0 + 0.5 * std::sin(3.0 * static_cast<double>(i));
    exact[i] = b[i] / (1.0 - eigenvalue(i));
    scale = std::max(scale, std::abs(exact[i]));
  }
  // The distributed form's sum over ranks: one process, nothing to add.
  AndersonAcceleration anderson(depth, [](std::vector<double>&) {});
  Outcome out;
  for (out.iterations = 1; out.iterations <= limit; ++out.iterations) {
    double change = 0;
    for (std::size_t i = 0; i < kSize; ++i) {
      g[i] = eigenvalue(i) * x[i] + b[i];
      change = std::max(change, std::abs(g[i] - x[i]));
    }
    if (change <= 1e-12 * scale) break;
    anderson.next(x, g);
  }
  for (std::size_t i = 0; i < kSize; ++i) out.error = std::max(out.error, std::abs(g[i] - exact[i]));
  out.error /= scale;
  return out;
}

}  // namespace

// With three slow modes, depth 5 converges within about twice as many iterations as the fast modes
// need (1e-12 at 0.1 a step: 12) plus the slow ones' count; 30 allows for the rounding of the small
// least-squares problem. The plain iteration needs log(1e-12) / log(0.95) = 539 iterations and has
// not converged after 30.
TEST_CASE("Anderson acceleration: a linear fixed point with slow modes converges in a few iterations") {
  const Outcome accelerated = iterate(5, 30);
  MESSAGE("depth 5: ", accelerated.iterations, " iterations, error ", accelerated.error);
  CHECK(accelerated.iterations <= 30);
  CHECK(accelerated.error <= 1e-10);  // the change bound 1e-12 over (1 - 0.95): within 2e-11

  const Outcome plain = iterate(0, 30);
  MESSAGE("depth 0 (plain iteration): error ", plain.error, " after 30");
  CHECK(plain.iterations > 30);
  CHECK(plain.error > 1e-2);
}

TEST_CASE("Anderson acceleration: after reset it starts afresh (the history of another iteration is dropped)") {
  AndersonAcceleration anderson(3, [](std::vector<double>&) {});
  std::vector<double> x{1.0, 2.0}, g{5.0, -1.0};
  anderson.next(x, g);
  anderson.next(x, std::vector<double>{7.0, 7.0});
  anderson.reset();
  std::vector<double> y{0.0, 0.0};
  const std::vector<double> gy{3.0, 4.0};
  anderson.next(y, gy);  // no history: the plain step x <- G(x)
  CHECK(y == gy);
}
