// Encoding of the shape map's texels (formats/revolution.md, "Encodings") and the safety margin a
// sphere tracer keeps. The distance scale S is the largest |d| in the map, so no texel clips.
// The 8-bit encoding stores sqrt(|d| / S): its steps are finest at the surface, where the march
// decides hits (the first code either side of d = 0 is S / 255^2 away, against 2S / 255 for linear).
// The margin is the largest amount by which a bilinear sample (filtered on the encoded values, as
// the GPU filters) exceeds the true signed distance near the surface, plus the encoding's
// quantisation half-step at the surface.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

#include <bake_formats/revolution.h>

#include "bake/revolution/shape_map.h"
#include "core/parallel.h"
#include "revolution/input/profile_geometry.h"

namespace bake::revolution {
namespace {

static_assert(std::endian::native == std::endian::little, "texels are written in host order");

double largestMagnitude(const std::vector<float>& values) {
  double largest = 0;
  for (float v : values)
    if (std::isfinite(v)) largest = std::max(largest, double(std::abs(v)));
  return largest;
}

// The encoded B channel as a real number in [0, 1] (before rounding to the integer code).
double encodeDistance(double d, double scale, DistanceEncoding encoding) {
  const double x = std::clamp(d / scale, -1.0, 1.0);
  if (encoding == DistanceEncoding::Sqrt8) return 0.5 + 0.5 * std::copysign(std::sqrt(std::abs(x)), x);
  return 0.5 + 0.5 * x;
}

double decodeDistance(double v, double scale, DistanceEncoding encoding) {
  const double x = 2.0 * v - 1.0;
  if (encoding == DistanceEncoding::Sqrt8) return std::copysign(x * x, x) * scale;
  return x * scale;
}

double unit(double v) { return std::clamp(0.5 + 0.5 * v, 0.0, 1.0); }

template <class T>
void putCode(std::vector<std::uint8_t>& bytes, std::size_t at, double normalised) {
  const T code = T(std::lround(std::clamp(normalised, 0.0, 1.0) * std::numeric_limits<T>::max()));
  std::memcpy(bytes.data() + at, &code, sizeof(T));
}

template <class T>
double getCode(const std::vector<std::uint8_t>& bytes, std::size_t at) {
  T code;
  std::memcpy(&code, bytes.data() + at, sizeof(T));
  return double(code) / std::numeric_limits<T>::max();
}

std::size_t componentBytes(DistanceEncoding encoding) {
  switch (encoding) {
    case DistanceEncoding::Float: return 4;
    case DistanceEncoding::Unorm16: return 2;
    case DistanceEncoding::Sqrt8: return 1;
  }
  return 4;
}

}  // namespace

const char* encodingName(DistanceEncoding encoding) {
  namespace f = bake::format::revolution;
  switch (encoding) {
    case DistanceEncoding::Float: return f::kEncodingFloat;
    case DistanceEncoding::Unorm16: return f::kEncodingUnorm16;
    case DistanceEncoding::Sqrt8: return f::kEncodingSqrt8;
  }
  return f::kEncodingFloat;
}

EncodedShapeMap encodeShapeMap(const ShapeField& field, DistanceEncoding encoding) {
  EncodedShapeMap map;
  map.encoding = encoding;
  const double largest = largestMagnitude(field.distance);
  map.distanceScale = largest > 0 ? largest : 1.0;
  const std::size_t count = field.distance.size();
  const std::size_t size = componentBytes(encoding);
  map.bytes.assign(count * 4 * size, 0);
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t at = k * 4 * size;
    const double coverage = field.coverage.empty() ? (field.distance[k] < 0 ? 1.0 : 0.0) : field.coverage[k];
    if (encoding == DistanceEncoding::Float) {
      const float texel[4] = {field.gradR[k], field.gradH[k], field.distance[k], float(coverage)};
      std::memcpy(map.bytes.data() + at, texel, sizeof texel);
      continue;
    }
    const double b = encodeDistance(field.distance[k], map.distanceScale, encoding);
    if (encoding == DistanceEncoding::Unorm16) {
      putCode<std::uint16_t>(map.bytes, at, unit(field.gradR[k]));
      putCode<std::uint16_t>(map.bytes, at + 2, unit(field.gradH[k]));
      putCode<std::uint16_t>(map.bytes, at + 4, b);
      putCode<std::uint16_t>(map.bytes, at + 6, coverage);
    } else {
      putCode<std::uint8_t>(map.bytes, at, unit(field.gradR[k]));
      putCode<std::uint8_t>(map.bytes, at + 1, unit(field.gradH[k]));
      putCode<std::uint8_t>(map.bytes, at + 2, b);
      putCode<std::uint8_t>(map.bytes, at + 3, coverage);
    }
  }
  return map;
}

