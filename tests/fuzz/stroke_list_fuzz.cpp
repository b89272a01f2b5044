// Stroke lists (strokebake's input, formats/paintstroke-input.md): JSON when the text opens with '{'
// (after blanks), CSV otherwise; then the tree generators the list names (grow generators read meshes,
// which the mesh target covers) and the validation and repair every bake runs.
#include "bake/core/diagnostics.h"
#include "bake/core/limits.h"
#include "bake/paintstrokes/generators.h"
#include "fuzz_support.h"
#include "paintstrokes/input/input.h"
#include "paintstrokes/input/validate.h"

// A control-point budget a thousand times below the default: a merely large list is the budget's
// business (tested elsewhere) and would only reach libFuzzer's time-out here.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  bake::Budgets small;
  small.controlPoints = 100'000;
  bake::setBudgets(small);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = bake::fuzz::asText(data, size);
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  const bool json = first != std::string::npos && text[first] == '{';
  bake::Result<bake::paintstrokes::StrokeInput> input =
      json ? bake::paintstrokes::parseStrokeJson(text, "fuzz.json") : bake::paintstrokes::parseStrokeCsv(text, "fuzz.csv");
  if (!input.isOk()) return 0;
  std::vector<std::string> inputs;
  for (const nlohmann::json& entry : input->generators) {
    if (!entry.is_object() || !entry.contains("type") || entry["type"] != "tree") continue;
    if (!bake::paintstrokes::runGenerator(entry, input->directory, {"fuzz.json", "generators"}, bake::budgets(), input->set,
                                     inputs, nullptr).isOk())
      return 0;
  }
  bake::Diagnostics quiet("fuzz", /*quiet=*/true);
  (void)bake::paintstrokes::validateStrokes(input->set, "fuzz", quiet);
  return 0;
}
