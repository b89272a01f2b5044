// The --report record of one tool run: what was read and written (with content hashes), the options,
// per-stage timings, the measured error against a stated reference, warnings and statistics.
// Layout: formats/report.md; schema: formats/report.schema.json.
#pragma once

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/core/diagnostics.h"
#include "bake/core/status.h"

namespace bake {

class Report {
 public:
  Report(std::string tool, std::string toolVersion);

  Status addInput(const std::filesystem::path& path);
  Status addOutput(const std::filesystem::path& path);  // call after the output is committed
  void setOptions(nlohmann::json options) { options_ = std::move(options); }
  void addStage(const std::string& name, double seconds);
  // One measured error: what was measured, against which reference, and the figures
  // (e.g. {"meanRelative": 0.003, "maxRelative": 0.02, "samples": 64}).
  void addAccuracy(const std::string& quantity, const std::string& reference, nlohmann::json metrics);
  void setStatistic(const std::string& key, nlohmann::json value) { statistics_[key] = std::move(value); }
  void setOutcome(const Status& status) { outcome_ = status; }
  void takeWarnings(const Diagnostics& diagnostics);

  nlohmann::json toJson() const;
  Status write(const std::filesystem::path& path) const;

 private:
  std::string tool_;
  std::string toolVersion_;
  nlohmann::json inputs_ = nlohmann::json::array();
  nlohmann::json outputs_ = nlohmann::json::array();
  nlohmann::json options_ = nlohmann::json::object();
  nlohmann::json stages_ = nlohmann::json::array();
  nlohmann::json accuracy_ = nlohmann::json::array();
  nlohmann::json warnings_ = nlohmann::json::array();
  nlohmann::json statistics_ = nlohmann::json::object();
  Status outcome_;
};

// Times a scope and records it as a stage of the report (when there is one).
class StageTimer {
 public:
  StageTimer(Report* report, std::string name);
  ~StageTimer();
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;
  double seconds() const;
  void stop();  // records now instead of at the end of the scope

 private:
  Report* report_;
  std::string name_;
  std::chrono::steady_clock::time_point start_;
  bool stopped_ = false;
};

}  // namespace bake
