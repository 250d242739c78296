// Whether a run uses a scene key: the keys of a part only matter when that part is selected, and
// the keys of a scheme only under that scheme. The run header lists the "auto" choices a run uses.
#pragma once
#include "core/scene.hpp"
#include "io/scene_catalog.hpp"

namespace arksph {

// False when `k` belongs to a part the scene does not select (owner "family: part"), to a group of
// keys of other schemes (owner "wcsph", "isph" for the projection schemes, "isph-gpps", or the
// key's own scheme list), or selects a family none of whose parts but "none" applies to the scheme.
bool key_in_use(const CatalogKey& k, const Scene& s);

}  // namespace arksph
