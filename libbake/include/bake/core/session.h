// One bake, start to finish, with the conventions every tool shares: inputs are recorded (for the
// report's hashes and the depfile), outputs are staged in temporary files and committed together
// only when the whole bake succeeded, then the depfile and the --report are written. A failed bake
// leaves no output and every earlier output untouched; its report still says what went wrong.
// With --cache-dir (core/cache.h), runCachedBake looks the run up before any work: a hit copies the cached
// outputs through the same session (atomic commit, depfile, report); a miss bakes, and the session
// stores what it committed.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "bake/core/atomic_file.h"
#include "bake/core/cache.h"
#include "bake/core/diagnostics.h"
#include "bake/core/options.h"
#include "bake/core/report.h"

namespace bake {

class BakeSession {
 public:
  BakeSession(const std::string& tool, const CommonOptions& options, Diagnostics& diagnostics);

  Report& report() { return report_; }
  Diagnostics& diagnostics() { return diagnostics_; }
  unsigned threads() const { return options_.threads; }

  void addInput(const std::filesystem::path& path);
  Status stageOutput(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);
  // An output another writer has already written atomically (e.g. an image through OpenImageIO);
  // call it last, since it cannot be rolled back.
  void recordWrittenOutput(const std::filesystem::path& path) { written_.push_back(path); }

  // Commits the outputs when `outcome` is ok, then writes the depfile (on success) and the report
  // (always, when asked for). Returns the first failure.
  Status finish(Status outcome);

  // A cache hit: records the run's inputs, stages the entry's outputs at the run's output paths,
  // gives the report the options, statistics and accuracy of the bake that made the entry and
  // "cache": "hit", and finishes.
  Status finishFromCache(const RunFiles& files, const CacheEntry& entry);

 private:
  void storeInCache(const std::vector<std::filesystem::path>& committed);

  bool cacheHit_ = false;
  CommonOptions options_;
  Diagnostics& diagnostics_;
  Report report_;
  OutputSet outputs_;
  std::vector<std::filesystem::path> inputs_;
  std::vector<std::filesystem::path> written_;
};

// One bake with the conventions around it. `files` is the tool's one "files of this run" function:
// --print-inputs prints its inputs and returns; with --cache-dir, a verified entry for the run's key
// (tool, version, normalised `given` options, input contents) becomes the outputs without any work;
// otherwise `bake` runs (a session made from `common` then stores what it commits). Without either
// option, `files` is not called.
Status runCachedBake(const std::string& tool, const GivenOptions& given, CommonOptions& common, Diagnostics& diagnostics,
               const std::function<Result<RunFiles>()>& files, const std::function<Status()>& bake);

}  // namespace bake
