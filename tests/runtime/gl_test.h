// Shared fixture for the GL runtime tests: each test gets its own headless OpenGL 4.5 core context
// (Mesa's llvmpipe when there is no GPU). Failing to make one fails the test with the reasons for
// every platform tried; the tests are labelled gl so machines without EGL can leave them out.
#pragma once

#include <gtest/gtest.h>

#include <memory>

#include "gl/context.h"

namespace bake::test {

class GlTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto context = gl::createHeadlessContext();
    ASSERT_TRUE(context.isOk()) << context.status().describe();
    context_ = std::move(context).value();
  }
  // Members are destroyed after the test body, so libraries made in a test go before the context.
  std::unique_ptr<gl::Context> context_;
};

}  // namespace bake::test
