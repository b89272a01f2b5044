// Shader programs built from the GLSL in shaders/, which the build embeds into the runtime (so a
// runtime can never load a mismatched file from disk). A variant is a program plus the set of
// #defines of the features a scene uses; only the variants a scene asks for are compiled, and the
// library lists them for the report. Sources may `#include "file.glsl"` (resolved against the
// embedded table). A compile or link failure names the shader file and line and quotes the driver.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "bake/core/status.h"

namespace bake::gl {

using GLuintHandle = unsigned int;

// An embedded shader source: its path under shaders/ ("standard/mesh.frag") and its text.
struct ShaderSource {
  const char* path;
  const char* text;
};
// The embedded table (generated at build time from shaders/).
const std::vector<ShaderSource>& embeddedShaders();
const ShaderSource* findShader(const std::string& path);

struct ProgramDesc {
  std::string vertex;    // paths under shaders/
  std::string fragment;
  std::string geometry;  // optional
  std::string tessControl, tessEvaluation;  // optional
};

struct Variant {
  ProgramDesc program;
  std::vector<std::string> defines;  // e.g. "HAS_NORMALS", "FIELD_COUNT 2"; order does not matter

  std::string key() const;  // stable description, e.g. "standard/mesh.vert+standard/mesh.frag[HAS_NORMALS]"
};

// Holds GL program names, so it must be destroyed while its context is still alive and current:
// the destructor deletes the programs only when a context is current (otherwise it leaves them to
// die with their context).
class ShaderLibrary {
 public:
  ShaderLibrary() = default;
  ~ShaderLibrary();
  ShaderLibrary(const ShaderLibrary&) = delete;
  ShaderLibrary& operator=(const ShaderLibrary&) = delete;

  // Compiles and links on first use; later calls return the cached program. Needs a current context.
  Result<GLuintHandle> program(const Variant& variant);
  // Keys of every variant compiled so far, sorted.
  std::vector<std::string> compiledVariants() const;

  // Compiles one variant from explicit sources (for tests of error reporting): `sources` maps paths to
  // text and takes precedence over the embedded table.
  Result<GLuintHandle> programFromSources(const Variant& variant, const std::map<std::string, std::string>& sources);

 private:
  std::map<std::string, GLuintHandle> programs_;
  std::vector<GLuintHandle> uncached_;  // programs made by programFromSources, deleted with the library
};

}  // namespace bake::gl
