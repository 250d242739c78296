#include "neighbors/cell_list.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

#include "core/errors.hpp"
#include "kernels/kernel.hpp"
#include "neighbors/neighborhood.hpp"

namespace arksph {

void pair_list_not_built() {
  std::fputs("arksph: internal error: pair list read at an f(t, y) that built none\n", stderr);
  std::abort();
}

void CellList::build(const double* x, const double* y, std::size_t n, double radius) {
  two_d_ = y != nullptr;
  r2_ = radius * radius;
  double xmin = std::numeric_limits<double>::max(), xmax = -xmin, ymin = 0, ymax = 0;
  for (std::size_t i = 0; i < n; ++i) {
    xmin = std::min(xmin, x[i]);
    xmax = std::max(xmax, x[i]);
  }
  if (y) {
    ymin = std::numeric_limits<double>::max();
    ymax = -ymin;
    for (std::size_t i = 0; i < n; ++i) {
      ymin = std::min(ymin, y[i]);
      ymax = std::max(ymax, y[i]);
    }
  }
  if (n == 0) xmin = xmax = ymin = ymax = 0;
  inv_side_ = 1.0 / radius;
  x0_ = xmin;
  y0_ = ymin;
  // Points spread over more cells than any run needs (or not finite) are a run that has blown up
  // between two state checks, e.g. in a stage: fail as such (exit 3), not by a huge allocation.
  const double cells_x = (xmax - xmin) * inv_side_ + 1, cells_y = y ? (ymax - ymin) * inv_side_ + 1 : 1;
  const double max_cells = 64.0 * static_cast<double>(n) + 1e7;
  if (!(cells_x * cells_y <= max_cells))
    throw NumericalFailure("particles spread over " + std::to_string(cells_x * cells_y) +
                           " neighbour cells (bounding box x [" + std::to_string(xmin) + ", " + std::to_string(xmax) +
                           "], y [" + std::to_string(ymin) + ", " + std::to_string(ymax) + "]): the run has blown up");
  nx_ = static_cast<long>(cells_x);
  ny_ = static_cast<long>(cells_y);
  const std::size_t ncell = static_cast<std::size_t>(nx_ * ny_);
  start_.assign(ncell + 1, 0);
  std::vector<std::uint32_t> cell(n);
  for (std::size_t i = 0; i < n; ++i) {
    const long c = (y ? cell_coord(y[i], y0_) * nx_ : 0) + cell_coord(x[i], x0_);
    cell[i] = static_cast<std::uint32_t>(c);
    ++start_[c + 1];
  }
  for (std::size_t c = 0; c < ncell; ++c) start_[c + 1] += start_[c];
  order_.resize(n);
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) order_[fill[cell[i]]++] = static_cast<std::uint32_t>(i);
  sx_.resize(n);
  sy_.resize(y ? n : 0);
  for (std::size_t k = 0; k < n; ++k) {
    sx_[k] = x[order_[k]];
    if (y) sy_[k] = y[order_[k]];
  }
}

namespace {
// Exclusive prefix sum of count into start (the compressed-row offsets); returns the total.
std::size_t row_starts(const std::vector<std::uint32_t>& count, std::vector<std::size_t>& start) {
  start.resize(count.size());
  std::size_t total = 0;
  for (std::size_t a = 0; a < count.size(); ++a) {
    start[a] = total;
    total += count[a];
  }
  return total;
}
}  // namespace

void build_pairs(const CellList& cells, const Kernel& kernel, const double* x, const double* y,
                 std::size_t n_real, PairList& pairs) {
  pairs.n_real = n_real;
  pairs.px = x;
  pairs.py = y;
  pairs.kernel = nullptr;
  pairs.count.assign(n_real, 0);
  // Pass 1: count; pass 2: fill the compressed rows.
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n_real; ++a) {
    std::uint32_t k = 0;
    cells.for_each_near(x[a], y ? y[a] : 0.0, [&](std::uint32_t b, double, double) { k += b != a ? 1 : 0; });
    pairs.count[a] = k;
  }
  pairs.reserve(row_starts(pairs.count, pairs.start));
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n_real; ++a) {
    std::size_t k = pairs.start[a];
    cells.for_each_near(x[a], y ? y[a] : 0.0, [&](std::uint32_t b, double dx, double dy) {
      if (b == a) return;
      double w, f;
      kernel.eval(std::sqrt(dx * dx + dy * dy), w, f);
      pairs.j[k] = b;
      pairs.w[k] = w;
      pairs.f[k] = f;
      ++k;
    });
  }
}



namespace {
// Candidates of a among the points of sorted entries [lo, hi): the same test as for_each_near
// (dx^2 + dy^2 < r2, self excluded), written without a branch so that the count vectorises.
struct CandidateTest {
  const double *sx, *sy;
  const std::uint32_t* point;
  double r2;
  bool accept(std::uint32_t k, double xa, double ya, std::uint32_t a) const {
    const double dx = xa - sx[k], dy = sy ? ya - sy[k] : 0.0;
    return (dx * dx + dy * dy < r2) & (point[k] != a);
  }
};
}  // namespace

