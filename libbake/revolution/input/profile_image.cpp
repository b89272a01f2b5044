// A coverage image as the input of a shape map, and its 0.5 iso-contour as a vector profile (for the
// projection choice and as the ray-march reference of image inputs). The contour is traced by
// marching squares over the texel centres, with crossing points interpolated linearly and saddles
// resolved by the cell's mean. The image is padded with an empty border, and with a mirrored column
// beyond the axis so that the solid's other half closes the contours there; the cut at r = 0 then
// leaves open contours that end on the axis, which is where a profile is allowed to end.
#include <algorithm>
#include <cmath>

#include "bake/io/image.h"
#include "revolution/input/profile_chain.h"
#include "revolution/input/profile_extract.h"

namespace bake::revolution {

Result<CoverageImage> readCoverageImage(const std::string& path, double texelSize) {
  BAKE_ASSIGN_OR_RETURN(const Image image, readImage(path));
  if (image.width < 2 || image.height < 2)
    return invalidInput("a profile image needs at least 2 x 2 pixels", {path, ""});
  CoverageImage coverage;
  coverage.width = image.width;
  coverage.height = image.height;
  coverage.texelSize = texelSize > 0 ? texelSize : 1.0 / image.height;
  coverage.coverage.resize(std::size_t(image.width) * image.height);
  // Alpha when there is one (an anti-aliased shape on any background), else the mean of the colours.
  const bool hasAlpha = image.channels == 2 || image.channels == 4;
  const int colours = hasAlpha ? image.channels - 1 : image.channels;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      float value = 0;
      if (hasAlpha) {
        value = image.at(x, y, image.channels - 1);
      } else {
        for (int c = 0; c < colours; ++c) value += image.at(x, y, c);
        value /= float(colours);
      }
      if (!std::isfinite(value) || value < -1e-6f || value > 1 + 1e-6f)
        return invalidInput("coverage " + std::to_string(value) + " outside [0, 1]",
                            {path, "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")"});
      // Image rows run top-down; the shape map's rows run up from hMin.
      coverage.coverage[std::size_t(image.height - 1 - y) * image.width + x] = std::clamp(value, 0.0f, 1.0f);
    }
  }
  return coverage;
}

namespace {

// The coverage minus 0.5 on the padded lattice: column -1 mirrors column 0, the other borders are empty.
struct Lattice {
  const CoverageImage& image;
  float value(int i, int j) const {
    if (i == -1) i = 0;
    if (i < 0 || j < 0 || i >= image.width || j >= image.height) return -0.5f;
    return image.coverage[std::size_t(j) * image.width + i] - 0.5f;
  }
  std::uint32_t node(int i, int j) const { return std::uint32_t(i + 1) + std::uint32_t(j + 1) * std::uint32_t(image.width + 2); }
  Point2 position(double i, double j) const {
    return {(i + 0.5) * image.texelSize, image.hMin + (j + 0.5) * image.texelSize};
  }
};

bool inside(float value) { return value >= 0; }

}  // namespace

Profile contourOfCoverage(const CoverageImage& image) {
  const Lattice lattice{image};
  std::vector<KeyedSegment> segments;
  for (int j = -1; j < image.height; ++j) {
    for (int i = -1; i < image.width; ++i) {
      // Corners a, b, c, d counter-clockwise from (i, j); edge e joins corner e and corner e + 1.
      const int ci[4] = {i, i + 1, i + 1, i};
      const int cj[4] = {j, j, j + 1, j + 1};
      float f[4];
      int insideCount = 0;
      for (int k = 0; k < 4; ++k) {
        f[k] = lattice.value(ci[k], cj[k]);
        insideCount += inside(f[k]) ? 1 : 0;
      }
      if (insideCount == 0 || insideCount == 4) continue;
      KeyedSegment crossing[4];
      bool crosses[4];
      for (int e = 0; e < 4; ++e) {
        const int k0 = e, k1 = (e + 1) % 4;
        crosses[e] = inside(f[k0]) != inside(f[k1]);
        if (!crosses[e]) continue;
        const double s = f[k0] / double(f[k0] - f[k1]);
        crossing[e].points[0] = lattice.position(ci[k0] + s * (ci[k1] - ci[k0]), cj[k0] + s * (cj[k1] - cj[k0]));
        crossing[e].ends[0] = pairKey(lattice.node(ci[k0], cj[k0]), lattice.node(ci[k1], cj[k1]));
      }
      auto join = [&](int e0, int e1) {
        KeyedSegment segment;
        segment.points[0] = crossing[e0].points[0];
        segment.ends[0] = crossing[e0].ends[0];
        segment.points[1] = crossing[e1].points[0];
        segment.ends[1] = crossing[e1].ends[0];
        if (clipToPositiveR(segment, axisKey(segments.size()))) segments.push_back(segment);
      };
      const bool saddle = insideCount == 2 && inside(f[0]) == inside(f[2]);
      if (saddle) {
        // Cut off the two corners whose state differs from the cell centre's.
        const bool centreInside = inside(0.25f * (f[0] + f[1] + f[2] + f[3]));
        if (inside(f[0]) == centreInside) {
          join(0, 1);  // corner b
          join(2, 3);  // corner d
        } else {
          join(3, 0);  // corner a
          join(1, 2);  // corner c
        }
        continue;
      }
      int found[2], n = 0;
      for (int e = 0; e < 4; ++e)
        if (crosses[e]) found[n++] = e;
      join(found[0], found[1]);
    }
  }
  Profile profile;
  profile.contours = chainKeyedSegments(segments);
  return profile;
}

}  // namespace bake::revolution
