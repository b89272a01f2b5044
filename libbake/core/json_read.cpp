#include "core/json_read.h"

#include "bake/core/input_file.h"

namespace bake {

Status checkJsonDepth(std::string_view text, const std::string& file) {
  int depth = 0;
  bool inString = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\') {
        ++i;  // the escaped character, whatever it is
      } else if (c == '"') {
        inString = false;
      }
      continue;
    }
    if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth) {
        return invalidInput("arrays and objects nested deeper than " + std::to_string(kMaxJsonDepth) + " levels",
                            {file, "byte " + std::to_string(i)});
      }
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return {};
}

Result<nlohmann::json> parseJsonText(std::string_view text, const std::string& file, const std::string& what) {
  text = withoutByteOrderMark(text);
  BAKE_RETURN_IF_ERROR(checkJsonDepth(text, file));
  try {
    return nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::parse_error& e) {
    return invalidInput(what + ": " + e.what(), {file, "byte " + std::to_string(e.byte)});
  } catch (const nlohmann::json::exception& e) {  // e.g. a number overflowing a double
    return invalidInput(what + ": " + e.what(), {file, ""});
  }
}

}  // namespace bake
