#include "core/build_syntax.h"

namespace bake {
namespace {

Status cannotHold(std::string_view path, const char* syntax, char c) {
  std::string shown;
  switch (c) {
    case '\n': shown = "a newline"; break;
    case '\r': shown = "a carriage return"; break;
    default: shown = std::string("'") + c + "'";
  }
  return usageError("the path '" + commentSafe(path) + "' holds " + shown + ", which " + syntax +
                    " cannot express; rename the file");
}

}  // namespace

Result<std::string> makeEscapedPath(std::string_view path) {
  std::string out;
  out.reserve(path.size() + 8);
  for (std::size_t i = 0; i < path.size(); ++i) {
    const char c = path[i];
    switch (c) {
      case '\n': case '\r': case ';': case '=': case '|':
        return cannotHold(path, "a Make dependency file", c);
      case ' ': case '#': case ':':
        // A backslash run before an escaped character is doubled, so it is not read as the escape.
        for (std::size_t j = i; j > 0 && path[j - 1] == '\\'; --j) out += '\\';
        out += '\\';
        out += c;
        break;
      case '$': out += "$$"; break;
      default: out += c;
    }
  }
  return out;
}

Result<std::string> ninjaEscapedPath(std::string_view path) {
  std::string out;
  out.reserve(path.size() + 8);
  for (const char c : path) {
    if (c == '\n' || c == '\r' || c == '|') return cannotHold(path, "a Ninja file", c);
    if (c == '$' || c == ' ' || c == ':') out += '$';
    out += c;
  }
  return out;
}

Result<std::string> ninjaEscapedValue(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 8);
  for (const char c : text) {
    if (c == '\n' || c == '\r') return cannotHold(text, "a Ninja file", c);
    if (c == '$') out += '$';
    out += c;
  }
  return out;
}

std::string commentSafe(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  }
  return out;
}

}  // namespace bake
