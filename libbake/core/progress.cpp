#include "core/progress.h"

#include <unistd.h>

#include <algorithm>

namespace bake {

bool progressEnabled(bool quiet) { return !quiet && ::isatty(STDERR_FILENO) == 1; }

Progress::Progress(std::string label, std::uint64_t total, bool enabled, std::FILE* stream)
    : label_(std::move(label)), total_(total), enabled_(enabled), stream_(stream) {}

Progress::~Progress() { finish(); }

std::string Progress::render(const std::string& label, std::uint64_t done, std::uint64_t total,
                             int width) {
  const double fraction = total == 0 ? 1.0 : std::min(1.0, double(done) / double(total));
  const int filled = int(fraction * width + 0.5);
  std::string bar = label + " [" + std::string(filled, '#') + std::string(width - filled, ' ') + "] ";
  bar += std::to_string(int(fraction * 100.0)) + "%";
  return bar;
}

std::string Progress::remaining(double elapsedSeconds, std::uint64_t done, std::uint64_t total) {
  // Too early (under 2 s or 1 %) the rate says little.
  if (elapsedSeconds < 2 || done == 0 || done >= total || double(done) < 0.01 * double(total)) return "";
  const long long left = (long long)(elapsedSeconds * double(total - done) / double(done) + 0.5);
  if (left < 60) return ", about " + std::to_string(left) + " s left";
  if (left < 3600) return ", about " + std::to_string(left / 60) + " min " + std::to_string(left % 60) + " s left";
  return ", about " + std::to_string(left / 3600) + " h " + std::to_string(left % 3600 / 60) + " min left";
}

void Progress::update(std::uint64_t done) {
  if (!enabled_ || finished_) return;
  const auto now = std::chrono::steady_clock::now();
  if (done < total_ && now - lastDraw_ < std::chrono::milliseconds(100)) return;
  lastDraw_ = now;
  lastDrawn_ = done;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  // "\033[K" clears what a longer earlier line left (only ever written to a terminal).
  std::fprintf(stream_, "\r%s%s\033[K", render(label_, done, total_).c_str(), remaining(elapsed, done, total_).c_str());
  std::fflush(stream_);
}

TaskProgress::TaskProgress(std::string label, std::size_t tasks, std::uint64_t units, bool enabled)
    : progress_(std::move(label), std::uint64_t(tasks) * units, enabled), done_(tasks, 0), units_(units) {}

void TaskProgress::set(std::size_t task, std::uint64_t done) {
  if (!progress_.enabled() || task >= done_.size()) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  done = std::min(done, units_);
  sum_ += done - std::min(done, done_[task]);  // never backwards
  done_[task] = std::max(done_[task], done);
  progress_.update(sum_);
}

void Progress::finish() {
  if (!enabled_ || finished_) return;
  if (lastDrawn_ != total_) {
    lastDraw_ = {};
    update(total_);
  }
  finished_ = true;
  std::fprintf(stream_, "\n");
  std::fflush(stream_);
}

}  // namespace bake
