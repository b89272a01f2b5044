// Tonal art map construction (Praun, Hoppe, Webb, Finkelstein, "Real-time hatching", SIGGRAPH 2001,
// section 3.2 "Tonal art maps"): the driver. Tones are filled light -> dark and, within a tone,
// stroke levels coarse -> fine. Each level's image starts as the same level of the lighter tone plus
// the strokes this tone already placed at coarser levels. At each step K random candidates
// (build_candidates.cpp) are rasterized at the level being filled and at every finer one, and scored
// by their tone progress summed over those levels per unit of ink, each level's progress and ink in
// units of its mean (progress measured against the blurred darkness, build_level.cpp). The best
// candidate (lowest index among equals) is drawn into that level and every finer level; the darker
// tones inherit it when they start, so nesting across tones and resolutions holds by construction.
// Candidates are scored in parallel (StepPool, build_pool.cpp) with random numbers keyed by
// (seed, tone, level, step, candidate), and the choice is made in candidate order, so the result
// does not depend on the thread count.
// An image stops when its mean darkness reaches the target, keeping the last stroke only if it
// brings the mean closer. The mip levels below the stroke levels are 2x2 box averages.
#include "hatching/bake/build.h"

#include <bake_formats/tam.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/parallel.h"
#include "hatching/bake/build_stages.h"

namespace bake::hatching {
namespace {

using detail::LevelImage;

bool isPowerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

int log2Int(int n) {
  int k = 0;
  while ((1 << (k + 1)) <= n) ++k;
  return k;
}

Status styleError(const Style& style, const std::string& pointer, const std::string& message) {
  return invalidInput(message, {style.source, pointer});
}

Status checkRange(const Style& style, const std::string& pointer, const Range& range, double lowest) {
  if (!std::isfinite(range.min) || !(range.min >= lowest))
    return styleError(style, pointer + "/min", "is " + std::to_string(range.min) + ", must be >= " + std::to_string(lowest));
  if (!std::isfinite(range.max) || !(range.max >= range.min))
    return styleError(style, pointer + "/max", "is " + std::to_string(range.max) + ", must be >= min (" + std::to_string(range.min) + ")");
  return Status::ok();
}

// One candidate stroke with its footprint at every level it is scored on.
struct Candidate {
  stroke::Paintstroke stroke;
  std::vector<stroke::InkFootprint> footprints;  // levels first .. last
  double score = -std::numeric_limits<double>::infinity();
  double darkening = 0;  // mean darkness added to the level being filled
};

class Builder {
 public:
  Builder(const Style& style, const BuildOptions& options, Tam& tam)
      : style_(style), options_(options), tam_(tam), kernel_(detail::gaussianKernel(style.blurSigma)),
        pool_(std::min<unsigned>(resolveThreadCount(unsigned(std::max(0, options.threads))), unsigned(style.candidates))),
        candidates_(std::size_t(style.candidates)) {}

  void run() {
    const int levels = tam_.strokeLevels;
    for (int l = 0; l < levels; ++l) levels_.push_back(detail::blankLevel(side(l), tam_.coloured));
    for (int l = 0; l < levels; ++l) thresholds_.emplace_back(side(l), side(l), 1, true);
    const int tones = tam_.tones;
    for (int t = 0; t < tones; ++t) {
      for (int l = 0; l < levels; ++l) {
        fill(t, l);
        if (options_.progress) options_.progress(double(t * levels + l + 1) / double(tones * levels));
      }
      for (int l = 0; l < levels; ++l) {
        const int mip = levels - 1 - l;
        tam_.images[std::size_t(t)][std::size_t(mip)] = levels_[std::size_t(l)].brightness;
        if (tam_.coloured) tam_.colourImages[std::size_t(t)][std::size_t(mip)] = levels_[std::size_t(l)].colour;
      }
    }
    tam_.thresholds.resize(std::size_t(tam_.mipLevels));
    for (int l = 0; l < levels; ++l) {
      respaceThresholds(thresholds_[std::size_t(l)], levels_[std::size_t(l)].brightness);  // the darkest tone's
      tam_.thresholds[std::size_t(levels - 1 - l)] = std::move(thresholds_[std::size_t(l)]);
    }
  }

