// bench-groove: the seed's method on the CPU (libbake/grooves/oracle/shade.h, seed 000 §4-§7) against the
// independent ray-traced reference (reference.h) on the scene set of bench/groove/scenes, rendered
// from the views of cases.json (view and light sweeps, footprint sizes, bounce counts). Per view:
// the fastest time per frame of the method, the reference's time at --spp samples per pixel (wall
// seconds per frame, and cost per pixel in CPU time), the
// method's error against the reference (RMSE, relative MSE, 99th percentile), and the reference's own
// noise floor: the RMSE between two reference renders with different seeds (small frames are rendered
// a few more times for timing alone, see kMinReferenceCpu). The criterion of the
// method is an RMSE within 3x that floor at 50x less cost per pixel. The method runs as the runtime
// shader computes it (exact trapezoid footprint density, grooves straightened at the footprint except
// for curved sections on tight arcs; --straight-arcs leaves those out; past kMaxFoundPerFootprint
// primitives under a footprint, the far level) and, for comparison, as the
// seed publishes it (uniform footprint segment, straight arcs): its RMSE is the seed_rmse column. Writes groove.csv (one row per view) and, with
// --images, EXR images of the method and the reference; progress on stderr.
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <bake_formats/grooves.h>
#include <nlohmann/json.hpp>

#include "grooves/bake/grid.h"
#include "grooves/input/scene.h"
#include "grooves/oracle/render.h"
#include "grooves/oracle/shade.h"
#include "grooves/reference/reference.h"
#include "runtime_view.h"

namespace {

using namespace bake::grooves;
using Clock = std::chrono::steady_clock;
constexpr double kMinMeasuredCpu = 0.05;  // seconds of CPU per measurement of the method
// Seconds of CPU the reference's timing renders add up to at least: a small frame (a single pixel of
// the dense set is ~30 ms at 256 spp) is rendered again (another seed, timing only) until they do,
// each extra render followed by one more measurement of the method, so that both sides keep the
// fastest of several and a short slow spell cannot decide either.
constexpr double kMinReferenceCpu = 0.3;
constexpr int kMaxExtraReferenceRenders = 16;

struct Options {
  std::string cases = "bench/groove/cases.json";
  std::string out = "build-bench/results";
  std::string images;
  std::string only;  // run the cases whose name contains this
  int spp = 256;
  int repeats = 3;
  // One thread for both renderers by default: cost per pixel is then the CPU time of the shading
  // alone. With more, every frame starts its threads anew, and a new thread's per-thread scratch
  // (grown buffers, reused pixel after pixel) is allocated again: on small frames that start-up is
  // a sizeable part of the method's CPU time and a negligible one of the reference's.
  int threads = 1;
  bool quick = false;  // first view of every case, 64 spp
  bool straightArcs = false;  // the method without curved sections on tight arcs
  bool runtime = false;       // also the runtime's GL image of every view (runtime_view.h)
};

// One rendering to measure: a scene, a window of it, a pixel count across, a view, a light.
struct Job {
  std::string caseName, sceneFile;
  Vec2 lower, upper;
  int width = 32;
  double viewTheta = 0, viewPhi = 0, lightTheta = 0, lightPhi = 0;
  int bounces = 0;
};

double radians(double degrees) { return degrees * std::numbers::pi / 180; }

std::vector<double> numbers(const nlohmann::json& j, const char* key, double fallback) {
  if (!j.contains(key)) return {fallback};
  if (j[key].is_number()) return {j[key].get<double>()};
  return j[key].get<std::vector<double>>();
}

// cases.json: {"cases": [{"name", "scene", "window": [[u0, v0], [u1, v1]], "width": n or [n...],
// "view": {"theta": deg or [...], "phi": ...}, "light": {"theta", "phi"}, "bounces": n or [...]}]}:
// every combination of the listed values is one job.
std::vector<Job> readJobs(const std::string& path, const std::string& only, bool quick) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read");
  const nlohmann::json doc = nlohmann::json::parse(in);
  std::vector<Job> jobs;
  for (const auto& c : doc.at("cases")) {
    const std::string name = c.at("name");
    if (!only.empty() && name.find(only) == std::string::npos) continue;
    const auto& window = c.at("window");
    const nlohmann::json view = c.value("view", nlohmann::json::object());
    const nlohmann::json light = c.value("light", nlohmann::json::object());
    std::size_t before = jobs.size();
    for (double width : numbers(c, "width", 32))
      for (double vt : numbers(view, "theta", 0))
        for (double vp : numbers(view, "phi", 0))
          for (double lt : numbers(light, "theta", 0))
            for (double lp : numbers(light, "phi", 0))
              for (double bounces : numbers(c, "bounces", 0)) {
                if (quick && jobs.size() > before) continue;
                Job job;
                job.caseName = name;
                job.sceneFile = (std::filesystem::path(path).parent_path() / "scenes" / c.at("scene").get<std::string>()).string();
                job.lower = {window[0][0], window[0][1]};
                job.upper = {window[1][0], window[1][1]};
                job.width = static_cast<int>(width);
                job.viewTheta = vt;
                job.viewPhi = vp;
                job.lightTheta = lt;
                job.lightPhi = lp;
                job.bounces = static_cast<int>(bounces);
                jobs.push_back(job);
              }
  }
  return jobs;
}

