// bench-geodesic: for every rung of the mesh ladder and for one and eight sources, runs every method
// (libbake's exact, heat and fast marching; CGAL's exact and heat), times it (median of repetitions;
// the heat methods' factorisation apart), measures its error against the exact distances (ours, or
// CGAL's where ours failed; each exact method is checked against the other) relative to the field's
// largest distance, and writes one CSV row per (mesh, method, sources). A summary of the ratios
// ours / CGAL measured in the same run goes to stdout and summary.txt. bench/README.md explains the
// columns; bench/geodesic/plot.gp draws error against time.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "bench_geodesic.h"

namespace bake::bench {
namespace {

std::filesystem::path defaultDataDir() {
  if (const char* fromEnvironment = std::getenv("BAKE_DATA_DIR"); fromEnvironment && *fromEnvironment)
    return std::filesystem::path(fromEnvironment) / "meshes" / "real";
  return std::filesystem::path("..") / "shared" / "data" / "meshes" / "real";
}

struct Settings {
  LadderOptions ladder;
  MethodSettings methods;
  std::filesystem::path out = "build-bench/results";
  // ../shared/data beside the project, or $BAKE_DATA_DIR (as for the tests).
  std::filesystem::path dataDir = defaultDataDir();
  std::vector<std::string> onlyMethods;
  std::size_t cgalExactMaxTriangles = 100'000;
  std::size_t exactMaxTriangles = 2'000'000;
  double timeoutSeconds = 600.0;
  double memoryLimitGb = 0.0;
  bool quick = false;
};

struct ErrorStats {
  double mean = NAN, max = NAN;
};

// |d - reference| relative to the reference's largest finite distance, over the vertices the
// reference reaches; a vertex the method leaves unreached (or NaN) counts as an infinite error.
ErrorStats relativeError(const std::vector<double>& d, const std::vector<double>& reference) {
  ErrorStats stats;
  if (d.size() != reference.size()) return stats;
  double largest = 0.0;
  for (double r : reference)
    if (std::isfinite(r)) largest = std::max(largest, r);
  if (largest <= 0.0) return stats;
  double sum = 0.0, worst = 0.0;
  std::size_t count = 0;
  for (std::size_t v = 0; v < d.size(); ++v) {
    if (!std::isfinite(reference[v])) continue;
    const double e = std::isfinite(d[v]) ? std::abs(d[v] - reference[v]) / largest : INFINITY;
    sum += e;
    worst = std::max(worst, e);
    ++count;
  }
  stats.mean = sum / double(count);
  stats.max = worst;
  return stats;
}

std::string number(double x) {
  if (std::isnan(x)) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

std::string csvField(std::string text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return quoted + "\"";
}

struct Row {
  std::string method;
  RunOutcome outcome;
  bool skipped = false;
  ErrorStats error;
  std::string reference;
};

// Runs every selected method on one rung with the first `sourceCount` sources.
std::vector<Row> runMethods(const Settings& settings, const std::vector<Method>& methods, const Rung& rung,
                            std::size_t sourceCount) {
  const std::vector<std::uint32_t> sources(rung.sources.begin(),
                                           rung.sources.begin() + std::min(sourceCount, rung.sources.size()));
  const std::size_t triangles = rung.surface.triangleCount();
  std::vector<Row> rows;
  for (const Method& method : methods) {
    Row row{method.name, {}, false, {}, {}};
    const bool tooBig = (method.name == "cgal-exact" && triangles > settings.cgalExactMaxTriangles) ||
                        (method.name == "exact" && triangles > settings.exactMaxTriangles);
    if (tooBig) {
      row.skipped = true;
      row.outcome.error = "skipped: above the triangle cap for this method";
    } else {
      std::cerr << "  " << rung.name << " " << method.name << " x" << sources.size() << " ..." << std::flush;
      row.outcome = runIsolated([&] { return method.run(rung.surface, sources); }, settings.timeoutSeconds,
                                settings.memoryLimitGb * 1e9);
      std::cerr << (row.outcome.ok ? " " + number(row.outcome.measurement.seconds) + " s" : " " + row.outcome.error)
                << "\n";
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

const Row* findRow(const std::vector<Row>& rows, const std::string& method) {
  for (const Row& row : rows)
    if (row.method == method && row.outcome.ok) return &row;
  return nullptr;
}

// Our exact distances are the reference, CGAL's where ours failed; each exact method is measured
// against the other one.
void measureErrors(std::vector<Row>& rows) {
  const Row* ours = findRow(rows, "exact");
  const Row* cgal = findRow(rows, "cgal-exact");
  for (Row& row : rows) {
    if (!row.outcome.ok) continue;
    const Row* reference = ours ? ours : cgal;
    if (row.method == "exact") reference = cgal;
    if (row.method == "cgal-exact") reference = ours;
    if (!reference) continue;
    row.reference = reference->method;
    row.error = relativeError(row.outcome.measurement.distances, reference->outcome.measurement.distances);
  }
}

void writeHeader(std::ostream& csv) {
  csv << "mesh,triangles,vertices,method,sources,seconds,setup_seconds,mean_rel_error,max_rel_error,reference,runs,"
         "status\n";
}

void writeRows(std::ostream& csv, const Rung& rung, std::size_t sourceCount, const std::vector<Row>& rows) {
  for (const Row& row : rows) {
    const Measurement& m = row.outcome.measurement;
    const bool ok = row.outcome.ok;
    csv << rung.name << ',' << rung.surface.triangleCount() << ',' << rung.surface.vertexCount() << ','
        << row.method << ',' << sourceCount << ',' << (ok ? number(m.seconds) : "") << ','
        << (ok ? number(m.setupSeconds) : "") << ',' << number(row.error.mean) << ',' << number(row.error.max)
        << ',' << row.reference << ',' << (ok ? std::to_string(m.runs) : "") << ','
        << csvField(ok ? "ok" : row.outcome.error) << '\n';
  }
  csv.flush();
}

std::string ratio(const Row* ours, const Row* peer, bool setup) {
  if (!ours || !peer) return "-";
  const double a = setup ? ours->outcome.measurement.setupSeconds : ours->outcome.measurement.seconds;
  const double b = setup ? peer->outcome.measurement.setupSeconds : peer->outcome.measurement.seconds;
  return b > 0.0 ? number(a / b) : "-";
}

std::string errorText(const Row* row) {
  return row && !std::isnan(row->error.mean) ? number(row->error.mean) + "/" + number(row->error.max) : "-";
}

void summarise(std::ostream& out, const Rung& rung, std::size_t sourceCount, const std::vector<Row>& rows) {
  const Row* exact = findRow(rows, "exact");
  const Row* cgalExact = findRow(rows, "cgal-exact");
  const Row* heat = findRow(rows, "heat");
  const Row* cgalHeat = findRow(rows, "cgal-heat");
  const Row* fmm = findRow(rows, "fmm");
  out << rung.name << " (" << rung.surface.triangleCount() << " triangles, " << sourceCount << " sources): "
      << "exact/cgal-exact time " << ratio(exact, cgalExact, false) << "; heat/cgal-heat setup "
      << ratio(heat, cgalHeat, true) << ", per field " << ratio(heat, cgalHeat, false)
      << "; mean/max rel. error: exact " << errorText(exact) << ", heat " << errorText(heat) << ", cgal-heat "
      << errorText(cgalHeat) << ", fmm " << errorText(fmm) << "\n";
  out.flush();
}

std::vector<std::filesystem::path> sharedMeshes(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> meshes;
  if (!std::filesystem::is_directory(dir)) return meshes;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const auto ext = entry.path().extension().string();
    if (ext == ".off" || ext == ".obj") meshes.push_back(entry.path());
  }
  std::sort(meshes.begin(), meshes.end());
  return meshes;
}

int run(Settings settings) {
  if (settings.quick) {
    settings.ladder.maxTriangles = std::min<std::size_t>(settings.ladder.maxTriangles, 30'000);
    settings.methods.repeat.repeats = std::min(settings.methods.repeat.repeats, 3);
  }
  if (settings.ladder.meshes.empty()) {
    settings.ladder.meshes = sharedMeshes(settings.dataDir);
    if (settings.ladder.meshes.empty())
      std::cerr << "bench-geodesic: warning: no meshes in " << settings.dataDir << "; only the sphere\n";
  } else {
    settings.ladder.sphere = false;
  }
  auto bases = loadBases(settings.ladder);
  if (!bases.isOk()) {
    std::cerr << "bench-geodesic: error: " << bases.status().describe() << "\n";
    return static_cast<int>(bases.status().code());
  }
  std::vector<Method> methods;
  for (Method& method : allMethods(settings.methods))
    if (settings.onlyMethods.empty() || std::count(settings.onlyMethods.begin(), settings.onlyMethods.end(), method.name))
      methods.push_back(std::move(method));

  std::filesystem::create_directories(settings.out);
  std::ofstream csv(settings.out / "geodesic.csv");
  std::ofstream summary(settings.out / "summary.txt");
  if (!csv || !summary) {
    std::cerr << "bench-geodesic: error: " << settings.out.string() << ": cannot write\n";
    return 2;
  }
  writeHeader(csv);
  for (const RungPlan& plan : planLadder(bases.value(), settings.ladder.maxTriangles)) {
    const Rung rung = buildRung(bases.value()[plan.base], plan.levels, settings.ladder.loopSmoothing);
    std::cerr << rung.name << ": " << rung.surface.triangleCount() << " triangles\n";
    for (std::size_t sourceCount : {std::size_t{1}, std::size_t{8}}) {
      std::vector<Row> rows = runMethods(settings, methods, rung, sourceCount);
      measureErrors(rows);
      writeRows(csv, rung, sourceCount, rows);
      summarise(std::cout, rung, sourceCount, rows);
      summarise(summary, rung, sourceCount, rows);
    }
  }
  std::cerr << "bench-geodesic: wrote " << (settings.out / "geodesic.csv").string() << "\n";
  return 0;
}

}  // namespace
}  // namespace bake::bench

int main(int argc, char** argv) {
  bake::bench::Settings settings;
  CLI::App app{"Geodesic distance methods: error against run time on a mesh ladder, ours and CGAL's"};
  std::vector<std::string> meshes;
  app.add_flag("--quick", settings.quick, "Small ladder (up to 30k triangles), 3 repetitions");
  app.add_option("--max-triangles", settings.ladder.maxTriangles, "Largest rung (triangles)");
  app.add_option("--out", settings.out, "Output directory (geodesic.csv, summary.txt)");
  app.add_option("--mesh", meshes, "Base mesh instead of the shared set (repeatable; no sphere then)");
  app.add_option("--data-dir", settings.dataDir, "Directory of the shared real meshes");
  app.add_option("--repeats", settings.methods.repeat.repeats, "Repetitions per field and set-up (median)");
  app.add_option("--min-seconds", settings.methods.repeat.minSeconds,
                 "Repeat a field or set-up (up to 200 times) until its runs add up to this many seconds");
  app.add_option("--repeat-budget", settings.methods.repeat.budgetSeconds, "Stop repeating after this many seconds");
  app.add_option("--methods", settings.onlyMethods, "Only these methods (exact heat fmm cgal-exact cgal-heat)")
      ->delimiter(',');
  app.add_option("--cgal-exact-max-triangles", settings.cgalExactMaxTriangles,
                 "Largest mesh for CGAL's exact method (slow and memory hungry)");
  app.add_option("--exact-max-triangles", settings.exactMaxTriangles, "Largest mesh for our exact method");
  app.add_option("--timeout", settings.timeoutSeconds, "Seconds allowed per method run");
  app.add_option("--memory-limit-gb", settings.memoryLimitGb, "Address-space limit per method run (0 = none)");
  app.add_flag("--loop", settings.ladder.loopSmoothing, "Loop subdivision instead of midpoint subdivision");
  CLI11_PARSE(app, argc, argv);
  for (const auto& mesh : meshes) settings.ladder.meshes.emplace_back(mesh);
  return bake::bench::run(std::move(settings));
}
