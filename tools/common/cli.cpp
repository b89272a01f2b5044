#include "common/cli.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <set>

#include "bake/core/input_file.h"
#include "bake/core/limits.h"
#include "bake/core/version.h"

namespace bake {

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
  app.add_flag_callback("--allow-outside-uris", [] { setOutsideUrisAllowed(true); },
                        "Let a .gltf read buffers outside its own folder (absolute paths, ../); refused otherwise");
  if (which.cacheDir) {
    app.add_option("--cache-dir", options.cacheDir,
                   "Content-addressed cache of outputs: reuse a verified earlier bake of the same inputs and options");
  }
}

namespace {

// One range for every numeric option of every tool, checked once after parsing, before a value can
// wrap (4294967296 into a 32-bit index), turn into inf or NaN, or reach a package as a number no
// reader accepts. Tools check tighter ranges of their own on top.
constexpr double kLargestMagnitude = 1e9;
constexpr double kSmallestMagnitude = 1e-9;
constexpr long long kLargestInteger = 2147483647LL;
constexpr unsigned long long kLargestUnsigned = 4294967295ULL;

std::string optionName(const CLI::Option& option) {
  const std::string name = option.get_name(false, true);
  return name.empty() ? option.get_name() : name;
}

Status outOfRange(const CLI::Option& option, const std::string& value, const std::string& range) {
  return usageError(optionName(option) + " " + value + ": " + range);
}

Status checkNumber(const CLI::Option& option, const std::string& type, const std::string& value) {
  const char* text = value.c_str();
  char* end = nullptr;
  errno = 0;
  if (type == "FLOAT") {
    const double number = std::strtod(text, &end);
    if (end == text || *end != '\0') return outOfRange(option, value, "not a number");
    char limits[160];
    std::snprintf(limits, sizeof limits, "out of range: give a finite number of magnitude %g to %g, or 0",
                  kSmallestMagnitude, kLargestMagnitude);
    const double magnitude = std::fabs(number);
    if (!std::isfinite(number) || magnitude > kLargestMagnitude || (number != 0 && magnitude < kSmallestMagnitude)) {
      return outOfRange(option, value, limits);
    }
    return {};
  }
  if (type == "UINT") {
    const unsigned long long number = std::strtoull(text, &end, 10);
    if (value.find('-') != std::string::npos || end == text || *end != '\0' || errno == ERANGE ||
        number > kLargestUnsigned) {
      return outOfRange(option, value, "out of range: give a whole number from 0 to " + std::to_string(kLargestUnsigned));
    }
    return {};
  }
  const long long number = std::strtoll(text, &end, 10);
  if (end == text || *end != '\0' || errno == ERANGE || number > kLargestInteger || number < -kLargestInteger) {
    return outOfRange(option, value,
                      "out of range: give a whole number from " + std::to_string(-kLargestInteger) + " to " +
                          std::to_string(kLargestInteger));
  }
  return {};
}

// Options that name files: an empty value names no file.
bool namesAFile(const CLI::Option& option) {
  static const std::set<std::string> kFileOptions{"output", "report", "depfile", "threshold", "package", "views",
                                                  "sources", "apply-to", "cache-dir", "height-map", "out-dir"};
  for (const std::string& name : option.get_lnames()) {
    if (kFileOptions.count(name)) return true;
  }
  return false;
}

Status checkOptionValues(const CLI::App& app) {
  for (const CLI::Option* option : app.get_options()) {
    if (option->count() == 0) continue;
    const std::string type = option->get_type_name();
    const bool numeric = type == "INT" || type == "UINT" || type == "FLOAT";
    for (const std::string& value : option->results()) {
      if (numeric) BAKE_RETURN_IF_ERROR(checkNumber(*option, type, value));
      if (value.empty() && namesAFile(*option)) return usageError(optionName(*option) + ": the file name is empty");
    }
  }
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    if (!sub->get_name().empty() && sub->parsed()) BAKE_RETURN_IF_ERROR(checkOptionValues(*sub));
  }
  return {};
}

bool isNumeric(const CLI::Option& option) {
  const std::string type = option.get_type_name();
  const std::string base = type.substr(0, type.find(':'));
  return base == "FLOAT" || base == "INT" || base == "UINT" || base == "NUMBER";
}

void collectGiven(const CLI::App& app, GivenOptions& out) {
  for (const CLI::Option* option : app.get_options()) {
    if (option->count() == 0) continue;
    out.push_back({option->get_single_name(), option->get_lnames(), option->results(), isNumeric(*option)});
  }
  // Option groups are nameless subcommands.
  for (const CLI::App* group : app.get_subcommands([](const CLI::App* sub) { return sub->get_name().empty(); })) {
    collectGiven(*group, out);
  }
}

}  // namespace

GivenOptions givenOptions(const CLI::App& app) {
  GivenOptions out;
  collectGiven(app, out);
  return out;
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
  if (const Status values = checkOptionValues(app); !values.isOk()) {
    diagnostics.error(values.message() + " (run with --help for usage)");
    return int(values.code());
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
