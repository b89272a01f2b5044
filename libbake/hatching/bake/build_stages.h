// The stages of the tonal art map construction (build.h), shared by build.cpp, build_candidates.cpp
// and build_level.cpp. Internal to libbake/hatching.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "bake/hatching/style.h"
#include "bake/stroke/paintstroke.h"

namespace bake::hatching::detail {

// Counter-based random numbers: the stream of one candidate stroke depends only on
// (seed, tone, level, step, candidate), never on the order candidates are evaluated in
// (SplitMix64 finaliser over the key, then SplitMix64 steps).
class StrokeRandom {
 public:
  StrokeRandom(std::uint64_t seed, int tone, int level, std::int64_t step, int candidate);
  std::uint64_t next();
  double uniform();                    // [0, 1)
  double uniform(double low, double high);

 private:
  std::uint64_t state_;
};

// A random candidate stroke of the style, in tile units ([0, 1)^2; the rasterizer wraps it), radii in
// pixels. Stipple dots are round dots of their width at every level.
stroke::Paintstroke candidateStroke(const Style& style, int tone, StrokeRandom& random);

// Normalised separable Gaussian, radius ceil(3 sigma) (sigma 0: the identity).
struct Kernel {
  int radius = 0;
  std::vector<float> weights;  // 2 radius + 1 taps
};
Kernel gaussianKernel(double sigma);

// One stroke level of the tone being built: its image, the darkness blurred by the kernel (kept up
// to date stroke by stroke) and the total darkness.
struct LevelImage {
  int side = 0;
  stroke::Raster brightness;   // 1 channel: ink as if black (the tone)
  stroke::Raster colour;       // 3 channels with coloured ink, else empty
  std::vector<float> blurred;  // blur of (1 - brightness), side x side, wrapping
  double darknessSum = 0;      // sum over texels of (1 - brightness)
  // Coarse grid of cells x cells (cells of 8 texels, at most 16 per side): darkness sum per cell, and
  // the cells' mean darkness smoothed over their neighbours ([1 2 1] / 4 both ways, wrapping).
  int cells = 1, cellShift = 0;  // cell of texel x: x >> cellShift
  std::vector<double> cellDarkness;
  std::vector<float> wide;
  double meanDarkness() const { return darknessSum / (double(side) * double(side)); }
};
LevelImage blankLevel(int side, bool coloured);

// A candidate's effect on one level: `gain` = sum over its texels of min(t, D + d) - min(t, D) with D
// the blurred darkness, d the darkness it adds and t the target (progress towards the tone, none
// where the neighbourhood is already dark enough), each texel's share weighted by
// max(0, 1 + kSpreadWeight (t - W) / t) with W the smoothed darkness of its coarse cell (cells behind
// the target count more); `ink` = its alpha sum; `darkening` = sum of d.
// Measured on the default style at 256^2, K 16, seeds 1-3 (bench-tam): the largest window CV of the
// images in quality.h's uniformity scope goes from 0.053-0.075 without the weight (0) to 0.042-0.049
// with 16, the low-frequency power from 1.7-2.0 % to 1.1-1.5 %, at the same tone errors.
inline constexpr double kSpreadWeight = 16.0;
struct Progress {
  double gain = 0, ink = 0, darkening = 0;
};
Progress measureProgress(const stroke::InkFootprint& footprint, const LevelImage& level, double target);

// Draws a footprint into the level: brightness *= 1 - alpha, colour composited, blurred darkness
// updated over the footprint's neighbourhood only (wrapping), darkness sum updated.
void applyFootprint(const stroke::InkFootprint& footprint, const Kernel& kernel, LevelImage& level);

// Persistent workers for the many small parallel steps of the construction (one per stroke: K
// candidates). The calling thread takes part and claims items itself, and waits only for items a
// worker has already claimed, so a worker that is slow to be scheduled on a busy machine costs
// nothing (core/parallel.h starts threads per call, which costs more than a stroke's candidates).
// Each item's result depends only on its index, whatever thread runs it.
class StepPool {
 public:
  explicit StepPool(unsigned threads);  // threads - 1 workers
  ~StepPool();
  StepPool(const StepPool&) = delete;
  StepPool& operator=(const StepPool&) = delete;
  // body(i) for every i in [0, count); rethrows the first exception a body threw.
  void run(std::size_t count, const std::function<void(std::size_t)>& body);

 private:
  void work();
  bool claimAndRun(std::uint32_t generation);

  std::mutex mutex_;
  std::condition_variable wake_;
  std::uint32_t generation_ = 0;  // under mutex_
  bool stop_ = false;             // under mutex_
  std::atomic<const std::function<void(std::size_t)>*> body_{nullptr};
  std::atomic<std::size_t> count_{0};
  std::atomic<std::uint64_t> ticket_{0};  // generation << 32 | next item
  std::atomic<std::size_t> done_{0};
  std::exception_ptr failure_;
  std::vector<std::thread> workers_;
};

// 2x2 box average (mean-preserving), any channel count; side must be even or 1 -> 1.
stroke::Raster boxHalve(const stroke::Raster& image);

}  // namespace bake::hatching::detail
