#include "core/cli.h"

#include <exception>
#include <new>

#include "core/limits.h"
#include "core/version.h"

namespace bake {

const char* toolkitVersion() { return kToolkitVersion; }

void addCommonOptions(CLI::App& app, CommonOptions& options, CommonOptionSet which) {
  if (which.version) app.set_version_flag("--version", std::string(app.get_name()) + " " + kToolkitVersion);
  app.add_flag("-q,--quiet", options.quiet, "Print nothing but errors");
  if (which.report) {
    app.add_option("--report", options.reportPath, "Write a JSON report (formats/report.md) to this file");
  }
  if (which.depfile) {
    app.add_option("--depfile", options.depfilePath, "Write a Make-syntax dependency file");
  }
  if (which.threads) {
    app.add_option("-j,--threads", options.threads, "Worker threads (0 = all cores); never changes the output")
        ->check(CLI::Range(0u, 1024u));
  }
  if (which.printInputs) {
    app.add_flag("--print-inputs", options.printInputs,
                 "List every file the run would read, one per line, and exit");
  }
  // Budgets are a process-wide policy (core/limits.h): applied as the option is parsed.
  app.add_option_function<std::vector<std::string>>(
         "--budget",
         [](const std::vector<std::string>& settings) {
           for (const std::string& setting : settings) {
             const Status status = applyBudgetSetting(setting);
             if (!status.isOk()) throw CLI::ValidationError(status.message());
           }
         },
         "Raise or lower a budget, NAME=N (repeatable); defaults: " + describeBudgets())
      ->type_name("NAME=N")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  if (which.cacheDir) {
    app.add_option("--cache-dir", options.cacheDir,
                   "Content-addressed cache of outputs: reuse a verified earlier bake of the same inputs and options");
  }
}

int runTool(CLI::App& app, Diagnostics& diagnostics, int argc, char** argv,
            const std::function<Status()>& body) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    diagnostics.error(std::string(e.what()) + " (run with --help for usage)");
    return int(ExitCode::Usage);
  }
  try {
    const Status status = body();
    if (!status.isOk()) diagnostics.error(status);
    return int(status.code());
  } catch (const std::bad_alloc&) {
    diagnostics.error("out of memory");
  } catch (const std::exception& e) {
    diagnostics.error(std::string("internal error: ") + e.what());
  }
  return int(ExitCode::Internal);
}

}  // namespace bake
