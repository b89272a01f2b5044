#include "core/depfile.h"

#include "core/atomic_file.h"

namespace bake {
namespace fs = std::filesystem;

std::string escapeDepfilePath(const std::string& path) {
  std::string out;
  out.reserve(path.size());
  for (std::size_t i = 0; i < path.size(); ++i) {
    const char c = path[i];
    if (c == ' ' || c == '#') {
      // A backslash run before a space must be doubled so Make does not read it as the escape.
      for (std::size_t j = i; j > 0 && path[j - 1] == '\\'; --j) out += '\\';
      out += '\\';
      out += c;
    } else if (c == '$') {
      out += "$$";
    } else {
      out += c;
    }
  }
  return out;
}

namespace {
std::string absoluteEscaped(const fs::path& path) {
  std::error_code ec;
  fs::path absolute = fs::absolute(path, ec);
  if (ec) absolute = path;
  return escapeDepfilePath(absolute.lexically_normal().string());
}
}  // namespace

std::string formatDepfile(const std::vector<fs::path>& outputs, const std::vector<fs::path>& inputs) {
  std::string text;
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    if (i) text += " \\\n ";
    text += absoluteEscaped(outputs[i]);
  }
  text += ":";
  for (const fs::path& input : inputs) text += " \\\n  " + absoluteEscaped(input);
  text += "\n";
  return text;
}

Status writeDepfile(const fs::path& depfile, const std::vector<fs::path>& outputs,
                    const std::vector<fs::path>& inputs) {
  return writeFileAtomic(depfile, formatDepfile(outputs, inputs));
}

}  // namespace bake
