// One bake, start to finish, with the conventions every tool shares: inputs are recorded (for the
// report's hashes and the depfile), outputs are staged in temporary files and committed together
// only when the whole bake succeeded, then the depfile and the --report are written. A failed bake
// leaves no output and every earlier output untouched; its report still says what went wrong.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "core/cli.h"
#include "core/diagnostics.h"
#include "core/report.h"

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

 private:
  CommonOptions options_;
  Diagnostics& diagnostics_;
  Report report_;
  OutputSet outputs_;
  std::vector<std::filesystem::path> inputs_;
  std::vector<std::filesystem::path> written_;
};

}  // namespace bake
