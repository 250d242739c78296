// The registered kernel shapes, in the order `arksph list` shows them: one include and one entry in
// the list per shape. A shape is a struct with name, summary, support(), sigma(dimension),
// eval(q, f, df) and d2(q) (and optionally eval_over_q(q, f, df/q)); kernels/kernel.hpp dispatches
// over this list, so no other file names a shape.
#pragma once
#include "kernels/CubicSpline_Monaghan.hpp"
#include "kernels/QuarticSpline_CumminsRudman1999.hpp"
#include "kernels/QuinticSpline_Morris1997.hpp"
#include "kernels/WendlandQuintic_Wendland1995.hpp"

namespace arksph {

template <class... Shapes>
struct ShapeList {
  static constexpr int size = sizeof...(Shapes);
};

using KernelShapes = ShapeList<CubicSpline, QuarticSpline, WendlandQuintic, QuinticSpline>;

}  // namespace arksph
