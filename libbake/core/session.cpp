#include "bake/core/session.h"

#include <cstdio>
#include <set>

#include "core/depfile.h"
#include "core/output_plan.h"

namespace bake {
namespace fs = std::filesystem;

namespace {

std::string samePath(const fs::path& path) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec);
  return (ec ? path : absolute).lexically_normal().string();
}

template <class Paths>
std::set<std::string> pathSet(const Paths& paths) {
  std::set<std::string> out;
  for (const auto& path : paths) out.insert(samePath(path));
  return out;
}

}  // namespace

BakeSession::BakeSession(const std::string& tool, const CommonOptions& options, Diagnostics& diagnostics)
    : options_(options), diagnostics_(diagnostics), report_(tool, toolkitVersion()) {}

void BakeSession::addInput(const std::filesystem::path& path) { inputs_.push_back(path); }

Status BakeSession::stageOutput(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
  // A tool plans its outputs before the work (core/output_plan.h); an output outside that plan is a
  // bug of the tool. Library callers that made no plan are still covered at finish(): no output may
  // replace an input, and the writer never replaces anything but a regular file.
  if (outputsPlanned() && !isPlannedOutput(path)) {
    return internalError("an output that was not planned before the bake", {path.string(), ""});
  }
  return outputs_.stage(path, bytes);
}

void BakeSession::storeInCache(const std::vector<fs::path>& committed) {
  const CommonOptions::CacheStore& plan = options_.cacheStore;
  // Only a run that read nothing but its declared inputs, and wrote exactly its declared outputs, is
  // described completely by its key.
  const std::set<std::string> declaredInputs = pathSet(plan.inputs);
  for (const fs::path& input : inputs_) {
    if (!declaredInputs.count(samePath(input))) {
      diagnostics_.warning("cache-not-stored", input.string() + ": read but not declared; the outputs are not cached");
      return;
    }
  }
  if (pathSet(committed) != pathSet(plan.outputs) || committed.size() != plan.outputs.size()) {
    diagnostics_.warning("cache-not-stored", "the outputs written differ from the declared ones; they are not cached");
    return;
  }
  CacheEntry entry;
  for (const std::string& output : plan.outputs) {
    Result<std::vector<std::uint8_t>> bytes = readFileBytes(output);
    if (!bytes.isOk()) {
      diagnostics_.warning("cache-not-stored", bytes.status().describe());
      return;
    }
    entry.outputs.push_back(std::move(*bytes));
  }
  nlohmann::json report = report_.toJson();
  nlohmann::json statistics = report.value("statistics", nlohmann::json::object());
  statistics.erase("cache");
  entry.report = {{"options", report.value("options", nlohmann::json::object())},
                  {"statistics", statistics},
                  {"accuracy", report.value("accuracy", nlohmann::json::array())}};
  if (const Status stored = Cache(options_.cacheDir).store(plan.key, entry); !stored.isOk()) {
    diagnostics_.warning("cache-not-stored", stored.describe());
  }
}

