#include "projection/grid/grid_poisson.hpp"

#include <klu.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include <Eigen/SparseCore>

#include "core/errors.hpp"
#include "projection/grid/grid_poisson_transform.hpp"

namespace arksph {

struct GridPoisson::Klu {
  klu_common common{};
  klu_symbolic* symbolic = nullptr;
  klu_numeric* numeric = nullptr;
  Eigen::SparseMatrix<double, Eigen::ColMajor, int> A;
  ~Klu() {
    if (numeric) klu_free_numeric(&numeric, &common);
    if (symbolic) klu_free_symbolic(&symbolic, &common);
  }
};

GridPoisson::GridPoisson(const GridSpec& grid, Solver solver) : grid_(grid), solver_(solver) {
  if (grid_.nx < 2 || grid_.ny < 1 || !(grid_.h > 0)) throw std::invalid_argument("GridPoisson: bad grid");
}

GridPoisson::~GridPoisson() = default;

long GridPoisson::neighbour(int i, int j, int k) const {
  int ii = i, jj = j;
  if (k == 0) --ii;
  if (k == 1) ++ii;
  if (k == 2) --jj;
  if (k == 3) ++jj;
  if (k >= 2 && grid_.ny == 1) return -1;  // 1D: no y faces
  if (ii < 0 || ii >= grid_.nx) {
    if (!grid_.periodic[0]) return -1;
    ii = (ii + grid_.nx) % grid_.nx;
  }
  if (jj < 0 || jj >= grid_.ny) {
    if (!grid_.periodic[1]) return -1;
    jj = (jj + grid_.ny) % grid_.ny;
  }
  const auto nb = static_cast<long>(grid_.index(ii, jj));
  return nb == static_cast<long>(grid_.index(i, j)) ? -1 : nb;  // a one-cell periodic axis couples to itself
}

bool GridPoisson::set_density(const std::vector<double>& rho) {
  if (rho.size() != grid_.cells()) throw std::invalid_argument("GridPoisson: density size");
  if ((klu_ || uniform_) && rho == rho_) return false;
  rho_ = rho;
  const bool uniform = solver_ == Solver::automatic &&
                       std::all_of(rho.begin(), rho.end(), [&](double r) { return r == rho.front(); });
  if (uniform) {
    if (!transform_) transform_ = std::make_unique<GridPoissonTransform>(grid_);
    klu_.reset();
    uniform_ = true;
    ++factorisations_;
  } else {
    uniform_ = false;
    factorise();
  }
  return true;
}

bool GridPoisson::set_density(double rho) {
  if (uniform_ && rho == rho_.front()) return false;
  return set_density(std::vector<double>(grid_.cells(), rho));
}

void GridPoisson::factorise() {
  const std::size_t n = grid_.cells();
  std::vector<Eigen::Triplet<double, int>> trip;
  trip.reserve(5 * n);
  for (int j = 0; j < grid_.ny; ++j)
    for (int i = 0; i < grid_.nx; ++i) {
      const auto a = static_cast<long>(grid_.index(i, j));
      double diag = 0;
      for (int k = 0; k < 4; ++k) {
        const long b = neighbour(i, j, k);
        if (b < 0) continue;
        const double c = 2.0 / (rho_[a] + rho_[b]);  // 1/rho at the face
        diag += c;
        if (a != 0 && b != 0) trip.emplace_back(static_cast<int>(a), static_cast<int>(b), -c);
      }
      trip.emplace_back(static_cast<int>(a), static_cast<int>(a), a == 0 ? 1.0 : diag);
    }
  auto klu = std::make_unique<Klu>();
  klu_defaults(&klu->common);
  klu->common.ordering = 0;  // AMD: less fill and a faster analysis than KLU's default COLAMD
  klu->common.btf = 0;
  klu->A.resize(static_cast<long>(n), static_cast<long>(n));
  klu->A.setFromTriplets(trip.begin(), trip.end());
  klu->A.makeCompressed();
  const int nn = static_cast<int>(n);
  klu->symbolic = klu_analyze(nn, klu->A.outerIndexPtr(), klu->A.innerIndexPtr(), &klu->common);
  if (!klu->symbolic) throw NumericalFailure("grid Poisson: KLU analyze failed (status " + std::to_string(klu->common.status) + ")");
  klu->numeric = klu_factor(klu->A.outerIndexPtr(), klu->A.innerIndexPtr(), klu->A.valuePtr(), klu->symbolic, &klu->common);
  if (!klu->numeric) throw NumericalFailure("grid Poisson: KLU factor failed (status " + std::to_string(klu->common.status) + ")");
  klu_ = std::move(klu);
  ++factorisations_;
}

double GridPoisson::solve(const std::vector<double>& source, std::vector<double>& p) {
  if (uniform_) return transform_->solve(source, rho_.front(), p);
  if (!klu_) throw std::logic_error("GridPoisson::solve before set_density");
  const std::size_t n = grid_.cells();
  const double mean = std::accumulate(source.begin(), source.end(), 0.0) / static_cast<double>(n);
  const double h2 = grid_.h * grid_.h;
  std::vector<double> b(n);
  for (std::size_t a = 0; a < n; ++a) b[a] = -h2 * (source[a] - mean);  // rows of -h^2 L
  b[0] = 0.0;
  p = b;
  if (!klu_solve(klu_->symbolic, klu_->numeric, static_cast<int>(n), 1, p.data(), &klu_->common))
    throw NumericalFailure("grid Poisson: KLU solve failed (status " + std::to_string(klu_->common.status) + ")");
  const Eigen::Map<const Eigen::VectorXd> bb(b.data(), static_cast<long>(n));
  const Eigen::Map<const Eigen::VectorXd> pp(p.data(), static_cast<long>(n));
  const double nb = bb.norm();
  const double res = nb > 0 ? (klu_->A * pp - bb).norm() / nb : (klu_->A * pp).norm();
  const double level = std::accumulate(p.begin(), p.end(), 0.0) / static_cast<double>(n);
  for (double& v : p) v -= level;
  return res;
}

std::vector<double> GridPoisson::apply(const std::vector<double>& p) const {
  std::vector<double> out(grid_.cells(), 0.0);
  const double h2 = grid_.h * grid_.h;
  for (int j = 0; j < grid_.ny; ++j)
    for (int i = 0; i < grid_.nx; ++i) {
      const auto a = static_cast<long>(grid_.index(i, j));
      double s = 0;
      for (int k = 0; k < 4; ++k) {
        const long b = neighbour(i, j, k);
        if (b >= 0) s += 2.0 / (rho_[a] + rho_[b]) * (p[b] - p[a]);
      }
      out[a] = s / h2;
    }
  return out;
}

void GridPoisson::acceleration(const std::vector<double>& p, std::vector<double>& ax, std::vector<double>& ay,
                               const std::array<int, 4>& box) const {
  const std::size_t n = grid_.cells();
  ax.assign(n, 0.0);
  ay.assign(n, 0.0);
  for (int j = std::max(box[2], 0); j <= std::min(box[3], grid_.ny - 1); ++j)
    for (int i = std::max(box[0], 0); i <= std::min(box[1], grid_.nx - 1); ++i) {
      const auto a = static_cast<long>(grid_.index(i, j));
      for (int axis = 0; axis < (grid_.ny > 1 ? 2 : 1); ++axis) {
        const long lo = neighbour(i, j, 2 * axis), hi = neighbour(i, j, 2 * axis + 1);
        double sum = 0;
        int faces = 0;
        if (lo >= 0) {
          sum += 2.0 / (rho_[a] + rho_[lo]) * (p[a] - p[lo]) / grid_.h;
          ++faces;
        }
        if (hi >= 0) {
          sum += 2.0 / (rho_[a] + rho_[hi]) * (p[hi] - p[a]) / grid_.h;
          ++faces;
        }
        (axis == 0 ? ax : ay)[a] = faces ? sum / faces : 0.0;
      }
    }
}

}  // namespace arksph
