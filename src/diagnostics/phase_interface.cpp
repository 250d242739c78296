#include "diagnostics/phase_interface.hpp"

#include <algorithm>
#include <cmath>

#include "kernels/kernel.hpp"
#include "neighbors/cell_list.hpp"

namespace arksph {

namespace {
// The crossing of level 0.5 on the edge from (xa, ya, ca) to (xb, yb, cb).
std::array<double, 2> crossing(double xa, double ya, double ca, double xb, double yb, double cb) {
  const double s = (0.5 - ca) / (cb - ca);
  return {xa + s * (xb - xa), ya + s * (yb - ya)};
}
}  // namespace

IndicatorGrid::IndicatorGrid(double xmin_, double ymin_, double xmax, double ymax, double spacing_)
    : nx(std::lround((xmax - xmin_) / spacing_) + 1),
      ny(std::lround((ymax - ymin_) / spacing_) + 1),
      xmin(xmin_),
      ymin(ymin_),
      spacing(spacing_),
      num(static_cast<std::size_t>(nx * ny), 0.0),
      den(static_cast<std::size_t>(nx * ny), 0.0) {}

void add_phase_indicator(const FluidFields& f, const std::int32_t* phase, IndicatorGrid& g,
                         const std::function<bool(double, double)>& owns) {
  const Kernel& K = *f.kernel;
  CellList cells;
  cells.build(f.x.data(), f.y.data(), f.n_all, K.radius());
#pragma omp parallel for schedule(static)
  for (long j = 0; j < g.ny; ++j)
    for (long i = 0; i < g.nx; ++i) {
      const double px = g.xmin + i * g.spacing, py = g.ymin + j * g.spacing;
      if (!owns(px, py)) continue;
      double num = 0, den = 0;
      cells.for_each_near(px, py, [&](std::uint32_t b, double dx, double dy) {
        const double w = K.W(std::hypot(dx, dy)) * f.m[b] / f.rho[b];
        den += w;
        if (phase[f.src[b]] >= 1) num += w;
      });
      g.num[static_cast<std::size_t>(j * g.nx + i)] += num;
      g.den[static_cast<std::size_t>(j * g.nx + i)] += den;
    }
}

PhaseInterface phase_interface(const FluidFields& f, const std::vector<std::int32_t>& phase, double xmin,
                               double ymin, double xmax, double ymax, double spacing) {
  IndicatorGrid grid(xmin, ymin, xmax, ymax, spacing);
  add_phase_indicator(f, phase.data(), grid, [](double, double) { return true; });
  return contour_phase_indicator(grid);
}

PhaseInterface contour_phase_indicator(const IndicatorGrid& g) {
  PhaseInterface out;
  const long nx = g.nx, ny = g.ny;
  const double xmin = g.xmin, ymin = g.ymin, spacing = g.spacing;
  std::vector<double> chi(g.num.size());
  for (std::size_t k = 0; k < chi.size(); ++k) chi[k] = g.den[k] > 0 ? g.num[k] / g.den[k] : NAN;  // a void: no contour
  // Marching squares; the saddle cases take the two segments that keep the centre value's side.
  auto at = [&](long i, long j) { return chi[static_cast<std::size_t>(j * nx + i)]; };
  double top = -HUGE_VAL, bottom = HUGE_VAL;
  for (long j = 0; j + 1 < ny; ++j)
    for (long i = 0; i + 1 < nx; ++i) {
      const double x0 = xmin + i * spacing, y0 = ymin + j * spacing, x1 = x0 + spacing, y1 = y0 + spacing;
      const double c[4] = {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};  // counter-clockwise
      if (std::isnan(c[0] + c[1] + c[2] + c[3])) continue;
      const double px[4] = {x0, x1, x1, x0}, py[4] = {y0, y0, y1, y1};
      std::vector<std::array<double, 2>> pts;  // crossings on edges 0-1, 1-2, 2-3, 3-0
      for (int e = 0; e < 4; ++e) {
        const int a = e, b = (e + 1) % 4;
        if ((c[a] >= 0.5) != (c[b] >= 0.5)) pts.push_back(crossing(px[a], py[a], c[a], px[b], py[b], c[b]));
      }
      if (pts.size() == 2) {
        out.segments.push_back({pts[0][0], pts[0][1], pts[1][0], pts[1][1]});
      } else if (pts.size() == 4) {
        const bool centre_in = 0.25 * (c[0] + c[1] + c[2] + c[3]) >= 0.5;
        const bool first_in = c[0] >= 0.5;
        if (centre_in == first_in) {  // corner 0's region joins the centre: cut off corners 1 and 3
          out.segments.push_back({pts[0][0], pts[0][1], pts[1][0], pts[1][1]});
          out.segments.push_back({pts[2][0], pts[2][1], pts[3][0], pts[3][1]});
        } else {
          out.segments.push_back({pts[3][0], pts[3][1], pts[0][0], pts[0][1]});
          out.segments.push_back({pts[1][0], pts[1][1], pts[2][0], pts[2][1]});
        }
      }
      for (const auto& p : pts) {
        top = std::max(top, p[1]);
        bottom = std::min(bottom, p[1]);
      }
    }
  out.bubble_y = out.segments.empty() ? NAN : top;
  out.spike_y = out.segments.empty() ? NAN : bottom;
  return out;
}

}  // namespace arksph
