// bench-groove-scene: a large, deterministic groove scene for timing groovebake (seed 000 §4.1: the
// grid must stay cheap to build for patterns of 10^5 grooves). Random short scratches (straight, of
// random length and direction, with two profiles) over a square domain, plus long straight lines
// across it, and optionally a share of scratches drawn as circular arcs.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace {

using nlohmann::json;

struct Options {
  int grooves = 100000;
  int longLines = 200;        // of the grooves, how many cross the whole domain
  double arcShare = 0.1;      // share of the scratches drawn as arcs
  double domain = 100;        // side of the square domain
  double minLength = 0.2, maxLength = 2;
  std::uint64_t seed = 1;
  bool wrap = false;
  std::string output;
};

json profiles() {
  return {{"vee", {{"points", {{-0.03, 0}, {0, -0.02}, {0.03, 0}}}}},
          {"scratch", {{"points", {{-0.05, 0}, {-0.035, 0.006}, {-0.02, 0}, {0, -0.015}, {0.02, 0}, {0.035, 0.006}, {0.05, 0}}}}}};
}

json scratch(std::mt19937_64& random, const Options& o, bool arc) {
  std::uniform_real_distribution<double> unit(0, 1);
  const double margin = o.maxLength;
  const double u = margin + unit(random) * (o.domain - 2 * margin), v = margin + unit(random) * (o.domain - 2 * margin);
  const double length = o.minLength + unit(random) * (o.maxLength - o.minLength);
  const double angle = unit(random) * 2 * M_PI;
  const std::string profile = unit(random) < 0.5 ? "vee" : "scratch";
  if (arc) {
    const double radius = 1 + unit(random) * 4, sweep = length / radius * 180 / M_PI;
    const double start = angle * 180 / M_PI;
    return {{"profile", profile}, {"path", {{"arc", {{"centre", {u, v}}, {"radius", radius}, {"start", start}, {"end", start + sweep}}}}}};
  }
  const double du = 0.5 * length * std::cos(angle), dv = 0.5 * length * std::sin(angle);
  return {{"profile", profile}, {"path", {{"line", {{u - du, v - dv}, {u + du, v + dv}}}}}};
}

json longLine(std::mt19937_64& random, const Options& o, int k) {
  std::uniform_real_distribution<double> unit(0.02, 0.98);
  const double a = unit(random) * o.domain, b = unit(random) * o.domain;
  const double lo = 0.01 * o.domain, hi = 0.99 * o.domain;
  const json path = k % 2 ? json{{"line", {{lo, a}, {hi, b}}}} : json{{"line", {{a, lo}, {b, hi}}}};
  return {{"profile", "vee"}, {"path", path}};
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"Writes a large random groove scene (formats/groove-scene.md) for timing groovebake.", "bench-groove-scene"};
  app.add_option("-o,--output", o.output, "Scene to write (.json)")->required();
  app.add_option("--grooves", o.grooves, "Grooves in all")->default_val(o.grooves);
  app.add_option("--long-lines", o.longLines, "Of them, straight lines across the domain")->default_val(o.longLines);
  app.add_option("--arc-share", o.arcShare, "Share of the scratches drawn as arcs")->default_val(o.arcShare);
  app.add_option("--domain", o.domain, "Side of the square domain")->default_val(o.domain);
  app.add_option("--seed", o.seed, "Random seed")->default_val(o.seed);
  app.add_flag("--wrap", o.wrap, "A repeating domain");
  CLI11_PARSE(app, argc, argv);

  std::mt19937_64 random(o.seed);
  std::uniform_real_distribution<double> unit(0, 1);
  json grooves = json::array();
  for (int k = 0; k < o.grooves; ++k)
    grooves.push_back(k < o.longLines ? longLine(random, o, k) : scratch(random, o, unit(random) < o.arcShare));
  const json scene = {{"version", 1},
                      {"units", "mm"},
                      {"domain", {{"size", {o.domain, o.domain}}}},
                      {"wrap", o.wrap ? "repeat" : "none"},
                      {"profiles", profiles()},
                      {"materials", {{"steel", {{"albedo", {0.55, 0.55, 0.6}}, {"specular", {0.9, 0.9, 0.9}}, {"shininess", 60}}}}},
                      {"base", "steel"},
                      {"grooves", grooves}};
  std::ofstream(o.output) << scene.dump() << "\n";
  std::printf("%s: %d grooves\n", o.output.c_str(), o.grooves);
  return 0;
}
