// Anderson acceleration of a fixed-point iteration x = G(x) (Anderson 1965; in the form of Walker &
// Ni 2011, "Anderson acceleration for fixed-point iterations", SIAM J. Numer. Anal. 49(4), eq. (2.1)
// with the least-squares problem (2.2) written for the differences of the residuals).
//
// With f_k = G(x_k) - x_k and the last m differences dF = [f_i+1 - f_i], dG = [G(x_i+1) - G(x_i)],
// the next iterate is
//
//   x_k+1 = G(x_k) - dG gamma,   gamma = argmin || f_k - dF gamma ||_2.
//
// A plain (Picard) iteration is the case m = 0. Where the map contracts slowly along a few modes
// (a factor near 1 a step), those modes are eliminated in about as many iterations as there are;
// the other modes contract as before. The vectors may be distributed: `sum` adds a vector of
// partial dot products over every rank in place (one process: nothing to do).
#pragma once
#include <cstddef>
#include <deque>
#include <functional>
#include <vector>

namespace arksph {

class AndersonAcceleration {
 public:
  using Sum = std::function<void(std::vector<double>&)>;
  // depth: m, the number of differences kept.
  AndersonAcceleration(int depth, Sum sum);
  // Forget the history: the next call starts a new iteration.
  void reset();
  // From x = x_k and g = G(x_k), the next iterate x_k+1 into x.
  void next(std::vector<double>& x, const std::vector<double>& g);

 private:
  int depth_;
  Sum sum_;
  std::vector<double> last_f_, last_g_;
  std::deque<std::vector<double>> df_, dg_;
};

}  // namespace arksph