ShapeField decodeShapeMap(const EncodedShapeMap& map, const ShapeGrid& grid) {
  ShapeField field;
  field.grid = grid;
  field.encoding = map.encoding;
  field.distanceScale = map.distanceScale;
  const std::size_t count = std::size_t(grid.width) * grid.height;
  const std::size_t size = componentBytes(map.encoding);
  field.distance.resize(count);
  field.gradR.resize(count);
  field.gradH.resize(count);
  field.coverage.resize(count);
  if (map.bytes.size() < count * 4 * size) return field;  // short data: zeros, caller validates sizes
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t at = k * 4 * size;
    if (map.encoding == DistanceEncoding::Float) {
      float texel[4];
      std::memcpy(texel, map.bytes.data() + at, sizeof texel);
      field.gradR[k] = texel[0];
      field.gradH[k] = texel[1];
      field.distance[k] = texel[2];
      field.coverage[k] = texel[3];
      continue;
    }
    double channel[4];
    for (int c = 0; c < 4; ++c)
      channel[c] = map.encoding == DistanceEncoding::Unorm16 ? getCode<std::uint16_t>(map.bytes, at + 2 * c)
                                                             : getCode<std::uint8_t>(map.bytes, at + c);
    field.gradR[k] = float(2 * channel[0] - 1);
    field.gradH[k] = float(2 * channel[1] - 1);
    field.distance[k] = float(decodeDistance(channel[2], map.distanceScale, map.encoding));
    field.coverage[k] = float(channel[3]);
  }
  return field;
}

namespace {

// Bilinear sample of the stored distance at (r, h), mirrored at r = 0 and clamped at the other
// edges, filtered on the encoded values and decoded afterwards (formats/revolution.md).
struct GpuSampler {
  const ShapeField& field;
  std::vector<double> encoded;
  double scale;

  explicit GpuSampler(const ShapeField& f) : field(f) {
    scale = f.distanceScale > 0 ? f.distanceScale : std::max(largestMagnitude(f.distance), 1e-300);
    encoded.resize(f.distance.size());
    for (std::size_t k = 0; k < encoded.size(); ++k) encoded[k] = encodeDistance(f.distance[k], scale, f.encoding);
  }
  int column(int i) const {
    if (i < 0) i = -i - 1;  // mirror at the axis edge
    return std::min(i, field.grid.width - 1);
  }
  int row(int j) const { return std::clamp(j, 0, field.grid.height - 1); }
  double operator()(double r, double h) const {
    const double x = std::abs(r) / field.grid.texelSize - 0.5, y = (h - field.grid.hMin) / field.grid.texelSize - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    const double u = x - fx, v = y - fy;
    const int i0 = int(fx), j0 = int(fy);
    auto value = [&](int i, int j) { return encoded[std::size_t(row(j)) * field.grid.width + column(i)]; };
    const double mixed = (1 - v) * ((1 - u) * value(i0, j0) + u * value(i0 + 1, j0)) +
                         v * ((1 - u) * value(i0, j0 + 1) + u * value(i0 + 1, j0 + 1));
    return decodeDistance(mixed, scale, field.encoding);
  }
};

}  // namespace

