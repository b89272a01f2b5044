// The profile of a surface of revolution: closed or open contours in the (r, h) half-plane (r the
// radius, h the height along the axis), made of straight segments and circular arcs. The solid is the
// region the contours enclose once each open contour is closed along the axis r = 0: those closing
// pieces, and any segment lying on the axis, are not surface (seed 001 revolves the profile about the
// axis, so the axis is interior to the solid, never a wall).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "bake/core/status.h"

namespace bake::revolution {

struct Point2 {
  double r = 0, h = 0;
};

// A piece of a contour from `a` to `b`: straight when bulge == 0, otherwise a circular arc whose
// bulge is tan(sweep / 4), positive counter-clockwise in (r, h) (the DXF / SVG-arc convention).
struct Segment {
  Point2 a, b;
  double bulge = 0;
  bool onAxis = false;  // set by validation: lies on r = 0, so it is not surface
};

struct Contour {
  std::vector<Segment> segments;  // consecutive: segments[i].b == segments[i + 1].a
  bool closed = false;            // closed: the last segment ends where the first starts
};

struct Profile {
  std::vector<Contour> contours;
  std::string source;  // file it came from, for messages
};

struct Bounds2 {
  double rMax = 0, hMin = 0, hMax = 0;
};

// Checks and normalises a profile: NaN/Inf, negative r, zero-length segments (dropped with a
// warning), contours crossing themselves or each other (error naming both segments and the point);
// closes open contours along the axis (their ends must lie on it or get a horizontal run to it) and
// flags segments on the axis. `warnings` collects what was repaired.
Status validateProfile(Profile& profile, std::vector<std::string>& warnings);

Bounds2 profileBounds(const Profile& profile);

// Readers. JSON: {"contours": [{"closed": bool, "points": [[r, h], ...], "bulges": [...]}]} or a bare
// list of points; CSV: lines "r,h[,bulge]", a blank line starts a new contour (formats/revolution.md).
Result<Profile> readProfileJson(const std::string& path);
Result<Profile> readProfileCsv(const std::string& path);
// An SVG file's first <path> (or the one with the given id): x = r, y = -h (SVG's y grows down).
Result<Profile> readProfileSvg(const std::string& path, const std::string& pathId = "");

}  // namespace bake::revolution
