// One stroke level of a tonal art map under construction (Praun et al. 2001, section 3.2): the image,
// and the darkness blurred by a small Gaussian, against which a candidate stroke's tone progress is
// measured, so that overlapping strokes score less and strokes spread evenly.
// A candidate's progress is summed over its own footprint only: a texel gains min(t, D + d) -
// min(t, D) where D is the blurred darkness there, d the darkness the stroke adds and t the target
// tone, so ink laid over or next to earlier strokes (where D already reaches t) counts for little.
// That blur (about a pixel) spreads strokes locally only; at the scale of the tile a coarse grid of
// 16 x 16 cells (smoothed over neighbours) weights each texel's progress by how far its cell lags
// behind the target (kSpreadWeight), which keeps the ink even over quarter-tile windows and out of the
// low frequencies (measured by bench/tam: see build_stages.h). The blurred image is kept up to date
// incrementally: after a stroke is placed, the darkness it added is blurred (separable kernel) over
// its footprint's neighbourhood only, found as the smallest wrapping
// interval of rows and of columns holding the footprint, widened by the kernel radius (the whole
// torus when that would not be smaller). No full-image pass runs per stroke.
#include <algorithm>
#include <cmath>
#include <utility>

#include "hatching/bake/build_stages.h"

namespace bake::hatching::detail {
namespace {

// A wrapping interval of rows or columns: [origin, origin + width) modulo the side.
struct Span {
  int origin = 0, width = 0;
  bool periodic = false;  // the whole torus: the blur wraps inside the buffer
};

// The smallest wrapping interval holding every used entry, widened by `margin` on both sides.
Span coverSpan(const std::vector<unsigned char>& used, int side, int margin) {
  int bestGap = 0, bestGapEnd = 0, run = 0;
  for (int i = 0; i < 2 * side; ++i) {
    if (!used[std::size_t(i % side)]) {
      if (++run > bestGap) bestGap = run, bestGapEnd = i + 1;
    } else {
      run = 0;
    }
  }
  bestGap = std::min(bestGap, side);
  const int covered = side - bestGap;
  if (covered + 2 * margin >= side) return {0, side, true};
  const int first = bestGapEnd % side;  // first used entry after the largest gap
  return {((first - margin) % side + side) % side, covered + 2 * margin, false};
}

int wrapIndex(int i, int n) {
  i %= n;
  return i < 0 ? i + n : i;
}

// out[i] = sum_k w[k] in[i + k - r] along a line of `count` samples (`stride` apart), zero outside
// unless periodic, for i in [from, to] only (the other outputs are left as they are).
void blurLine(const float* in, float* out, int count, std::size_t stride, const Kernel& kernel, bool periodic,
              int from, int to) {
  const int r = kernel.radius;
  for (int i = from; i <= to; ++i) {
    float sum = 0;
    for (int k = -r; k <= r; ++k) {
      int j = i + k;
      if (periodic) {
        j = wrapIndex(j, count);
      } else if (j < 0 || j >= count) {
        continue;
      }
      sum += kernel.weights[std::size_t(k + r)] * in[std::size_t(j) * stride];
    }
    out[std::size_t(i) * stride] = sum;
  }
}

// The outputs of a line blur that can be non-zero when the input is zero outside [first, last]: all
// of them on a periodic line, else [first - r, last + r] clipped to the line. Empty (first > last) stays empty.
std::pair<int, int> blurReach(int first, int last, int count, int r, bool periodic) {
  if (first > last) return {0, -1};
  if (periodic) return {0, count - 1};
  return {std::max(0, first - r), std::min(count - 1, last + r)};
}

// The cells' mean darkness, smoothed by [1 2 1] / 4 along both axes (wrapping).
void updateWide(LevelImage& level) {
  const int c = level.cells;
  const double area = double(1 << level.cellShift) * double(1 << level.cellShift);
  std::vector<double> rows(level.cellDarkness.size());
  for (int y = 0; y < c; ++y) {
    for (int x = 0; x < c; ++x) {
      const auto at = [&](int i) { return level.cellDarkness[std::size_t(y) * std::size_t(c) + std::size_t(wrapIndex(i, c))]; };
      rows[std::size_t(y) * std::size_t(c) + std::size_t(x)] = 0.25 * (at(x - 1) + 2 * at(x) + at(x + 1)) / area;
    }
  }
  for (int y = 0; y < c; ++y) {
    for (int x = 0; x < c; ++x) {
      const auto at = [&](int j) { return rows[std::size_t(wrapIndex(j, c)) * std::size_t(c) + std::size_t(x)]; };
      level.wide[std::size_t(y) * std::size_t(c) + std::size_t(x)] = float(0.25 * (at(y - 1) + 2 * at(y) + at(y + 1)));
    }
  }
}

}  // namespace

Kernel gaussianKernel(double sigma) {
  Kernel kernel;
  if (!(sigma > 0)) {
    kernel.weights = {1.0f};
    return kernel;
  }
  kernel.radius = std::max(1, int(std::ceil(3.0 * sigma)));
  double total = 0;
  std::vector<double> w(std::size_t(2 * kernel.radius + 1));
  for (int k = -kernel.radius; k <= kernel.radius; ++k) {
    w[std::size_t(k + kernel.radius)] = std::exp(-0.5 * double(k * k) / (sigma * sigma));
    total += w[std::size_t(k + kernel.radius)];
  }
  for (double v : w) kernel.weights.push_back(float(v / total));
  return kernel;
}

LevelImage blankLevel(int side, bool coloured) {
  LevelImage level;
  level.side = side;
  level.brightness = stroke::Raster(side, side, 1, true);
  if (coloured) level.colour = stroke::Raster(side, side, 3, true);
  level.blurred.assign(std::size_t(side) * std::size_t(side), 0.0f);
  level.cells = std::min(side, 16);
  while ((level.cells << level.cellShift) < side) ++level.cellShift;
  level.cellDarkness.assign(std::size_t(level.cells) * std::size_t(level.cells), 0.0);
  level.wide.assign(level.cellDarkness.size(), 0.0f);
  return level;
}

Progress measureProgress(const stroke::InkFootprint& footprint, const LevelImage& level, double target) {
  Progress progress;
  const float t = float(target), spread = float(kSpreadWeight / target);
  for (const stroke::InkFootprint::Pixel& p : footprint.pixels) {
    const std::size_t index = std::size_t(p.y) * std::size_t(level.side) + std::size_t(p.x);
    const float d = level.brightness.values[index] * p.alpha;
    const float blurred = level.blurred[index];
    const float wide = level.wide[std::size_t(p.y >> level.cellShift) * std::size_t(level.cells) + std::size_t(p.x >> level.cellShift)];
    const float weight = std::max(0.0f, 1.0f + spread * (t - wide));
    progress.gain += double((std::min(t, blurred + d) - std::min(t, blurred)) * weight);
    progress.ink += double(p.alpha);
    progress.darkening += double(d);
  }
  return progress;
}

void applyFootprint(const stroke::InkFootprint& footprint, const Kernel& kernel, LevelImage& level) {
  if (footprint.pixels.empty()) return;
  const int side = level.side;
  std::vector<unsigned char> usedX(std::size_t(side), 0), usedY(std::size_t(side), 0);
  for (const stroke::InkFootprint::Pixel& p : footprint.pixels) {
    usedX[std::size_t(p.x)] = 1;
    usedY[std::size_t(p.y)] = 1;
  }
  const Span sx = coverSpan(usedX, side, kernel.radius);
  const Span sy = coverSpan(usedY, side, kernel.radius);
  const std::size_t wx = std::size_t(sx.width), wy = std::size_t(sy.width);
  std::vector<float> added(wx * wy, 0.0f), rows(wx * wy, 0.0f);

  // The darkness each texel gains, composited into the images.
  double darkening = 0;
  for (const stroke::InkFootprint::Pixel& p : footprint.pixels) {
    float& b = level.brightness.at(p.x, p.y);
    const float d = b * p.alpha;
    b -= d;  // b * (1 - alpha)
    darkening += double(d);
    level.cellDarkness[std::size_t(p.y >> level.cellShift) * std::size_t(level.cells) + std::size_t(p.x >> level.cellShift)] += double(d);
    const std::size_t lx = std::size_t(wrapIndex(p.x - sx.origin, side));
    const std::size_t ly = std::size_t(wrapIndex(p.y - sy.origin, side));
    added[ly * wx + lx] = d;
  }
  if (level.colour.channels == 3) stroke::composite(footprint, level.colour);
  level.darknessSum += darkening;
  updateWide(level);

  // The separable blur of `added`, computed only where it can be non-zero: a row without ink stays 0
  // through the row pass, a row with ink spreads over its ink's span widened by the radius, and so
  // for the columns. The outputs skipped are sums of zeros, so the result is bit for bit that of the
  // passes over the whole rectangle (and adding 0 to `blurred` changes nothing), at the cost of the
  // stroke's neighbourhood instead of its bounding box (a slanted stroke fills a fraction of it).
  const int r = kernel.radius;
  std::vector<int> rowFirst(wy, int(wx)), rowLast(wy, -1);
  for (const stroke::InkFootprint::Pixel& p : footprint.pixels) {
    const std::size_t lx = std::size_t(wrapIndex(p.x - sx.origin, side));
    const std::size_t ly = std::size_t(wrapIndex(p.y - sy.origin, side));
    rowFirst[ly] = std::min(rowFirst[ly], int(lx));
    rowLast[ly] = std::max(rowLast[ly], int(lx));
  }
  std::vector<int> columnFirst(wx, int(wy)), columnLast(wx, -1);
  for (std::size_t y = 0; y < wy; ++y) {
    const auto [from, to] = blurReach(rowFirst[y], rowLast[y], int(wx), r, sx.periodic);
    blurLine(&added[y * wx], &rows[y * wx], int(wx), 1, kernel, sx.periodic, from, to);
    for (int x = from; x <= to; ++x) {
      columnFirst[std::size_t(x)] = std::min(columnFirst[std::size_t(x)], int(y));
      columnLast[std::size_t(x)] = std::max(columnLast[std::size_t(x)], int(y));
    }
  }
  std::fill(added.begin(), added.end(), 0.0f);  // the column pass's output
  for (std::size_t x = 0; x < wx; ++x) {
    const auto [from, to] = blurReach(columnFirst[x], columnLast[x], int(wy), r, sy.periodic);
    blurLine(&rows[x], &added[x], int(wy), wx, kernel, sy.periodic, from, to);
    const std::size_t gx = std::size_t(wrapIndex(sx.origin + int(x), side));
    for (int y = from; y <= to; ++y) {
      const std::size_t gy = std::size_t(wrapIndex(sy.origin + y, side));
      level.blurred[gy * std::size_t(side) + gx] += added[std::size_t(y) * wx + x];
    }
  }
}

stroke::Raster boxHalve(const stroke::Raster& image) {
  const int w = std::max(1, image.width / 2), h = std::max(1, image.height / 2);
  stroke::Raster half(w, h, image.channels, image.wrap);
  const int sx = image.width > 1 ? 2 : 1, sy = image.height > 1 ? 2 : 1;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < image.channels; ++c) {
        double sum = 0;
        for (int j = 0; j < sy; ++j) {
          for (int i = 0; i < sx; ++i) sum += double(image.at(sx * x + i, sy * y + j, c));
        }
        half.at(x, y, c) = float(sum / double(sx * sy));
      }
    }
  }
  return half;
}

}  // namespace bake::hatching::detail