void build_candidates(const CellList& cells, const double* x, const double* y, std::size_t n_real,
                      CandidateList& cand) {
  cand.n_real = n_real;
  cand.count.assign(n_real, 0);
  const CandidateTest test{cells.sorted_x(), cells.sorted_y(), cells.point(), cells.radius2()};
  // Pass 1: count.
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n_real; ++a) {
    const double xa = x[a], ya = y ? y[a] : 0.0;
    const auto self = static_cast<std::uint32_t>(a);
    std::uint32_t k = 0;
    cells.for_each_run(xa, ya, [&](std::uint32_t lo, std::uint32_t hi) {
      for (std::uint32_t s = lo; s < hi; ++s) k += test.accept(s, xa, ya, self) ? 1 : 0;
    });
    cand.count[a] = k;
  }
  const std::size_t total = row_starts(cand.count, cand.start);
  if (cand.j.size() < total) PairList::regrow(cand.j, total + total / 64);
  std::uint32_t* __restrict cj = cand.j.data();
  // Pass 2: fill a's row by branch-free compaction (every entry is written, the next one overwrites
  // a rejected one). Stopping once the row is full keeps the writes inside it, where no other
  // thread writes.
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n_real; ++a) {
    std::size_t pos = cand.start[a];
    const std::size_t end = pos + cand.count[a];
    const double xa = x[a], ya = y ? y[a] : 0.0;
    const auto self = static_cast<std::uint32_t>(a);
    cells.for_each_run(xa, ya, [&, test](std::uint32_t lo, std::uint32_t hi) {
      std::size_t p = pos;  // locals: the stores to cj cannot then alias them
      std::uint32_t* __restrict out = cj;
      for (std::uint32_t s = lo; s < hi && p < end; ++s) {
        out[p] = test.point[s];
        p += test.accept(s, xa, ya, self) ? 1 : 0;
      }
      pos = p;
    });
  }
}

namespace {
// Pass 1 of both storages: how many candidates of each particle are inside the support.
void count_in_support(const CandidateList& cand, double r_max2, const double* x, const double* y,
                      std::uint32_t* __restrict pcount) {
  const std::uint32_t* cj = cand.j.data();
  const std::uint32_t* ccount = cand.count.data();
  const std::size_t* cstart = cand.start.data();
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < cand.n_real; ++a) {
    const double xa = x[a], ya = y ? y[a] : 0.0;
    std::uint32_t k = 0;
    for (std::size_t c = cstart[a]; c < cstart[a] + ccount[a]; ++c) {
      const std::uint32_t b = cj[c];
      const double dx = xa - x[b], dy = y ? ya - y[b] : 0.0;
      k += dx * dx + dy * dy < r_max2 ? 1 : 0;
    }
    pcount[a] = k;
  }
}
}  // namespace

void lean_pairs_from_candidates(const CandidateList& cand, const Kernel& kernel, const double* x, const double* y,
                                PairList& pairs) {
  pairs.n_real = cand.n_real;
  pairs.px = x;
  pairs.py = y;
  pairs.count.resize(cand.n_real);
  pairs.r2_max = kernel.radius() * kernel.radius();
  count_in_support(cand, pairs.r2_max, x, y, pairs.count.data());
  pairs.cand_start = &cand.start;
  pairs.cand_count = &cand.count;
  pairs.cand_j = &cand.j;
  pairs.kernel = &kernel;
}

void pairs_from_candidates(const CandidateList& cand, const Kernel& kernel, const double* x, const double* y,
                           PairList& pairs) {
  const std::size_t n_real = cand.n_real;
  pairs.n_real = n_real;
  pairs.px = x;
  pairs.py = y;
  pairs.kernel = nullptr;
  pairs.count.resize(n_real);
  const double r_max2 = kernel.radius() * kernel.radius();
  count_in_support(cand, r_max2, x, y, pairs.count.data());
  pairs.reserve(row_starts(pairs.count, pairs.start));
  const std::uint32_t* cj = cand.j.data();
  const std::uint32_t* ccount = cand.count.data();
  const std::size_t* cstart = cand.start.data();
  // Raw pointers: the compiler need not reload the vectors' data after every store.
  std::uint32_t* __restrict pj = pairs.j.data();
  double* __restrict pw = pairs.w.data();
  double* __restrict pf = pairs.f.data();
  const std::size_t* pstart = pairs.start.data();
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n_real; ++a) {
    const std::size_t base = pstart[a];
    std::size_t k = base;
    const double xa = x[a], ya = y ? y[a] : 0.0;
    // Pass 2: squared distances (kept in f for now) of the pairs inside the support, in candidate order.
    for (std::size_t c = cstart[a]; c < cstart[a] + ccount[a]; ++c) {
      const std::uint32_t b = cj[c];
      const double dx = xa - x[b], dy = y ? ya - y[b] : 0.0;
      const double r2 = dx * dx + dy * dy;
      if (r2 < r_max2) {
        pj[k] = b;
        pf[k] = r2;
        ++k;
      }
    }
    // Pass 3: kernel values of the kept pairs.
    kernel.eval_many(k - base, pf + base, pw + base, pf + base);
  }
}

