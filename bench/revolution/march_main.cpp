// bench-revolution-march: error against run time of revolution mapping, per profile.
//   bake.csv:  for each resolution and distance encoding, the bake's two costs (the exact signed
//              distance field; encode + decode + safety margin) and what the encoding stores (margin
//              and largest stored error, in texels).
//   march.csv: at one resolution (unorm16, the proxy bands revolbake writes), the CPU march (identical
//              to the shader) against the analytic intersection, per iteration budget, with and
//              without the proxy bands and with plain (omega 1.0) and over-relaxed (1.6) steps; each
//              row also times one single-threaded march of a fixed ray set under that budget.
// Errors are deterministic; times are medians of --repeats runs. Progress on stderr.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bake/revolution/profile.h"
#include "bake/revolution/shape_map.h"
#include "revolution/oracle/march.h"

namespace {

using namespace bake::revolution;
using bake::Vec3d;

constexpr int kPaddingTexels = 4;  // revolbake's default
constexpr int kProxyBands = 32;    // revolbake's default

struct Options {
  std::vector<std::string> profiles;
  std::vector<int> resolutions{256, 512, 1024, 2048, 4096};
  int repeats = 3;
  int marchResolution = 1024;
  int timingRays = 65536;
  unsigned threads = 0;
  std::string out = "build-bench/results";
  bool quick = false;
};

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Median wall time of `repeats` calls of `work`.
template <class Work>
double medianSeconds(int repeats, Work&& work) {
  std::vector<double> times;
  for (int k = 0; k < std::max(1, repeats); ++k) {
    const auto start = std::chrono::steady_clock::now();
    work();
    times.push_back(secondsSince(start));
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

std::string stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

bake::Result<Profile> loadProfile(const std::string& path) {
  const std::string extension = std::filesystem::path(path).extension().string();
  bake::Result<Profile> read = extension == ".csv"   ? readProfileCsv(path)
                               : extension == ".svg" ? readProfileSvg(path)
                                                     : readProfileJson(path);
  if (!read) return read;
  std::vector<std::string> repairs;
  bake::Status valid = validateProfile(*read, repairs);
  if (!valid) return valid.inFile(path);
  return read;
}

// Largest |decoded - field| over the texel centres, in texels.
double storedErrorTexels(const ShapeField& field, const ShapeField& decoded) {
  double worst = 0;
  for (std::size_t k = 0; k < field.distance.size(); ++k)
    worst = std::max(worst, double(std::abs(decoded.distance[k] - field.distance[k])));
  return worst / field.grid.texelSize;
}

void bakeRows(const std::string& name, const Profile& profile, const Options& options, std::FILE* csv) {
  const Bounds2 bounds = profileBounds(profile);
  for (int resolution : options.resolutions) {
    const ShapeGrid grid = gridForBounds(bounds, resolution, kPaddingTexels);
    ShapeField field;
    const double distanceSeconds = medianSeconds(options.repeats, [&] { field = distanceFromProfile(profile, grid); });
    for (DistanceEncoding encoding : {DistanceEncoding::Float, DistanceEncoding::Unorm16, DistanceEncoding::Sqrt8}) {
      ShapeField decoded;
      SafetyMargin margin;
      const double encodeSeconds = medianSeconds(options.repeats, [&] {
        const EncodedShapeMap encoded = encodeShapeMap(field, encoding);
        decoded = decodeShapeMap(encoded, grid);
        margin = measureSafetyMargin(decoded, &profile);
      });
      std::fprintf(csv, "%s,%d,%d,%d,%s,%.6g,%.6g,%.6g,%.6g\n", name.c_str(), resolution, grid.width, grid.height,
                   encodingName(encoding), distanceSeconds, encodeSeconds, margin.total() / grid.texelSize,
                   storedErrorTexels(field, decoded));
      std::fflush(csv);
      std::fprintf(stderr, "  bake %s %d %s: distance %.3g s, encode+margin %.3g s\n", name.c_str(), resolution,
                   encodingName(encoding), distanceSeconds, encodeSeconds);
    }
  }
}

// A double in [0, 1) from the generator's raw output (the same on every platform).
double unit(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

// The timing rays: towards points spread uniformly through the shape box's cylinder, from directions
// spread uniformly over the sphere, starting well outside. Every one enters the box.
std::vector<Ray> timingRays(const ShapeGrid& grid, int count) {
  const double radius = grid.width * grid.texelSize, height = grid.height * grid.texelSize;
  const double back = 4 * std::hypot(radius, height);
  std::mt19937_64 rng(20261130);
  std::vector<Ray> rays;
  for (int k = 0; k < count; ++k) {
    const double angle = 2 * M_PI * unit(rng), r = radius * std::sqrt(unit(rng));
    const Vec3d target{r * std::cos(angle), grid.hMin + height * unit(rng), r * std::sin(angle)};
    const double y = 2 * unit(rng) - 1, azimuth = 2 * M_PI * unit(rng), ring = std::sqrt(1 - y * y);
    Ray ray;
    ray.direction = {ring * std::cos(azimuth), y, ring * std::sin(azimuth)};
    for (int c = 0; c < 3; ++c) ray.origin[c] = target[c] - back * ray.direction[c];
    rays.push_back(ray);
  }
  return rays;
}

struct MarchSetup {
  ShapeGrid grid;
  EncodedShapeMap encoded;
  SafetyMargin margin;
  std::vector<ProxyBand> bands;
};

// What revolbake measures: unorm16, the margin of the decoded map, 32 bands less those without solid.
MarchSetup prepareMarch(const Profile& profile, int resolution) {
  MarchSetup setup;
  const ShapeField field = distanceFromProfile(profile, gridForBounds(profileBounds(profile), resolution, kPaddingTexels));
  setup.grid = field.grid;
  setup.encoded = encodeShapeMap(field, DistanceEncoding::Unorm16);
  setup.margin = measureSafetyMargin(decodeShapeMap(setup.encoded, setup.grid), &profile);
  setup.bands = buildProxyBands(field, kProxyBands, setup.margin.total());
  std::erase_if(setup.bands, [](const ProxyBand& band) { return !(band.rMax > 0); });
  return setup;
}

// One single-threaded march of every timing ray under `settings`: the median seconds and the mean
// fetches per ray (the count also keeps the marches from being optimised away).
struct Sweep {
  double seconds = 0, fetchesPerRay = 0;
};
Sweep timeSweep(const MarchSetup& setup, const std::vector<Ray>& rays, const MarchSettings& settings, int repeats) {
  long fetches = 0;
  Sweep sweep;
  sweep.seconds = medianSeconds(repeats, [&] {
    fetches = 0;
    for (const Ray& ray : rays) fetches += marchRay(ray, setup.encoded, setup.grid, setup.bands, settings).fetches;
  });
  sweep.fetchesPerRay = double(fetches) / double(std::max<std::size_t>(1, rays.size()));
  return sweep;
}

void marchRows(const std::string& name, const Profile& profile, const Options& options, std::FILE* csv) {
  const MarchSetup setup = prepareMarch(profile, options.marchResolution);
  const std::vector<Ray> rays = timingRays(setup.grid, options.timingRays);
  const double texel = setup.grid.texelSize;
  MarchErrorSettings sweep;
  sweep.threads = options.threads;
  for (bool proxy : {false, true}) {
    for (double omega : {1.0, 1.6}) {
      MarchSettings settings;
      settings.safetyMargin = setup.margin.total();
      settings.overRelaxation = omega;
      settings.useProxy = proxy;
      const auto start = std::chrono::steady_clock::now();
      const std::vector<MarchErrorPoint> curve =
          measureMarchError(profile, setup.encoded, setup.grid, setup.bands, settings, sweep);
      const double measureSeconds = secondsSince(start);
      for (const MarchErrorPoint& point : curve) {
        settings.maxIterations = point.iterations;
        const Sweep timed = timeSweep(setup, rays, settings, options.repeats);
        std::fprintf(csv, "%s,%d,%.2f,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", name.c_str(), proxy ? 1 : 0, omega,
                     point.iterations, point.silhouetteMismatch, point.meanHitError / texel, point.maxHitError / texel,
                     point.meanFetches, timed.seconds, 1e9 * timed.seconds / double(rays.size()), timed.fetchesPerRay,
                     measureSeconds);
      }
      std::fflush(csv);
      std::fprintf(stderr, "  march %s proxy %d omega %.1f: %.3g s to measure\n", name.c_str(), proxy ? 1 : 0, omega,
                   measureSeconds);
    }
  }
}

std::FILE* openCsv(const std::string& path, const char* header) {
  std::FILE* file = std::fopen(path.c_str(), "w");
  if (file) std::fprintf(file, "%s\n", header);
  return file;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{"Revolution mapping: bake cost per resolution and encoding, march error against run time"};
  app.add_option("--profile", options.profiles, "profile file (repeatable; default: pipelines/revolution/*.json)");
  auto* resolutions = app.add_option("--resolutions", options.resolutions, "shape map sizes (larger side)")->delimiter(',');
  auto* repeats = app.add_option("--repeats", options.repeats, "timing repetitions (median)")->check(CLI::PositiveNumber);
  app.add_option("--march-resolution", options.marchResolution, "shape map size for march.csv")->check(CLI::PositiveNumber);
  app.add_option("--timing-rays", options.timingRays, "rays in the single-threaded timing march")->check(CLI::PositiveNumber);
  app.add_option("--threads", options.threads, "threads for the measured march (0: all)");
  app.add_option("--out", options.out, "output directory");
  app.add_flag("--quick", options.quick, "resolutions 256,512,1024 and one repeat (unless given)");
  CLI11_PARSE(app, argc, argv);
  if (options.quick && resolutions->count() == 0) options.resolutions = {256, 512, 1024};
  if (options.quick && repeats->count() == 0) options.repeats = 1;
  if (options.profiles.empty())
    for (const char* name : {"vase", "ring", "plate"})
      options.profiles.push_back(std::string(BAKE_SOURCE_DIR) + "/pipelines/revolution/" + name + ".json");

  std::filesystem::create_directories(options.out);
  std::FILE* bakeCsv = openCsv(options.out + "/bake.csv",
                               "profile,resolution,width,height,encoding,distance_s,encode_margin_s,margin_texels,"
                               "stored_max_error_texels");
  std::FILE* marchCsv = openCsv(options.out + "/march.csv",
                                "profile,proxy,omega,iterations,silhouette_mismatch,mean_hit_error_texels,"
                                "max_hit_error_texels,mean_fetches,seconds,ns_per_ray,timing_fetches_per_ray,measure_total_s");
  if (!bakeCsv || !marchCsv) {
    std::fprintf(stderr, "bench-revolution-march: cannot write into %s\n", options.out.c_str());
    return 2;
  }
  for (const std::string& path : options.profiles) {
    bake::Result<Profile> profile = loadProfile(path);
    if (!profile) {
      std::fprintf(stderr, "bench-revolution-march: %s\n", profile.status().describe().c_str());
      return 3;
    }
    std::fprintf(stderr, "%s\n", path.c_str());
    bakeRows(stem(path), *profile, options, bakeCsv);
    marchRows(stem(path), *profile, options, marchCsv);
  }
  std::fclose(bakeCsv);
  std::fclose(marchCsv);
  std::fprintf(stderr, "results: %s/bake.csv, %s/march.csv\n", options.out.c_str(), options.out.c_str());
  return 0;
}
