// A drawing's shapes as grooves (svg_file.h): the drawing's rectangle (its viewBox, or 0 0 width
// height in user units) has its bottom-left corner placed at the origin, y flipped, scaled.
#include "grooves/input/svg_file.h"

#include "io/svg_drawing.h"

namespace bake::grooves {
namespace {

// The drawing's rectangle in user units: its viewBox, or 0 0 width height.
Result<std::array<double, 4>> drawingRectangle(const svg::Frame& frame, const std::string& file, const std::string& where) {
  if (frame.viewBox) return *frame.viewBox;
  auto userUnits = [](const std::optional<svg::Length>& length) { return length && (length->unit.empty() || length->unit == "px"); };
  if (!userUnits(frame.width) || !userUnits(frame.height))
    return invalidInput(frame.rootElement + ": needs a viewBox, or width and height in user units, to place the drawing",
                        {file, where});
  return std::array<double, 4>{0, 0, frame.width->value, frame.height->value};
}

}  // namespace

Result<std::vector<std::vector<PathPiece>>> readSvgFile(const std::filesystem::path& file, const SvgPlacement& placement,
                                                        const std::string& where) {
  auto place = [&](const svg::Frame& frame) -> Result<svg::Affine> {
    BAKE_ASSIGN_OR_RETURN(const auto rect, drawingRectangle(frame, file.string(), where));
    // User space -> texture space: shift the rectangle's bottom-left corner to the origin, flip y, scale.
    const double s = placement.scale;
    return svg::Affine{s, 0, 0, -s, placement.origin.u - s * rect[0], placement.origin.v + s * (rect[1] + rect[3])};
  };
  BAKE_ASSIGN_OR_RETURN(std::vector<svg::Shape> shapes, svg::readDrawing(file, where, place));
  std::vector<std::vector<PathPiece>> out;
  for (svg::Shape& shape : shapes)
    for (std::vector<PathPiece>& pieces : shape.subpaths) out.push_back(std::move(pieces));
  if (out.empty()) return invalidInput("the drawing has no shapes to follow", {file.string(), where});
  return out;
}

}  // namespace bake::grooves
