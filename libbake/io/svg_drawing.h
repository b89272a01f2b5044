// SVG drawings (svg_drawing.cpp): the one SVG reader of the library. libxml2 parses the document; the
// centreline of every shape (path, line, polyline, polygon, rect, circle, and ellipses that are
// circles) comes back as path pieces with every element transform applied (matrix, translate, scale,
// rotate, skewX, skewY) and then the caller's placement of the drawing's user space. An arc under a
// map that is not a similarity would become an ellipse and is refused; an element we do not follow is
// an error naming it, never skipped in silence. Errors name the file, the element (tag, line, id) and,
// through `where`, the caller's location; I/O errors exit 2, bad content 3.
#pragma once

#include <array>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bake/core/status.h"
#include "io/planar_path.h"

namespace bake::svg {

using planar::PathPiece;
using planar::Vec2;

// x' = a x + c y + e, y' = b x + d y + f (SVG 1.1 §7.4).
struct Affine {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;

  Vec2 apply(Vec2 p) const { return {a * p.u + c * p.v + e, b * p.u + d * p.v + f}; }
  Vec2 applyLinear(Vec2 p) const { return {a * p.u + c * p.v, b * p.u + d * p.v}; }
  Affine then(const Affine& outer) const {  // outer ∘ this
    return {outer.a * a + outer.c * b, outer.b * a + outer.d * b, outer.a * c + outer.c * d,
            outer.b * c + outer.d * d, outer.a * e + outer.c * f + outer.e, outer.b * e + outer.d * f + outer.f};
  }
  double determinant() const { return a * d - b * c; }
};

// A length of the root element: a number and its unit ("" for user units, "px", "mm", "cm", "in",
// "pt", "pc").
struct Length {
  double value = 0;
  std::string unit;
};

// What the root <svg> says about its user space, for the caller to place it.
struct Frame {
  std::optional<std::array<double, 4>> viewBox;  // min-x min-y width height (width, height > 0)
  std::optional<Length> width, height;   // when given as a positive number with one of the units above
  std::string widthText, heightText;     // as written (empty when absent)
  std::string preserveAspectRatio;  // as written; empty when absent
  std::string rootElement;          // "<svg> (line 1)", for messages
};

struct Shape {
  std::string tag, id;
  std::string element;  // "<path id="logo"> (line 12)", for messages
  std::vector<std::vector<PathPiece>> subpaths;
};

// The shapes of the drawing in document order. `placement` maps the root's user space to the
// caller's space (its errors are the caller's: a drawing it cannot place).
using Placement = std::function<Result<Affine>(const Frame&)>;
Result<std::vector<Shape>> readDrawing(const std::filesystem::path& file, const std::string& where, const Placement& placement);

}  // namespace bake::svg
