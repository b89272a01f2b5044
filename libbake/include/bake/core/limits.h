// Budgets: the largest input each stage accepts. A baker in a build farm must fail at once with a
// clear error on an input that would exhaust memory or run for hours, not be killed by the system
// half-way. Each budget is checked as soon as the size is known (a file's size before reading it, a
// mesh header's face count before parsing, a texture side when options are read, a groove count
// before generators expand), and an input beyond it is invalid input (exit 3) naming the file, the
// amount and the way to raise the budget: `--budget NAME=N` on every tool.
//
// The budgets are a process-wide policy, set once from the command line (core/cli.cpp), because the
// readers that check them are reached from many places (tools, the runtime's loader, tests).
#pragma once

#include <cstdint>
#include <string>

#include "bake/core/status.h"

namespace bake {

enum class Budget {
  InputBytes,   // size of any one input file read into memory
  Triangles,    // triangles of one mesh (from its header where the format declares them)
  TextureSide,  // side of any texture a tool makes or an image it reads (texels: side squared)
  Grooves,      // grooves of one groove scene, after generators
  Primitives,   // segments and arcs of one groove scene once its curves are flattened
  FieldValues,  // geodesic field values: vertices times fields
  ControlPoints,  // paintstroke control points of one stroke list, generators included
  DecodedBytes,   // memory one decoded texture or image takes (KTX2 levels inflated, image pixels as floats)
  Crossings,      // pairs of groove primitives that may cross (share a grid cell), counted before they are tried
  ProfileWork,    // texels of a shape map times the pieces of its profile (each texel's distance visits every piece)
  TamWork,        // candidate strokes per choice times the texels of every TAM level drawn
};

struct Budgets {
  // The defaults keep every tool well under 8 GB (each budget's cost model is in docs/conventions.md).
  std::uint64_t inputBytes = std::uint64_t(256) << 20;
  std::uint64_t triangles = 50'000'000;
  std::uint64_t textureSide = 16384;
  std::uint64_t grooves = 10'000'000;
  std::uint64_t primitives = 20'000'000;
  std::uint64_t fieldValues = std::uint64_t(1) << 30;
  std::uint64_t controlPoints = 10'000'000;
  std::uint64_t decodedBytes = std::uint64_t(512) << 20;
  std::uint64_t crossings = 100'000'000;
  std::uint64_t profileWork = 1'000'000'000;
  std::uint64_t tamWork = 500'000'000;

  std::uint64_t& operator[](Budget which);
  std::uint64_t operator[](Budget which) const;
};

// The option name of a budget ("input-bytes", "triangles", ...), and the reverse (false if unknown).
const char* budgetName(Budget which);
bool budgetFromName(const std::string& name, Budget& which);
// Every budget with its current value, "NAME=N, ..." (for --help and error messages).
std::string describeBudgets();

const Budgets& budgets();
void setBudgets(const Budgets& values);
// Applies one "NAME=N" setting; usage error if the name or the number is not valid.
Status applyBudgetSetting(const std::string& setting);

// Invalid input if `amount` exceeds the budget: "<amount> <what> exceed the budget of N (raise it with
// --budget NAME=M)", located at `where`.
Status checkBudget(Budget which, std::uint64_t amount, const std::string& what, Location where);

}  // namespace bake
