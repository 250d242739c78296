// Scenes shared by the benchmarks: a doubly periodic Taylor-Green box of n x n particles, Wendland
// kernel with h = 2 dx (about 50 neighbours, the setting of the 5e6 evaluations/s target),
// WCSPH or ISPH, and a fully evaluated model on it.
#pragma once
#include <string>
#include <vector>

#include "run/setup.hpp"
#include "core/scene.hpp"

namespace arksph::bench {

Scene periodic_box(int n, const std::string& scheme, const std::vector<std::string>& sets = {});

// A model with its state at t = 0, its particles sorted by cell as a run does at t = 0, and one
// right-hand-side evaluation done (pairs, ghosts, fields).
struct Prepared {
  Scene scene;
  Model model;
  std::vector<double> y, ydot;
};
Prepared prepare(int n, const std::string& scheme, const std::vector<std::string>& sets = {});

}  // namespace arksph::bench
