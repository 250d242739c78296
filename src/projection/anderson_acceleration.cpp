#include "projection/anderson_acceleration.hpp"

#include <Eigen/Dense>
#include <utility>

namespace arksph {

AndersonAcceleration::AndersonAcceleration(int depth, Sum sum) : depth_(depth), sum_(std::move(sum)) {}

void AndersonAcceleration::reset() {
  last_f_.clear();
  last_g_.clear();
  df_.clear();
  dg_.clear();
}

void AndersonAcceleration::next(std::vector<double>& x, const std::vector<double>& g) {
  const std::size_t n = x.size();
  std::vector<double> f(n);
  for (std::size_t i = 0; i < n; ++i) f[i] = g[i] - x[i];
  if (!last_f_.empty() && depth_ > 0) {
    std::vector<double> d(n), e(n);
    for (std::size_t i = 0; i < n; ++i) d[i] = f[i] - last_f_[i], e[i] = g[i] - last_g_[i];
    df_.push_back(std::move(d));
    dg_.push_back(std::move(e));
    if (static_cast<int>(df_.size()) > depth_) df_.pop_front(), dg_.pop_front();
  }
  last_f_ = f;
  last_g_ = g;
  const std::size_t m = df_.size();
  x = g;
  if (m == 0) return;
  // The normal equations dF^T dF gamma = dF^T f: m (m + 1) / 2 + m dot products, summed over the
  // ranks in one call. A rank-revealing solve, so that nearly parallel differences do not blow
  // gamma up.
  std::vector<double> dots;
  dots.reserve(m * (m + 1) / 2 + m);
  for (std::size_t a = 0; a < m; ++a) {
    for (std::size_t b = 0; b <= a; ++b) {
      double s = 0;
      for (std::size_t i = 0; i < n; ++i) s += df_[a][i] * df_[b][i];
      dots.push_back(s);
    }
    double s = 0;
    for (std::size_t i = 0; i < n; ++i) s += df_[a][i] * f[i];
    dots.push_back(s);
  }
  sum_(dots);
  Eigen::MatrixXd gram(m, m);
  Eigen::VectorXd rhs(m);
  std::size_t at = 0;
  for (std::size_t a = 0; a < m; ++a) {
    for (std::size_t b = 0; b <= a; ++b) gram(a, b) = gram(b, a) = dots[at++];
    rhs(a) = dots[at++];
  }
  const Eigen::VectorXd gamma = gram.completeOrthogonalDecomposition().solve(rhs);
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t i = 0; i < n; ++i) x[i] -= gamma(a) * dg_[a][i];
}

}  // namespace arksph
