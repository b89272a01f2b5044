// The bakeinfo tool as a library call: describe each file, print text or JSON on stdout, continue
// past a file that fails and return the first failure (so batches report every bad file).
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "bake/core/diagnostics.h"
#include "bake/core/options.h"
#include "bake/core/status.h"

namespace bake::info {

struct Settings {
  std::vector<std::string> files;
  bool json = false;
  CommonOptions common;
};

Status run(const Settings& settings, Diagnostics& diagnostics, std::FILE* out = stdout);

}  // namespace bake::info
