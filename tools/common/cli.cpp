#include "common/cli.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <new>
#include <regex>
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
  static const std::set<std::string> kFileOptions{"output", "report", "depfile", "threshold", "package", "views", "base-color", "golden", "screenshot",
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

bool namesADirectory(const CLI::Option& option) {
  static const std::set<std::string> kDirectoryOptions{"views", "cache-dir", "out-dir", "tools"};
  for (const std::string& name : option.get_lnames()) {
    if (kDirectoryOptions.count(name)) return true;
  }
  return false;
}

// ---- Help and errors in our words -------------------------------------------------------------
// CLI11 shows its own type names ("ENUM:value in {exact->0,fmm->2} OR {0,2}", "UINT:UINT in [0 -
// 1024]", "TEXT"), defaults as std::to_string wrote them ("2.500000") and messages such as "Check
// dijkstra value in {...} FAILED". The help below says what to type (exact|fmm, N (0 to 1024),
// FILE, default 2.5) and the errors say what was wrong in the same words.

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    items.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return items;
}

// The names of an enumeration or a set of allowed values, from "...{a->0,b->1}..." or "...{a,b}...".
std::vector<std::string> choicesIn(const std::string& text) {
  const std::size_t open = text.find('{'), close = text.find('}', open);
  if (open == std::string::npos || close == std::string::npos) return {};
  std::vector<std::string> names;
  for (const std::string& item : splitList(text.substr(open + 1, close - open - 1))) {
    names.push_back(item.substr(0, item.find("->")));
  }
  return names;
}

std::string joined(const std::vector<std::string>& items, const std::string& separator) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

// A number as users write it: "2.5", not "2.500000".
std::string plainNumber(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !std::isfinite(value)) return text;
  char buffer[64];
  const auto written = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, written.ptr);
}

// " (0 to 1024)" from CLI11's range and sign validators in the type name.
std::string rangeIn(const std::string& type) {
  const std::size_t open = type.find('['), close = type.find(']', open);
  if (open != std::string::npos && close != std::string::npos) {
    std::string range = type.substr(open + 1, close - open - 1);
    if (const std::size_t dash = range.find(" - "); dash != std::string::npos) range.replace(dash, 3, " to ");
    return " (" + range + ")";
  }
  if (type.find("NONNEGATIVE") != std::string::npos) return " (0 or more)";
  if (type.find("POSITIVE") != std::string::npos) return " (more than 0)";
  return "";
}

std::string valueLabel(const CLI::Option& option) {
  const std::string type = option.get_type_name();
  if (type.find('{') != std::string::npos) return joined(choicesIn(type), "|");
  const std::string base = type.substr(0, type.find(':'));
  if (base == "INT" || base == "UINT") return "N" + rangeIn(type);
  if (base == "FLOAT" || base == "NUMBER") return "X" + rangeIn(type);
  if (base == "TEXT") {
    if (namesADirectory(option)) return "DIR";
    return option.get_positional() || namesAFile(option) ? "FILE" : "VALUE";
  }
  return type;  // a name the tool gave: "X,Y,Z", "NAME=N", ...
}

class HelpFormatter : public CLI::Formatter {
 public:
  // A flag declared "--no-shadows{false}" is shown as --no-shadows.
  std::string make_option_name(const CLI::Option* option, bool positional) const override {
    std::string name = CLI::Formatter::make_option_name(option, positional);
    for (std::size_t open; (open = name.find('{')) != std::string::npos;) {
      const std::size_t close = name.find('}', open);
      if (close == std::string::npos) break;
      name.erase(open, close - open + 1);
    }
    return name;
  }

  std::string make_option_opts(const CLI::Option* option) const override {
    std::string out;
    if (option->get_type_size() != 0) {
      const std::string label = valueLabel(*option);
      if (!label.empty()) out += " " + label;
      if (option->get_expected_max() == CLI::detail::expected_max_vector_size) out += " ...";
      if (!option->get_default_str().empty()) out += " (default: " + plainNumber(option->get_default_str()) + ")";
      if (option->get_required()) out += " (required)";
    }
    if (!option->get_needs().empty()) {
      std::vector<std::string> names;
      for (const CLI::Option* other : option->get_needs()) names.push_back(other->get_name());
      out += " (needs " + joined(names, ", ") + ")";
    }
    if (!option->get_excludes().empty()) {
      std::vector<std::string> names;
      for (const CLI::Option* other : option->get_excludes()) names.push_back(other->get_name());
      out += " (not with " + joined(names, ", ") + ")";
    }
    return out;
  }
};

void useHelpFormatter(CLI::App& app, const std::shared_ptr<CLI::Formatter>& formatter) {
  app.formatter(formatter);
  for (CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) useHelpFormatter(*sub, formatter);
}

// A parse error in our words (see above); messages already in words pass unchanged.
std::string inOurWords(const std::string& message) {
  std::smatch m;
  // "--method: Check dijkstra value in {exact->0,...} OR {0,...} FAILED" (an enumeration)
  static const std::regex kEnumeration(R"(^(.*): Check (.*) value in (\{[^}]*\}).* FAILED$)");
  if (std::regex_match(message, m, kEnumeration)) {
    return m[1].str() + ": '" + m[2].str() + "' is not one of " + joined(choicesIn(m[3].str()), ", ");
  }
  // "--orientation: sideways not in {toward-light,across-light}" (a set of values)
  static const std::regex kMember(R"(^(.*): (.*) not in (\{[^}]*\})$)");
  if (std::regex_match(message, m, kMember)) {
    return m[1].str() + ": '" + m[2].str() + "' is not one of " + joined(choicesIn(m[3].str()), ", ");
  }
  // "--skip-levels: Number less then 0: (-1)" (CLI11's sign validators)
  static const std::regex kSign(R"(^(.*): Number less (?:then|than) 0: \((.*)\)$)");
  if (std::regex_match(message, m, kSign)) return m[1].str() + ": " + m[2].str() + " is below 0";
  // "--threads: Value 2000 not in range 0 to 1024" (CLI11's Range, NonNegativeNumber, ...)
  static const std::regex kRange(R"(^(.*): Value (.*) not in range \[?(.*?)(?: - | to )(.*?)\]?$)");
  if (std::regex_match(message, m, kRange)) {
    const std::string low = plainNumber(m[3].str()), high = m[4].str();
    if (std::strtod(high.c_str(), nullptr) > 1e300) return m[1].str() + ": " + m[2].str() + " is below " + low;
    return m[1].str() + ": " + m[2].str() + " is outside " + low + " to " + plainNumber(high);
  }
  // "Could not convert: --resolution = abc"
  static const std::regex kConversion(R"(^Could not convert: (.*) = (.*)$)");
  if (std::regex_match(message, m, kConversion)) return m[1].str() + ": '" + m[2].str() + "' is not a number";
  return message;
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
  useHelpFormatter(app, std::make_shared<HelpFormatter>());
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    diagnostics.error(inOurWords(e.what()) + " (run with --help for usage)");
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
