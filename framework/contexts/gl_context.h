// An OpenGL 3.3 core context, whatever made it: OSMesa (headless), EGL surfaceless (headless),
// or a GLFW window (the viewer).
//
// Design notes
// - Nothing here includes a GL header: the GL functions come from our own loader
//   (contexts/gl_functions.h), fed by getProcAddress() of the context that will run them.
// - Headless contexts have no useful default framebuffer: the renderer draws into a framebuffer
//   object of the size it is asked for, so every backend behaves the same.
// - OSMesa is removed from Mesa 25.1 onwards; it stays behind this interface, beside EGL.
// - Errors are values: creating a context returns the context or a message saying what failed
//   and what to do about it.
#pragma once

#include <memory>
#include <string>

namespace a6 {

/// A GL function as returned by a context, before it is cast to its real type.
using GLProc = void (*)();

class GLContext {
 public:
  virtual ~GLContext() = default;
  GLContext(const GLContext&) = delete;
  GLContext& operator=(const GLContext&) = delete;

  /// Makes this context current on the calling thread. False (with error()) when it fails.
  virtual bool makeCurrent() = 0;
  /// The address of a GL function of this context, nullptr if it has none by that name.
  virtual GLProc getProcAddress(const char* name) const = 0;
  /// The size of the context's own drawing surface, pixels (the window, or the size asked for).
  virtual int width() const = 0;
  virtual int height() const = 0;
  /// The backend: "osmesa", "egl" or "glfw".
  virtual std::string backend() const = 0;
  /// GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits); 4.5 (Core Profile)
  /// Mesa 22.3.6". Golden images are only comparable between identical renderers.
  const std::string& description() const { return description_; }
  const std::string& renderer() const { return renderer_; }
  const std::string& version() const { return version_; }
  /// The last error (empty if none).
  const std::string& error() const { return error_; }

 protected:
  GLContext() = default;
  /// Reads GL_RENDERER and GL_VERSION; call once the context is current.
  void readDescription();
  std::string error_;

 private:
  std::string renderer_, version_, description_;
};

/// Which headless implementation to use.
enum class HeadlessBackend {
  Auto,    ///< OSMesa if it works, else EGL surfaceless
  OSMesa,  ///< OSMesa (libosmesa6): always software (llvmpipe), the reference for goldens
  EGL,     ///< EGL surfaceless (EGL_MESA_platform_surfaceless): Mesa's GPU driver or llvmpipe
};

/// "auto", "osmesa", "egl"; parseHeadlessBackend returns false for anything else.
const char* toString(HeadlessBackend backend);
bool parseHeadlessBackend(const std::string& text, HeadlessBackend* backend);

/// A context, or why there is none.
struct ContextResult {
  std::unique_ptr<GLContext> context;
  std::string error;  ///< empty on success
  explicit operator bool() const { return context != nullptr; }
};

/// Creates a headless OpenGL 3.3 core context, current on the calling thread. width and height
/// (pixels, > 0) are the size of its surface; the renderer draws into its own framebuffer object
/// anyway. With Auto, each backend is tried in turn and the error lists why each one failed.
ContextResult makeHeadlessContext(int width, int height,
                                  HeadlessBackend backend = HeadlessBackend::Auto);

/// The backends this build was compiled with (e.g. "osmesa egl").
std::string availableHeadlessBackends();

}  // namespace a6
