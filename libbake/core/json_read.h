// Reading JSON inputs (scenes, styles, profiles, stroke lists, source files, the glTF JSON chunk):
// one parse for all of them that first refuses nesting deeper than kMaxJsonDepth, so that no reader,
// walker or printer of a document can recurse without bound on a hostile file (100,000 nested arrays
// would overflow the stack of any recursive walk), and that skips a UTF-8 byte-order mark. Syntax
// errors are invalid input naming the file and the byte.
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "bake/core/status.h"

namespace bake {

// Far deeper than any document of ours (a glTF is about 6 levels deep), far shallower than a stack.
inline constexpr int kMaxJsonDepth = 200;

// Invalid input when arrays and objects in `text` nest deeper than kMaxJsonDepth, at the byte where
// the limit is passed. Strings are skipped, so brackets inside them do not count.
Status checkJsonDepth(std::string_view text, const std::string& file);

// checkJsonDepth, then the parse; a syntax error is invalid input "<what>: <parser's message>" at
// "byte N". Numbers that overflow a double are errors too.
Result<nlohmann::json> parseJsonText(std::string_view text, const std::string& file,
                                     const std::string& what = "not valid JSON");

}  // namespace bake
