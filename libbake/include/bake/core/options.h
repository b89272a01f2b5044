// What the library needs of a tool's command line, without the parser: the options every tool shares
// (set by tools/common/cli.h from --quiet, --report, ...) and the options a run was given, by name,
// for the cache key (core/cache.h). The command-line parser itself (CLI11) stays in tools/common.
#pragma once

#include <string>
#include <vector>

namespace bake {

const char* toolkitVersion();

struct CommonOptions {
  bool quiet = false;
  std::string reportPath;
  std::string depfilePath;
  unsigned threads = 0;  // 0 = all hardware threads
  bool printInputs = false;
  std::string cacheDir;  // --cache-dir: content-addressed cache of outputs (core/cache.h)

  // Set by runCachedBake (core/session.h) when the cache missed: the bake's session stores what it
  // commits under `key`, provided it read no file but `inputs` and wrote exactly `outputs`.
  struct CacheStore {
    std::string key;
    std::vector<std::string> inputs;
    std::vector<std::string> outputs;
  } cacheStore;
};

// One option given on a command line: its key (the first long name, without dashes), every long
// name it answers to, the values given, and whether they are numbers (compared as numbers).
struct GivenOption {
  std::string name;
  std::vector<std::string> longNames;
  std::vector<std::string> values;
  bool numeric = false;
};
using GivenOptions = std::vector<GivenOption>;

}  // namespace bake
