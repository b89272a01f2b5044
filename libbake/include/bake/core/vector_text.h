// Option values made of a few numbers separated by commas ("X,Y,Z", "R,G,B", "U,V"): one parser for
// every tool, so every option of this kind accepts the same text and refuses it with the same words.
#pragma once

#include <array>
#include <string>

#include "bake/core/status.h"

namespace bake {

// Exactly N finite numbers separated by commas (spaces around a number allowed), or a usage error
// "OPTION TEXT: expected FORM (N finite numbers)", FORM as the help writes it ("X,Y,Z").
Result<std::array<double, 3>> parseTriple(const std::string& text, const std::string& option, const char* form = "X,Y,Z");
Result<std::array<double, 2>> parsePair(const std::string& text, const std::string& option, const char* form = "U,V");

}  // namespace bake