 private:
  int side(int level) const { return tam_.resolution >> (tam_.strokeLevels - 1 - level); }

  // A bound on the strokes of one image, so that unreachable tones end (the stop rule ends the rest):
  // 64 times the strokes of the smallest ink that would cover the image once.
  long long strokeCap(int level) const {
    const double n = double(side(level));
    const double width = std::max(0.25, style_.stroke.width.min);
    const double length = style_.stroke.kind == StrokeKind::Stippling ? width : std::max(0.25, style_.stroke.length.min * n);
    return 100 + (long long)(64.0 * n * n / (width * length));
  }

  // Whether a step's candidates are worth handing to the workers. Waking them and waiting for them
  // costs about as much as rasterizing a few thousand pixels of ink, so the steps of small strokes
  // (a stipple dot is some 16 pixels a level) run on the calling thread: with two threads the
  // stippling example took 1.7 s against 1.4 s on one. Each candidate is scored the same either way,
  // so the result does not depend on this choice (nor on the thread count).
  bool stepWorthThreads(int level) const {
    constexpr double kMinThreadedStepPixels = 4096;
    const StrokeStyle& s = style_.stroke;
    const double width = 0.5 * (s.width.min + s.width.max) + 2;  // with the filter's reach
    double pixels = 0;
    for (int l = level; l < tam_.strokeLevels; ++l) {
      const double length = s.kind == StrokeKind::Stippling ? 0.0 : 0.5 * (s.length.min + s.length.max) * side(l);
      pixels += width * (length + width);
    }
    return pixels * double(candidates_.size()) >= kMinThreadedStepPixels;
  }

  void score(Candidate& candidate, int tone, int level, long long step, int index) const {
    detail::StrokeRandom random(style_.seed, tone, level, step, index);
    candidate.stroke = detail::candidateStroke(style_, tone, random);
    if (style_.stroke.kind == StrokeKind::Image) candidate.stroke.texture = tam_.strokeTexture.get();
    const double target = tam_.targets[std::size_t(tone)];
    const int levels = tam_.strokeLevels;
    candidate.footprints.resize(std::size_t(levels - level));
    double gain = 0, ink = 0;
    for (int l = level; l < levels; ++l) {
      const int n = side(l);
      stroke::InkFootprint& footprint = candidate.footprints[std::size_t(l - level)];
      footprint = stroke::rasterize(stroke::scaledPositions(candidate.stroke, double(n)), n, n, true);
      const detail::Progress progress = detail::measureProgress(footprint, levels_[std::size_t(l)], target);
      const double area = double(n) * double(n);
      gain += progress.gain / area;
      ink += progress.ink / area;
      if (l == level) candidate.darkening = progress.darkening / area;
    }
    candidate.score = ink > 0 ? gain / ink : -std::numeric_limits<double>::infinity();
  }

  // Strokes for tone `tone` at stroke level `level` until its mean darkness reaches the target.
  void fill(int tone, int level) {
    const double target = tam_.targets[std::size_t(tone)];
    LevelImage& image = levels_[std::size_t(level)];
    const long long cap = strokeCap(level);
    const bool threaded = stepWorthThreads(level);
    for (long long step = 0; step < cap; ++step) {
      const double mean = image.meanDarkness();
      if (mean >= target) return;
      if (threaded) {
        pool_.run(candidates_.size(), [&](std::size_t i) { score(candidates_[i], tone, level, step, int(i)); });
      } else {
        for (std::size_t i = 0; i < candidates_.size(); ++i) score(candidates_[i], tone, level, step, int(i));
      }
      tam_.candidatesEvaluated += (long long)candidates_.size();
      std::size_t best = 0;
      for (std::size_t i = 1; i < candidates_.size(); ++i) {
        if (candidates_[i].score > candidates_[best].score) best = i;
      }
      const Candidate& chosen = candidates_[best];
      if (!(chosen.darkening > 0)) return;  // no candidate can darken the image any more
      if (std::abs(mean + chosen.darkening - target) >= std::abs(mean - target)) return;
      for (int l = level; l < tam_.strokeLevels; ++l) {
        detail::applyFootprint(chosen.footprints[std::size_t(l - level)], kernel_, levels_[std::size_t(l)]);
        markThresholds(chosen.footprints[std::size_t(l - level)], tone, l);
      }
      tam_.strokes.push_back({tone, level, chosen.stroke});
    }
  }

