// The additive split of the particle ODE for time.imex: f = f_E + f_I with f_I the viscous
// acceleration (velocity block only) and f_E everything else (positions' rate, pressure, body
// force, continuity, energy). Implicit viscosity removes the explicit viscous step limit
// 0.125 h^2 / nu (Szewc et al. 2012 eq. 36).
//
// ARKStep asks for f_E, f_I and J at overlapping states; one full RHS evaluation serves all three
// at a given state. During a stage solve only the velocities change, so f_I there is one pass of
// the viscous terms over the frozen fields (RhsEvaluator::viscous_acceleration), and J is
// re-probed only when the frozen part of the state (positions, densities, energies) has changed.
#pragma once
#include <functional>
#include <vector>

#include "core/scene.hpp"
#include "integrate/imex_integrator.hpp"
#include "integrate/viscous_jacobian.hpp"
#include "rhs/evaluator.hpp"

namespace arksph {

class ViscousSplit {
 public:
  // Switches rhs to the split evaluation (RhsOptions::imex_split).
  ViscousSplit(const Scene& scene, RhsEvaluator& rhs);
  void explicit_rhs(double t, const double* y, double* ydot);
  void implicit_rhs(double t, const double* y, double* ydot);
  const SparseCsr& jacobian(double t, const double* y);
  ImexFunctions functions();
  const ViscousJacobian& jacobian_builder() const { return jac_; }
  // A constraint on f_E that must see the whole acceleration (the constrained projection): called
  // after each full evaluation as constraint(y, f_E, au_I, av_I) with f_I's acceleration.
  using Constraint = std::function<void(const double* y, double* fe, const double* au, const double* av)>;
  void set_constraint(Constraint c) {
    constraint_ = std::move(c);
    valid_ = false;
  }
  // Drops every cached evaluation and the Jacobian pattern (the particles were re-ordered).
  void forget() {
    valid_ = false;
    jac_last_ = nullptr;
    jac_y_.clear();
    jac_.invalidate();
  }

 private:
  bool frozen_equal(const double* y, const std::vector<double>& ref) const;
  void evaluate_at(double t, const double* y);
  RhsEvaluator& rhs_;
  ViscousJacobian jac_;
  std::vector<double> y_, fe_;   // the state of the last full evaluation and its f_E
  double t_ = 0;
  bool valid_ = false;
  std::vector<double> jac_y_;    // the state J was probed at (frozen rows matter)
  const SparseCsr* jac_last_ = nullptr;
  std::vector<double> au_, av_;
  Constraint constraint_;
  std::vector<double> fi_;  // f_I of the last full evaluation (for the constraint)
};

}  // namespace arksph
