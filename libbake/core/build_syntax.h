// Paths written into build files: the one escaper for Make syntax (depfiles) and Ninja files. Each
// escapes what its syntax can escape and refuses, as a usage error naming the path, what it cannot
// hold, so that a file name can never become a rule, a recipe or a command:
// - Make (GNU Make and Ninja's depfile reader alike): ' ', '#', ':' take a backslash, '$' is doubled;
//   a newline, carriage return, ';' (would start a recipe), '=' (a variable assignment) and '|' (an
//   order-only separator, which Ninja reads differently) are refused.
// - Ninja paths: '$', ' ' and ':' take a '$'; a newline, carriage return or '|' is refused.
// - Ninja variable values (command lines): '$' is doubled; a newline or carriage return is refused.
// - Comments: control characters are shown as '?' (a comment needs no exact path).
#pragma once

#include <string>
#include <string_view>

#include "bake/core/status.h"

namespace bake {

Result<std::string> makeEscapedPath(std::string_view path);
Result<std::string> ninjaEscapedPath(std::string_view path);
Result<std::string> ninjaEscapedValue(std::string_view text);
std::string commentSafe(std::string_view text);

}  // namespace bake
