// One stroke level under construction (hatching/bake/build_level.cpp): the blurred darkness that
// applyFootprint keeps up to date stroke by stroke, over each stroke's neighbourhood only, must equal a
// blur of the whole image's darkness computed from scratch here (a direct periodic 2D convolution in
// double precision, sharing no code with the incremental one). The footprints are slanted lines,
// lines that wrap over the tile's edges, scattered texels that span the whole torus and a block wider
// than the tile minus the kernel, so every path of the incremental update (narrow spans, wrapped
// spans, a whole periodic axis) is checked.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "hatching/bake/build_stages.h"

namespace bake::hatching::detail {
namespace {

stroke::InkFootprint::Pixel inked(int x, int y, float alpha) { return {x, y, alpha, {0.0f, 0.0f, 0.0f}}; }

// A straight line of texels from (x0, y0), `count` steps of (dx, dy) per step in 1/8 texel, wrapped.
stroke::InkFootprint line(int side, int x0, int y0, int dx, int dy, int count, float alpha) {
  stroke::InkFootprint footprint;
  std::vector<char> seen(std::size_t(side) * std::size_t(side), 0);
  for (int k = 0; k < count; ++k) {
    const int x = ((x0 + k * dx / 8) % side + side) % side, y = ((y0 + k * dy / 8) % side + side) % side;
    if (seen[std::size_t(y) * std::size_t(side) + std::size_t(x)]) continue;
    seen[std::size_t(y) * std::size_t(side) + std::size_t(x)] = 1;
    footprint.pixels.push_back(inked(x, y, alpha * float(0.5 + 0.5 * std::sin(0.7 * k) * std::sin(0.7 * k))));
  }
  return footprint;
}

// The Gaussian blur of the darkness (1 - brightness) over the torus, straight from the definition.
std::vector<double> blurFromScratch(const LevelImage& level, const Kernel& kernel) {
  const int n = level.side, r = kernel.radius;
  std::vector<double> out(std::size_t(n) * std::size_t(n), 0.0);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      double sum = 0;
      for (int j = -r; j <= r; ++j)
        for (int i = -r; i <= r; ++i) {
          const int sx = ((x + i) % n + n) % n, sy = ((y + j) % n + n) % n;
          const double darkness = 1.0 - double(level.brightness.values[std::size_t(sy) * std::size_t(n) + std::size_t(sx)]);
          sum += double(kernel.weights[std::size_t(i + r)]) * double(kernel.weights[std::size_t(j + r)]) * darkness;
        }
      out[std::size_t(y) * std::size_t(n) + std::size_t(x)] = sum;
    }
  return out;
}

void expectBlurMatches(const LevelImage& level, const Kernel& kernel, const char* after) {
  const std::vector<double> reference = blurFromScratch(level, kernel);
  double worst = 0;
  std::size_t worstAt = 0;
  for (std::size_t k = 0; k < reference.size(); ++k) {
    const double error = std::abs(double(level.blurred[k]) - reference[k]);
    if (error > worst) worst = error, worstAt = k;
  }
  // Float sums of a few hundred terms below 1: rounding stays near 1e-6; a texel the update missed
  // is off by the whole of a stroke's blurred ink (1e-3 and more).
  EXPECT_LT(worst, 2e-5) << "after " << after << ": texel (" << worstAt % std::size_t(level.side) << ", "
                         << worstAt / std::size_t(level.side) << ") blurred " << level.blurred[worstAt]
                         << ", from scratch " << reference[worstAt];
}

TEST(ApplyFootprint, IncrementalBlurEqualsBlurFromScratch) {
  for (const double sigma : {0.8, 2.0}) {
    SCOPED_TRACE(sigma);
    const Kernel kernel = gaussianKernel(sigma);
    const int side = 64;
    LevelImage level = blankLevel(side, false);
    level.brightness.values.assign(std::size_t(side) * std::size_t(side), 1.0f);

    applyFootprint(line(side, 10, 20, 8, 3, 40, 0.9f), kernel, level);  // slanted, inside the tile
    expectBlurMatches(level, kernel, "a slanted line");
    applyFootprint(line(side, 50, 60, 5, 7, 60, 0.7f), kernel, level);  // wraps over both edges
    expectBlurMatches(level, kernel, "a line wrapping over the corner");
    applyFootprint(line(side, 12, 21, 8, 3, 40, 0.6f), kernel, level);  // over the first one
    expectBlurMatches(level, kernel, "a line over an earlier one");

    stroke::InkFootprint scattered;  // texels all over the torus: periodic rows and columns
    for (int k = 0; k < 24; ++k) scattered.pixels.push_back(inked((k * 37) % side, (k * 23 + 5) % side, 0.5f));
    applyFootprint(scattered, kernel, level);
    expectBlurMatches(level, kernel, "scattered texels");

    stroke::InkFootprint block;  // wider than the tile less twice the radius in x only
    for (int y = 30; y < 34; ++y)
      for (int x = 0; x < side - 3; ++x) block.pixels.push_back(inked(x, y, 0.25f));
    applyFootprint(block, kernel, level);
    expectBlurMatches(level, kernel, "a band across the tile");

    applyFootprint(stroke::InkFootprint{}, kernel, level);  // nothing: nothing changes
    expectBlurMatches(level, kernel, "an empty footprint");
  }
}

}  // namespace
}  // namespace bake::hatching::detail
