// Quality figures of a tonal art map (quality.h). Tone error: |1 - mean brightness - target| per
// stroke image. Nesting across tones: texels of tone k + 1 brighter than the same texel of tone k
// (beyond 1e-6), counted over every mip. Nesting across resolutions: each placed stroke is
// rasterized again at its own level and every finer one, and wherever its alpha is >= 0.5 the image
// of its tone must be at least as dark as that stroke alone on paper (compositing is multiplicative,
// so other strokes only darken further); a (stroke, level) pair failing anywhere counts once.
// Uniformity: the coefficient of variation of the mean darkness of the 16 quarter-tile windows, and
// the share of the darkness's spectral power (mean removed) at frequencies of radius < 4 cycles per
// tile, from a 2D DFT computed as separable 1D radix-2 FFTs (Cooley-Tukey, iterative, bit-reversed).
#include "hatching/bake/quality.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "core/parallel.h"

namespace bake::hatching {
namespace {

using Complex = std::complex<double>;

// In-place radix-2 FFT of `n` samples `stride` apart (n a power of two).
void fft(Complex* data, int n, std::size_t stride) {
  for (int i = 1, j = 0; i < n; ++i) {  // bit-reversal permutation
    int bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(data[std::size_t(i) * stride], data[std::size_t(j) * stride]);
  }
  for (int len = 2; len <= n; len <<= 1) {
    const double angle = -2.0 * std::numbers::pi / double(len);
    const Complex step(std::cos(angle), std::sin(angle));
    for (int start = 0; start < n; start += len) {
      Complex w(1.0, 0.0);
      for (int k = 0; k < len / 2; ++k) {
        Complex& a = data[std::size_t(start + k) * stride];
        Complex& b = data[std::size_t(start + k + len / 2) * stride];
        const Complex t = b * w;
        b = a - t;
        a += t;
        w *= step;
      }
    }
  }
}

int signedFrequency(int k, int n) { return k <= n / 2 ? k : k - n; }

int side(const Tam& tam, int mip) { return std::max(1, tam.resolution >> mip); }

// Strokes of `tam` missing from a level they should be in.
long long missingStrokes(const Tam& tam) {
  return parallelReduce<long long>(
      tam.strokes.size(), 16, 0, 0LL,
      [&](std::size_t begin, std::size_t end) {
        long long missing = 0;
        for (std::size_t i = begin; i < end; ++i) {
          const PlacedStroke& placed = tam.strokes[i];
          for (int level = placed.level; level < tam.strokeLevels; ++level) {
            const int mip = tam.strokeLevels - 1 - level;
            const int n = side(tam, mip);
            const stroke::Raster& image = tam.images[std::size_t(placed.tone)][std::size_t(mip)];
            const stroke::InkFootprint footprint =
                stroke::rasterize(stroke::scaledPositions(placed.stroke, double(n)), n, n, true);
            for (const stroke::InkFootprint::Pixel& p : footprint.pixels) {
              if (p.alpha >= 0.5f && image.at(p.x, p.y) > 1.0f - p.alpha + 1e-4f) {
                ++missing;
                break;
              }
            }
          }
        }
        return missing;
      },
      [](long long a, long long b) { return a + b; });
}

}  // namespace

double meanDarkness(const stroke::Raster& brightness) {
  double sum = 0;
  for (int y = 0; y < brightness.height; ++y) {
    for (int x = 0; x < brightness.width; ++x) sum += 1.0 - double(brightness.at(x, y));
  }
  const double count = double(brightness.width) * double(brightness.height);
  return count > 0 ? sum / count : 0.0;
}

double inkVariation(const stroke::Raster& brightness) {
  const int wx = std::max(1, brightness.width / 4), wy = std::max(1, brightness.height / 4);
  const int cx = brightness.width / wx, cy = brightness.height / wy;
  std::vector<double> windows(std::size_t(cx) * std::size_t(cy), 0.0);
  for (int y = 0; y < cy * wy; ++y) {
    for (int x = 0; x < cx * wx; ++x) {
      windows[std::size_t(y / wy) * std::size_t(cx) + std::size_t(x / wx)] += 1.0 - double(brightness.at(x, y));
    }
  }
  double mean = 0;
  for (double& w : windows) mean += (w /= double(wx) * double(wy));
  mean /= double(windows.size());
  if (!(mean > 1e-12)) return 0.0;
  double variance = 0;
  for (double w : windows) variance += (w - mean) * (w - mean);
  variance /= double(windows.size());
  return std::sqrt(variance) / mean;
}

double lowFrequencyPower(const stroke::Raster& brightness) {
  const int w = brightness.width, h = brightness.height;
  const double mean = meanDarkness(brightness);
  std::vector<Complex> spectrum(std::size_t(w) * std::size_t(h));
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) spectrum[std::size_t(y) * std::size_t(w) + std::size_t(x)] = 1.0 - double(brightness.at(x, y)) - mean;
  }
  for (int y = 0; y < h; ++y) fft(&spectrum[std::size_t(y) * std::size_t(w)], w, 1);
  for (int x = 0; x < w; ++x) fft(&spectrum[std::size_t(x)], h, std::size_t(w));
  double low = 0, total = 0;
  for (int y = 0; y < h; ++y) {
    const int fy = signedFrequency(y, h);
    for (int x = 0; x < w; ++x) {
      if (x == 0 && y == 0) continue;
      const int fx = signedFrequency(x, w);
      const double power = std::norm(spectrum[std::size_t(y) * std::size_t(w) + std::size_t(x)]);
      total += power;
      if (fx * fx + fy * fy < 16) low += power;
    }
  }
  // Round-off of a uniform image leaves ~1e-30 of power: no structure, no share.
  const double floor = 1e-20 * double(w) * double(w) * double(h) * double(h);
  return total > floor ? low / total : 0.0;
}

