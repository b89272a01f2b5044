// Atomic outputs: bytes go to a temporary file beside the target, are flushed to disk, and only then
// renamed over the target. After any failure no partial output exists and an earlier output is
// untouched. A tool with several outputs stages them all and commits them together at the end.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "bake/core/status.h"

namespace bake {

Status writeFileAtomic(const std::filesystem::path& target, std::span<const std::uint8_t> bytes);
Status writeFileAtomic(const std::filesystem::path& target, const std::string& text);

Result<std::vector<std::uint8_t>> readFileBytes(const std::filesystem::path& path);

// Whether writeFileAtomic(target, ...) could create its temporary beside `target` and replace it:
// the same errors, found before anything else is committed. Leaves nothing behind.
Status checkWritable(const std::filesystem::path& target);

// Outputs of one bake: staged in temporary files as they are produced, renamed into place by
// commit(); the destructor removes whatever was not committed.
class OutputSet {
 public:
  OutputSet() = default;
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  Status stage(const std::filesystem::path& target, std::span<const std::uint8_t> bytes);
  Status stage(const std::filesystem::path& target, const std::string& text);
  Status commit();
  void discard();

  const std::vector<std::filesystem::path>& targets() const { return targets_; }

 private:
  std::vector<std::filesystem::path> targets_;
  std::vector<std::filesystem::path> temporaries_;
};

}  // namespace bake
