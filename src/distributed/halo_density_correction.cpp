#include "distributed/halo_density_correction.hpp"

#include <chrono>
#include <stdexcept>

namespace arksph::distributed {

HaloDensityCorrection::HaloDensityCorrection(const Scene& scene, const parallel::Communicator& comm, HaloRhs& f,
                                             const RankParticles& owned)
    : comm_(comm),
      f_(f),
      owned_(owned),
      threshold_(scene.correction_threshold),
      max_iterations_(scene.correction_max_iterations),
      spacing_(scene.spacing) {}

CorrectionSpan HaloDensityCorrection::span() const {
  CorrectionSpan s;
  s.own = owned_.layout().n;
  s.sum = [this](double v) { return comm_.sum(v); };
  s.extend = [this](std::vector<double>& v) {
    const std::vector<double> copies = f_.halo_values(v);
    v.insert(v.end(), copies.begin(), copies.end());
    if (v.size() != f_.evaluator().fields().n_real)
      throw std::logic_error("density correction: the halo values do not match the evaluator's points");
  };
  s.gather = [this](const std::vector<double>& v) { return comm_.allgatherv(v); };
  s.any = [this](bool v) { return comm_.max(static_cast<std::int64_t>(v)) > 0; };
  return s;
}

void HaloDensityCorrection::apply(double t, double* y) {
  const auto t0 = std::chrono::steady_clock::now();
  const bool record = stats_.applications == 0;
  f_.eval(t, y, nullptr);
  std::vector<double> s;
  const double error = density_fluctuation(f_.evaluator().fields(), span(), s);
  if (error <= threshold_) return;
  ++stats_.applications;
  if (record) stats_.first_history.push_back(error);
  const NewtonCorrectionResult r = correct_density_newton(
      [&](const double* state) { f_.eval(t, state, nullptr); },
      [&]() -> const FluidFields& { return f_.evaluator().fields(); }, [&] { return span(); }, owned_.layout(), y,
      max_iterations_, threshold_, spacing_);
  stats_.iterations += r.iterations;
  if (record) stats_.first_history.push_back(r.error);
  stats_.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace arksph::distributed