namespace {

#if defined(__AVX2__)
// Compaction of four candidates at once: for each 4-bit mask of kept lanes, the permutation that
// moves the kept lanes to the front, in order (as 32-bit lane indices: 8 for four doubles, 4 for
// four indices).
struct CompressTables {
  alignas(32) std::int32_t doubles[16][8];
  alignas(16) std::int32_t indices[16][4];
  constexpr CompressTables() : doubles{}, indices{} {
    for (int mask = 0; mask < 16; ++mask) {
      int out = 0;
      for (int lane = 0; lane < 4; ++lane) {
        if (!(mask >> lane & 1)) continue;
        doubles[mask][2 * out] = 2 * lane;
        doubles[mask][2 * out + 1] = 2 * lane + 1;
        indices[mask][out] = lane;
        ++out;
      }
    }
  }
};
constexpr CompressTables kCompress;

// Candidates [c, end) of a point at (xa, ya), four at a time, appended from k on; returns the new k
// and leaves c at the first candidate not done (fewer than four left). Each step stores four
// entries from k on, kept ones first; since k never exceeds the candidates done, the highest index
// stored is below the row's candidate count, the room a Neighborhood has. The arithmetic is that of
// the scalar loop.
std::size_t gather_four_at_a_time(const std::uint32_t* cj, std::size_t& c, std::size_t end, const double* x,
                                  const double* y, double xa, double ya, double r_max2, std::uint32_t* pb,
                                  double* prx, double* pry, std::size_t k) {
  const __m256d vxa = _mm256_set1_pd(xa), vya = _mm256_set1_pd(ya), vr2 = _mm256_set1_pd(r_max2);
  for (; c + 4 <= end; c += 4) {
    const __m128i b4 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(cj + c));
    // Scalar loads: the hardware gathers (vgatherdpd) are slower here.
    const std::uint32_t b0 = cj[c], b1 = cj[c + 1], b2 = cj[c + 2], b3 = cj[c + 3];
    const __m256d dx = _mm256_sub_pd(vxa, _mm256_set_pd(x[b3], x[b2], x[b1], x[b0]));
    const __m256d dy = _mm256_sub_pd(vya, _mm256_set_pd(y[b3], y[b2], y[b1], y[b0]));
    const __m256d rr = _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy));
    const int mask = _mm256_movemask_pd(_mm256_cmp_pd(rr, vr2, _CMP_LT_OQ));
    const __m256i pd = _mm256_load_si256(reinterpret_cast<const __m256i*>(kCompress.doubles[mask]));
    const __m128i pi = _mm_load_si128(reinterpret_cast<const __m128i*>(kCompress.indices[mask]));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(pb + k),
                     _mm_castps_si128(_mm_permutevar_ps(_mm_castsi128_ps(b4), pi)));
    _mm256_storeu_pd(prx + k, _mm256_castps_pd(_mm256_permutevar8x32_ps(_mm256_castpd_ps(dx), pd)));
    _mm256_storeu_pd(pry + k, _mm256_castps_pd(_mm256_permutevar8x32_ps(_mm256_castpd_ps(dy), pd)));
    k += static_cast<std::size_t>(__builtin_popcount(static_cast<unsigned>(mask)));
  }
  return k;
}
#endif

}  // namespace

void gather_neighborhood(const CandidateList& cand, const Kernel& kernel, const double* x, const double* y,
                         std::size_t a, Neighborhood& nb) {
  const double r_max2 = kernel.radius() * kernel.radius();
  const std::uint32_t* cj = cand.j.data();
  std::uint32_t* __restrict pb = nb.b.data();
  double* __restrict prx = nb.rx.data();
  double* __restrict pry = nb.ry.data();
  const double xa = x[a], ya = y ? y[a] : 0.0;
  std::size_t k = 0;
  std::size_t c = cand.start[a];
  const std::size_t end = c + cand.count[a];
#if defined(__AVX2__)
  if (y) k = gather_four_at_a_time(cj, c, end, x, y, xa, ya, r_max2, pb, prx, pry, k);
#endif
  // The same operations as pairs_from_candidates then PairList::for_pairs: r_ab = r_a - r_b,
  // r2 = rx^2 + ry^2, kept when r2 < R^2, kernel values from rx, ry by eval_many_xy.
  for (; c < end; ++c) {
    const std::uint32_t bb = cj[c];
    const double dx = xa - x[bb], dy = y ? ya - y[bb] : 0.0;
    const double rr = dx * dx + dy * dy;
    pb[k] = bb;
    prx[k] = dx;
    pry[k] = dy;
    k += rr < r_max2 ? 1 : 0;  // branch-free compaction: a rejected entry is overwritten
  }
  nb.count = k;
  // r2 again for the kept pairs inside the vectorised kernel loop (the same operations, so the same
  // bits) rather than stored by the loops above.
  kernel.eval_many_xy(k, prx, pry, nb.with_w ? nb.w.data() : nullptr, nb.f.data());
}

std::size_t max_candidates(const CandidateList& cand) {
  std::size_t m = 0;
  for (std::uint32_t c : cand.count) m = std::max<std::size_t>(m, c);
  return m;
}

}  // namespace arksph
