#include "gl/shader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "runtime/gl_test.h"

namespace bake {
namespace {

using test::GlTest;

gl::Variant standardMesh(std::vector<std::string> defines) {
  return {{"standard/mesh.vert", "standard/mesh.frag"}, std::move(defines)};
}

// A vertex stage that works with the fragment stages below.
const char* kPlainVertex = R"(layout(location = 0) in vec3 aPosition;
void main() { gl_Position = vec4(aPosition, 1.0); }
)";

TEST(EmbeddedShaders, TableHoldsTheShadersFolderSorted) {
  const gl::ShaderSource* vertex = gl::findShader("standard/mesh.vert");
  ASSERT_NE(vertex, nullptr);
  EXPECT_NE(std::string(vertex->text).find("uViewProj"), std::string::npos);
  EXPECT_NE(gl::findShader("standard/mesh.frag"), nullptr);
  EXPECT_NE(gl::findShader("common/lighting.glsl"), nullptr);
  EXPECT_EQ(gl::findShader("README.md"), nullptr) << "only GLSL files are embedded";
  EXPECT_EQ(gl::findShader("standard/missing.vert"), nullptr);
  std::vector<std::string> paths;
  for (const gl::ShaderSource& source : gl::embeddedShaders()) paths.push_back(source.path);
  EXPECT_TRUE(std::is_sorted(paths.begin(), paths.end()));
  EXPECT_EQ(std::set<std::string>(paths.begin(), paths.end()).size(), paths.size());
}

TEST(Variant, KeyIgnoresDefineOrderAndSpacing) {
  const gl::Variant a = standardMesh({"HAS_TEXCOORD0", "FIELD_COUNT   2", "HAS_NORMALS"});
  const gl::Variant b = standardMesh({" HAS_NORMALS", "FIELD_COUNT 2", "HAS_TEXCOORD0", "HAS_NORMALS"});
  EXPECT_EQ(a.key(), "standard/mesh.vert+standard/mesh.frag[FIELD_COUNT 2,HAS_NORMALS,HAS_TEXCOORD0]");
  EXPECT_EQ(a.key(), b.key());
  EXPECT_EQ(standardMesh({}).key(), "standard/mesh.vert+standard/mesh.frag[]");
}

using ShaderLibraryTest = GlTest;

TEST_F(ShaderLibraryTest, CompilesOnlyTheVariantsAskedFor) {
  gl::ShaderLibrary library;
  EXPECT_TRUE(library.compiledVariants().empty());
  auto withNormals = library.program(standardMesh({"HAS_NORMALS"}));
  ASSERT_TRUE(withNormals.isOk()) << withNormals.status().describe();
  auto flat = library.program(standardMesh({}));
  ASSERT_TRUE(flat.isOk()) << flat.status().describe();
  EXPECT_NE(*withNormals, *flat);
  // A second request is served from the cache.
  auto again = library.program(standardMesh({"HAS_NORMALS"}));
  ASSERT_TRUE(again.isOk());
  EXPECT_EQ(*again, *withNormals);
  EXPECT_EQ(library.compiledVariants(), (std::vector<std::string>{
                                            "standard/mesh.vert+standard/mesh.frag[HAS_NORMALS]",
                                            "standard/mesh.vert+standard/mesh.frag[]",
                                        }));
}

TEST_F(ShaderLibraryTest, EveryStandardVariantCompiles) {
  gl::ShaderLibrary library;
  for (const auto& defines : std::vector<std::vector<std::string>>{
           {}, {"HAS_NORMALS"}, {"HAS_TEXCOORD0"}, {"HAS_NORMALS", "HAS_TEXCOORD0"}}) {
    auto program = library.program(standardMesh(defines));
    EXPECT_TRUE(program.isOk()) << program.status().describe();
  }
  EXPECT_EQ(library.compiledVariants().size(), 4u);
}

TEST_F(ShaderLibraryTest, ErrorInIncludedFileNamesThatFileAndLine) {
  gl::ShaderLibrary library;
  const std::map<std::string, std::string> sources = {
      {"test/plain.vert", kPlainVertex},
      {"test/broken.frag", "#include \"helper.glsl\"\n"
                           "layout(location = 0) out vec4 fragColor;\n"
                           "void main() { fragColor = vec4(helper()); }\n"},
      {"test/helper.glsl", "// A helper whose third line is wrong.\n"
                           "float helper() {\n"
                           "  return undefinedThing;\n"
                           "}\n"},
  };
  auto program = library.programFromSources({{"test/plain.vert", "test/broken.frag"}, {}}, sources);
  ASSERT_FALSE(program.isOk());
  const Status& status = program.status();
  EXPECT_EQ(status.code(), ExitCode::InvalidInput);
  EXPECT_EQ(status.where().file, "shaders/test/helper.glsl") << status.describe();
  EXPECT_EQ(status.where().element, "line 3") << status.describe();
  EXPECT_NE(status.message().find("undefinedThing"), std::string::npos) << "driver message: " << status.message();
  EXPECT_NE(status.message().find("fragment stage"), std::string::npos) << status.message();
  EXPECT_TRUE(library.compiledVariants().empty()) << "failed and ad-hoc programs are not listed";
}

// After an include the lines of the including file count on from where they were.
TEST_F(ShaderLibraryTest, ErrorAfterAnIncludeNamesTheIncludingFile) {
  gl::ShaderLibrary library;
  const std::map<std::string, std::string> sources = {
      {"test/plain.vert", kPlainVertex},
      {"test/after.frag", "#include \"common/lighting.glsl\"\n"
                          "layout(location = 0) out vec4 fragColor;\n"
                          "void main() {\n"
                          "  fragColor = vec4(blinnPhong(vec3(0.0), 1.0));\n"
                          "}\n"},
  };
  auto program = library.programFromSources({{"test/plain.vert", "test/after.frag"}, {}}, sources);
  ASSERT_FALSE(program.isOk());
  EXPECT_EQ(program.status().where().file, "shaders/test/after.frag") << program.status().describe();
  EXPECT_EQ(program.status().where().element, "line 4") << program.status().describe();
}

// Preprocessor errors take the other path through the driver (the source-string number).
TEST_F(ShaderLibraryTest, PreprocessorErrorInIncludedFile) {
  gl::ShaderLibrary library;
  const std::map<std::string, std::string> sources = {
      {"test/plain.vert", kPlainVertex},
      {"test/main.frag", "layout(location = 0) out vec4 fragColor;\n"
                         "#include \"sub/stop.glsl\"\n"
                         "void main() { fragColor = vec4(1.0); }\n"},
      {"test/sub/stop.glsl", "\n#error stop here\n"},
  };
  auto program = library.programFromSources({{"test/plain.vert", "test/main.frag"}, {}}, sources);
  ASSERT_FALSE(program.isOk());
  EXPECT_EQ(program.status().where().file, "shaders/test/sub/stop.glsl") << program.status().describe();
  EXPECT_EQ(program.status().where().element, "line 2") << program.status().describe();
  EXPECT_NE(program.status().message().find("stop here"), std::string::npos) << program.status().message();
}

TEST_F(ShaderLibraryTest, IncludeCycleIsAnError) {
  gl::ShaderLibrary library;
  const std::map<std::string, std::string> sources = {
      {"test/plain.vert", kPlainVertex},
      {"test/cycle.frag", "#include \"a.glsl\"\nvoid main() {}\n"},
      {"test/a.glsl", "// a\n#include \"b.glsl\"\n"},
      {"test/b.glsl", "#include \"test/a.glsl\"  // from the root this time\n"},
  };
  auto program = library.programFromSources({{"test/plain.vert", "test/cycle.frag"}, {}}, sources);
  ASSERT_FALSE(program.isOk());
  EXPECT_EQ(program.status().code(), ExitCode::InvalidInput);
  EXPECT_NE(program.status().message().find("include cycle: test/a.glsl -> test/b.glsl -> test/a.glsl"),
            std::string::npos)
      << program.status().message();
  EXPECT_EQ(program.status().where().file, "shaders/test/b.glsl");
  EXPECT_EQ(program.status().where().element, "line 1");
}

TEST_F(ShaderLibraryTest, MissingShaderFileIsAnError) {
  gl::ShaderLibrary library;
  auto program = library.program({{"standard/mesh.vert", "standard/nope.frag"}, {}});
  ASSERT_FALSE(program.isOk());
  EXPECT_NE(program.status().message().find("standard/nope.frag"), std::string::npos) << program.status().message();
  EXPECT_TRUE(library.compiledVariants().empty());
}

TEST_F(ShaderLibraryTest, MissingIncludeNamesTheIncludingLine) {
  gl::ShaderLibrary library;
  const std::map<std::string, std::string> sources = {
      {"test/plain.vert", kPlainVertex},
      {"test/main.frag", "// first\n#include \"nowhere.glsl\"\nvoid main() {}\n"},
  };
  auto program = library.programFromSources({{"test/plain.vert", "test/main.frag"}, {}}, sources);
  ASSERT_FALSE(program.isOk());
  EXPECT_NE(program.status().message().find("nowhere.glsl"), std::string::npos) << program.status().message();
  EXPECT_EQ(program.status().where().file, "shaders/test/main.frag");
  EXPECT_EQ(program.status().where().element, "line 2");
}

TEST_F(ShaderLibraryTest, VersionDirectiveInAShaderIsAnError) {
  gl::ShaderLibrary library;
  const std::map<std::string, std::string> sources = {
      {"test/plain.vert", kPlainVertex},
      {"test/versioned.frag", "#version 330 core\nvoid main() {}\n"},
  };
  auto program = library.programFromSources({{"test/plain.vert", "test/versioned.frag"}, {}}, sources);
  ASSERT_FALSE(program.isOk());
  EXPECT_EQ(program.status().where().file, "shaders/test/versioned.frag");
  EXPECT_NE(program.status().message().find("#version"), std::string::npos);
}

TEST_F(ShaderLibraryTest, BadDefinesAreErrors) {
  gl::ShaderLibrary library;
  for (const std::string& bad : {"1ST_FEATURE", "HAS_NORMALS\n#define X", "A 1\\", ""}) {
    auto program = library.program(standardMesh({bad}));
    EXPECT_FALSE(program.isOk()) << "define '" << bad << "' was accepted";
  }
  auto twice = library.program(standardMesh({"N 1", "N 2"}));
  ASSERT_FALSE(twice.isOk());
  EXPECT_NE(twice.status().message().find("two values"), std::string::npos);
  EXPECT_TRUE(library.compiledVariants().empty());
}

TEST_F(ShaderLibraryTest, LinkErrorQuotesTheProgramLog) {
  gl::ShaderLibrary library;
  const std::map<std::string, std::string> sources = {
      {"test/plain.vert", kPlainVertex},
      {"test/reads.frag", "in vec3 vNeverWritten;\nlayout(location = 0) out vec4 fragColor;\n"
                          "void main() { fragColor = vec4(vNeverWritten, 1.0); }\n"},
  };
  auto program = library.programFromSources({{"test/plain.vert", "test/reads.frag"}, {}}, sources);
  ASSERT_FALSE(program.isOk());
  EXPECT_NE(program.status().message().find("failed to link"), std::string::npos) << program.status().message();
  EXPECT_NE(program.status().message().find("vNeverWritten"), std::string::npos) << program.status().message();
}

}  // namespace
}  // namespace bake
