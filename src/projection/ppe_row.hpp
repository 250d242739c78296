// One row of the pressure Poisson matrix -V L of ppe_assembly.hpp (C&R 1999 eq. 19, rows scaled by
// -V_a), shared by the one-process assembly (assemble_ppe) and the distributed one
// (distributed_ppe/ppe_rows.hpp), so that both build the same coefficients from the same fields.
#pragma once
#include <cstddef>
#include <cstdint>

#include "kernels/kernel.hpp"
#include "rhs/fluid_fields.hpp"

namespace arksph {

// eta^2 = 0.01 h^2 of C&R eq. 19 (keeps the coefficient finite at r -> 0).
inline double ppe_eta2(const FluidFields& f) { return 0.01 * f.kernel->h() * f.kernel->h(); }

// Coefficient c_ab of (P_a - P_b) in L(P)_a, C&R eq. 19: r . grad W = F r^2.
inline double laplacian_coeff(const FluidFields& f, std::size_t a, std::uint32_t b, double r2, double F, double eta2) {
  return f.m[b] / f.rho[b] * 4.0 / (f.rho[a] + f.rho[b]) * F * r2 / (r2 + eta2);
}

// Row a of -V L over a's pairs (real neighbours and ghosts): column(s) names the unknown of the real
// particle s a neighbour stands for (f.src; a ghost's pressure is its source's, C&R §2.5), and
// off(col, value) receives each off-diagonal term in pair order (value = V_a c_ab with the sign of
// -V L, < 0; several images of one source give several terms). Neighbours whose column is a's own
// (a's mirror image; on a rank of a decomposed run also a's own periodic copy) add P_a - P_a = 0 and
// are skipped. Returns the diagonal, the sum of -V_a c_ab over the other terms.
template <class Column, class Off>
double ppe_row(const FluidFields& f, std::size_t a, double eta2, Column&& column, Off&& off) {
  const double va = f.m[a] / f.rho[a];
  const auto own = column(static_cast<std::uint32_t>(a));
  double diag = 0;
  f.pairs.for_pairs(a, [&](std::uint32_t b, double, double, double r2, double, double F) {
    const auto col = column(f.src[b]);
    if (col == own) return;
    const double c = -va * laplacian_coeff(f, a, b, r2, F, eta2);  // > 0
    diag += c;
    off(col, -c);
  });
  return diag;
}

// The diagonal entry of a row after ppe_row, and its source b: the pinned row reads P = 0 (1, b
// left as it is); a row of given P (a free surface) reads P_a = value, scaled like the row it
// replaces (1 for a lone particle); any other row keeps its diagonal and takes the given columns'
// values it dropped (`moved`, the sum of coefficient x value) into its source.
inline double close_row(bool pinned, bool given, double diag, double value, double moved, double& b) {
  if (pinned) return 1.0;
  if (given) {
    const double scale = diag > 0 ? diag : 1.0;
    b = scale * value;
    return scale;
  }
  b -= moved;
  return diag;
}

// Sorts the first len entries of a row by column (stable insertion sort: equal columns keep their
// pair order) and merges equal columns, summing in that order. Returns the merged length.
template <class Index>
int sort_merge_row(Index* col, double* val, int len) {
  for (int k = 1; k < len; ++k) {
    const Index ck = col[k];
    const double vk = val[k];
    int i = k;
    for (; i > 0 && col[i - 1] > ck; --i) {
      col[i] = col[i - 1];
      val[i] = val[i - 1];
    }
    col[i] = ck;
    val[i] = vk;
  }
  int m = 0;
  for (int k = 0; k < len; ++k) {
    if (m > 0 && col[m - 1] == col[k]) {
      val[m - 1] += val[k];
    } else {
      col[m] = col[k];
      val[m++] = val[k];
    }
  }
  return m;
}

}  // namespace arksph
