#include "projection/grid/grid_poisson_transform.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numeric>
#include <stdexcept>

#include <unsupported/Eigen/FFT>

namespace arksph {

// One axis: the transform that diagonalises its second-difference matrix K, in place on a
// contiguous line of n values, its exact inverse, and the eigenvalues of K in the order of the
// transformed line.
struct GridPoissonTransform::Axis {
  using Complex = std::complex<double>;
  int n;
  bool periodic;
  std::vector<double> lambda;
  std::vector<Complex> twiddle;  // DCT-II: exp(-i pi k / 2n), k = 0 .. n/2
  Eigen::FFT<double> fft;
  std::vector<double> v;
  std::vector<Complex> V;

  Axis(int cells, bool wraps) : n(cells), periodic(wraps), lambda(cells), v(cells), V(cells / 2 + 1) {
    fft.SetFlag(Eigen::FFT<double>::HalfSpectrum);  // real transforms: the spectrum k = 0 .. n/2
    const double pi = std::acos(-1.0);
    for (int k = 0; k < n; ++k) {
      // 2 - 2 cos(theta) written as 4 sin^2(theta/2): no cancellation for the small eigenvalues.
      const int m = periodic ? std::min(k, n - k) : k;
      const double half = periodic ? pi * m / n : pi * k / (2.0 * n);
      lambda[k] = 4.0 * std::sin(half) * std::sin(half);
    }
    if (!periodic) {
      twiddle.resize(n / 2 + 1);
      for (int k = 0; k <= n / 2; ++k) twiddle[k] = std::polar(1.0, -pi * k / (2.0 * n));
    }
  }

  // Forward: DCT-II y_k = sum_i a_i cos(pi k (2i+1) / 2n) (Neumann), or the DFT X_k = sum_i a_i
  // exp(-2 pi i k i' / n) held half-complex: Re X_k at k = 0 .. n/2, Im X_k at n - k (periodic).
  void forward(double* a) {
    if (n == 1) return;
    if (periodic) {
      std::copy(a, a + n, v.begin());
      fft.fwd(V.data(), v.data(), n);
      for (int k = 0; k <= n / 2; ++k) a[k] = V[k].real();
      for (int k = 1; k <= (n - 1) / 2; ++k) a[n - k] = V[k].imag();
      return;
    }
    // Makhoul's reordering: the even samples, then the odd ones reversed.
    const int evens = (n + 1) / 2;
    for (int i = 0; i < evens; ++i) v[i] = a[2 * i];
    for (int i = evens; i < n; ++i) v[i] = a[2 * (n - 1 - i) + 1];
    fft.fwd(V.data(), v.data(), n);
    for (int k = 0; k <= n / 2; ++k) a[k] = (twiddle[k] * V[k]).real();
    // k > n/2: V_k = conj(V_{n-k}) and exp(-i pi k / 2n) = -i conj(exp(-i pi (n-k) / 2n)).
    for (int k = n / 2 + 1; k < n; ++k) a[k] = (Complex(0, -1) * std::conj(twiddle[n - k] * V[n - k])).real();
  }

