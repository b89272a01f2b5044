// Numbers in text for people. Option values made of a few numbers separated by commas ("X,Y,Z", "R,G,B", "U,V"): one parser for
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

// A number for a message, as people write it: "0.5", "1e-09", "2.5e+06" (printf's %g with `digits`
// significant digits), never std::to_string's "0.500000".
std::string numberText(double value, int digits = 6);

}  // namespace bake
