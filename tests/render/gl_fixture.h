// One headless context for the GL tests. They skip (with the reason) only when no headless GL
// can be created at all; with A6_REQUIRE_GL=1 in the environment (CI) that fails instead.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>

#include "contexts/gl_context.h"
#include "render/renderer.h"

namespace a6::test {

class HeadlessGL : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (context_) return;
    ContextResult result = makeHeadlessContext(256, 256);
    if (!result) {
      error_ = result.error;
      return;
    }
    context_ = std::move(result.context);
    renderer_ = std::make_unique<Renderer>(*context_);
  }
  static void TearDownTestSuite() {
    renderer_.reset();
    context_.reset();
  }

  void SetUp() override {
    if (!context_) {
      const char* require = std::getenv("A6_REQUIRE_GL");
      if (require != nullptr && std::string(require) == "1") {
        FAIL() << "A6_REQUIRE_GL=1 but no headless OpenGL context: " << error_;
      }
      GTEST_SKIP() << "no headless OpenGL context (install libosmesa6 or Mesa's EGL): " << error_;
    }
    ASSERT_TRUE(renderer_->ok()) << renderer_->error();
  }

  static std::unique_ptr<GLContext> context_;
  static std::unique_ptr<Renderer> renderer_;
  static std::string error_;
};

inline std::unique_ptr<GLContext> HeadlessGL::context_;
inline std::unique_ptr<Renderer> HeadlessGL::renderer_;
inline std::string HeadlessGL::error_;

}  // namespace a6::test
