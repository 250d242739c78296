#include "projection/poisson/coarse_pressure_space.hpp"

#include <cmath>
#include <vector>

#include <Eigen/SparseCore>

#include "core/errors.hpp"

namespace arksph {

namespace {
// The cubic B-spline on [-2, 2] (unit node spacing) and its derivative.
double bspline(double t) {
  const double s = std::abs(t);
  if (s < 1) return 2.0 / 3.0 - s * s + 0.5 * s * s * s;
  if (s < 2) return (2 - s) * (2 - s) * (2 - s) / 6.0;
  return 0;
}
double bspline_slope(double t) {
  const double s = std::abs(t), sign = t < 0 ? -1.0 : 1.0;
  if (s < 1) return sign * (-2 * s + 1.5 * s * s);
  if (s < 2) return sign * (-0.5 * (2 - s) * (2 - s));
  return 0;
}
}  // namespace

CoarsePressureSpace::CoarsePressureSpace(const Scene& scene, double ratio) {
  if (scene.dimension != 2) throw InputError(scene.source + ": method.projection = \"orthogonal\": 2D scenes only");
  const bool periodic[2] = {scene.sides[0].kind == SideKind::periodic, scene.sides[2].kind == SideKind::periodic};
  nodes_ = 1;
  for (int k = 0; k < 2; ++k) {
    Axis& a = axis_[k];
    a.periodic = periodic[k];
    a.origin = scene.min[k];
    a.length = scene.max[k] - scene.min[k];
    const int m = std::max(1, static_cast<int>(std::lround(a.length / (ratio * scene.spacing))));
    a.spacing = a.length / m;
    a.nodes = a.periodic ? m : m + 1;
    if (m < 4)
      throw InputError(scene.source + ": method.orthogonal_spacing: at least 4 pressure node spacings across the box are needed (got " +
                       std::to_string(m) + ")");
    nodes_ *= static_cast<std::size_t>(a.nodes);
  }
  nodes_ -= 1;  // the pinned first node
}

void CoarsePressureSpace::stencil(const Axis& a, double x, int* node, double* w, double* dw) const {
  const double s = (x - a.origin) / a.spacing;  // in node units from the origin
  const int base = static_cast<int>(std::floor(s)) - 1;
  for (int i = 0; i < 4; ++i) {
    const int j = base + i;  // node index along the axis, counted from the origin
    const double t = s - j;
    w[i] = bspline(t);
    dw[i] = bspline_slope(t) / a.spacing;
    node[i] = a.periodic ? ((j % a.nodes) + a.nodes) % a.nodes : j;
  }
  if (a.periodic) return;
  // Walls: the B-splines of the nodes one spacing outside (j = -1, j = m) are folded into the two
  // nodes next to them by linear extrapolation, q_-1 = 2 q_0 - q_1 (and at the far wall alike), so
  // that the basis still reproduces linear pressures and no node is seen by only a sliver of
  // particles (such nodes left K_c with eigenvalues 1e-8 of its largest and made f jump).
  const int last = a.nodes - 1;
  for (int i = 0; i < 4; ++i) {
    int inner = -1, next = -1;
    if (node[i] < 0) inner = 0, next = 1;
    if (node[i] > last) inner = last, next = last - 1;
    if (inner < 0) continue;
    for (int k = 0; k < 4; ++k) {
      if (node[k] == inner) w[k] += 2 * w[i], dw[k] += 2 * dw[i];
      if (node[k] == next) w[k] -= w[i], dw[k] -= dw[i];
    }
    w[i] = dw[i] = 0;
    node[i] = inner;
  }
}

void CoarsePressureSpace::assemble(const FluidFields& f, const DivergenceOperator& op) {
  n_ = f.n_real;
  col_.assign(16 * n_, -1);
  w_.assign(16 * n_, 0.0);
  wx_.assign(16 * n_, 0.0);
  wy_.assign(16 * n_, 0.0);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(16 * n_);
  for (std::size_t a = 0; a < n_; ++a) {
    int nx[4], ny[4];
    double bx[4], by[4], dbx[4], dby[4];
    stencil(axis_[0], f.x[a], nx, bx, dbx);
    stencil(axis_[1], f.y[a], ny, by, dby);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        const std::size_t e = 16 * a + static_cast<std::size_t>(4 * i + j);
        const long node = static_cast<long>(ny[j]) * axis_[0].nodes + nx[i] - 1;  // -1: the pinned node 0
        if (node < 0 || (bx[i] * by[j] == 0 && dbx[i] * by[j] == 0 && bx[i] * dby[j] == 0)) continue;
        col_[e] = static_cast<std::int32_t>(node);
        w_[e] = bx[i] * by[j];
        wx_[e] = dbx[i] * by[j];
        wy_[e] = bx[i] * dby[j];
        entries.emplace_back(node, static_cast<long>(a), w_[e]);
      }
  }
  // Periodic stencils may hit one node twice (few nodes): the triplets are summed.
  Eigen::SparseMatrix<double> pi_t(static_cast<long>(nodes_), static_cast<long>(n_));
  pi_t.setFromTriplets(entries.begin(), entries.end());
  Eigen::VectorXd vol(static_cast<long>(n_)), inv_sqrt_m(static_cast<long>(n_));
  for (std::size_t a = 0; a < n_; ++a) {
    vol[static_cast<long>(a)] = op.volume()[a];
    inv_sqrt_m[static_cast<long>(a)] = 1.0 / std::sqrt(f.m[a]);
  }
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(static_cast<long>(nodes_), static_cast<long>(nodes_));
  for (int c = 0; c < op.dimension(); ++c) {
    const Eigen::SparseMatrix<double> b = pi_t * vol.asDiagonal() * op.component(c) * inv_sqrt_m.asDiagonal();
    k += Eigen::MatrixXd(b * Eigen::SparseMatrix<double>(b.transpose()));
  }
  factor_.compute(k);
  if (factor_.info() != Eigen::Success)
    throw NumericalFailure("orthogonal projection: K_c could not be factorised (singular at this particle "
                           "distribution; a larger method.orthogonal_spacing conditions it better)");
}

Eigen::VectorXd CoarsePressureSpace::restrict_weighted(const FluidFields& f, const double* s) const {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(static_cast<long>(nodes_));
  for (std::size_t a = 0; a < n_; ++a) {
    const double vs = f.m[a] / f.rho[a] * s[a];
    for (std::size_t e = 16 * a; e < 16 * a + 16; ++e)
      if (col_[e] >= 0) out[col_[e]] += w_[e] * vs;
  }
  return out;
}

Eigen::VectorXd CoarsePressureSpace::motion_rate(const FluidFields& f, const double* u, const double* v,
                                                 const double* d) const {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(static_cast<long>(nodes_));
  for (std::size_t a = 0; a < n_; ++a) {
    const double vd = f.m[a] / f.rho[a] * d[a];
    for (std::size_t e = 16 * a; e < 16 * a + 16; ++e)
      if (col_[e] >= 0) out[col_[e]] += (wx_[e] * u[a] + wy_[e] * v[a]) * vd;
  }
  return out;
}

void CoarsePressureSpace::pressure(const Eigen::VectorXd& c, std::vector<double>& p) const {
  const Eigen::VectorXd q = -factor_.solve(c);
  p.assign(n_, 0.0);
  for (std::size_t a = 0; a < n_; ++a)
    for (std::size_t e = 16 * a; e < 16 * a + 16; ++e)
      if (col_[e] >= 0) p[a] += w_[e] * q[col_[e]];
}

}  // namespace arksph
