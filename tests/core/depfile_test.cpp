#include <gtest/gtest.h>

#include "core/depfile.h"
#include "support/golden.h"

namespace bake {
namespace {

TEST(Depfile, EscapesMakeSpecialCharacters) {
  EXPECT_EQ(escapeDepfilePath("/a b/c"), "/a\\ b/c");
  EXPECT_EQ(escapeDepfilePath("/x#1"), "/x\\#1");
  EXPECT_EQ(escapeDepfilePath("/cost$"), "/cost$$");
  EXPECT_EQ(escapeDepfilePath("/tail\\ space"), "/tail\\\\\\ space");
  EXPECT_EQ(escapeDepfilePath("/plain/path.glb"), "/plain/path.glb");
}

TEST(Depfile, EveryOutputIsATargetWithAbsolutePaths) {
  const std::string text = formatDepfile({"/out/a.glb", "/out/a.json"}, {"/in/mesh one.obj", "/in/../in/h.png"});
  EXPECT_EQ(text,
            "/out/a.glb \\\n /out/a.json: \\\n  /in/mesh\\ one.obj \\\n  /in/h.png\n");
  const std::string relative = formatDepfile({"rel.glb"}, {});
  EXPECT_EQ(relative.front(), '/');
}

}  // namespace
}  // namespace bake
