// The scene description reader (pipe/scene.h): what it accepts, and errors that name the element.
#include <gtest/gtest.h>

#include "pipe/scene.h"

namespace {

TEST(PipeScene, RejectsMissingObjects) {
  const auto scene = bake::pipe::parseScene(nlohmann::json{{"version", 1}, {"materials", nlohmann::json::array()}},
                                            "scene.json");
  ASSERT_FALSE(scene.isOk());
  EXPECT_EQ(scene.status().code(), bake::ExitCode::InvalidInput);
}

}  // namespace
