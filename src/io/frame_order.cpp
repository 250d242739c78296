#include "io/frame_order.hpp"

#include <algorithm>
#include <iterator>
#include <numeric>

namespace arksph {

FrameInIdOrder::FrameInIdOrder(const Frame& f, bool copy) : view_(f) {
  const bool sorted = !f.id || std::is_sorted(f.id, f.id + f.n);
  if (sorted && !copy) return;
  std::vector<std::size_t> order(f.n);  // row k shows particle order[k]
  std::iota(order.begin(), order.end(), std::size_t{0});
  if (!sorted) std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return f.id[a] < f.id[b]; });
  static constexpr const double* Frame::*kFields[] = {&Frame::x,        &Frame::y,       &Frame::u,
                                                      &Frame::v,        &Frame::pressure, &Frame::density,
                                                      &Frame::summation_density, &Frame::mass};
  doubles_.reserve(std::size(kFields));
  for (const double* Frame::*field : kFields) {
    const double* src = f.*field;
    if (!src) continue;
    std::vector<double>& rows = doubles_.emplace_back(f.n);
    for (std::size_t k = 0; k < f.n; ++k) rows[k] = src[order[k]];
    view_.*field = rows.data();
  }
  if (f.id) {
    id_.resize(f.n);
    for (std::size_t k = 0; k < f.n; ++k) id_[k] = f.id[order[k]];
    view_.id = id_.data();
  }
  if (f.kind) {
    kind_.resize(f.n);
    for (std::size_t k = 0; k < f.n; ++k) kind_[k] = f.kind[order[k]];
    view_.kind = kind_.data();
  }
  if (f.free_surface) {
    free_surface_.resize(f.n);
    for (std::size_t k = 0; k < f.n; ++k) free_surface_[k] = f.free_surface[order[k]];
    view_.free_surface = free_surface_.data();
  }
  if (f.phase) {
    phase_.resize(f.n);
    for (std::size_t k = 0; k < f.n; ++k) phase_[k] = f.phase[order[k]];
    view_.phase = phase_.data();
  }
}

}  // namespace arksph
