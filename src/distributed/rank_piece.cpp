#include "distributed/rank_piece.hpp"

#include <vector>

#include "diagnostics/flow_metrics.hpp"
#include "io/frame_order.hpp"
#include "io/vtp_writer.hpp"

namespace arksph::distributed {

void write_rank_piece(const std::string& path, double t, const HaloRhs& f, const RankParticles& mine,
                      const parallel::Domain& domain, const double* pressure) {
  const FluidFields& ff = f.evaluator().fields();
  const std::size_t n = mine.size();
  const int dim = mine.index().dim;
  std::vector<double> x(n), y(n);
  for (std::size_t a = 0; a < n; ++a) {
    double p[3] = {ff.x[a], dim == 2 ? ff.y[a] : 0.0, 0.0};
    domain.wrap(p);
    x[a] = p[0];
    y[a] = p[1];
  }
  std::vector<double> rho_sum = number_density(ff);  // Szewc eq. 21: m_a sum_b W_ab, as a whole frame
  rho_sum.resize(n);
  for (std::size_t a = 0; a < n; ++a) rho_sum[a] *= ff.m[a];
  const auto& phase_field = mine.fields().field[static_cast<std::size_t>(mine.index().phase())];
  const std::vector<std::int32_t> phase(phase_field.begin(), phase_field.end());
  Frame fr;
  fr.dimension = dim;
  fr.n = n;
  fr.time = t;
  fr.x = x.data();
  fr.y = dim == 2 ? y.data() : nullptr;
  fr.u = ff.u.data();
  fr.v = dim == 2 ? ff.v.data() : nullptr;
  fr.pressure = pressure ? pressure : ff.p.data();
  fr.density = ff.rho.data();
  fr.summation_density = rho_sum.data();
  fr.mass = ff.m.data();
  fr.id = mine.ids().data();
  fr.phase = phase.data();
  write_vtp(path, FrameInIdOrder(fr).frame());
}

}  // namespace arksph::distributed
