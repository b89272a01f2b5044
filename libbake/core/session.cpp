#include "core/session.h"

#include "core/depfile.h"

namespace bake {

BakeSession::BakeSession(const std::string& tool, const CommonOptions& options, Diagnostics& diagnostics)
    : options_(options), diagnostics_(diagnostics), report_(tool, toolkitVersion()) {}

void BakeSession::addInput(const std::filesystem::path& path) { inputs_.push_back(path); }

Status BakeSession::stageOutput(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
  return outputs_.stage(path, bytes);
}

Status BakeSession::finish(Status outcome) {
  if (outcome.isOk()) outcome = outputs_.commit();
  if (!outcome.isOk()) outputs_.discard();
  std::vector<std::filesystem::path> outputs = outputs_.targets();
  outputs.insert(outputs.end(), written_.begin(), written_.end());
  if (outcome.isOk() && !options_.depfilePath.empty()) {
    outcome = writeDepfile(options_.depfilePath, outputs, inputs_);
  }
  if (!options_.reportPath.empty()) {
    for (const auto& input : inputs_) {
      if (const Status s = report_.addInput(input); !s.isOk() && outcome.isOk()) outcome = s;
    }
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

}  // namespace bake
