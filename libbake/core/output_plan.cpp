#include "core/output_plan.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <mutex>
#include <optional>

#include "bake/core/atomic_file.h"
#include "core/build_syntax.h"

namespace bake {
namespace fs = std::filesystem;

namespace {

// What decides whether two paths are one file: device and inode when it exists (following links),
// else its name made absolute with every existing folder resolved.
struct FileIdentity {
  bool exists = false;
  dev_t device = 0;
  ino_t inode = 0;
  std::string name;

  bool operator==(const FileIdentity& other) const {
    if (exists != other.exists) return false;
    return exists ? device == other.device && inode == other.inode : name == other.name;
  }
};

FileIdentity identityOf(const fs::path& path) {
  FileIdentity id;
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0) {
    id.exists = true;
    id.device = info.st_dev;
    id.inode = info.st_ino;
    return id;
  }
  std::error_code ec;
  fs::path resolved = fs::weakly_canonical(fs::absolute(path, ec), ec);
  id.name = (ec ? path : resolved).lexically_normal().string();
  return id;
}

struct PlanState {
  std::mutex mutex;
  bool planned = false;
  std::vector<FileIdentity> outputs;
};

PlanState& planState() {
  static PlanState state;
  return state;
}

// Every output named with the option that gave it, for messages.
struct NamedOutput {
  fs::path path;
  std::string option;
};

std::vector<NamedOutput> outputsOf(const RunFiles& files, const CommonOptions& common) {
  std::vector<NamedOutput> outputs;
  for (const std::string& output : files.outputs) outputs.push_back({output, "output"});
  if (!common.reportPath.empty()) outputs.push_back({common.reportPath, "--report"});
  if (!common.depfilePath.empty()) outputs.push_back({common.depfilePath, "--depfile"});
  return outputs;
}

Status checkDepfilePaths(const RunFiles& files, const std::vector<NamedOutput>& outputs) {
  for (const NamedOutput& output : outputs) {
    if (Result<std::string> escaped = makeEscapedPath(fs::absolute(output.path).string()); !escaped.isOk()) {
      return Status(escaped.status()).inFile(output.path.string());
    }
  }
  for (const std::string& input : files.inputs) {
    if (Result<std::string> escaped = makeEscapedPath(fs::absolute(input).string()); !escaped.isOk()) {
      return Status(escaped.status()).inFile(input);
    }
  }
  return {};
}

}  // namespace

Status checkReplaceable(const fs::path& target) {
  struct stat info {};
  if (::stat(target.c_str(), &info) != 0) return {};
  if (S_ISREG(info.st_mode)) return {};
  if (S_ISDIR(info.st_mode)) return ioError("is a directory, not a file", {target.string(), ""});
  const char* kind = S_ISCHR(info.st_mode)    ? "a character device"
                     : S_ISBLK(info.st_mode)  ? "a block device"
                     : S_ISFIFO(info.st_mode) ? "a FIFO"
                     : S_ISSOCK(info.st_mode) ? "a socket"
                                              : "a special file";
  return ioError(std::string("is ") + kind + ", not a regular file; outputs are written to a temporary file and "
                     "renamed over the target, which would replace it: name a regular file",
                 {target.string(), ""});
}

Status checkDistinctFiles(const std::vector<fs::path>& inputs, const std::vector<fs::path>& outputs) {
  std::vector<FileIdentity> seen;
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const FileIdentity id = identityOf(outputs[i]);
    for (std::size_t j = 0; j < seen.size(); ++j) {
      if (seen[j] == id) {
        return usageError(outputs[i].string() + ": named twice as an output (also as " + outputs[j].string() +
                          "); every output needs its own file");
      }
    }
    seen.push_back(id);
  }
  for (const fs::path& input : inputs) {
    const FileIdentity id = identityOf(input);
    for (std::size_t j = 0; j < seen.size(); ++j) {
      if (seen[j] == id) {
        return usageError(outputs[j].string() + ": is also an input of this run (" + input.string() +
                          "); writing it would destroy the input: name another output file");
      }
    }
  }
  return {};
}

Status planOutputs(const RunFiles& files, const CommonOptions& common) {
  const std::vector<NamedOutput> outputs = outputsOf(files, common);
  for (const NamedOutput& output : outputs) {
    if (output.path.empty()) return usageError("the " + output.option + " file name is empty");
  }
  std::vector<fs::path> inputPaths(files.inputs.begin(), files.inputs.end());
  std::vector<fs::path> outputPaths;
  for (const NamedOutput& output : outputs) outputPaths.push_back(output.path);
  BAKE_RETURN_IF_ERROR(checkDistinctFiles(inputPaths, outputPaths));
  for (const NamedOutput& output : outputs) BAKE_RETURN_IF_ERROR(checkReplaceable(output.path));
  if (!common.depfilePath.empty()) BAKE_RETURN_IF_ERROR(checkDepfilePaths(files, outputs));
  // Before any work: an output folder that is missing, read-only or full fails now, not after the bake.
  for (const NamedOutput& output : outputs) BAKE_RETURN_IF_ERROR(checkWritable(output.path));

  PlanState& state = planState();
  std::lock_guard<std::mutex> lock(state.mutex);
  state.planned = true;
  state.outputs.clear();
  for (const NamedOutput& output : outputs) state.outputs.push_back(identityOf(output.path));
  return {};
}

bool reportIsSafe(const RunFiles& files, const CommonOptions& common) {
  if (common.reportPath.empty()) return false;
  std::vector<fs::path> others(files.inputs.begin(), files.inputs.end());
  others.insert(others.end(), files.outputs.begin(), files.outputs.end());
  if (!common.depfilePath.empty()) others.push_back(common.depfilePath);
  return checkDistinctFiles(others, {common.reportPath}).isOk() && checkReplaceable(common.reportPath).isOk() &&
         checkWritable(common.reportPath).isOk();
}

bool outputsPlanned() {
  PlanState& state = planState();
  std::lock_guard<std::mutex> lock(state.mutex);
  return state.planned;
}

bool isPlannedOutput(const fs::path& target) {
  const FileIdentity id = identityOf(target);
  PlanState& state = planState();
  std::lock_guard<std::mutex> lock(state.mutex);
  for (const FileIdentity& output : state.outputs) {
    if (output == id) return true;
  }
  return false;
}

void forgetOutputPlan() {
  PlanState& state = planState();
  std::lock_guard<std::mutex> lock(state.mutex);
  state.planned = false;
  state.outputs.clear();
}

std::string temporaryPatternFor(const fs::path& target, const std::string& suffix) {
  constexpr std::size_t kMaxName = 255;
  const std::string tail = ".tmp.XXXXXX" + suffix;
  std::string name = target.filename().string();
  const std::size_t room = kMaxName - 1 - std::min(tail.size(), kMaxName - 1);  // 1 for the leading '.'
  if (name.size() > room) name.resize(room);
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  return (dir / ("." + name + tail)).string();
}

}  // namespace bake
