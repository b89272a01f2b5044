// Small pieces shared by the JSON input readers (style files, groove scenes, scene descriptions): JSON
// pointers to name the element at fault (RFC 6901 escaping), the check that an object holds only
// known keys, with the nearest known key suggested for a typo (Levenshtein distance), and the checks
// every strict reader starts from.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/core/status.h"

namespace bake {

// "<parent>/<key>" with '~' and '/' in the key escaped as "~0" and "~1".
std::string jsonPointerChild(const std::string& parent, const std::string& key);
std::string jsonPointerChild(const std::string& parent, std::size_t index);

// Lenient access for readers of JSON they do not own (glTF parts, extensions in a package): any part
// may have any type, and json::value() throws on a non-object or a mismatched type. A member, or null
// when `object` is not an object or lacks it; a member's number or string, or `fallback` when it is
// missing or of another type.
const nlohmann::json& jsonMember(const nlohmann::json& object, const char* key);
double jsonNumberOr(const nlohmann::json& object, const char* key, double fallback);
std::string jsonStringOr(const nlohmann::json& object, const char* key, const std::string& fallback);
// A member that is a non-negative integer (a glTF index), or -1.
std::int64_t jsonIndexOr(const nlohmann::json& object, const char* key);

// Levenshtein distance (insertions, deletions and substitutions of single characters).
std::size_t editDistance(const std::string& a, const std::string& b);

struct UnknownKey {
  std::string key;      // the first key of the object not in `known`
  std::string message;  // "unknown key \"widht\" (did you mean \"width\"?)"
};

// The first key of `object` that is not one of `known`, with a message suggesting the nearest known
// key when it is close (distance <= max(2, length / 3)); nothing when every key is known.
std::optional<UnknownKey> findUnknownKey(const nlohmann::json& object, std::initializer_list<const char*> known);
std::optional<UnknownKey> findUnknownKey(const nlohmann::json& object, const std::vector<const char*>& known);

// The checks every strict JSON reader shares; each failure is invalid input naming `file` and the
// JSON pointer of the element. Readers derive from it and add their own value kinds.
struct JsonReader {
  std::string file;

  Status error(const std::string& where, const std::string& message) const;
  // A JSON object holding only `known` keys.
  Status object(const nlohmann::json& node, const std::string& where, std::initializer_list<const char*> known) const;
  Status object(const nlohmann::json& node, const std::string& where, const std::vector<const char*>& known) const;
  // A finite number (NaN and Inf are refused even where the parser let them through).
  Result<double> number(const nlohmann::json& node, const std::string& where) const;
  Result<std::string> string(const nlohmann::json& node, const std::string& where) const;
};

}  // namespace bake
