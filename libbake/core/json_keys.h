// Small pieces shared by the JSON input readers (style files, groove scenes): JSON pointers to name
// the element at fault (RFC 6901 escaping), and the check that an object holds only known keys, with
// the nearest known key suggested for a typo (Levenshtein distance).
#pragma once

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace bake {

// "<parent>/<key>" with '~' and '/' in the key escaped as "~0" and "~1".
std::string jsonPointerChild(const std::string& parent, const std::string& key);
std::string jsonPointerChild(const std::string& parent, std::size_t index);

// Levenshtein distance (insertions, deletions and substitutions of single characters).
std::size_t editDistance(const std::string& a, const std::string& b);

struct UnknownKey {
  std::string key;      // the first key of the object not in `known`
  std::string message;  // "unknown key \"widht\" (did you mean \"width\"?)"
};

// The first key of `object` that is not one of `known`, with a message suggesting the nearest known
// key when it is close (distance <= max(2, length / 3)); nothing when every key is known.
std::optional<UnknownKey> findUnknownKey(const nlohmann::json& object, std::initializer_list<const char*> known);

}  // namespace bake
