// `bakeplay render`: loads a scene (or the bundled example), renders it headless into an offscreen
// target, writes PNG (sRGB, 8-bit) or EXR (linear, half), and with --frames N times N frames (GPU
// timer queries and CPU wall time, median and p95) for the report; --compare-standard times the same
// scene drawn with standard shading too.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bake/core/diagnostics.h"
#include "bake/core/options.h"
#include "bake/core/status.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace bake::play {

struct ViewSettings {
  std::vector<std::string> scenes;  // empty: the bundled example scene
  int width = 512;
  int height = 512;
  std::string camera;  // "x,y,z[:tx,ty,tz]"; empty: from the file, else framed automatically
  std::string light;   // "x,y,z" towards the light; empty: from the file, else a default
  std::string environment;  // "r,g,b": the constant environment grooves' mirror bounces see; empty: black
  bool quiet = false;  // for commands without the common options
  std::string geotexture;  // GeoTexture preset for every primitive with geodesic fields; empty: the files'
  float time = 0.0f;       // seconds, for animated techniques
  // Paintstrokes (BAKE_paintstrokes): quality level 0, 1, 2 (1, 2 or 4 polygons across), the
  // screen-space tolerance of the subdivision along the length in pixels, and "SIDESxSTEPS" to draw
  // fixed CPU-tessellated tubes instead (the reference); checked by makePaintstrokeOptions.
  int strokeQuality = 1;
  double strokeTolerance = 0.5;
  std::string strokeTubes;
  // Hatching: "blend" (the two nearest TAM layers, seed 004) or "threshold" (Webb et al. 2002 fine
  // tone control by the package's threshold texture).
  std::string hatchingTone = "blend";
  // Grooves: "environment" (a mirror piece in area-sampled footprints reflects the environment only:
  // the cheaper model) or "traced" (its bounces followed as beams, seed 000 §7, as the CPU method).
  std::string grooveReflections = "environment";
  // Grooves: the most retry draws per frame for area samples a driver's loop cap cut short
  // (GroovesOptions::retryDraws).
  std::uint32_t grooveRetries = 2048;
  // GeoTextures' wave preset: an equirectangular environment image reflected by the displaced
  // surface (seed 003 C.6.4); empty: none.
  std::string environmentMap;
};

struct RenderSettings {
  ViewSettings view;
  std::string output;  // .png or .exr
  int frames = 1;
  // Also time the scene with every technique replaced by standard shading (Blinn-Phong), as seed 004
  // compares hatching with Phong; both frame times go to the report.
  bool compareStandard = false;
  CommonOptions common;
};

// "WxH"
Status parseSize(const std::string& text, ViewSettings& view);

// The scene of the settings (the bundled example when no file is given), its camera and its light.
struct ViewSetup {
  Scene scene;
  Camera camera;
  Light light;
};
Result<ViewSetup> setUpView(const ViewSettings& view, Diagnostics& diagnostics);
// The built-in renderers with the options of the settings (paintstrokes); usage errors for bad values.
Result<RendererRegistry> renderersFor(const ViewSettings& view);

Status runRender(const RenderSettings& settings, Diagnostics& diagnostics);

struct Percentiles {
  double median = 0, p95 = 0;
};
// Nearest-rank percentiles of a sample (empty: zeros).
Percentiles percentiles(std::vector<double> samples);

}  // namespace bake::play
