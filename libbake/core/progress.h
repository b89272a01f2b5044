// A progress bar for long work. It draws only when stderr is a terminal and the tool is not --quiet,
// so logs of build systems stay clean; redraws are rate-limited so it costs nothing in hot loops.
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <string>
#include <vector>

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
  // ", about 2 min 5 s left" from the time spent on `done` of `total`; empty while too early to tell.
  static std::string remaining(double elapsedSeconds, std::uint64_t done, std::uint64_t total);

 private:
  std::string label_;
  std::uint64_t total_;
  bool enabled_;
  bool finished_ = false;
  std::FILE* stream_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point lastDraw_{};
  std::uint64_t lastDrawn_ = ~std::uint64_t(0);
};

// One bar over `tasks` tasks of `units` units each, fed from the threads that run them (a field per
// thread, say): each task says how far it got, the bar shows the sum.
class TaskProgress {
 public:
  TaskProgress(std::string label, std::size_t tasks, std::uint64_t units, bool enabled);
  void set(std::size_t task, std::uint64_t done);
  bool enabled() const { return progress_.enabled(); }

 private:
  std::mutex mutex_;
  Progress progress_;
  std::vector<std::uint64_t> done_;
  std::uint64_t units_ = 0, sum_ = 0;
};

// True when stderr is a terminal and --quiet was not given.
bool progressEnabled(bool quiet);

}  // namespace bake
