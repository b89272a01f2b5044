// `bakeplay validate`: checks packages the way a loader must trust them. Structure first (the
// package reader's bounds checks on buffers, views, accessors and indices; then finite attribute
// values, the attribute types glTF demands, and every BAKE_* extension carrying an integer version);
// then the shaders the package needs must compile; then its reference views are rendered and, with
// --golden, compared to an expected image with a stated metric. One verdict line per package on
// stdout, a JSON record with --report, exit 0 when every package passes and 3 otherwise.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "bake/core/diagnostics.h"
#include "bake/core/options.h"
#include "bake/core/status.h"
#include "bake/io/glb.h"
#include "io/image_compare.h"

namespace bake::play {

struct ValidateSettings {
  std::vector<std::string> packages;
  std::vector<std::string> goldens;  // one per package, in order, compared with its first view
  ImageTolerance tolerance;
  std::string viewsDirectory;  // when set, the rendered views are written there as PNG
  int size = 256;
  CommonOptions common;
};

// The structural checks alone (no GL): the first fault, naming the element.
Status checkPackageStructure(const glb::Package& package, const std::string& name);

Status runValidate(const ValidateSettings& settings, Diagnostics& diagnostics, std::FILE* out = stdout);

}  // namespace bake::play
