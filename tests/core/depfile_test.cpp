#include <gtest/gtest.h>

#include "core/build_syntax.h"
#include "core/depfile.h"
#include "support/golden.h"

namespace bake {
namespace {

std::string escaped(const std::string& path) {
  Result<std::string> text = escapeDepfilePath(path);
  EXPECT_TRUE(text.isOk()) << path;
  return text.isOk() ? *text : std::string();
}

TEST(Depfile, EscapesMakeSpecialCharacters) {
  EXPECT_EQ(escaped("/a b/c"), "/a\\ b/c");
  EXPECT_EQ(escaped("/x#1"), "/x\\#1");
  EXPECT_EQ(escaped("/cost$"), "/cost$$");
  EXPECT_EQ(escaped("/c:/drive"), "/c\\:/drive");
  EXPECT_EQ(escaped("/tail\\ space"), "/tail\\\\\\ space");
  EXPECT_EQ(escaped("/plain/path.glb"), "/plain/path.glb");
}

TEST(Depfile, RefusesWhatMakeCannotHold) {
  for (const std::string bad : {"/a\nb", "/a\rb", "/a;touch x", "/x=y", "/a|b"}) {
    const Result<std::string> text = escapeDepfilePath(bad);
    ASSERT_FALSE(text.isOk()) << bad;
    EXPECT_EQ(text.status().code(), ExitCode::Usage);
    EXPECT_NE(text.status().message().find("cannot express"), std::string::npos);
  }
}

TEST(Depfile, EveryOutputIsATargetWithAbsolutePaths) {
  const Result<std::string> text = formatDepfile({"/out/a.glb", "/out/a.json"}, {"/in/mesh one.obj", "/in/../in/h.png"});
  ASSERT_TRUE(text.isOk());
  EXPECT_EQ(*text, "/out/a.glb \\\n /out/a.json: \\\n  /in/mesh\\ one.obj \\\n  /in/h.png\n");
  const Result<std::string> relative = formatDepfile({"rel.glb"}, {});
  ASSERT_TRUE(relative.isOk());
  EXPECT_EQ(relative->front(), '/');
  EXPECT_FALSE(formatDepfile({"/out/a.glb"}, {"/in/new\nline.obj"}).isOk());
}

TEST(NinjaSyntax, EscapesPathsAndRefusesWhatNinjaCannotHold) {
  EXPECT_EQ(*ninjaEscapedPath("/a b/c:d$e"), "/a$ b/c$:d$$e");
  EXPECT_FALSE(ninjaEscapedPath("/a\nbuild x: phony").isOk());
  EXPECT_FALSE(ninjaEscapedPath("/a|b").isOk());
  EXPECT_EQ(*ninjaEscapedValue("echo $x 'a b'"), "echo $$x 'a b'");
  EXPECT_FALSE(ninjaEscapedValue("a\nrule evil").isOk());
  EXPECT_EQ(commentSafe("scene\nbuild x: phony"), "scene?build x: phony");
}

}  // namespace
}  // namespace bake
