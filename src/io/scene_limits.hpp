// Checks of a read scene that no single key can make (used by scene_reader.cpp only):
//   scales   - the lengths of the scene must be representable in the arithmetic of the run: the
//              squares of the spacing, smoothing length, kernel radius and box, and the kernel
//              constants sigma / h^d and sigma / h^(d+2), must be normal doubles (no overflow to
//              infinity, no underflow to a subnormal or zero);
//   progress - a run must be able to reach time.end: a fixed step that t + dt cannot resolve at
//              time.end, or more frames or checkpoints than kMaxScheduledWrites, is refused;
//   scene    - the metrics and the boundary and method options must apply to the scene they are in.
// Each failure is one InputError line naming the key (scene_schema::Section::fail).
#pragma once
#include <map>
#include <string>

#include "core/scene.hpp"
#include "io/scene_schema.hpp"

namespace arksph {

// Frames (time.end / output.every) or checkpoints (time.end / output.checkpoint_every) a run may
// schedule at most.
inline constexpr double kMaxScheduledWrites = 100000;
// The smallest time.end: the square of a smaller time underflows a double.
inline constexpr double kMinEndTime = 1e-150;

void check_scene_limits(const std::map<std::string, scene_schema::Section>& sections, const Scene& s);

}  // namespace arksph
