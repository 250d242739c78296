// The kernel_correction term: fills <1>, <grad 1> and the Bonet-Lok matrix of Basa et al. 2008
// eqs. 21-26 for the real particles (see KernelCorrection_Basa2008.hpp), then copies them to the
// ghosts, reflected where the ghost is a mirror image (the point set is mirror-symmetric there).
// Runs in the pressure stage, when the densities of all points (V_b = m_b / rho_b) are final.
#include "rhs/KernelCorrection_Basa2008.hpp"
#include "rhs/term_registry.hpp"

#include <cmath>

#include "core/errors.hpp"
#include "kernels/kernel.hpp"
#include "rhs/terms.hpp"

namespace arksph {

double shepard_interpolate(const FluidFields& f, std::size_t a, const double* field) {
  double num = f.m[a] / f.rho[a] * field[a] * f.kernel->W(0.0), den = f.m[a] / f.rho[a] * f.kernel->W(0.0);
  f.pairs.for_pairs(a, [&](std::uint32_t b, double, double, double, double w, double) {
    const double vb = f.m[b] / f.rho[b];
    num += vb * field[b] * w;
    den += vb * w;
  });
  return num / den;
}

namespace {

class KernelCorrection final : public Term {
 public:
  explicit KernelCorrection(FluidFields::Correction kind) : kind_(kind) {}
  std::string name() const override {
    return kind_ == FluidFields::Correction::shepard ? "kernel_correction:shepard" : "kernel_correction:bonet_lok";
  }
  Stage stage() const override { return Stage::pressure; }
  void apply(FluidFields& f) const override {
    const std::size_t n = f.n_real, n_all = f.n_all;
    f.correction = FluidFields::Correction::none;  // plain gradients while the data is built
    f.one.assign(n_all, 1.0);
    f.grad1x.assign(n_all, 0.0);
    f.grad1y.assign(n_all, 0.0);
    f.lmat.assign(4 * n_all, 0.0);
    const double w0 = f.kernel->W(0.0);
#pragma omp parallel for schedule(static)
    for (std::size_t a = 0; a < n; ++a) {
      double one = f.m[a] / f.rho[a] * w0, gx = 0, gy = 0;
      f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double w, double F) {
        const double vb = f.m[b] / f.rho[b];
        one += vb * w;
        gx += vb * F * rx;
        gy += vb * F * ry;
      });
      f.one[a] = one;
      f.grad1x[a] = gx;
      f.grad1y[a] = gy;
    }
    f.correction = FluidFields::Correction::shepard;
    if (kind_ == FluidFields::Correction::bonet_lok) {
#pragma omp parallel for schedule(static)
      for (std::size_t a = 0; a < n; ++a) {
        // M_ij = sum_b V_b G0_i (r_b - r_a)_j, with r_b - r_a = -r_ab.
        double m00 = 0, m01 = 0, m10 = 0, m11 = 0;
        f.pairs.for_pairs(a, [&](std::uint32_t b, double rx, double ry, double, double w, double F) {
          const double vb = f.m[b] / f.rho[b];
          double gx, gy;
          corrected_gradient(f, a, rx, ry, w, F, gx, gy);
          m00 -= vb * gx * rx;
          m01 -= vb * gx * ry;
          m10 -= vb * gy * rx;
          m11 -= vb * gy * ry;
        });
        double* L = &f.lmat[4 * a];
        if (f.dim == 1) {
          L[0] = 1.0 / m00, L[3] = 1.0;
          continue;
        }
        const double det = m00 * m11 - m01 * m10;
        if (!(std::abs(det) > 1e-12 * (m00 * m00 + m11 * m11))) {  // too few neighbours: no first-order fix
          L[0] = L[3] = 1.0;
          continue;
        }
        L[0] = m11 / det, L[1] = -m01 / det, L[2] = -m10 / det, L[3] = m00 / det;
      }
    } else {
      for (std::size_t a = 0; a < n; ++a) f.lmat[4 * a] = f.lmat[4 * a + 3] = 1.0;
    }
    // Ghosts: the source's data, reflected (<grad 1> flips with the axis, L -> P L P).
    for (std::size_t i = n; i < n_all; ++i) {
      const std::size_t s = f.src[i];
      const double sx = f.flip_x.empty() ? 1.0 : f.flip_x[i], sy = f.flip_y.empty() ? 1.0 : f.flip_y[i];
      f.one[i] = f.one[s];
      f.grad1x[i] = sx * f.grad1x[s];
      f.grad1y[i] = sy * f.grad1y[s];
      f.lmat[4 * i] = f.lmat[4 * s];
      f.lmat[4 * i + 1] = sx * sy * f.lmat[4 * s + 1];
      f.lmat[4 * i + 2] = sx * sy * f.lmat[4 * s + 2];
      f.lmat[4 * i + 3] = f.lmat[4 * s + 3];
    }
    f.correction = kind_;
  }

 private:
  FluidFields::Correction kind_;
};

}  // namespace

Part<TermFactory> kernel_correction_none() { return {"none", "plain kernel gradients"}; }
Part<TermFactory> kernel_correction_shepard() {
  return {"shepard", "Shepard-normalised kernel gradients (Basa et al. 2008 eqs. 21-23)", [](const Scene&) -> std::unique_ptr<Term> {
            return std::make_unique<KernelCorrection>(FluidFields::Correction::shepard);
          }};
}
Part<TermFactory> kernel_correction_bonet_lok() {
  return {"bonet_lok", "Bonet-Lok corrected gradients, exact for linear fields (Basa et al. 2008 eqs. 24-26)",
          [](const Scene&) -> std::unique_ptr<Term> {
            return std::make_unique<KernelCorrection>(FluidFields::Correction::bonet_lok);
          }};
}

}  // namespace arksph