  // Webb et al. draw the darkest layer's ink where the darkness asked for has reached the threshold,
  // so the thresholds must reproduce the tone: with every texel whose threshold is <= d inked, the
  // image's mean darkness must be d. The placement order is kept and the values respaced: the texels
  // one stroke turned to ink (one value) get the mean darkness of the darkest image's ink over them and
  // every texel inked before them.
  static void respaceThresholds(stroke::Raster& thresholds, const stroke::Raster& darkest) {
    std::vector<std::size_t> inked;
    for (std::size_t i = 0; i < thresholds.values.size(); ++i)
      if (thresholds.values[i] < 1.0f) inked.push_back(i);
    std::stable_sort(inked.begin(), inked.end(),
                     [&](std::size_t a, std::size_t b) { return thresholds.values[a] < thresholds.values[b]; });
    const double texels = double(thresholds.values.size());
    double ink = 0;
    for (std::size_t begin = 0; begin < inked.size();) {
      std::size_t end = begin;
      const float value = thresholds.values[inked[begin]];
      for (; end < inked.size() && thresholds.values[inked[end]] == value; ++end) ink += 1.0 - double(darkest.values[inked[end]]);
      const float respaced = float(std::min(ink / texels, 1.0));
      for (std::size_t k = begin; k < end; ++k) thresholds.values[inked[k]] = respaced;
      begin = end;
    }
  }

  // The texels of the footprint that this stroke turned to ink get the image's darkness now, kept
  // within the tone's range: Webb et al.'s threshold, graded by the order of placement (respaced
  // once the darkest tone is built).
  void markThresholds(const stroke::InkFootprint& footprint, int tone, int level) {
    const LevelImage& image = levels_[std::size_t(level)];
    const double low = tone > 0 ? tam_.targets[std::size_t(tone - 1)] : 0.0;
    const float value = float(std::clamp(image.meanDarkness(), low, tam_.targets[std::size_t(tone)]));
    stroke::Raster& thresholds = thresholds_[std::size_t(level)];
    for (const stroke::InkFootprint::Pixel& p : footprint.pixels) {
      float& threshold = thresholds.at(p.x, p.y);
      if (threshold == 1.0f && 1.0 - double(image.brightness.at(p.x, p.y)) >= format::tam::kThresholdInk) threshold = value;
    }
  }

