// Command-line plumbing shared by every tool: the common option group (--quiet, --report,
// --depfile, --threads, --print-inputs, --cache-dir, --budget), --version, and one fatal path that maps CLI11's own errors
// onto ExitCode::Usage and a failed Status onto its exit code with a "TOOL: error: ..." line.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/diagnostics.h"
#include "core/status.h"

namespace bake {

const char* toolkitVersion();

struct CommonOptions {
  bool quiet = false;
  std::string reportPath;
  std::string depfilePath;
  unsigned threads = 0;  // 0 = all hardware threads
  bool printInputs = false;
  std::string cacheDir;  // --cache-dir: content-addressed cache of outputs (core/cache.h)

  // Set by runCachedBake (core/session.h) when the cache missed: the bake's session stores what it
  // commits under `key`, provided it read no file but `inputs` and wrote exactly `outputs`.
  struct CacheStore {
    std::string key;
    std::vector<std::string> inputs;
    std::vector<std::string> outputs;
  } cacheStore;
};

// Which of the common options a tool offers.
struct CommonOptionSet {
  bool version = true;  // false for subcommands: --version belongs to the main command
  bool report = true;
  bool depfile = true;
  bool threads = true;
  bool printInputs = true;
  bool cacheDir = false;  // bakers that run through runCachedBake (core/session.h) turn it on
};

void addCommonOptions(CLI::App& app, CommonOptions& options, CommonOptionSet which = {});

// Parses argv with `app` and then runs `body`. Help and version exit 0; CLI11 parse errors print
// "TOOL: error: ..." and exit 1; a failed Status from body prints its message and exits with its code;
// an escaped exception is an internal error (exit 4).
int runTool(CLI::App& app, Diagnostics& diagnostics, int argc, char** argv,
            const std::function<Status()>& body);

}  // namespace bake
