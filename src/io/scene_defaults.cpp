#include "io/scene_defaults.hpp"

#include "io/key_use.hpp"

namespace arksph {

Scene scene_defaults() {
  Scene s{};  // value-initialised: the members bound to keys are zero until stored below
  std::vector<const CatalogKey*> automatic;
  for (const CatalogKey& k : scene_catalog()) {
    const Param& p = k.param;
    if (p.custom) continue;  // the box, the sides, the phases: read by the reader's own code
    if (p.automatic) automatic.push_back(&k);
    else p.store(s, p.fallback);
  }
  resolve_automatic(s, automatic);
  s.directory = default_output_directory(s);
  return s;
}

void resolve_automatic(Scene& s, const std::vector<const CatalogKey*>& automatic) {
  s.automatic.clear();
  for (const CatalogKey* k : automatic)  // a flag keeps its value until its rule gives one (it cannot hold "auto")
    if (k->param.type != Param::Type::boolean) k->param.store(s, std::string("auto"));
  for (const CatalogKey* k : automatic) {
    const Param& p = k->param;
    const std::string value = p.automatic(s);
    if (p.type == Param::Type::boolean) p.store(s, value == "true");
    else p.store(s, value);
    s.automatic.emplace_back(p.key, value);
  }
  s.automatic_unused.clear();  // once every choice is made: a rule's choice may select a part
  for (const CatalogKey* k : automatic)
    if (!key_in_use(*k, s)) s.automatic_unused.push_back(k->param.key);
}

std::string default_output_directory(const Scene& s) { return "runs/" + s.name; }

}  // namespace arksph
