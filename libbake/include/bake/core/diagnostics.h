// Messages to the user: every line goes to stderr as "TOOL: error: ..." or "TOOL: warning: ...".
// Warnings are also counted by kind so the --report can list them; --quiet silences all but errors.
#pragma once

#include <cstdio>
#include <map>
#include <string>

#include "bake/core/status.h"

namespace bake {

class Diagnostics {
 public:
  explicit Diagnostics(std::string tool, bool quiet = false, std::FILE* stream = stderr)
      : tool_(std::move(tool)), quiet_(quiet), stream_(stream) {}

  const std::string& tool() const { return tool_; }
  bool quiet() const { return quiet_; }
  void setQuiet(bool quiet) { quiet_ = quiet; }

  void error(const Status& status);
  void error(const std::string& message);
  // `kind` is a short stable key ("welded-vertices") used to count repeats in the report.
  void warning(const std::string& kind, const std::string& message);
  void info(const std::string& message);

  // Warnings seen so far, by kind, with their first message and count.
  struct WarningRecord {
    std::string message;
    int count = 0;
  };
  const std::map<std::string, WarningRecord>& warnings() const { return warnings_; }

 private:
  void print(const char* severity, const std::string& message);

  std::string tool_;
  bool quiet_ = false;
  std::FILE* stream_ = stderr;
  std::map<std::string, WarningRecord> warnings_;
};

// "TOOL: error: FILE: ELEMENT: message"
std::string formatError(const std::string& tool, const Status& status);

}  // namespace bake
