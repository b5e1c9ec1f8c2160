#pragma once
// A GoogleTest fixture with a headless debug GL 4.5 core context. Any GL error
// reported through KHR_debug during a test fails that test.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "foveate/gpu/context.hpp"
#include "foveate/gpu/gl.hpp"

namespace foveate::test {

/// Whether the current context is Mesa's llvmpipe, where the references
/// and the tightest tolerances were made; another renderer rounds
/// otherwise, and a test that holds bits says how it holds them there.
inline bool on_llvmpipe() {
  const auto* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return r && std::string(r).find("llvmpipe") != std::string::npos;
}

class GlTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!context_) {
      gpu::ContextOptions o;
      o.debug = true;
      context_ = gpu::create_headless_context(o);
    }
    context_->make_current();
  }
  void TearDown() override {
    for (const auto& e : context_->take_debug_errors())
      ADD_FAILURE() << "GL debug error: " << e.text;
  }
  static gpu::Context& context() { return *context_; }

 private:
  static inline std::unique_ptr<gpu::Context> context_;
};

}  // namespace foveate::test
