#include "core/path.h"

#include <cctype>

namespace bake {

std::string lowercaseExtension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

Status checkWrittenExtension(const std::string& path, const std::string& option, const std::string& extension,
                             const std::string& what) {
  if (lowercaseExtension(path) == extension) return {};
  return usageError(option + " " + path + ": " + what + " is a " + extension + " file");
}

}  // namespace bake