  const Style& style_;
  const BuildOptions& options_;
  Tam& tam_;
  std::vector<stroke::Raster> thresholds_;  // per stroke level, level 0 = coarsest
  detail::Kernel kernel_;
  detail::StepPool pool_;
  std::vector<Candidate> candidates_;
  std::vector<LevelImage> levels_;  // the tone being built, level 0 = coarsest stroke level
};

}  // namespace

int strokeLevelCount(const Style& style) {
  if (!isPowerOfTwo(style.resolution)) return 1;
  int levels = std::clamp(style.levels, 1, log2Int(style.resolution) + 1);
  const double minSide = std::max(8.0, 4.0 * style.stroke.width.max);
  while (levels > 1 && double(style.resolution >> (levels - 1)) < minSide) --levels;
  return levels;
}

Status checkStyle(const Style& style) {
  if (style.tones.empty()) return styleError(style, "/tones", "needs at least one tone");
  if (int(style.tones.size()) > format::tam::kMaxTones)
    return styleError(style, "/tones", "has " + std::to_string(style.tones.size()) + " tones, at most " +
                                           std::to_string(format::tam::kMaxTones) + " are allowed");
  for (std::size_t k = 0; k < style.tones.size(); ++k) {
    const double t = style.tones[k];
    const std::string pointer = "/tones/" + std::to_string(k);
    if (!std::isfinite(t) || t <= 0 || t >= 1) return styleError(style, pointer, "is " + std::to_string(t) + ", must be in (0, 1)");
    if (k > 0 && !(t > style.tones[k - 1])) return styleError(style, pointer, "must be greater than the previous tone");
  }
  if (!isPowerOfTwo(style.resolution) || style.resolution > 16384)
    return styleError(style, "/resolution", "is " + std::to_string(style.resolution) + ", must be a power of two <= 16384");
  if (style.levels < 1) return styleError(style, "/levels", "must be >= 1");
  if (style.candidates < 1) return styleError(style, "/candidates", "must be >= 1");
  if (!std::isfinite(style.blurSigma) || style.blurSigma < 0 || style.blurSigma > 64)
    return styleError(style, "/blurSigma", "must be in [0, 64]");
  const StrokeStyle& s = style.stroke;
  BAKE_RETURN_IF_ERROR(checkRange(style, "/stroke/width", s.width, 1e-3));
  if (s.width.max > double(style.resolution))
    return styleError(style, "/stroke/width/max", "is wider than the tile (" + std::to_string(style.resolution) + " pixels)");
  if (s.kind != StrokeKind::Stippling) BAKE_RETURN_IF_ERROR(checkRange(style, "/stroke/length", s.length, 1e-6));
  if (s.length.max > 4) return styleError(style, "/stroke/length/max", "must be <= 4 tiles");
  for (double v : {s.angleDegrees, s.angleJitterDegrees, s.curvature, s.crossAngleDegrees, s.taper}) {
    if (!std::isfinite(v)) return styleError(style, "/stroke", "has a non-finite value");
  }
  if (!(s.opacity > 0 && s.opacity <= 1)) return styleError(style, "/stroke/opacity", "must be in (0, 1]");
  if (!(s.centreOpacity >= 0 && s.centreOpacity <= 1)) return styleError(style, "/stroke/centreOpacity", "must be in [0, 1]");
  if (!(s.edgeOpacity >= 0 && s.edgeOpacity <= 1)) return styleError(style, "/stroke/edgeOpacity", "must be in [0, 1]");
  for (int c = 0; c < 3; ++c) {
    if (!(s.colour[std::size_t(c)] >= 0 && s.colour[std::size_t(c)] <= 1))
      return styleError(style, "/stroke/colour/" + std::to_string(c), "must be in [0, 1]");
  }
  if (s.kind == StrokeKind::Image) {
    if (s.texture.width < 1 || s.texture.height < 1 ||
        s.texture.alpha.size() != std::size_t(s.texture.width) * std::size_t(s.texture.height))
      return styleError(style, "/stroke/image", "stroke image " + s.image + " has no pixels");
    for (float a : s.texture.alpha) {
      if (!(a >= 0 && a <= 1)) return styleError(style, "/stroke/image", "stroke image " + s.image + " has alpha outside [0, 1]");
    }
  }
  return Status::ok();
}

Result<Tam> buildTam(const Style& style, const BuildOptions& options) {
  BAKE_RETURN_IF_ERROR(checkStyle(style));
  Tam tam;
  tam.tones = int(style.tones.size());
  tam.resolution = style.resolution;
  tam.strokeLevels = strokeLevelCount(style);
  tam.mipLevels = log2Int(style.resolution) + 1;
  tam.coloured = style.coloured();
  tam.targets = style.tones;
  if (style.stroke.kind == StrokeKind::Image) tam.strokeTexture = std::make_shared<stroke::StrokeTexture>(style.stroke.texture);
  tam.images.assign(std::size_t(tam.tones), std::vector<stroke::Raster>(std::size_t(tam.mipLevels)));
  if (tam.coloured) tam.colourImages = tam.images;

  Builder(style, options, tam).run();

  // Mips below the stroke levels: 2x2 box averages (mean-preserving), the thresholds too.
  for (int m = tam.strokeLevels; m < tam.mipLevels; ++m)
    tam.thresholds[std::size_t(m)] = detail::boxHalve(tam.thresholds[std::size_t(m - 1)]);
  for (int t = 0; t < tam.tones; ++t) {
    for (int m = tam.strokeLevels; m < tam.mipLevels; ++m) {
      auto& chain = tam.images[std::size_t(t)];
      chain[std::size_t(m)] = detail::boxHalve(chain[std::size_t(m - 1)]);
      if (tam.coloured) {
        auto& colour = tam.colourImages[std::size_t(t)];
        colour[std::size_t(m)] = detail::boxHalve(colour[std::size_t(m - 1)]);
      }
    }
  }
  return tam;
}

std::vector<stroke::Raster> thresholdTexture(const Tam& tam) { return tam.thresholds; }

}  // namespace bake::hatching
