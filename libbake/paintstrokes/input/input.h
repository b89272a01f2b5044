// Stroke lists (formats/paintstroke-input.md): a JSON document of styles, strokes and generators, or
// a CSV table of control points grouped by stroke id. The readers only read: the values' ranges are
// checked and repaired by validate.cpp, the generators run by bake.cpp (they read meshes).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bake/core/status.h"
#include "bake/paintstrokes/model.h"

namespace bake::paintstrokes {

struct StrokeInput {
  StrokeSet set;
  nlohmann::json generators = nlohmann::json::array();  // the JSON "generators" entries, unrun
  std::filesystem::path directory;                      // the input's folder (generators' paths are relative to it)
};

// "stroke 12, control point 3" (indices from 0), the element every stroke message names.
std::string strokeElement(std::size_t stroke);
std::string pointElement(std::size_t stroke, std::size_t point);

// JSON text; `source` names it in messages. Control points beyond the control-points budget are
// refused before the strokes are built.
Result<StrokeInput> parseStrokeJson(const std::string& text, const std::string& source);
// CSV text with a header row (stroke,x,y,z,radius required; r,g,b,opacity,reflectance,nx,ny,nz,
// depth,style optional).
Result<StrokeInput> parseStrokeCsv(const std::string& text, const std::string& source);
// By extension: .json or .csv (any case); other extensions are unsupported here.
Result<StrokeInput> readStrokeInput(const std::filesystem::path& path);
bool isStrokeList(const std::filesystem::path& path);

}  // namespace bake::paintstrokes
