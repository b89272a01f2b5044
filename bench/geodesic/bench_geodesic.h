// bench-geodesic: error against run time of every geodesic method, ours and CGAL's, on a ladder of
// meshes from a thousand to over a million triangles. The stages, in the order the program runs them:
//
//   ladder.cpp        meshes: the shared real meshes and a sphere, refined by 1:4 subdivision
//   isolated_run.cpp  each method runs in a child process (a crash, a hang or an exhausted memory is a
//                     failed row, not a failed benchmark), timed as a median of repetitions
//   methods.cpp       the methods: exact, heat and fast marching (libbake), CGAL's exact and heat
//   main.cpp          options, errors against the exact reference, CSV and a summary of ratios
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "bake/core/status.h"
#include "bake/geodesic/surface.h"

namespace bake::bench {

// ---- ladder.cpp ----
struct Rung {
  std::string name;  // "teapot/2" = teapot subdivided twice
  geodesic::Surface surface;
  std::vector<std::uint32_t> sources;  // 8 vertices of the base mesh (kept by subdivision), spread apart
};

struct LadderOptions {
  std::vector<std::filesystem::path> meshes;  // base meshes; the sphere joins unless `meshes` was given
  bool sphere = true;
  std::size_t maxTriangles = 1'400'000;
  bool loopSmoothing = false;  // Loop's smoothing rules instead of plain midpoints
};

// A base mesh of the ladder: welded and cleaned, with its sources.
struct LadderBase {
  std::string name;  // file stem, or "sphere"
  geodesic::Surface surface;
  std::vector<std::uint32_t> sources;
};
Result<std::vector<LadderBase>> loadBases(const LadderOptions& options);

// The rungs (base, subdivision levels) up to maxTriangles, smallest first.
struct RungPlan {
  std::size_t base;
  int levels;
  std::size_t triangles;
};
std::vector<RungPlan> planLadder(const std::vector<LadderBase>& bases, std::size_t maxTriangles);
Rung buildRung(const LadderBase& base, int levels, bool loopSmoothing);

geodesic::Surface subdivide(const geodesic::Surface& surface, bool loopSmoothing);
geodesic::Surface icosphere(int levels);

// ---- isolated_run.cpp ----
struct Measurement {
  std::vector<double> distances;
  double seconds = 0.0;       // median per field
  double setupSeconds = 0.0;  // once per mesh (factorisation); 0 when a method has none
  int runs = 0;
};

struct RunOutcome {
  bool ok = false;
  std::string error;
  Measurement measurement;
};

// Runs `job` in a forked child and returns what it measured, or why it failed (exception, signal,
// time-out after `timeoutSeconds`, address space above `memoryLimitBytes` when that is not 0).
RunOutcome runIsolated(const std::function<Measurement()>& job, double timeoutSeconds, double memoryLimitBytes);

// How often a measurement repeats: `repeats` times, and more while they add up to under `minSeconds`
// (a field of 0.1 ms measured three times is mostly the machine's noise), at most kMaxRepeats; fewer
// once `budgetSeconds` is spent, at least once. The same rule for every method, ours and the peers'.
struct RepeatRule {
  int repeats = 5;
  double minSeconds = 0.25;
  double budgetSeconds = 20.0;
  static constexpr int kMaxRepeats = 200;
  bool again(int done, double elapsedSeconds) const;
};

// Times `field` as `rule` says; the median.
double medianSeconds(const std::function<void()>& field, const RepeatRule& rule, int* runs);
double medianOf(std::vector<double> times);  // of a non-empty list; 0 for none

// ---- methods.cpp ----
struct MethodSettings {
  RepeatRule repeat;
};

struct Method {
  std::string name;  // exact, heat, fmm, cgal-exact, cgal-heat
  std::function<Measurement(const geodesic::Surface&, const std::vector<std::uint32_t>&)> run;
};
std::vector<Method> allMethods(const MethodSettings& settings);

}  // namespace bake::bench
