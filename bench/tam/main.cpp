// bench-tam: the tonal art map construction (libbake/hatching/build.h) on the default style (6 tones
// evenly spaced up to darkness 0.9, 4 stroke levels, hatching; --kind cross-hatching crosses from
// tone 3 on, --kind stippling draws dots 1.5-2.5 px wide), sweeping the candidate count K and the
// finest resolution. Per (K, resolution): the median construction time over --repeats builds and the
// quality figures of hatching/bake/quality.h (deterministic for the seed): the largest tone error and its ratio
// to the tolerance max(0.25 %, 0.8 / N), the largest coefficient of variation over quarter-tile
// windows and the largest low-frequency power share, over the images the uniformity targets apply to
// and over all stroke images. Writes tam.csv (and, with --detail, images.csv: every image's figures);
// progress on stderr.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "hatching/bake/build.h"
#include "hatching/bake/quality.h"

namespace {

using namespace bake::hatching;

struct Options {
  std::vector<int> candidates{1, 2, 4, 8, 16, 32};
  std::vector<int> resolutions{64, 128, 256, 512};
  int repeats = 3;
  int threads = 2;
  std::uint64_t seed = 1;
  std::string out = "build-bench/results";
  bool detail = false;
  std::string images;  // folder for PGM images of the last build
  std::string kind = "hatching";
};

// Binary PGM of a brightness image.
void writePgm(const std::string& path, const bake::stroke::Raster& image) {
  std::ofstream out(path, std::ios::binary);
  out << "P5\n" << image.width << ' ' << image.height << "\n255\n";
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) out.put(char(static_cast<unsigned char>(std::lround(255.0f * image.at(x, y)))));
  }
}

Style benchStyle(int candidates, int resolution, std::uint64_t seed, const std::string& kind) {
  Style style;
  if (kind == "cross-hatching") {
    style.stroke.kind = StrokeKind::CrossHatching;
    style.stroke.crossFrom = 3;  // the darker half crosses
  } else if (kind == "stippling") {
    style.stroke.kind = StrokeKind::Stippling;
    style.stroke.width = {1.5, 2.5};
  }
  style.source = "default";
  for (int k = 1; k <= 6; ++k) style.tones.push_back(0.9 * k / 6.0);
  style.resolution = resolution;
  style.levels = 4;
  style.candidates = candidates;
  style.seed = seed;
  return style;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{"TAM construction: quality against construction time over K and resolution"};
  app.add_option("--candidates", options.candidates, "candidate counts K")->delimiter(',');
  app.add_option("--resolutions", options.resolutions, "finest resolutions")->delimiter(',');
  app.add_option("--repeats", options.repeats, "builds per point (median time)");
  app.add_option("--threads", options.threads, "construction threads");
  app.add_option("--seed", options.seed, "construction seed");
  app.add_option("--kind", options.kind, "stroke kind")->check(CLI::IsMember({"hatching", "cross-hatching", "stippling"}));
  app.add_option("--out", options.out, "output folder");
  app.add_flag("--detail", options.detail, "also write every image's figures (images.csv)");
  app.add_option("--images", options.images, "write the stroke images of each build as PGM into this folder");
  bool quick = false;
  app.add_flag("--quick", quick, "K 1,4,16 at 64,128,256, one repeat");
  CLI11_PARSE(app, argc, argv);
  if (quick) {
    options.candidates = {1, 4, 16};
    options.resolutions = {64, 128, 256};
    options.repeats = 1;
  }
  std::filesystem::create_directories(options.out);
  std::ofstream csv(options.out + "/tam.csv");
  csv << "candidates,resolution,seconds,max_tone_error,max_tone_error_over_tolerance,max_cv,max_low_frequency_power,"
         "max_cv_all,max_low_frequency_power_all,nesting_violations,strokes,candidates_evaluated\n";
  std::ofstream images;
  if (options.detail) {
    images.open(options.out + "/images.csv");
    images << "candidates,resolution,tone,mip,side,target,darkness,tone_error,tone_tolerance,cv,low_frequency_power,"
              "strokes,uniformity_checked\n";
  }
  for (int resolution : options.resolutions) {
    for (int k : options.candidates) {
      const Style style = benchStyle(k, resolution, options.seed, options.kind);
      BuildOptions build;
      build.threads = options.threads;
      std::vector<double> times;
      Tam tam;
      for (int r = 0; r < std::max(1, options.repeats); ++r) {
        const auto start = std::chrono::steady_clock::now();
        bake::Result<Tam> result = buildTam(style, build);
        times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        if (!result.isOk()) {
          std::fprintf(stderr, "bench-tam: error: %s\n", result.status().describe().c_str());
          return 4;
        }
        tam = std::move(result).value();
      }
      std::sort(times.begin(), times.end());
      const double seconds = times[times.size() / 2];
      const Quality q = measureQuality(tam);
      csv << k << ',' << resolution << ',' << seconds << ',' << q.maxToneError << ',' << q.maxToneErrorOverTolerance << ','
          << q.maxInkVariation << ',' << q.maxLowFrequencyPower << ',' << q.maxInkVariationAll << ','
          << q.maxLowFrequencyPowerAll << ',' << q.nestingViolationsTone + q.nestingViolationsResolution << ','
          << tam.strokes.size() << ',' << tam.candidatesEvaluated << '\n';
      std::fprintf(stderr, "K %2d  %4d^2  %7.3f s  tone error %.4f (%.2f of tolerance)  cv %.3f  lfp %.4f  (all: cv %.3f lfp %.4f)  %zu strokes\n",
                   k, resolution, seconds, q.maxToneError, q.maxToneErrorOverTolerance, q.maxInkVariation,
                   q.maxLowFrequencyPower, q.maxInkVariationAll, q.maxLowFrequencyPowerAll, tam.strokes.size());
      if (!options.images.empty()) {
        std::filesystem::create_directories(options.images);
        for (int t = 0; t < tam.tones; ++t) {
          for (int m = 0; m < tam.strokeLevels; ++m) {
            writePgm(options.images + "/k" + std::to_string(k) + "_r" + std::to_string(resolution) + "_t" + std::to_string(t) +
                         "_m" + std::to_string(m) + ".pgm",
                     tam.images[std::size_t(t)][std::size_t(m)]);
          }
        }
      }
      if (options.detail) {
        for (const ImageQuality& iq : q.images) {
          images << k << ',' << resolution << ',' << iq.tone << ',' << iq.mip << ',' << iq.side << ',' << iq.target << ','
                 << iq.darkness << ',' << iq.toneError << ',' << iq.toneTolerance << ',' << iq.inkVariation << ','
                 << iq.lowFrequencyPower << ',' << iq.strokes << ',' << (iq.uniformityChecked ? 1 : 0) << '\n';
        }
      }
    }
  }
  return 0;
}
