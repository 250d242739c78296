// Exceptions thrown in a callback that SUNDIALS calls (right-hand sides, Jacobian, stability and
// post-processing functions) come out of the integrator unchanged, type and message, once ARKODE
// has returned, instead of unwinding through ARKODE's C frames. From the command line, a run whose
// right-hand side fails inside a step (the neighbour cell list of a blown-up stage) exits 3 with
// that failure's message.
#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli_outcome.hpp"
#include "core/errors.hpp"
#include "integrate/callback_guard.hpp"
#include "integrate/erk_integrator.hpp"
#include "integrate/imex_integrator.hpp"

using namespace arksph;
namespace fs = std::filesystem;

namespace {
// A type no code of arksph throws or converts: it arrives only if the very exception is kept.
struct TestError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// y' = -y, throwing at its `fail_at`-th evaluation (counted from 1).
struct FailingDecay {
  int calls = 0;
  int fail_at;
  explicit FailingDecay(int k) : fail_at(k) {}
  void operator()(const double* y, double* ydot, std::size_t n) {
    if (++calls == fail_at) throw TestError("decay: evaluation " + std::to_string(fail_at) + " failed");
    for (std::size_t i = 0; i < n; ++i) ydot[i] = -y[i];
  }
};

const std::vector<double> kY0 = {1.0, 2.0};

// y' = f_E + f_I with f_E = 0, f_I = -y, J = df_I/dy = -I.
struct DecaySplit {
  SparseCsr J;
  DecaySplit() {
    J.n = 2;
    J.ptr = {0, 1, 2};
    J.idx = {0, 1};
    J.val = {-1.0, -1.0};
  }
};

ImexFunctions decay_functions(DecaySplit& split) {
  ImexFunctions f;
  f.explicit_rhs = [](double, const double*, double* yd) { yd[0] = yd[1] = 0; };
  f.implicit_rhs = [](double, const double* y, double* yd) { yd[0] = -y[0], yd[1] = -y[1]; };
  f.jacobian = [&split](double, const double*) -> const SparseCsr& { return split.J; };
  return f;
}

// The arksph binary with arguments, stderr captured (tests/process/cli_outcome.hpp).
using Outcome = arksph::testing::CliOutcome;
Outcome run_cli_line(const std::string& args) { return arksph::testing::run_cli(args); }
}  // namespace

TEST_CASE("callback guard: the first exception is kept, the flag is negative, rethrow clears it") {
  std::exception_ptr error;
  CHECK(guarded_callback(error, [] { return 7; }) == 7);
  CHECK(guarded_callback(error, [] {}) == 0);
  CHECK_FALSE(error);
  CHECK(guarded_callback(error, []() -> int { throw TestError("first"); }) == kCallbackFailed);
  CHECK(kCallbackFailed < 0);  // unrecoverable for ARKODE and KINSOL (positive would mean "retry")
  CHECK(guarded_callback(error, [] { throw InputError("second"); }) == kCallbackFailed);
  CHECK_THROWS_WITH_AS(rethrow_callback_error(error), "first", TestError);
  CHECK_FALSE(error);
  CHECK_NOTHROW(rethrow_callback_error(error));
}

TEST_CASE("callback errors: an exception in f inside ERKStep arrives unchanged") {
  for (const double dt : {0.0, 0.01}) {  // adaptive and fixed step
    CAPTURE(dt);
    ErkOptions o;
    o.table = "ARKODE_BOGACKI_SHAMPINE_4_2_3";
    o.fixed_dt = dt;
    SUBCASE("in a stage of a later step: the original type and message") {
      FailingDecay f(10);
      ErkIntegrator integ([&](double, const double* y, double* yd) { f(y, yd, 2); }, kY0, 0.0, o);
      CHECK_THROWS_WITH_AS(integ.evolve_to(1.0), "decay: evaluation 10 failed", TestError);
      CHECK(f.calls == 10);  // ARKODE stopped at the failure: no retry after an unrecoverable flag
    }
    SUBCASE("NumericalFailure and InputError keep their type (exit codes 3 and 2)") {
      ErkIntegrator numerical([](double, const double*, double*) { throw NumericalFailure("cell list: blown up"); }, kY0,
                              0.0, o);
      CHECK_THROWS_WITH_AS(numerical.step(1.0), "cell list: blown up", NumericalFailure);
      ErkIntegrator input([](double, const double*, double*) { throw InputError("scene.toml: key: bad"); }, kY0, 0.0, o);
      CHECK_THROWS_WITH_AS(input.step(1.0), "scene.toml: key: bad", InputError);
    }
  }
}

