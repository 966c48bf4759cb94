#include "contexts/glfw_context.h"

#include <GLFW/glfw3.h>

namespace a6 {
namespace {

// GLFW reports errors through a callback: keep the last one for our messages.
std::string gLastGlfwError;
int gWindows = 0;

void onGlfwError(int code, const char* description) {
  gLastGlfwError = std::string(description) + " (GLFW error " + std::to_string(code) + ")";
}

}  // namespace

GlfwContext::Result GlfwContext::create(const Options& options) {
  glfwSetErrorCallback(onGlfwError);
  if (gWindows == 0 && !glfwInit()) {
    return {nullptr, "GLFW: could not initialise: " + gLastGlfwError +
                         ". Is there a display (DISPLAY set, or run under xvfb-run)?"};
  }
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SAMPLES, 0);  // no MSAA: the same pixels as the headless renderer
  glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
  GLFWwindow* window =
      glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
  if (window == nullptr) {
    if (gWindows == 0) glfwTerminate();
    return {nullptr,
            "GLFW: could not open a window with an OpenGL 3.3 core context: " + gLastGlfwError};
  }
  ++gWindows;
  std::unique_ptr<GlfwContext> context(new GlfwContext(window));
  if (!context->makeCurrent()) return {nullptr, context->error()};
  glfwSwapInterval(options.vsync ? 1 : 0);
  context->readDescription();
  return {std::move(context), ""};
}

GlfwContext::~GlfwContext() {
  glfwDestroyWindow(window_);
  if (--gWindows == 0) glfwTerminate();
}

bool GlfwContext::makeCurrent() {
  glfwMakeContextCurrent(window_);
  return true;
}

GLProc GlfwContext::getProcAddress(const char* name) const {
  return reinterpret_cast<GLProc>(glfwGetProcAddress(name));
}

int GlfwContext::width() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return w;
}

int GlfwContext::height() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return h;
}

}  // namespace a6
