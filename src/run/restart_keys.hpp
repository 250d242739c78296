// What a restart may not change: the keys that shape the particle set (the lattice, its offset, the
// phases) and the walls (box, side kinds and slip, wall particles). The checkpoint's arrays are
// compared bit for bit too (run/checkpointing.cpp), but a changed box with the same particle count
// passes that comparison and would put the stored particles into other walls.
#pragma once
#include <string>

#include "core/scene.hpp"

namespace arksph {

// Throws InputError("SOURCE: KEY: ...") naming the first such key whose value in `now` (the scene
// with the --set overrides) differs from `earlier` (the checkpoint's scene_toml).
void check_restart_keys(const Scene& earlier, const Scene& now, const std::string& source);

}  // namespace arksph
