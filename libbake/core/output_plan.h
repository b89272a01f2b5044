// Output planning: every file a run will write is resolved before any work starts, so that a bake
// fails in a second rather than after minutes of work, and never destroys what it was given.
// planOutputs takes the run's declared files (the same RunFiles that --print-inputs and the cache
// use) plus the common --report and --depfile, and refuses, before anything is read or baked:
// - an empty output name (usage);
// - an output that is also an input, or two outputs that are the same file: compared by device and
//   inode when the file exists (hard links, symbolic links, ./x and d/../x all match), by their
//   canonical name when it does not (usage);
// - an output that exists and is not a regular file (/dev/null, a FIFO, a directory): outputs are
//   replaced by rename, which must never put a file where a device node was (I/O, exit 2);
// - an output whose folder cannot take the temporary file an atomic write needs (I/O);
// - with --depfile, a path Make's syntax cannot hold (core/build_syntax.h; usage).
// Every tool plans before its work (the bakers through runCachedBake, core/session.h; bakeplay and
// bakepipe explicitly). The plan is process-wide (one run per process): once made, BakeSession stages
// only planned outputs. Whether planned or not (a library caller), BakeSession checks again at commit,
// against every input the run actually read (a .gltf's buffers, a style's image), that no output
// replaces one of them, and the atomic writer never renames over anything but a regular file.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "bake/core/cache.h"
#include "bake/core/options.h"
#include "bake/core/status.h"

namespace bake {

// Checks the run's outputs as above and records them as the run's plan.
Status planOutputs(const RunFiles& files, const CommonOptions& common);

// Whether --report names a file a failure report may be written to although the plan failed: a
// regular or absent file in a writable folder, none of the run's inputs or other outputs.
bool reportIsSafe(const RunFiles& files, const CommonOptions& common);

// Whether an output plan was made in this process, and whether `target` is one of its outputs.
bool outputsPlanned();
bool isPlannedOutput(const std::filesystem::path& target);
// Drops the plan (for a process that runs several bakes, such as a test).
void forgetOutputPlan();
// Forgets the plan when the operation that made it ends, so a later operation in the same process (a
// library user's second bake, a test) starts unplanned.
class OutputPlanScope {
 public:
  OutputPlanScope() = default;
  OutputPlanScope(const OutputPlanScope&) = delete;
  OutputPlanScope& operator=(const OutputPlanScope&) = delete;
  ~OutputPlanScope() { forgetOutputPlan(); }
};

// Usage error when one of `outputs` is the same file as one of `inputs`, or as another output.
Status checkDistinctFiles(const std::vector<std::filesystem::path>& inputs,
                          const std::vector<std::filesystem::path>& outputs);

// I/O error unless `target` does not exist or is a regular file (following symbolic links).
Status checkReplaceable(const std::filesystem::path& target);

// The pattern (for mkstemps) of a hidden temporary beside `target`: DIR/.NAME.tmp.XXXXXX + suffix, with
// NAME shortened so the file name stays within the 255 bytes a name may have.
std::string temporaryPatternFor(const std::filesystem::path& target, const std::string& suffix = "");

}  // namespace bake
