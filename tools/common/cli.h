// Command-line plumbing shared by every tool, the one layer that knows the parser (CLI11): the common
// option group (--quiet, --report, --depfile, --threads, --print-inputs, --cache-dir, --budget),
// --version, one range check of every numeric option, and one fatal path that maps CLI11's own errors
// onto ExitCode::Usage and a failed Status onto its exit code with a "TOOL: error: ..." line. The
// library sees only what it needs of a command line (core/options.h).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bake/core/diagnostics.h"
#include "bake/core/options.h"
#include "bake/core/session.h"
#include "bake/core/status.h"

namespace bake {

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

// The options given on the parsed command line (option groups included, subcommands not), for the
// cache key.
GivenOptions givenOptions(const CLI::App& app);

// runCachedBake (core/session.h) with the options given to `app`.
inline Status runCachedBake(const std::string& tool, const CLI::App& app, CommonOptions& common,
                            Diagnostics& diagnostics, const std::function<Result<RunFiles>()>& files,
                            const std::function<Status()>& bake) {
  return runCachedBake(tool, givenOptions(app), common, diagnostics, files, bake);
}

// A baker's whole run after its options are declared: parse (runTool), `prepare` (what the main
// still turns from text into settings), then runCachedBake with the module's inputs() and run(),
// found by argument-dependent lookup in the settings' namespace. Every baker offers the same
// Settings / check / inputs / run (check is made by run).
template <class Settings>
int runBaker(const char* tool, CLI::App& app, Settings& settings, Diagnostics& diagnostics, int argc, char** argv,
             const std::function<Status()>& prepare = {}) {
  return runTool(app, diagnostics, argc, argv, [&]() -> Status {
    diagnostics.setQuiet(settings.common.quiet);
    if (prepare) BAKE_RETURN_IF_ERROR(prepare());
    return runCachedBake(
        tool, app, settings.common, diagnostics, [&] { return inputs(settings); },
        [&] { return run(settings, diagnostics); });
  });
}

}  // namespace bake
