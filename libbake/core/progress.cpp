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

void Progress::update(std::uint64_t done) {
  if (!enabled_ || finished_) return;
  const auto now = std::chrono::steady_clock::now();
  if (done < total_ && now - lastDraw_ < std::chrono::milliseconds(100)) return;
  lastDraw_ = now;
  lastDrawn_ = done;
  std::fprintf(stream_, "\r%s", render(label_, done, total_).c_str());
  std::fflush(stream_);
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