SafetyMargin measureSafetyMargin(const ShapeField& decoded, const Profile* exactProfile) {
  SafetyMargin margin;
  const ShapeGrid& grid = decoded.grid;
  const double texel = grid.texelSize;
  const double scale = decoded.distanceScale > 0 ? decoded.distanceScale : largestMagnitude(decoded.distance);
  // Quantisation half-step at the surface: float rounding, half a 16-bit step of 2S / 65535, or for
  // sqrt8 half a code (1/510) around the centre 0.5, which is S (1/255)^2 in distance.
  switch (decoded.encoding) {
    case DistanceEncoding::Float: margin.quantisation = scale * std::ldexp(1.0, -24); break;
    case DistanceEncoding::Unorm16: margin.quantisation = scale / 65535.0; break;
    case DistanceEncoding::Sqrt8: margin.quantisation = scale / (255.0 * 255.0); break;
  }
  // Ceiling for a 1-Lipschitz f sampled exactly at the texel centres c_k: the bilinear value at p is
  // sum w_k f(c_k) <= f(p) + sum w_k |c_k - p| <= f(p) + sqrt(sum w_k |c_k - p|^2) (Jensen), and for
  // bilinear weights sum w_k |c_k - p|^2 = u(1 - u) + v(1 - v) <= 1/2 texel^2, so the overestimate is
  // at most texel / sqrt(2).
  const double ceiling = texel * std::sqrt(0.5);
  if (!exactProfile) {
    margin.bilinearOverestimate = ceiling;
    return margin;
  }
  // Measured: n x n sub-samples in every texel within 3 texels of the surface, first n = 4, then
  // n = 16 in the texels whose coarse maximum comes within half of the largest (the worst points
  // sit at convex corners and between lattice points; the finer pass finds them).
  const GpuSampler sample(decoded);
  const double band = 3 * texel;
  std::vector<const Segment*> pieces, surface;
  for (const Contour& contour : exactProfile->contours)
    for (const Segment& s : contour.segments) {
      pieces.push_back(&s);
      if (!s.onAxis) surface.push_back(&s);
    }
  if (surface.empty()) {
    margin.bilinearOverestimate = ceiling;
    return margin;
  }
  // Worst (sample - exact) over sub x sub samples of the wanted texels of row j, exactly but fast:
  // the parity crossings of each sample row are sorted once, and each run of 8 texels measures only
  // the pieces that can be nearest in it (those within the nearest distance + 2 half-diagonals of
  // its centre, by the triangle inequality).
  auto rowWorst = [&](int j, int sub, const std::vector<char>& wanted, double* out) {
    std::vector<std::vector<double>> crossings(sub);
    for (int b = 0; b < sub; ++b) {
      const double h = grid.hMin + (j + (b + 0.5) / sub) * texel;
      for (const Segment* s : pieces) parityCrossings(*s, h, crossings[b]);
      std::sort(crossings[b].begin(), crossings[b].end());
    }
    std::vector<const Segment*> candidates;
    std::vector<double> toCentre(surface.size());
    for (int i0 = 0; i0 < grid.width; i0 += 8) {
      const int i1 = std::min(grid.width, i0 + 8);
      if (std::none_of(wanted.begin() + i0, wanted.begin() + i1, [](char w) { return w != 0; })) continue;
      const Point2 centre{0.5 * (i0 + i1) * texel, grid.hMin + (j + 0.5) * texel};
      const double halfDiagonal = std::hypot(0.5 * (i1 - i0) * texel, 0.5 * texel);
      double nearest = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < surface.size(); ++k) {
        toCentre[k] = distanceToPiece(*surface[k], centre).distance;
        nearest = std::min(nearest, toCentre[k]);
      }
      candidates.clear();
      for (std::size_t k = 0; k < surface.size(); ++k)
        if (toCentre[k] <= nearest + 2 * halfDiagonal + 1e-12 * (1 + nearest)) candidates.push_back(surface[k]);
      for (int i = i0; i < i1; ++i) {
        if (!wanted[i]) continue;
        double local = -std::numeric_limits<double>::infinity();
        for (int b = 0; b < sub; ++b) {
          const auto& row = crossings[b];
          for (int a = 0; a < sub; ++a) {
            const Point2 p{(i + (a + 0.5) / sub) * texel, grid.hMin + (j + (b + 0.5) / sub) * texel};
            double exact = std::numeric_limits<double>::infinity();
            for (const Segment* s : candidates) exact = std::min(exact, distanceToPiece(*s, p).distance);
            const auto right = row.end() - std::upper_bound(row.begin(), row.end(), p.r);
            if (right & 1) exact = -exact;
            local = std::max(local, sample(p.r, p.h) - exact);
          }
        }
        out[i] = local;
      }
    }
  };
  const std::size_t count = std::size_t(grid.width) * grid.height;
  std::vector<double> coarse(count, -std::numeric_limits<double>::infinity());
  parallelFor(std::size_t(grid.height), 0, [&](std::size_t j) {
    std::vector<char> wanted(grid.width);
    for (int i = 0; i < grid.width; ++i) wanted[i] = std::abs(decoded.at(i, int(j))) <= band;
    rowWorst(int(j), 4, wanted, coarse.data() + j * grid.width);
  }, 1);
  double worst = 0;
  for (double v : coarse) worst = std::max(worst, v);
  const double threshold = 0.5 * worst;
  std::vector<double> fine(coarse);
  parallelFor(std::size_t(grid.height), 0, [&](std::size_t j) {
    std::vector<char> wanted(grid.width);
    bool any = false;
    for (int i = 0; i < grid.width; ++i) {
      const double c = coarse[j * grid.width + i];
      wanted[i] = c > threshold && c > 0;
      any = any || wanted[i];
    }
    if (any) rowWorst(int(j), 16, wanted, fine.data() + j * grid.width);
  }, 1);
  for (double v : fine) worst = std::max(worst, v);
  // The profile's corners themselves (where the exact distance has its kinks).
  for (const Contour& contour : exactProfile->contours)
    for (const Segment& s : contour.segments) {
      if (s.a.r > grid.width * texel || s.a.h < grid.hMin || s.a.h > grid.hMin + grid.height * texel) continue;
      worst = std::max(worst, sample(s.a.r, s.a.h) - signedDistance(*exactProfile, s.a).distance);
    }
  // A field exact at the centres stays under the ceiling; one that is not (from an image) keeps
  // what was measured, which is then the honest figure.
  margin.bilinearOverestimate = worst;
  return margin;
}

}  // namespace bake::revolution
