// Content-addressed cache of bake outputs (--cache-dir DIR). A run's key is the hash of the tool, the
// toolkit version, the normalised options and the content of every input; an entry holds the bytes of
// every output the bake committed, with a manifest of their sizes and hashes that is verified on every
// read, so a partial or damaged entry is never used (it is a miss). Entries appear atomically: they are
// written into a temporary directory inside DIR and renamed to DIR/<key>/.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/core/options.h"
#include "bake/core/status.h"

namespace bake {

// The files one run reads and writes, known before any work is done: --print-inputs lists `inputs`,
// the cache keys on their content and stores `outputs` (in this order).
struct RunFiles {
  std::vector<std::string> inputs;
  std::vector<std::string> outputs;
};

// The options of a parsed command line, independent of their order on it: every option given, by
// name, with its values (numbers in one canonical form). A value naming an input of `files` becomes
// {"file": file name, "hash": content hash}; one naming an output, its extension. --report, --depfile,
// --cache-dir, --quiet, --threads, --print-inputs, --help and --version never change the outputs and
// are left out, so `-j1` and `-j2` share an entry.
Result<nlohmann::json> normalisedOptions(const GivenOptions& given, const RunFiles& files);

// What the key is the hash of: {"tool", "toolVersion", "options", "inputs": [{"file", "hash"}],
// "outputs": [extension]}. Fails when an input cannot be read, or when an input may pull in files the
// run does not declare (a .gltf's external buffers): such a run is not cached.
Result<nlohmann::json> describeRun(const std::string& tool, const std::string& toolVersion, const GivenOptions& given,
                                   const RunFiles& files);

// 32 hex digits: XXH3-128 of the description's canonical JSON text.
std::string cacheKey(const nlohmann::json& description);

struct CacheEntry {
  std::vector<std::vector<std::uint8_t>> outputs;  // in the order of RunFiles::outputs
  nlohmann::json report = nlohmann::json::object();  // "options", "statistics", "accuracy" of the bake
};

class Cache {
 public:
  explicit Cache(std::filesystem::path directory) : directory_(std::move(directory)) {}

  std::filesystem::path entryPath(const std::string& key) const { return directory_ / key; }

  // The entry when it exists, is complete and every output matches its recorded size and hash;
  // nothing otherwise (a miss).
  std::optional<CacheEntry> load(const std::string& key) const;

  // Writes the entry into a temporary directory and renames it into place; an invalid entry already
  // under the key is replaced, a valid one kept.
  Status store(const std::string& key, const CacheEntry& entry) const;

 private:
  std::filesystem::path directory_;
};

}  // namespace bake
