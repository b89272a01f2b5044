#include "bake/core/cache.h"

#include <stdlib.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>

#include "bake/core/atomic_file.h"
#include "core/hash.h"
#include "core/json_read.h"

namespace bake {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr const char* kManifest = "manifest.json";
constexpr const char* kEntrySchema = "bake-cache-entry";
constexpr int kEntryVersion = 1;

// Options that never change what a run writes.
bool leftOut(const GivenOption& option) {
  for (const char* name : {"report", "depfile", "cache-dir", "quiet", "threads", "print-inputs", "budget", "help",
                           "version"}) {
    for (const std::string& longName : option.longNames) {
      if (longName == name) return true;
    }
  }
  return false;
}

// "0.50" and "0.5" are the same number; anything that is not a whole number text stays as it is.
std::string canonicalNumber(const std::string& text) {
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [at, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || at != end || !std::isfinite(value)) return text;
  char out[64];
  std::snprintf(out, sizeof out, "%.17g", value);
  return out;
}

std::string normalPath(const std::string& path) { return fs::path(path).lexically_normal().string(); }

void collectOptions(const GivenOptions& given, const std::map<std::string, json>& inputs,
                    const std::map<std::string, std::string>& outputs, json& out) {
  for (const GivenOption& option : given) {
    if (leftOut(option)) continue;
    json values = json::array();
    for (const std::string& value : option.values) {
      if (const auto input = inputs.find(normalPath(value)); input != inputs.end()) {
        values.push_back(input->second);
      } else if (const auto output = outputs.find(normalPath(value)); output != outputs.end()) {
        values.push_back({{"output", output->second}});
      } else {
        values.push_back(option.numeric ? canonicalNumber(value) : value);
      }
    }
    out[option.name] = values;
  }
}

Result<std::map<std::string, json>> hashInputs(const RunFiles& files) {
  std::map<std::string, json> inputs;
  for (const std::string& input : files.inputs) {
    BAKE_ASSIGN_OR_RETURN(const std::string hash, hashFile(input));
    inputs[normalPath(input)] = {{"file", fs::path(input).filename().string()}, {"hash", hash}};
  }
  return inputs;
}

std::map<std::string, std::string> outputExtensions(const RunFiles& files) {
  std::map<std::string, std::string> outputs;
  for (const std::string& output : files.outputs) outputs[normalPath(output)] = fs::path(output).extension().string();
  return outputs;
}

std::string lowercase(std::string text) {
  for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

Result<json> readManifest(const fs::path& path) {
  BAKE_ASSIGN_OR_RETURN(const std::vector<std::uint8_t> bytes, readFileBytes(path));
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  BAKE_ASSIGN_OR_RETURN(json manifest, parseJsonText(text, path.string()));
  if (!manifest.is_object()) return invalidInput("not a JSON object", {path.string(), ""});
  return manifest;
}

}  // namespace

Result<json> normalisedOptions(const GivenOptions& given, const RunFiles& files) {
  BAKE_ASSIGN_OR_RETURN(const auto inputs, hashInputs(files));
  json out = json::object();
  collectOptions(given, inputs, outputExtensions(files), out);
  return out;
}

Result<json> describeRun(const std::string& tool, const std::string& toolVersion, const GivenOptions& given,
                         const RunFiles& files) {
  for (const std::string& input : files.inputs) {
    if (lowercase(fs::path(input).extension().string()) == ".gltf") {
      return unsupported("a .gltf input may read external buffers and images; runs reading one are not cached",
                         {input, ""});
    }
  }
  BAKE_ASSIGN_OR_RETURN(const auto inputs, hashInputs(files));
  json options = json::object();
  collectOptions(given, inputs, outputExtensions(files), options);
  json inputList = json::array();
  for (const std::string& input : files.inputs) inputList.push_back(inputs.at(normalPath(input)));
  json outputList = json::array();
  for (const std::string& output : files.outputs) outputList.push_back(fs::path(output).extension().string());
  return json{{"tool", tool}, {"toolVersion", toolVersion}, {"options", options}, {"inputs", inputList},
              {"outputs", outputList}};
}

std::string cacheKey(const json& description) {
  std::string text;
  try {
    text = description.dump();
  } catch (const json::type_error&) {
    // A file name is any bytes, and JSON text must be UTF-8: a description naming a file whose name
    // is not UTF-8 is keyed by its CBOR bytes instead, which keep every byte (distinct names, distinct
    // keys), with a prefix no JSON text starts with.
    const std::vector<std::uint8_t> cbor = json::to_cbor(description);
    text = "cbor:" + std::string(cbor.begin(), cbor.end());
  }
  const std::string hash = hashBytes({reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
  return hash.substr(hash.find(':') + 1);
}

std::optional<CacheEntry> Cache::load(const std::string& key) const {
  const fs::path entry = entryPath(key);
  std::error_code ec;
  if (!fs::is_directory(entry, ec)) return std::nullopt;
  Result<json> manifest = readManifest(entry / kManifest);
  if (!manifest.isOk()) return std::nullopt;
  const json& m = *manifest;
  if (m.value("schema", "") != kEntrySchema || m.value("version", 0) != kEntryVersion || m.value("key", "") != key ||
      !m.contains("outputs") || !m["outputs"].is_array()) {
    return std::nullopt;
  }
  CacheEntry out;
  for (const json& output : m["outputs"]) {
    if (!output.is_object() || !output.contains("file") || !output["file"].is_string() || !output.contains("bytes") ||
        !output["bytes"].is_number_unsigned() || !output.contains("hash") || !output["hash"].is_string()) {
      return std::nullopt;
    }
    const std::string file = output["file"];
    if (file.empty() || file.find('/') != std::string::npos || file == "." || file == "..") return std::nullopt;
    Result<std::vector<std::uint8_t>> bytes = readFileBytes(entry / file);
    if (!bytes.isOk() || bytes->size() != output["bytes"].get<std::uint64_t>() ||
        hashBytes(*bytes) != output["hash"].get<std::string>()) {
      return std::nullopt;
    }
    out.outputs.push_back(std::move(*bytes));
  }
  if (m.contains("report") && m["report"].is_object()) out.report = m["report"];
  return out;
}

Status Cache::store(const std::string& key, const CacheEntry& entry) const {
  std::error_code ec;
  fs::create_directories(directory_, ec);
  if (ec) return ioError("cannot create the cache directory: " + ec.message(), {directory_.string(), ""});
  std::string pattern = (directory_ / ("." + key + ".tmp.XXXXXX")).string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    return ioError("cannot create a directory in the cache", {directory_.string(), ""});
  }
  const fs::path temporary = pattern;
  auto fail = [&](Status status) {
    fs::remove_all(temporary, ec);
    return status;
  };
  json outputs = json::array();
  for (std::size_t i = 0; i < entry.outputs.size(); ++i) {
    const std::string file = std::to_string(i) + ".bin";
    if (Status s = writeFileAtomic(temporary / file, entry.outputs[i]); !s.isOk()) return fail(s);
    outputs.push_back({{"file", file}, {"bytes", entry.outputs[i].size()}, {"hash", hashBytes(entry.outputs[i])}});
  }
  const json manifest = {{"schema", kEntrySchema}, {"version", kEntryVersion}, {"key", key},
                         {"outputs", outputs},     {"report", entry.report}};
  // The manifest is written last: an entry without one is incomplete.
  // The stored report may name files whose names are not UTF-8: those bytes become U+FFFD.
  const std::string manifestText = manifest.dump(1, ' ', false, json::error_handler_t::replace) + "\n";
  if (Status s = writeFileAtomic(temporary / kManifest, manifestText); !s.isOk()) return fail(s);

  const fs::path target = entryPath(key);
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (::rename(temporary.c_str(), target.c_str()) == 0) return {};
    if (errno != ENOTEMPTY && errno != EEXIST) break;
    // Someone stored this key first: keep a valid entry, move an invalid one out of the way.
    if (load(key)) return fail({});
    std::string stale = (directory_ / ("." + key + ".tmp.XXXXXX")).string();
    if (::mkdtemp(stale.data()) == nullptr) break;
    if (::rename(target.c_str(), (fs::path(stale) / "entry").c_str()) != 0) {
      fs::remove_all(stale, ec);
      break;
    }
    fs::remove_all(stale, ec);
  }
  return fail(ioError("cannot move the entry into place", {target.string(), ""}));
}

}  // namespace bake
