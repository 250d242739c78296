// Registries of the ARKODE tables and IMEX pairs, and the [time] keys read by the integrators.
#include "integrate/time_params.hpp"

#include <algorithm>

#include "core/param_builder.hpp"
#include "integrate/erk_integrator.hpp"
#include "integrate/imex_integrator.hpp"

namespace arksph {

const Registry<Selected>& erk_tables() {
  static const Registry<Selected> r = [] {
    std::vector<Part<Selected>> parts;
    for (const auto& name : erk_table_names())
      parts.push_back({name, "explicit Runge-Kutta table of order " + std::to_string(erk_table_order(name)) +
                                 (erk_table_has_embedding(name) ? ", adaptive or fixed step" : ", fixed step only") +
                                 (erk_table_has_fsal_bug(name) ? " (SUNDIALS 6.4.1 FSAL bug: worked around, +1 RHS a step)" : "")});
    return Registry<Selected>("erk_table", "time.integrator", std::move(parts));
  }();
  return r;
}

const Registry<Selected>& imex_pairs() {
  static const Registry<Selected> r = [] {
    std::vector<Part<Selected>> parts;
    for (const auto& name : imex_pair_names())
      parts.push_back({name, "ARKODE additive Runge-Kutta pair of order " + std::to_string(imex_pair_order(name)) +
                                 ", " + imex_pair_dirk_table(name) + " + " + imex_pair_erk_table(name) +
                                 " (time.imex: viscosity implicit)"});
    return Registry<Selected>("imex_pair", "time.imex_pair", std::move(parts));
  }();
  return r;
}

const std::vector<Param>& time_params() {
  static const std::vector<Param> params = {
      choice("time.integrator", "ARKODE_HEUN_EULER_2_1_2").family("erk_table")
          .doc("ARKODE explicit Butcher table").to(&Scene::integrator),
      number("time.dt", 0.0).in(at_least(0)).unit("s")
          .doc("0: adaptive, limited by the stability bounds; > 0: fixed step, at least the spacing of doubles at time.end").to(&Scene::dt),
      number("time.cfl", 0.25).in(between(0, 1, true, false))
          .doc("coefficient of the stability limits (Szewc et al. 2012 eqs. 34-35)").to(&Scene::cfl),
      number("time.rtol", 1e-2).in(above(0))
          .doc("relative tolerance (adaptive mode; loose, so that the stability limits govern; with a fixed time.dt "
               "the implicit solves of IMEX use min(time.rtol, 1e-10))").to(&Scene::rtol),
      number("time.atol", 1e-4).in(above(0))
          .doc("absolute tolerance (adaptive mode; with a fixed time.dt the implicit solves use min(time.atol, 1e-12))")
          .to(&Scene::atol),
      integer("time.max_steps", 100000000).in(at_least(1)).doc("abort after this many steps").to(&Scene::max_steps),
      // Read by the state check after every step (run/state_check.cpp).
      number("time.blowup_speed", 0.0).in(at_least(0)).unit("m/s")
          .doc("a particle faster than this has blown up: the run stops with exit 3, keeping its output (0: 100 times "
               "the scene's largest speed scale: the sound speed of wcsph, wall and initial speeds, 10 sqrt(a L) with a "
               "the largest acceleration at the start and L the domain's width)")
          .to(&Scene::blowup_speed),
  };
  return params;
}

const std::vector<Param>& imex_params() {
  static const std::vector<Param> params = {
      flag("time.imex", false)
          .doc("ARKStep IMEX: viscous term implicit (Newton + KLU; on MPI ranks Newton + SPGMR, matrix-free, Jacobi), "
               "no viscous step limit; time.integrator unused")
          .to(&Scene::imex),
      choice("time.imex_pair", "ARK324L2SA").family("imex_pair").doc("imex: ARKODE additive pair").to(&Scene::imex_pair),
      flag("time.imex_linear", false)
          .doc("imex: true: ARKStepSetLinear, exact J at every stage, one Newton iteration; false: Newton, J reused "
               "(on MPI ranks J v is always at the stage's state)")
          .to(&Scene::imex_linear),
  };
  return params;
}

Tolerances integrator_tolerances(const Scene& scene, double dt) {
  if (dt <= 0) return {scene.rtol, scene.atol};
  return {std::min(scene.rtol, kFixedStepRtol), std::min(scene.atol, kFixedStepAtol)};
}

}  // namespace arksph