Quality measureQuality(const Tam& tam) {
  Quality q;
  std::vector<std::vector<double>> darkness(std::size_t(tam.tones), std::vector<double>(std::size_t(tam.strokeLevels), 0.0));
  std::vector<ImageQuality> images(std::size_t(tam.tones) * std::size_t(tam.strokeLevels));
  for (const PlacedStroke& placed : tam.strokes) {  // in every darker tone and finer level
    for (int t = placed.tone; t < tam.tones; ++t) {
      for (int mip = 0; mip < tam.strokeLevels - placed.level; ++mip) ++images[std::size_t(t * tam.strokeLevels + mip)].strokes;
    }
  }
  parallelFor(images.size(), 0, [&](std::size_t i) {
    const int t = int(i) / tam.strokeLevels, mip = int(i) % tam.strokeLevels;
    const stroke::Raster& image = tam.images[std::size_t(t)][std::size_t(mip)];
    ImageQuality& iq = images[i];
    iq.tone = t;
    iq.mip = mip;
    iq.side = image.width;
    iq.target = tam.targets[std::size_t(t)];
    iq.darkness = meanDarkness(image);
    iq.toneError = std::abs(iq.darkness - iq.target);
    iq.toneTolerance = std::max(0.0025, 0.8 / double(iq.side));
    iq.inkVariation = inkVariation(image);
    iq.lowFrequencyPower = lowFrequencyPower(image);
    iq.uniformityChecked = iq.side >= kUniformityMinSide && iq.strokes >= kUniformityMinStrokes;
  }, 1);
  for (const ImageQuality& iq : images) {
    darkness[std::size_t(iq.tone)][std::size_t(iq.mip)] = iq.darkness;
    q.maxToneError = std::max(q.maxToneError, iq.toneError);
    q.maxToneErrorOverTolerance = std::max(q.maxToneErrorOverTolerance, iq.toneError / iq.toneTolerance);
    q.maxInkVariationAll = std::max(q.maxInkVariationAll, iq.inkVariation);
    q.maxLowFrequencyPowerAll = std::max(q.maxLowFrequencyPowerAll, iq.lowFrequencyPower);
    if (iq.uniformityChecked) {
      q.maxInkVariation = std::max(q.maxInkVariation, iq.inkVariation);
      q.maxLowFrequencyPower = std::max(q.maxLowFrequencyPower, iq.lowFrequencyPower);
    }
  }
  q.images = std::move(images);

  for (int t = 1; t < tam.tones; ++t) {
    for (int m = 0; m < tam.mipLevels; ++m) {
      const stroke::Raster& lighter = tam.images[std::size_t(t - 1)][std::size_t(m)];
      const stroke::Raster& darker = tam.images[std::size_t(t)][std::size_t(m)];
      for (std::size_t i = 0; i < darker.values.size(); ++i) {
        if (darker.values[i] > lighter.values[i] + 1e-6f) ++q.nestingViolationsTone;
      }
    }
    for (int m = 0; m < tam.strokeLevels; ++m) {
      if (!(darkness[std::size_t(t)][std::size_t(m)] > darkness[std::size_t(t - 1)][std::size_t(m)])) q.monotoneTones = false;
    }
  }
  q.nestingViolationsResolution = missingStrokes(tam);

  double levelDifference = 0;
  int pairs = 0;
  for (int t = 0; t < tam.tones; ++t) {
    for (int m = 0; m + 1 < tam.strokeLevels; ++m, ++pairs) {
      levelDifference += std::abs(darkness[std::size_t(t)][std::size_t(m)] - darkness[std::size_t(t)][std::size_t(m + 1)]);
    }
  }
  q.meanLevelDifference = pairs > 0 ? levelDifference / double(pairs) : 0.0;
  return q;
}

std::string uniformityScope() {
  return "stroke images of side >= " + std::to_string(kUniformityMinSide) + " holding >= " +
         std::to_string(kUniformityMinStrokes) + " strokes (" + std::to_string(kUniformityMinStrokes / 16) +
         " per quarter-tile window)";
}

nlohmann::json Quality::toJson() const {
  nlohmann::json out;
  out["maxToneError"] = maxToneError;
  out["maxToneErrorOverTolerance"] = maxToneErrorOverTolerance;
  out["nestingViolationsTone"] = nestingViolationsTone;
  out["nestingViolationsResolution"] = nestingViolationsResolution;
  out["monotoneTones"] = monotoneTones;
  out["meanLevelDifference"] = meanLevelDifference;
  out["maxInkVariation"] = maxInkVariation;
  out["maxLowFrequencyPower"] = maxLowFrequencyPower;
  out["maxInkVariationAll"] = maxInkVariationAll;
  out["maxLowFrequencyPowerAll"] = maxLowFrequencyPowerAll;
  out["uniformityApplies"] = {{"minSide", kUniformityMinSide}, {"minStrokes", kUniformityMinStrokes}};
  nlohmann::json list = nlohmann::json::array();
  for (const ImageQuality& iq : images) {
    list.push_back({{"tone", iq.tone}, {"mip", iq.mip}, {"side", iq.side}, {"target", iq.target},
                    {"darkness", iq.darkness}, {"toneError", iq.toneError}, {"toneTolerance", iq.toneTolerance},
                    {"inkVariation", iq.inkVariation}, {"lowFrequencyPower", iq.lowFrequencyPower}, {"strokes", iq.strokes},
                    {"uniformityChecked", iq.uniformityChecked}});
  }
  out["images"] = std::move(list);
  return out;
}

}  // namespace bake::hatching
