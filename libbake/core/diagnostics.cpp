#include "bake/core/diagnostics.h"

namespace bake {

std::string formatError(const std::string& tool, const Status& status) {
  return tool + ": error: " + status.describe();
}

namespace {

// The whole message: a NUL or another control byte from a file (a key, a name) is shown as \xHH
// instead of cutting the message short or moving the cursor; newlines and tabs stay.
std::string printable(const std::string& message) {
  std::string out;
  out.reserve(message.size());
  for (const char c : message) {
    const unsigned char byte = static_cast<unsigned char>(c);
    if ((byte < 0x20 && c != '\n' && c != '\t') || byte == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      out += escaped;
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

void Diagnostics::print(const char* severity, const std::string& message) {
  const std::string line = printable(message);
  std::fprintf(stream_, "%s: %s: %s\n", tool_.c_str(), severity, line.c_str());
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