TEST_CASE("callback errors: post-processing and stability functions inside ERKStep") {
  auto decay = [](double, const double* y, double* yd) { yd[0] = -y[0], yd[1] = -y[1]; };
  SUBCASE("step post-processing (ISPH projection)") {
    ErkOptions o;
    o.fixed_dt = 0.01;
    o.postprocess = [](double t, double*) {
      if (t > 0.025) throw TestError("projection failed");
    };
    ErkIntegrator integ(decay, kY0, 0.0, o);
    CHECK_THROWS_WITH_AS(integ.evolve_to(1.0), "projection failed", TestError);
  }
  SUBCASE("stage post-processing") {
    ErkOptions o;
    o.fixed_dt = 0.01;
    o.postprocess_stage = [](double, double*) { throw TestError("stage projection failed"); };
    ErkIntegrator integ(decay, kY0, 0.0, o);
    CHECK_THROWS_WITH_AS(integ.step(1.0), "stage projection failed", TestError);
  }
  SUBCASE("stability function (adaptive)") {
    ErkOptions o;
    o.stability = [](double, const double*) -> double { throw TestError("no stable step"); };
    ErkIntegrator integ(decay, kY0, 0.0, o);
    CHECK_THROWS_WITH_AS(integ.evolve_to(1.0), "no stable step", TestError);
  }
}

TEST_CASE("callback errors: an exception in f_E, f_I or J inside ARKStep (IMEX) arrives unchanged") {
  for (const double dt : {0.0, 0.01}) {
    CAPTURE(dt);
    ImexOptions o;
    o.fixed_dt = dt;
    DecaySplit split;
    ImexFunctions f = decay_functions(split);
    SUBCASE("explicit part") {
      FailingDecay fe(6);
      f.explicit_rhs = [&](double, const double* y, double* yd) {
        fe(y, yd, 2);
        yd[0] = yd[1] = 0;
      };
      ImexIntegrator integ(f, kY0, 0.0, o);
      CHECK_THROWS_WITH_AS(integ.evolve_to(1.0), "decay: evaluation 6 failed", TestError);
    }
    SUBCASE("implicit part (inside the Newton iteration)") {
      FailingDecay fi(6);
      f.implicit_rhs = [&](double, const double* y, double* yd) { fi(y, yd, 2); };
      ImexIntegrator integ(f, kY0, 0.0, o);
      CHECK_THROWS_WITH_AS(integ.evolve_to(1.0), "decay: evaluation 6 failed", TestError);
    }
    SUBCASE("Jacobian (linear system callback)") {
      f.jacobian = [](double, const double*) -> const SparseCsr& { throw TestError("no Jacobian"); };
      ImexIntegrator integ(f, kY0, 0.0, o);
      CHECK_THROWS_WITH_AS(integ.step(1.0), "no Jacobian", TestError);
    }
    SUBCASE("NumericalFailure keeps its type") {
      f.implicit_rhs = [](double, const double*, double*) { throw NumericalFailure("cell list: blown up"); };
      ImexIntegrator integ(f, kY0, 0.0, o);
      CHECK_THROWS_WITH_AS(integ.step(1.0), "cell list: blown up", NumericalFailure);
    }
  }
}

// Velocities 1e12 x spread the particles over ~1e12 cell widths in the first stage after t = 0:
// the cell list of that stage's f throws NumericalFailure inside ARKODE (ERKStep, ARKStep, and the
// ISPH projection in ERKStep's step post-processing), before any check of the step's end state.
TEST_CASE("cli: a right-hand side failing inside a step exits 3 with its own message") {
  const std::string blowup = "--quiet --set 'initial.velocity=[\"1e12*x\", \"0\"]' --set time.end=0.05";
  const fs::path spin_down = fs::path(ARKSPH_SOURCE_DIR) / "cases" / "spin_down" / "scene.toml";
  const std::vector<std::string> runs = {
      "run " + blowup + " --set time.dt=0.01",                       // ERKStep, stage 2 of Heun-Euler
      "run " + blowup + " --set time.dt=0.01 --set time.imex=true",  // ARKStep IMEX
      "run " + spin_down.string() + " " + blowup,                    // ISPH: projection after the step
  };
  for (const std::string& args : runs) {
    CAPTURE(args);
    const fs::path dir = fs::temp_directory_path() / ("arksph_callback_blowup_" + std::to_string(getpid()));
    fs::remove_all(dir);
    const Outcome o = run_cli_line(args + " --out " + dir.string());
    CHECK(o.code == 3);
    CHECK(o.err.find("neighbour cells") != std::string::npos);  // CellList::build's own message
    CHECK(o.err.find("the run has blown up") != std::string::npos);
    CHECK(o.err.find("ARKODE") == std::string::npos);  // not ARKODE's flag for the failed callback
    fs::remove_all(dir);
  }
}
