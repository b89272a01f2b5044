// The layout of a sampled paintstroke for the rasterizer: one straight piece per pair of consecutive
// centreline samples (its direction, radii, opacities, colours and pixel filter), with how far past its
// ends it must reach. A pixel is drawn by the piece its centre projects onto; on the outside of a turn
// by angle a two neighbouring pieces' bands leave a wedge of width about r a between them, so each
// reaches past the joint by that much, and a joint turning more than kSharpTurn also gets a round join
// (a disc). The stroke's two ends get round caps (the swept disc of seed 002's generalized cylinder,
// seen in the image plane), which draw the pixels within half a pixel of the end; a stroke whose
// points all coincide is a dot. Stroke-wide values (opacities across, texture) are checked here once.
#include <algorithm>
#include <cmath>

#include "bake/stroke/paintstroke.h"
#include "stroke/coverage.h"
#include "stroke/stroke_stages.h"

namespace bake::stroke::detail {
namespace {

std::array<float, 3> inkColour(const Sample& s) {
  return {float(s.colour[0]), float(s.colour[1]), float(s.colour[2])};
}

}  // namespace

Geometry buildGeometry(const Paintstroke& stroke, double dx, double dy, double maxRadius, const RasterOptions& options) {
  Geometry out;
  double piece = options.maxPieceLength;
  if (!(piece > 0) || !std::isfinite(piece)) piece = RasterOptions{}.maxPieceLength;
  piece = std::clamp(piece, 1e-3, 64.0);
  out.samples = detail::sampleCentreline(stroke, piece, options.maxDeviation, kMaxSamples);
  if (out.samples.size() < 2) return out;
  for (Sample& s : out.samples) {
    s.x -= dx, s.y -= dy;
    s.radius = std::min(s.radius, maxRadius);
  }
  out.length = out.samples.back().arc;
  out.centreOpacity = std::clamp(std::isfinite(stroke.centreOpacity) ? stroke.centreOpacity : 1.0, 0.0, 1.0);
  out.edgeOpacity = std::clamp(std::isfinite(stroke.edgeOpacity) ? stroke.edgeOpacity : 1.0, 0.0, 1.0);
  out.texture = stroke.texture;

  const auto& s = out.samples;
  out.pieces.reserve(s.size() - 1);
  int previous = -1;  // the last piece with a direction, for the joint margins
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    const double ex = s[i + 1].x - s[i].x, ey = s[i + 1].y - s[i].y;
    const double len = std::hypot(ex, ey);
    if (!(len > 1e-12) || std::max(s[i].radius, s[i + 1].radius) < kMinRadius) continue;
    const PixelFilter filter(ey, -ex);
    // A pixel is drawn by the piece its centre projects onto; the first and last pieces reach a pixel
    // further, for the along-length filter of the butt ends (the caps are discs).
    Piece p{s[i].x, s[i].y, ex / len, ey / len, len, s[i].radius, s[i + 1].radius, s[i].arc,
            s[i].opacity, s[i + 1].opacity, 0, 0, filter, inkColour(s[i]), inkColour(s[i + 1])};
    if (previous >= 0 && out.pieces[previous].arc0 + out.pieces[previous].length >= p.arc0 - 1e-9) {
      // Joints: on the outside of a turn the two pieces' bands leave a wedge of width r x turn
      // between them, so each reaches past the joint by that much (and a little more for rounding).
      Piece& q = out.pieces[previous];
      const double chord = std::sqrt(std::max(0.0, 2 - 2 * (q.tx * p.tx + q.ty * p.ty)));  // ~ turn angle
      const double r = std::max(q.r1, p.r0);
      const double margin = 0.05 + r * std::min(1.1 * chord, kSharpTurn);
      q.after = margin;
      p.before = margin;
      if (chord > kSharpTurn && s[i].radius >= kMinRadius)
        out.discs.push_back({s[i].x, s[i].y, s[i].radius, s[i].opacity, p.tx, p.ty, s[i].arc, inkColour(s[i])});
    }
    out.pieces.push_back(p);
    previous = int(out.pieces.size()) - 1;
  }
  if (!out.pieces.empty()) {
    out.pieces.front().before = out.pieces.front().filter.halfWidth();
    out.pieces.back().after = out.pieces.back().filter.halfWidth();
  }
  if (out.pieces.empty()) {  // a dot
    if (s.front().radius >= kMinRadius)
      out.discs.push_back({s.front().x, s.front().y, s.front().radius, s.front().opacity, 1, 0, 0.0, inkColour(s.front())});
    return out;
  }
  // Round caps, drawn with the band's end; the first and last pieces leave them the end pixels.
  Piece& first = out.pieces.front();
  Piece& last = out.pieces.back();
  if (s.front().radius >= kMinRadius) {
    Disc cap{s.front().x, s.front().y, s.front().radius, s.front().opacity, first.tx, first.ty, 0.0, inkColour(s.front())};
    cap.cap = true, cap.ix = first.tx, cap.iy = first.ty, cap.band = out.length;
    out.discs.push_back(cap);
    first.before = -first.filter.halfWidth();
  }
  if (s.back().radius >= kMinRadius) {
    Disc cap{s.back().x, s.back().y, s.back().radius, s.back().opacity, last.tx, last.ty, out.length, inkColour(s.back())};
    cap.cap = true, cap.ix = -last.tx, cap.iy = -last.ty, cap.band = out.length;
    out.discs.push_back(cap);
    last.after = -last.filter.halfWidth();
  }
  if (out.discs.size() >= 2) {
    Disc& a = out.discs[out.discs.size() - 2];
    Disc& b = out.discs.back();
    if (a.cap && b.cap && out.length < a.r + b.r + 2) {
      a.ox = b.x, a.oy = b.y, a.oix = b.ix, a.oiy = b.iy, a.orad = b.r;
      b.ox = a.x, b.oy = a.y, b.oix = a.ix, b.oiy = a.iy, b.orad = a.r;
    }
  }
  return out;
}


}  // namespace bake::stroke::detail
