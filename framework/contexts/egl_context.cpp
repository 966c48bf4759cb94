// The EGL surfaceless backend (EGL_MESA_platform_surfaceless): no window, no pbuffer; the
// renderer draws into a framebuffer object. Mesa picks a GPU render node when it can, llvmpipe
// otherwise (LIBGL_ALWAYS_SOFTWARE=1 forces llvmpipe).
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>

#include "contexts/headless_backends.h"

namespace a6::detail {
namespace {

std::string eglErrorText() {
  char text[32];
  std::snprintf(text, sizeof text, "EGL error 0x%04X", static_cast<unsigned>(eglGetError()));
  return text;
}

bool hasExtension(const char* extensions, const char* name) {
  if (extensions == nullptr) return false;
  const size_t length = std::strlen(name);
  for (const char* s = extensions; (s = std::strstr(s, name)) != nullptr; s += length) {
    const bool starts = s == extensions || s[-1] == ' ';
    const bool ends = s[length] == '\0' || s[length] == ' ';
    if (starts && ends) return true;
  }
  return false;
}

class EGLGLContext : public GLContext {
 public:
  EGLGLContext(EGLDisplay display, EGLContext context, int width, int height)
      : display_(display), context_(context), width_(width), height_(height) {}

  ~EGLGLContext() override {
    if (eglGetCurrentContext() == context_) {
      eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    eglDestroyContext(display_, context_);
    // The display stays initialised: it is one per process, shared by every context made
    // here, and eglTerminate would unload Mesa's driver (which then leaks a block).
  }

  bool makeCurrent() override {
    if (eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) return true;
    error_ = "EGL: eglMakeCurrent without a surface failed (" + eglErrorText() + ")";
    return false;
  }

  GLProc getProcAddress(const char* name) const override {
    return reinterpret_cast<GLProc>(eglGetProcAddress(name));
  }
  int width() const override { return width_; }
  int height() const override { return height_; }
  std::string backend() const override { return "egl"; }

  void describe() { readDescription(); }

 private:
  EGLDisplay display_;
  EGLContext context_;
  int width_, height_;
};

ContextResult fail(const std::string& what) { return {nullptr, "EGL: " + what}; }

}  // namespace

ContextResult makeEGLContext(int width, int height) {
  // The surfaceless platform is a client extension: query it before any display exists.
  const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
    return fail(
        "EGL_MESA_platform_surfaceless is not available (is Mesa's libegl-mesa0 "
        "installed?)");
  }
  EGLDisplay display =
      eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) {
    return fail("no surfaceless display (" + eglErrorText() + ")");
  }
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) {
    return fail("eglInitialize failed on the surfaceless display (" + eglErrorText() + ")");
  }
  const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
  if (!hasExtension(extensions, "EGL_KHR_surfaceless_context")) {
    return fail("the display lacks EGL_KHR_surfaceless_context");
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    return fail("desktop OpenGL is not available (eglBindAPI: " + eglErrorText() + ")");
  }

  // Any config that renders desktop GL: we draw into FBOs, never into an EGL surface.
  const EGLint configAttributes[] = {EGL_SURFACE_TYPE, 0, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                     EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (!eglChooseConfig(display, configAttributes, &config, 1, &count) || count < 1) {
    return fail("no config renders desktop OpenGL (" + eglErrorText() + ")");
  }
  const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                      3,
                                      EGL_CONTEXT_MINOR_VERSION,
                                      3,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                      EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
  if (context == EGL_NO_CONTEXT) {
    return fail("could not create a 3.3 core context (" + eglErrorText() + ")");
  }
  auto result = std::make_unique<EGLGLContext>(display, context, width, height);
  if (!result->makeCurrent()) return {nullptr, result->error()};
  result->describe();
  return {std::move(result), ""};
}

}  // namespace a6::detail
