#include "run/run_loop.hpp"

#include <algorithm>
#include <new>

#include "core/errors.hpp"
#include "core/seconds_since.hpp"
#include "run/checkpointing.hpp"
#include "run/interrupt.hpp"
#include "run/progress.hpp"
#include "run/state_check.hpp"

namespace arksph {

namespace {

using Clock = std::chrono::steady_clock;

// The loop's own verdict on a step to t: the step size (adaptive mode; the same on every rank).
Verdict step_size_verdict(const Scene& scene, double t, double dt, int& tiny_steps) {
  if (scene.dt != 0) return {};
  try {
    check_step_size(t, dt, scene.end, tiny_steps);
  } catch (const NumericalFailure& e) {
    return {3, e.what()};
  }
  return {};
}

// The step budget and the signals, after this process's own checks.
Verdict budget_and_signals(const Scene& scene, double t, long steps, Verdict v) {
  if (!v.code && steps >= scene.max_steps)
    v = {3, "time.max_steps = " + std::to_string(scene.max_steps) + " reached at t = " + arksph::message_number(t) +
                " before time.end"};
  if (const int sig = pending_interrupt(); sig && !v.code)
    v = {128 + sig, std::string("interrupted by ") + interrupt_name(sig) + " at t = " + arksph::message_number(t)};
  return v;
}

}  // namespace

double next_output_time(const Scene& scene, int frame) {
  const double t_next = scene.every > 0 ? scheduled_time(frame, scene.every) : scene.end;  // 3 * 0.1 -> 0.3
  return t_next > scene.end * (1 - 1e-12) ? scene.end : t_next;
}

RunResult run_loop(const Scene& scene, RunStrategy& run, bool quiet, double progress_every,
                   Clock::time_point wall_start) {
  Progress progress(scene.end, quiet, progress_every);
  double t = run.start_time();
  int frame = run.first_frame();
  int tiny_steps = 0;  // adaptive steps in a row below the underflow floor (check_step_size)
  double stepping = 0;  // the steps alone (summary.json timing.stepping)
  RunResult result;
  const auto stop = [&result](const Verdict& v) {
    result.exit_code = v.code;
    result.message = v.message;
  };
  try {
    run.start();
    ViscousDissipation* dissipation = run.viscous_dissipation();  // metrics.energy_budget
    if (dissipation) dissipation->start(t, run.viscous_power(t));
    while (t < scene.end) {
      const double t_next = next_output_time(scene, frame);
      double dt_max = 0;  // largest step since the last output (the last one may be cut to hit t_next)
      while (t < t_next) {
        const auto step_start = Clock::now();
        t = run.step(t, run.limit(t_next));  // checkpoint times are stop times too
        const StepStats st = run.integrator().stats();
        dt_max = std::max(dt_max, st.last_step);
        Verdict v = step_size_verdict(scene, t, st.last_step, tiny_steps);
        if (v.code) v.message += run.failure_location(t);
        v = run.reflect_and_check(t, v);
        v = run.agree_after_step(t, budget_and_signals(scene, t, st.steps, v));
        if (v.code) {
          stop(v);
          break;
        }
        run.sync_point(t, st.steps);
        if (dissipation) dissipation->step(t, run.viscous_power(t));
        progress.step(t, st.steps, st.last_step);
        stepping += seconds_since(step_start);
        if (t < t_next) run.checkpoint_if_due(t, frame);
      }
      if (result.exit_code) break;
      StepStats st = run.integrator().stats();
      st.last_step = dt_max;
      run.write_frame(t, st);
      progress.frame(t, st.steps, dt_max);
      ++frame;
      if (run.steady() && t < scene.end) {  // time.steady_tolerance: end here as at time.end
        result.steady_time = t;
        result.steady_rate = run.steady_rate();
        break;
      }
      run.checkpoint_if_due(t, frame);
    }
    if (result.exit_code > 128) {  // a signal: the checkpoint at the last completed step
      result.interrupted = true;
      result.checkpoint = run.checkpoint_now(t, frame);
    } else if (!result.exit_code) {
      result.checkpoint = run.checkpoint_at_end(t, frame);
    }
  } catch (const NumericalFailure& e) {  // ARKODE gave up
    stop(run.numerical_failure(t, e.what()));
  } catch (const OutputError& e) {  // disk full, size limit: keep what still fits, exit 5
    result.exit_code = 5;
    result.message = e.what();
    result.checkpoint.clear();
    if (result.message.rfind("cannot write " + run.checkpoint_path() + ":", 0) != 0) {
      try {
        result.checkpoint = run.checkpoint_now(t, frame);
      } catch (const OutputError& again) {
        result.message += std::string("; ") + again.what();
      }
    }
  } catch (const std::bad_alloc&) {
    stop(run.out_of_memory(t));
  }
  result.final_time = t;
  progress.finish();
  run.finish(result, seconds_since(wall_start), stepping);
  return result;
}

}  // namespace arksph
