// Frame rows in particle id order. The run keeps its particles in a memory order that changes
// (method.reorder_every re-sorts them by cell); the VTP files list them by id instead, so that row k
// of every frame is the same particle and frames can be compared row by row.
#pragma once
#include <cstdint>
#include <vector>

#include "io/frame.hpp"

namespace arksph {

// A copy of a frame's arrays with the rows sorted by id (frame() views them). If the rows are in id
// order already, nothing is copied and frame() is the original view, unless a copy is asked for.
class FrameInIdOrder {
 public:
  // copy: the rows are the object's own even when f is already in id order (f's arrays may then
  // be freed before frame() is written).
  explicit FrameInIdOrder(const Frame& f, bool copy = false);
  const Frame& frame() const { return view_; }

 private:
  Frame view_;
  std::vector<std::vector<double>> doubles_;
  std::vector<std::int64_t> id_;
  std::vector<std::int32_t> phase_, kind_;
  std::vector<std::uint8_t> free_surface_;
};

}  // namespace arksph
