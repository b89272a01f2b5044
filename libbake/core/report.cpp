#include "bake/core/report.h"

#include <bake_formats/report.h>

#include "bake/core/atomic_file.h"
#include "bake/core/input_file.h"
#include "core/hash.h"

namespace bake {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {
Result<json> describeFile(const fs::path& path) {
  // An input read through readFileBytes (a pipe among them) is described from what was read, never
  // opened again.
  if (const std::optional<ReadInput> read = readInputRecord(path)) {
    return json{{"path", path.string()}, {"bytes", read->bytes}, {"hash", read->hash}};
  }
  std::error_code ec;
  const auto bytes = fs::file_size(path, ec);
  if (ec) return ioError("cannot stat: " + ec.message(), {path.string(), ""});
  BAKE_ASSIGN_OR_RETURN(std::string hash, hashFile(path));
  return json{{"path", path.string()}, {"bytes", bytes}, {"hash", hash}};
}
}  // namespace

Report::Report(std::string tool, std::string toolVersion)
    : tool_(std::move(tool)), toolVersion_(std::move(toolVersion)) {}

Status Report::addInput(const fs::path& path) {
  BAKE_ASSIGN_OR_RETURN(json entry, describeFile(path));
  inputs_.push_back(std::move(entry));
  return {};
}

Status Report::addOutput(const fs::path& path) {
  BAKE_ASSIGN_OR_RETURN(json entry, describeFile(path));
  outputs_.push_back(std::move(entry));
  return {};
}

void Report::addStage(const std::string& name, double seconds) {
  stages_.push_back({{"name", name}, {"seconds", seconds}});
}

void Report::addAccuracy(const std::string& quantity, const std::string& reference, json metrics) {
  accuracy_.push_back({{"quantity", quantity}, {"reference", reference}, {"metrics", std::move(metrics)}});
}

void Report::takeWarnings(const Diagnostics& diagnostics) {
  warnings_ = json::array();
  for (const auto& [kind, record] : diagnostics.warnings()) {
    warnings_.push_back({{"kind", kind}, {"message", record.message}, {"count", record.count}});
  }
}

json Report::toJson() const {
  double total = 0.0;
  for (const json& stage : stages_) total += stage["seconds"].get<double>();
  json status = {{"exitCode", int(outcome_.code())}, {"name", exitCodeName(outcome_.code())}};
  if (!outcome_.isOk()) status["message"] = outcome_.describe();
  return json{{"schema", format::report::kSchemaId},
              {"reportVersion", format::report::kVersion},
              {"tool", tool_},
              {"toolVersion", toolVersion_},
              {"status", status},
              {"inputs", inputs_},
              {"options", options_},
              {"outputs", outputs_},
              {"stages", stages_},
              {"totalSeconds", total},
              {"accuracy", accuracy_},
              {"warnings", warnings_},
              {"statistics", statistics_}};
}

Status Report::write(const fs::path& path) const {
  // Paths, options and messages may hold bytes that are not UTF-8 (a file name is any bytes); they
  // become U+FFFD so that the report stays JSON instead of the serializer throwing.
  return writeFileAtomic(path, toJson().dump(2, ' ', false, json::error_handler_t::replace) + "\n");
}

StageTimer::StageTimer(Report* report, std::string name)
    : report_(report), name_(std::move(name)), start_(std::chrono::steady_clock::now()) {}

double StageTimer::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void StageTimer::stop() {
  if (report_ && !stopped_) report_->addStage(name_, seconds());
  stopped_ = true;
}

StageTimer::~StageTimer() { stop(); }

}  // namespace bake