// Wall and CPU seconds (all threads of the process) of one call. Cost per pixel is CPU time: it does
// not depend on waits for a core on a shared machine (thread start-up on a busy 2-core machine can
// take a scheduler slice, milliseconds, longer than a small frame itself).
struct Seconds {
  double wall = 0, cpu = 0;
};

double processCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

template <typename F>
Seconds secondsOf(F&& f) {
  const auto start = Clock::now();
  const double cpuStart = processCpuSeconds();
  f();
  return {std::chrono::duration<double>(Clock::now() - start).count(), processCpuSeconds() - cpuStart};
}

// The fastest of several measurements: on a shared machine, noise only ever adds time, so the
// minimum is the steadiest estimate of a frame's cost. Both renderers are measured the same way.
double fastest(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }

struct LoadedScene {
  std::string file;
  GrooveScene scene;
  GrooveGrid grid;
};

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"bench-groove: the seed's groove shading against the ray-traced reference, error against time"};
  app.add_option("--cases", o.cases, "the views to render (cases.json)");
  app.add_option("--out", o.out, "results folder (groove.csv)");
  app.add_option("--images", o.images, "write method and reference EXR images here");
  app.add_option("--only", o.only, "only the cases whose name contains this");
  app.add_option("--spp", o.spp, "reference samples per pixel (a square)");
  app.add_option("--repeats", o.repeats,
                 "method measurements per view, interleaved with the reference's two renders (the fastest of each is "
                 "kept; frames under 0.3 s of reference CPU get more of both)");
  app.add_option("--threads", o.threads, "threads for both renderers (default 1: CPU time of the shading alone)");
  app.add_flag("--quick", o.quick, "one view per case at 64 samples per pixel");
  app.add_flag("--straight-arcs", o.straightArcs, "the method without its curved sections on tight arcs (as the seed)");
  app.add_flag("--runtime", o.runtime,
               "also draw every view with bakeplay's grooves renderer (headless GL) and measure it against the reference");
  CLI11_PARSE(app, argc, argv);
  if (o.quick) o.spp = std::min(o.spp, 64);

  std::vector<Job> jobs;
  try {
    jobs = readJobs(o.cases, o.only, o.quick);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench-groove: %s\n", e.what());
    return 2;
  }
  std::filesystem::create_directories(o.out);
  if (!o.images.empty()) std::filesystem::create_directories(o.images);
  std::ofstream csv(std::filesystem::path(o.out) / "groove.csv");
  csv << "case,scene,width,pixels,view_theta,view_phi,light_theta,light_phi,bounces,footprint_over_width,"
         "special_fraction,method_frame_s,method_ns_per_pixel,reference_frame_s,reference_ns_per_pixel,"
         "cost_ratio,rmse,relative_mse,p99,max,noise_floor,rmse_over_floor,seed_rmse,seed_rmse_over_floor,"
         "runtime_rmse,runtime_rmse_over_floor,runtime_far_fragments\n";
  std::unique_ptr<RuntimeViews> runtime;
  if (o.runtime) {
    auto created = RuntimeViews::create();
    if (!created.isOk()) {
      std::fprintf(stderr, "bench-groove: --runtime: %s\n", created.status().describe().c_str());
      return 3;
    }
    runtime = std::move(created).value();
  }

  LoadedScene loaded;
  std::size_t index = 0;
  for (const Job& job : jobs) {
    ++index;
    if (loaded.file != job.sceneFile) {
      auto scene = readGrooveScene(job.sceneFile);
      if (!scene.isOk()) {
        std::fprintf(stderr, "bench-groove: %s\n", scene.status().message().c_str());
        return 3;
      }
      loaded.scene = std::move(scene.value());
      GridSettings gridSettings;
      gridSettings.threads = o.threads;
      auto grid = buildGrooveGrid(loaded.scene, gridSettings);
      if (!grid.isOk()) {
        std::fprintf(stderr, "bench-groove: %s\n", grid.status().message().c_str());
        return 3;
      }
      loaded.grid = std::move(grid.value());
      loaded.file = job.sceneFile;
      if (runtime) {
        const bake::Status status = runtime->load(loaded.scene, loaded.grid, std::filesystem::path(o.out) / "runtime");
        if (!status.isOk()) {
          std::fprintf(stderr, "bench-groove: --runtime: %s\n", status.describe().c_str());
          return 3;
        }
      }
    }
    const View view = windowView(job.lower, job.upper, job.width, radians(job.viewTheta), radians(job.viewPhi));
    Lighting lighting;
    lighting.toLight = directionFromAngles(radians(job.lightTheta), radians(job.lightPhi));
    lighting.maxBounces = job.bounces;

    SeedSettings ours;
    ours.curvedSections = !o.straightArcs;
    // As the shader holds it: a footprint over more primitives is shaded from the far level.
    ours.foundCap = bake::format::grooves::kMaxFoundPerFootprint;
    SeedSettings published;
    published.density = FootprintDensity::SeedSegment;
    published.curvedSections = false;
    bake::Image method;
    // Small frames are rendered several times per measurement, so that one takes at least
    // kMinMeasuredCpu: the clock's resolution and the threads' start-up are then negligible.
    const auto renderMethod = [&] { method = renderSeed(loaded.scene, loaded.grid, view, lighting, o.threads, ours); };
    const Seconds first = secondsOf(renderMethod);
    const int framesPerMeasurement = int(std::clamp(std::ceil(kMinMeasuredCpu / std::max(first.cpu, 1e-9)), 1.0, 1e4));
    std::vector<double> wallTimes, cpuTimes;
    const auto measureMethod = [&] {
      const Seconds t = secondsOf([&] {
        for (int k = 0; k < framesPerMeasurement; ++k) renderMethod();
      });
      wallTimes.push_back(t.wall / framesPerMeasurement);
      cpuTimes.push_back(t.cpu / framesPerMeasurement);
    };

    ReferenceSettings reference;
    reference.samplesPerPixel = o.spp;
    reference.threads = o.threads;
    bake::Image truth, second;
    // The method's measurements are interleaved with the reference's two renders (M R M R M ...), so
    // that both sample the same stretch of time on a machine whose speed drifts: each side keeps its
    // fastest, and a slow spell cannot fall on one side alone.
    const int repeats = std::max(1, o.repeats);
    measureMethod();
    reference.seed = 1;
    const Seconds referenceTime = secondsOf([&] { truth = renderReference(loaded.scene, view, lighting, reference); });
    if (repeats > 1) measureMethod();
    reference.seed = 2;
    // The second render (another seed: the noise floor) is a second measurement of the same cost.
    const Seconds secondTime = secondsOf([&] { second = renderReference(loaded.scene, view, lighting, reference); });
    for (int r = 2; r < repeats; ++r) measureMethod();
    std::vector<double> referenceWall{referenceTime.wall, secondTime.wall};
    std::vector<double> referenceCpus{referenceTime.cpu, secondTime.cpu};
    double referenceCpuTotal = referenceTime.cpu + secondTime.cpu;
    for (int extra = 0; extra < kMaxExtraReferenceRenders && referenceCpuTotal < kMinReferenceCpu; ++extra) {
      reference.seed = 3 + std::uint64_t(extra);
      bake::Image timingOnly;
      const Seconds t = secondsOf([&] { timingOnly = renderReference(loaded.scene, view, lighting, reference); });
      referenceWall.push_back(t.wall);
      referenceCpus.push_back(t.cpu);
      referenceCpuTotal += t.cpu;
      measureMethod();
    }
    const double methodSeconds = fastest(wallTimes), methodCpu = fastest(cpuTimes);
    const double referenceSeconds = fastest(referenceWall);
    const double referenceCpu = fastest(referenceCpus);
    const bake::Image seedMethod = renderSeed(loaded.scene, loaded.grid, view, lighting, o.threads, published);

    // How many pixels took the special-case path.
    std::size_t special = 0;
    {
      const SeedShader shader(loaded.scene, loaded.grid, ours);
      for (int y = 0; y < view.height; ++y)
        for (int x = 0; x < view.width; ++x) {
          ShadeStats stats;
          shader.shade(view.pixel(x, y), view.toViewer, lighting, &stats);
          special += stats.special ? 1 : 0;
        }
    }

    const ImageError error = imageError(method, truth);
    const ImageError floor = imageError(second, truth);
    const ImageError seedError = imageError(seedMethod, truth);
    // The runtime's own image of the view (-1 without --runtime).
    double runtimeRmse = -1, runtimeRatio = -1;
    std::size_t farFragments = 0;
    if (runtime) {
      auto drawn = runtime->render(view, lighting, &farFragments);
      if (!drawn.isOk()) {
        std::fprintf(stderr, "bench-groove: --runtime: %s\n", drawn.status().describe().c_str());
        return 3;
      }
      runtimeRmse = imageError(*drawn, truth).rmse;
      runtimeRatio = floor.rmse > 0 ? runtimeRmse / floor.rmse : 0;
    }
    const double pixels = double(view.width) * view.height;
    const double footprint = std::hypot(view.axisX.u, view.axisX.v);
    const double grooveWidth = 2 * loaded.scene.wmax;
    const std::string sceneName = std::filesystem::path(job.sceneFile).stem().string();
    char row[1024];
    std::snprintf(row, sizeof row,
                  "%s,%s,%d,%.0f,%g,%g,%g,%g,%d,%.6g,%.4f,%.6g,%.6g,%.6g,%.6g,%.4g,%.6g,%.6g,%.6g,%.6g,%.6g,%.4g,%.6g,%.4g,"
                  "%.6g,%.4g,%zu\n",
                  job.caseName.c_str(), sceneName.c_str(), job.width, pixels, job.viewTheta, job.viewPhi,
                  job.lightTheta, job.lightPhi, job.bounces, grooveWidth > 0 ? footprint / grooveWidth : 0,
                  special / pixels, methodSeconds, 1e9 * methodCpu / pixels, referenceSeconds,
                  1e9 * referenceCpu / pixels, referenceCpu / methodCpu, error.rmse, error.relativeMse,
                  error.p99, error.max, floor.rmse, floor.rmse > 0 ? error.rmse / floor.rmse : 0, seedError.rmse,
                  floor.rmse > 0 ? seedError.rmse / floor.rmse : 0, runtimeRmse, runtimeRatio, farFragments);
    csv << row << std::flush;
    std::fprintf(stderr,
                 "[%zu/%zu] %s %s view %g/%g light %g/%g b%d: rmse %.3g (floor %.3g, x%.2f; seed's x%.2f; runtime x%.2f), "
                 "%.0f ns/px vs %.0f ns/px\n",
                 index, jobs.size(), job.caseName.c_str(), sceneName.c_str(), job.viewTheta, job.viewPhi, job.lightTheta,
                 job.lightPhi, job.bounces, error.rmse, floor.rmse, floor.rmse > 0 ? error.rmse / floor.rmse : 0.0,
                 floor.rmse > 0 ? seedError.rmse / floor.rmse : 0.0, runtimeRatio, 1e9 * methodCpu / pixels,
                 1e9 * referenceCpu / pixels);
    if (!o.images.empty()) {
      char stem[256];
      std::snprintf(stem, sizeof stem, "%s-%03zu", job.caseName.c_str(), index);
      const std::filesystem::path dir(o.images);
      (void)bake::writeImage(dir / (std::string(stem) + "-method.exr"), method, bake::PixelType::Float);
      (void)bake::writeImage(dir / (std::string(stem) + "-reference.exr"), truth, bake::PixelType::Float);
    }
  }
  return 0;
}