Status BakeSession::finish(Status outcome) {
  std::vector<std::filesystem::path> outputs = outputs_.targets();
  outputs.insert(outputs.end(), written_.begin(), written_.end());
  // The depfile is staged with the outputs and the report's folder is tried before anything is
  // committed: a --depfile or --report that cannot be written fails the bake with every earlier
  // output still in place.
  // Checked again against every input the bake actually read (a .gltf's buffers, a style's images):
  // no output may replace one of them.
  if (outcome.isOk()) {
    std::vector<fs::path> targets = outputs;
    if (!options_.depfilePath.empty()) targets.push_back(options_.depfilePath);
    if (!options_.reportPath.empty()) targets.push_back(options_.reportPath);
    outcome = checkDistinctFiles(inputs_, targets);
  }
  if (outcome.isOk() && !options_.depfilePath.empty()) {
    Result<std::string> depfile = formatDepfile(outputs, inputs_);
    outcome = depfile.isOk() ? outputs_.stage(options_.depfilePath, *depfile) : Status(depfile.status()).inFile(options_.depfilePath);
  }
  if (outcome.isOk() && !options_.reportPath.empty()) outcome = checkWritable(options_.reportPath);
  // The report's input entries are made before the commit too: an input it cannot describe fails the
  // bake while every earlier output is still in place.
  if (!options_.reportPath.empty()) {
    for (const auto& input : inputs_) {
      if (const Status s = report_.addInput(input); !s.isOk() && outcome.isOk()) outcome = s;
    }
  }
  if (outcome.isOk()) outcome = outputs_.commit();
  if (!outcome.isOk()) outputs_.discard();
  if (!options_.cacheDir.empty() && !cacheHit_) {
    report_.setStatistic("cache", "miss");
    if (outcome.isOk() && !options_.cacheStore.key.empty()) storeInCache(outputs);
  }
  if (!options_.reportPath.empty()) {
    if (outcome.isOk()) {
      for (const auto& output : outputs) {
        if (const Status s = report_.addOutput(output); !s.isOk()) outcome = s;
      }
    }
    report_.takeWarnings(diagnostics_);
    report_.setOutcome(outcome);
    const Status written = report_.write(options_.reportPath);
    if (outcome.isOk()) outcome = written;
  }
  return outcome;
}

Status BakeSession::finishFromCache(const RunFiles& files, const CacheEntry& entry) {
  cacheHit_ = true;
  const nlohmann::json& stored = entry.report;
  if (stored.contains("options")) report_.setOptions(stored["options"]);
  if (stored.contains("statistics") && stored["statistics"].is_object()) {
    for (const auto& [key, value] : stored["statistics"].items()) report_.setStatistic(key, value);
  }
  if (stored.contains("accuracy") && stored["accuracy"].is_array()) {
    for (const nlohmann::json& a : stored["accuracy"]) {
      report_.addAccuracy(a.value("quantity", ""), a.value("reference", ""), a.value("metrics", nlohmann::json::object()));
    }
  }
  report_.setStatistic("cache", "hit");
  for (const std::string& input : files.inputs) addInput(input);
  Status outcome;
  {
    StageTimer timer(&report_, "cache");
    for (std::size_t i = 0; i < files.outputs.size() && outcome.isOk(); ++i) {
      outcome = stageOutput(files.outputs[i], entry.outputs[i]);
    }
  }
  return finish(outcome);
}

Status runCachedBake(const std::string& tool, const GivenOptions& given, CommonOptions& common, Diagnostics& diagnostics,
               const std::function<Result<RunFiles>()>& files, const std::function<Status()>& bake) {
  if (common.printInputs) {
    BAKE_ASSIGN_OR_RETURN(const RunFiles run, files());
    for (const std::string& input : run.inputs) std::printf("%s\n", input.c_str());
    return {};
  }
  common.cacheStore = {};
  // Every output is resolved and checked before any work (core/output_plan.h). A run whose files
  // cannot be known (its input does not parse) is baked unplanned: the bake reports the error, and
  // the session's own checks at commit still keep every input.
  Result<RunFiles> run = files();
  if (!run.isOk()) return bake();
  const OutputPlanScope planScope;
  if (Status planned = planOutputs(*run, common); !planned.isOk()) {
    // The failure is still reported in --report, when that file itself is safe to write.
    if (reportIsSafe(*run, common)) static_cast<void>(BakeSession(tool, common, diagnostics).finish(planned));
    return planned;
  }
  if (common.cacheDir.empty()) return bake();
  // A run whose key cannot be known is baked without the cache: the bake reports any error.
  Result<nlohmann::json> description = describeRun(tool, toolkitVersion(), given, *run);
  if (!description.isOk()) return bake();
  const std::string key = cacheKey(*description);
  if (std::optional<CacheEntry> entry = Cache(common.cacheDir).load(key);
      entry && entry->outputs.size() == run->outputs.size()) {
    BakeSession session(tool, common, diagnostics);
    return session.finishFromCache(*run, *entry);
  }
  common.cacheStore = {key, run->inputs, run->outputs};
  return bake();
}

}  // namespace bake
