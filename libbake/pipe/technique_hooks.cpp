// The techniques a scene may use: the registry's rows that carry scene hooks (pipe/technique_hooks.h).
#include "pipe/technique_hooks.h"

#include "techniques/registry.h"

namespace bake::pipe {

const TechniqueHooks* hooksOf(std::string_view technique) {
  const techniques::Technique* row = techniques::byName(technique);
  return row ? row->pipe : nullptr;
}

std::vector<std::string> sceneTechniques() {
  std::vector<std::string> names;
  for (const techniques::Technique& technique : techniques::all())
    if (technique.pipe) names.push_back(technique.name);
  return names;
}

}  // namespace bake::pipe
