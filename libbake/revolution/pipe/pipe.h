// Revolution objects in scene pipelines (pipe/technique_hooks.h): what a scene may say of them, their
// revolbake step, and how their packages are assembled.
#pragma once

#include "pipe/technique_hooks.h"

namespace bake::revolution {

const pipe::TechniqueHooks& pipeHooks();              // pipe/plan.cpp
const pipe::detail::TechniqueRules& assembleRules();  // pipe/assemble.cpp

}  // namespace bake::revolution
