// The one renderer: draws a Snapshot with OpenGL 3.3 core, for the viewer, the headless
// renderer, the tests and the grader alike.
//
//   ContextResult ctx = makeHeadlessContext(w, h);          // or a GlfwContext in the viewer
//   Renderer renderer(*ctx.context);                        // once per context
//   Image image = renderer.render(snapshot, w, h, options); // empty image: see error()
//   std::string error = writePng(image, "frame.png");
//
// Design notes (docs/rendering.md, "Determinism"): every line and disc is made of triangles
// computed on the CPU in double and rounded once to float (render/geometry.h); colours are flat
// (no interpolation), there is no blending, no wide GL line, no GL_LINE_SMOOTH, no MSAA. On
// llvmpipe the same snapshot then gives the same bytes on every run.
#pragma once

#include <string>

#include "contexts/gl_context.h"
#include "contexts/gl_functions.h"
#include "image/image.h"
#include "render/render_options.h"
#include "scenes/snapshot.h"

namespace a6 {

class Renderer {
 public:
  /// Compiles the shaders and creates the buffers in `context`, which must outlive the
  /// renderer. On failure ok() is false and error() says why; render() then returns nothing.
  explicit Renderer(GLContext& context);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  bool ok() const { return error_.empty(); }
  /// Why the last call failed (empty if it did not).
  const std::string& error() const { return error_; }

  /// Draws `snapshot` into an offscreen width x height framebuffer and reads it back (rows top
  /// to bottom). Returns an empty image on failure (see error()). Makes the context current.
  Image render(const Snapshot& snapshot, int width, int height,
               const RenderOptions& options = RenderOptions());

  /// Draws `snapshot` into the framebuffer bound now (e.g. a window's), in the viewport
  /// (left, 0, width, height), background included, leaving the pixels outside it alone. For
  /// the viewer; does not change the context.
  bool draw(const Snapshot& snapshot, int width, int height,
            const RenderOptions& options = RenderOptions(), int left = 0);

  /// The GL functions of the context (for the viewer's own few calls).
  const GLFunctions& gl() const { return gl_; }
  const GLContext& context() const { return context_; }

 private:
  bool fail(const std::string& message);
  GLuint compileShader(GLenum kind, const char* source, const char* name);
  bool buildProgram();
  void makeVertexBuffer();
  bool ensureFramebuffer(int width, int height);

  GLContext& context_;
  GLFunctions gl_;
  std::string error_;
  unsigned int program_ = 0, vertexArray_ = 0, vertexBuffer_ = 0;
  unsigned int framebuffer_ = 0, colorBuffer_ = 0;
  int framebufferWidth_ = 0, framebufferHeight_ = 0;
};

}  // namespace a6
