// A progress bar for long work. It draws only when stderr is a terminal and the tool is not --quiet,
// so logs of build systems stay clean; redraws are rate-limited so it costs nothing in hot loops.
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

namespace bake {

class Progress {
 public:
  // `enabled` is normally progressEnabled(quiet).
  Progress(std::string label, std::uint64_t total, bool enabled, std::FILE* stream = stderr);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void update(std::uint64_t done);
  void finish();
  bool enabled() const { return enabled_; }

  // The text drawn for a given state; public so tests can check it without a terminal.
  static std::string render(const std::string& label, std::uint64_t done, std::uint64_t total,
                            int width = 30);

 private:
  std::string label_;
  std::uint64_t total_;
  bool enabled_;
  bool finished_ = false;
  std::FILE* stream_;
  std::chrono::steady_clock::time_point lastDraw_{};
  std::uint64_t lastDrawn_ = ~std::uint64_t(0);
};

// True when stderr is a terminal and --quiet was not given.
bool progressEnabled(bool quiet);

}  // namespace bake
