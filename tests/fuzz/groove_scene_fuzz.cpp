// Groove scene JSON (groovebake's input): parsing, checking and finishing the scene (paths, SVG path
// data, cross-sections, flattening).
#include "bake/core/limits.h"
#include "fuzz_support.h"
#include "grooves/input/scene.h"

// Budgets a thousand times below the defaults: an input that is merely large (a spiral of thousands of
// turns) is the budgets' business, tested elsewhere; here it would only hit libFuzzer's 10 s timeout.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  bake::Budgets small;
  small.grooves = 10'000;
  small.primitives = 20'000;
  bake::setBudgets(small);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  (void)bake::grooves::parseGrooveScene(bake::fuzz::asText(data, size), "fuzz.json");
  return 0;
}
