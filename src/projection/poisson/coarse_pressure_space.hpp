// The pressure space of the orthogonal projection (method.projection = "orthogonal"): pressures
// p = Pi q spanned by cubic B-splines on a regular grid of spacing about H = ratio x dx
// (method.orthogonal_spacing), Pi_aJ = B((x_a - X_J)/H) B((y_a - Y_J)/H) at the particle positions.
//
// With D and G = -M^-1 D^T V the adjoint pair of projection/divergence_operator.hpp, the constraint
// is D_c u = Pi^T V D u = 0 (D u = 0 in the weak sense of the coarse space) and the projection
//
//   P = I - M^-1 D_c^T K_c^-1 D_c,   K_c = D_c M^-1 D_c^T = Pi^T K Pi,
//
// is orthogonal in <u, w>_m = sum_a m_a u_a . w_a, hence idempotent to round-off. On particles
// (Pi = I) K = V D M^-1 D^T V has near-null odd-even modes on a disordered set, and enforcing D u = 0
// through them moves a smooth divergence-free field by several per cent; on the coarse space those
// modes are not represented (the B-spline of a particle-scale pattern is smooth). Measured on a
// 24 x 24 Taylor-Green field, lattice shaken by 0.2 dx, Wendland h = 2 dx: |P u - u| / |u| = 0.061
// on particles, 0.015 with H = 2 dx, 0.0043 with H = 3 dx, 0.0026 with H = 4 dx.
//
// Grid: m = round(L / (ratio dx)) spacings across the box (at least 4). A periodic axis has m nodes,
// wrapped; an axis with walls has the m + 1 nodes from wall to wall, the B-splines of the nodes
// outside folded into their neighbours by linear extrapolation (stencil). The first node is held at q = 0: it removes the constant, which on a
// periodic lattice is in the null space of K_c, and leaves K_c positive definite (one constraint,
// the total volume flux, is given up). K_c is small (N / ratio^2 nodes) and factorised densely
// (Eigen LDLT) at every evaluation.
#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Dense>

#include "core/scene.hpp"
#include "projection/divergence_operator.hpp"
#include "rhs/fluid_fields.hpp"

namespace arksph {

class CoarsePressureSpace {
 public:
  CoarsePressureSpace(const Scene& scene, double ratio);
  // Pi at the positions of f, K_c = Pi^T K Pi from op (assembled at the same fields), factorised.
  void assemble(const FluidFields& f, const DivergenceOperator& op);
  std::size_t size() const { return nodes_; }
  // Pi^T (V s): a particle field (one value per real particle) restricted to the coarse space.
  Eigen::VectorXd restrict_weighted(const FluidFields& f, const double* s) const;
  // sum_a (grad Pi_aJ . u_a) V_a d_a: the rate of change of Pi^T V d that the particles' motion
  // makes (grid fixed, particles moving with (u, v)).
  Eigen::VectorXd motion_rate(const FluidFields& f, const double* u, const double* v, const double* d) const;
  // q = -K_c^-1 c and p = Pi q at the particles: the pressure whose gradient G p removes the
  // coarse divergence c (D_c (u - G p) = D_c u + K_c q).
  void pressure(const Eigen::VectorXd& c, std::vector<double>& p) const;

 private:
  struct Axis {
    bool periodic = false;
    double origin = 0, spacing = 1, length = 1;
    int nodes = 0;  // node i sits at origin + i spacing
  };
  // The 4 nodes of axis `a` around coordinate x with their B-spline values and derivatives.
  void stencil(const Axis& a, double x, int* node, double* w, double* dw) const;

  Axis axis_[2];
  std::size_t nodes_ = 0;
  // Pi row by row: 16 entries per particle (node index, or -1 for the pinned node), weights and
  // gradients.
  std::vector<std::int32_t> col_;
  std::vector<double> w_, wx_, wy_;
  std::size_t n_ = 0;
  Eigen::LDLT<Eigen::MatrixXd> factor_;
};

}  // namespace arksph
