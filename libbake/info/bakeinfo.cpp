#include "bake/info/bakeinfo.h"

#include "info/describe.h"

namespace bake::info {

Status run(const Settings& settings, Diagnostics& diagnostics, std::FILE* out) {
  Status first;
  nlohmann::json all = nlohmann::json::array();
  for (const std::string& file : settings.files) {
    auto description = describeFile(file);
    if (!description.isOk()) {
      Status failure = description.takeStatus();
      failure.inFile(file);
      if (settings.files.size() > 1) diagnostics.error(failure);  // the last one is printed by the caller
      if (first.isOk()) first = failure;
      continue;
    }
    if (settings.json) {
      all.push_back(std::move(*description));
    } else {
      std::fputs(formatText(*description).c_str(), out);
    }
  }
  if (settings.json && !all.empty()) {
    const nlohmann::json& document = settings.files.size() == 1 ? all[0] : all;
    std::fputs((document.dump(2) + "\n").c_str(), out);
  }
  if (!first.isOk() && settings.files.size() > 1) {
    return Status(first.code(), "some files could not be described (see above)");
  }
  return first;
}

}  // namespace bake::info
