// The viewer's context: a GLFW window with an OpenGL 3.3 core context (no MSAA).
//
// Its own library (a6_contexts_glfw), so that headless programs (the grader, the golden
// renderer) do not link GLFW and X11.
#pragma once

#include <memory>
#include <string>

#include "contexts/gl_context.h"

struct GLFWwindow;

namespace a6 {

class GlfwContext : public GLContext {
 public:
  struct Options {
    int width = 1280, height = 800;  ///< window size, screen coordinates
    std::string title = "a6";
    bool visible = true;  ///< false: a hidden window (smoke tests under Xvfb)
    bool vsync = true;
  };
  struct Result {
    std::unique_ptr<GlfwContext> context;
    std::string error;  ///< empty on success
    explicit operator bool() const { return context != nullptr; }
  };

  /// Initialises GLFW (once per process), opens the window and makes its context current.
  static Result create(const Options& options);
  ~GlfwContext() override;

  bool makeCurrent() override;
  GLProc getProcAddress(const char* name) const override;
  /// The framebuffer size, pixels (differs from the window size on high-DPI screens).
  int width() const override;
  int height() const override;
  std::string backend() const override { return "glfw"; }

  /// The window, for input callbacks, ImGui's GLFW backend and glfwSwapBuffers.
  GLFWwindow* window() const { return window_; }

 private:
  explicit GlfwContext(GLFWwindow* window) : window_(window) {}
  GLFWwindow* window_;
};

}  // namespace a6
