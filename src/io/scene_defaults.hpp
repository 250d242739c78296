// The default scene, made from the key declarations of the scene catalog: the one place a default
// is written (core/scene.hpp).
#pragma once
#include <string>
#include <vector>

#include "core/scene.hpp"
#include "io/scene_catalog.hpp"

namespace arksph {

// Every key at its declared default (a required key at its declared value, which a file must set
// anyway), each "auto" key at the value its rule gives for this scene, output.directory at
// runs/<scene.name>, the box, sides and phases at Scene's initialisers: the scene that a file
// setting only the required keys, to these values, gives (tests/unit/test_scene_defaults.cpp).
// The scene reader starts from it.
Scene scene_defaults();

// Each key of `automatic` (keys left at "auto") takes the value its rule gives for `s` (text for a
// choice, "true" or "false" for a flag), recorded in s.automatic; those the scene does not use are
// listed in s.automatic_unused. A family's rule that reads another family's part asks SelectedParts,
// which applies that family's rule where its key is still "auto", so their order does not matter.
void resolve_automatic(Scene& s, const std::vector<const CatalogKey*>& automatic);

// output.directory of a scene that does not set it.
std::string default_output_directory(const Scene& s);

}  // namespace arksph
