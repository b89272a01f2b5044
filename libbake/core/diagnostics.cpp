#include "core/diagnostics.h"

namespace bake {

std::string formatError(const std::string& tool, const Status& status) {
  return tool + ": error: " + status.describe();
}

void Diagnostics::print(const char* severity, const std::string& message) {
  std::fprintf(stream_, "%s: %s: %s\n", tool_.c_str(), severity, message.c_str());
  std::fflush(stream_);
}

void Diagnostics::error(const Status& status) { print("error", status.describe()); }

void Diagnostics::error(const std::string& message) { print("error", message); }

void Diagnostics::warning(const std::string& kind, const std::string& message) {
  WarningRecord& record = warnings_[kind];
  if (record.count++ == 0) record.message = message;
  if (!quiet_) print("warning", message);
}

void Diagnostics::info(const std::string& message) {
  if (!quiet_) print("info", message);
}

}  // namespace bake