  // The exact inverse of forward.
  void inverse(double* a) {
    if (n == 1) return;
    if (periodic) {
      V[0] = Complex(a[0], 0.0);
      for (int k = 1; k <= (n - 1) / 2; ++k) V[k] = Complex(a[k], a[n - k]);
      if (n % 2 == 0) V[n / 2] = Complex(a[n / 2], 0.0);
      fft.inv(v.data(), V.data(), n);
      std::copy(v.begin(), v.end(), a);
      return;
    }
    // V_k = exp(i pi k / 2n) (y_k - i y_{n-k}), y_n = 0, then the inverse real FFT and the order back.
    V[0] = Complex(a[0], 0.0);
    for (int k = 1; k <= n / 2; ++k) V[k] = std::conj(twiddle[k]) * Complex(a[k], -a[n - k]);
    fft.inv(v.data(), V.data(), n);
    const int evens = (n + 1) / 2;
    for (int i = 0; i < evens; ++i) a[2 * i] = v[i];
    for (int i = evens; i < n; ++i) a[2 * (n - 1 - i) + 1] = v[i];
  }
};

GridPoissonTransform::GridPoissonTransform(const GridSpec& grid) : grid_(grid) {
  if (grid_.nx < 2 || grid_.ny < 1 || !(grid_.h > 0)) throw std::invalid_argument("GridPoissonTransform: bad grid");
  x_ = std::make_unique<Axis>(grid_.nx, grid_.periodic[0]);
  if (grid_.ny > 1) y_ = std::make_unique<Axis>(grid_.ny, grid_.periodic[1]);
}

GridPoissonTransform::~GridPoissonTransform() = default;

double GridPoissonTransform::solve(const std::vector<double>& source, double rho, std::vector<double>& p) {
  const int nx = grid_.nx, ny = grid_.ny;
  const std::size_t n = grid_.cells();
  if (source.size() != n) throw std::invalid_argument("GridPoissonTransform: source size");
  const double mean = std::accumulate(source.begin(), source.end(), 0.0) / static_cast<double>(n);
  p.resize(n);
  for (std::size_t a = 0; a < n; ++a) p[a] = source[a] - mean;
  const double scale = -grid_.h * grid_.h * rho;  // L = -(1 / rho h^2) (K_x + K_y)
  for (int j = 0; j < ny; ++j) x_->forward(p.data() + static_cast<std::size_t>(j) * nx);
  if (!y_) {
    p[0] = 0.0;  // the constant mode
    for (int k = 1; k < nx; ++k) p[k] *= scale / x_->lambda[k];
  } else {
    // Columns in blocks of 8 (a cache line of a row), copied out and back row by row.
    constexpr int kBlock = 8;
    std::vector<double> columns(static_cast<std::size_t>(kBlock) * ny);
    for (int i0 = 0; i0 < nx; i0 += kBlock) {
      const int width = std::min(kBlock, nx - i0);
      for (int j = 0; j < ny; ++j)
        for (int b = 0; b < width; ++b) columns[static_cast<std::size_t>(b) * ny + j] = p[static_cast<std::size_t>(j) * nx + i0 + b];
      for (int b = 0; b < width; ++b) {
        const int i = i0 + b;
        double* column = columns.data() + static_cast<std::size_t>(b) * ny;
        y_->forward(column);
        for (int l = 0; l < ny; ++l) {
          const double lam = x_->lambda[i] + y_->lambda[l];
          column[l] = (i == 0 && l == 0) ? 0.0 : column[l] * scale / lam;
        }
        y_->inverse(column);
      }
      for (int j = 0; j < ny; ++j)
        for (int b = 0; b < width; ++b) p[static_cast<std::size_t>(j) * nx + i0 + b] = columns[static_cast<std::size_t>(b) * ny + j];
    }
  }
  for (int j = 0; j < ny; ++j) x_->inverse(p.data() + static_cast<std::size_t>(j) * nx);
  const double level = std::accumulate(p.begin(), p.end(), 0.0) / static_cast<double>(n);
  for (double& v : p) v -= level;

  // Residual of the five-point equation, sum over the faces (p_nb - p_i) / (rho h^2) = s_i - mean.
  double r2 = 0, b2 = 0;
  const bool px = grid_.periodic[0], py = grid_.periodic[1] && ny > 1;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const std::size_t a = static_cast<std::size_t>(j) * nx + i;
      double s = 0;
      if (i > 0) s += p[a - 1] - p[a];
      else if (px) s += p[a + nx - 1] - p[a];
      if (i < nx - 1) s += p[a + 1] - p[a];
      else if (px) s += p[a + 1 - nx] - p[a];
      if (ny > 1) {
        if (j > 0) s += p[a - nx] - p[a];
        else if (py) s += p[a + (ny - 1) * static_cast<std::size_t>(nx)] - p[a];
        if (j < ny - 1) s += p[a + nx] - p[a];
        else if (py) s += p[a - (ny - 1) * static_cast<std::size_t>(nx)] - p[a];
      }
      const double b = source[a] - mean;
      const double r = s / (-scale) - b;
      r2 += r * r;
      b2 += b * b;
    }
  return b2 > 0 ? std::sqrt(r2 / b2) : std::sqrt(r2);
}

}  // namespace arksph
