// Small path helpers shared by the readers and writers.
#pragma once

#include <filesystem>
#include <string>

#include "bake/core/status.h"

namespace bake {

// ".png" for "Frame.PNG": file formats are chosen by extension, case-insensitively.
std::string lowercaseExtension(const std::filesystem::path& path);

// Every baker's check of a file it writes: the extension names the format written (a GLB named
// x.png would be opened by the wrong program). A usage error "OPTION PATH: WHAT is a EXTENSION
// file" otherwise; `extension` is lower case with its dot.
Status checkWrittenExtension(const std::string& path, const std::string& option, const std::string& extension,
                             const std::string& what);

}  // namespace bake
