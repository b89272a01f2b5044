// The stages of revolbake's run (bake.cpp), in order, with the state they hand on.
//   bake.cpp          read the profile (vector, image, mesh) and compute the distance field
//   bake_measure.cpp  thin-feature warning, encoding + safety margin, iteration budget by CPU march
//   bake_texture.cpp  projection choice, arc-length map, displacement map
//   bake_package.cpp  the BAKE_revolution package (formats/revolution.md)
#pragma once

#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/core/report.h"
#include "bake/io/glb.h"
#include "bake/revolution/bake.h"
#include "revolution/bake/displacement.h"
#include "revolution/input/profile_extract.h"
#include "revolution/oracle/march.h"

namespace bake::revolution {

struct BakeState {
  Profile profile;           // vector input, or the 0.5 contour of an image, or the section of a mesh
  bool exactReference = true;  // the profile is the input itself (false: an image's contour)
  bool binaryInput = false;
  std::optional<AxisFit> meshAxis;        // mesh input: where the object sits in the mesh's space
  nlohmann::json meshDeviation;           // mesh input: distance to a true surface of revolution
  ShapeField field;                       // exact (vector) or EDT (image) distances
  EncodedShapeMap encoded;
  SafetyMargin margin;
  double storedErrorTexels = 0;           // max |decoded - exact| at texel centres
  ProjectionChoice projection;
  double repeat[2] = {1, 1};
  std::vector<std::uint8_t> arcLengthMap;  // unorm16 per texel, only for the arc-length projection
  std::optional<DisplacementMap> displacement;
  std::vector<ProxyBand> bands;
  std::vector<MarchErrorPoint> marchCurve;
  int iterations = 35;
  double hitEpsilon = 0;
};

void warnAboutThinFeatures(const BakeState& state, Diagnostics& diagnostics);
void encodeAndMeasure(const Settings& settings, BakeState& state, Report& report, Diagnostics& diagnostics);
void measureMarch(const Settings& settings, BakeState& state, Report& report, Diagnostics& diagnostics);

void chooseTextureProjection(const Settings& settings, BakeState& state);
Status buildDisplacement(const Settings& settings, BakeState& state);

Result<glb::Package> buildPackage(const Settings& settings, const BakeState& state);

}  // namespace bake::revolution
