// Runs one of the independent Node.js checkers in tests/js (glTF-Validator, ktx-parse, Ajv) on a file
// and returns its JSON answer. The checkers are installed by scripts/setup.sh; a missing install is
// a test failure with that advice, never a skip.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace bake::test {

// Runs `node tests/js/<script> <arguments...>`; fails the calling test (returns null) on error.
nlohmann::json runNodeChecker(const std::string& script, const std::vector<std::string>& arguments);

}  // namespace bake::test
