#include "render/renderer.h"

#include <algorithm>
#include <cstring>

#include "render/geometry.h"
#include "render/palette.h"

namespace a6 {
namespace {

// Positions arrive in normalized device coordinates; colours are flat, so a triangle's pixels
// get exactly its RGBA8 colour.
const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec2 position;
layout(location = 1) in vec4 color;
flat out vec4 vColor;
void main() {
  vColor = color;
  gl_Position = vec4(position, 0.0, 1.0);
}
)";

const char* kFragmentShader = R"(#version 330 core
flat in vec4 vColor;
out vec4 fragColor;
void main() { fragColor = vColor; }
)";

std::string size(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

}  // namespace

Renderer::Renderer(GLContext& context) : context_(context) {
  if (!context_.makeCurrent()) {
    fail("Renderer: " + context_.error());
    return;
  }
  if (std::string missing = gl_.load(context_); !missing.empty()) {
    fail("Renderer: " + missing);
    return;
  }
  if (!buildProgram()) return;
  makeVertexBuffer();
  if (GLenum e = gl_.GetError(); e != GL_NO_ERROR) {
    fail("Renderer: setting up failed with " + glErrorName(e));
  }
}

// A compiled shader, or 0 (and error() says why).
GLuint Renderer::compileShader(GLenum kind, const char* source, const char* name) {
  GLuint shader = gl_.CreateShader(kind);
  gl_.ShaderSource(shader, 1, &source, nullptr);
  gl_.CompileShader(shader);
  GLint compiled = GL_FALSE;
  gl_.GetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
  if (!compiled) {
    char log[2048] = {};
    gl_.GetShaderInfoLog(shader, sizeof log, nullptr, log);
    fail(std::string("Renderer: the ") + name + " shader does not compile on " +
         context_.description() + ": " + log);
    gl_.DeleteShader(shader);
    return 0;
  }
  return shader;
}

// The shaders, compiled and linked into program_.
bool Renderer::buildProgram() {
  GLuint vertex = compileShader(GL_VERTEX_SHADER, kVertexShader, "vertex");
  GLuint fragment = vertex ? compileShader(GL_FRAGMENT_SHADER, kFragmentShader, "fragment") : 0;
  if (!vertex || !fragment) {
    if (vertex) gl_.DeleteShader(vertex);
    return false;
  }
  program_ = gl_.CreateProgram();
  gl_.AttachShader(program_, vertex);
  gl_.AttachShader(program_, fragment);
  gl_.LinkProgram(program_);
  gl_.DeleteShader(vertex);
  gl_.DeleteShader(fragment);
  GLint linked = GL_FALSE;
  gl_.GetProgramiv(program_, GL_LINK_STATUS, &linked);
  if (!linked) {
    char log[2048] = {};
    gl_.GetProgramInfoLog(program_, sizeof log, nullptr, log);
    return fail(std::string("Renderer: the shaders do not link: ") + log);
  }
  return true;
}

// One vertex buffer, refilled per frame: position (2 floats), colour (4 normalized bytes).
void Renderer::makeVertexBuffer() {
  gl_.GenVertexArrays(1, &vertexArray_);
  gl_.GenBuffers(1, &vertexBuffer_);
  gl_.BindVertexArray(vertexArray_);
  gl_.BindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
  gl_.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, x)));
  gl_.VertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, r)));
  gl_.EnableVertexAttribArray(0);
  gl_.EnableVertexAttribArray(1);
  gl_.BindVertexArray(0);
  gl_.BindBuffer(GL_ARRAY_BUFFER, 0);
}

Renderer::~Renderer() {
  if (gl_.DeleteProgram == nullptr || !context_.makeCurrent()) return;
  if (framebuffer_) gl_.DeleteFramebuffers(1, &framebuffer_);
  if (colorBuffer_) gl_.DeleteRenderbuffers(1, &colorBuffer_);
  if (vertexBuffer_) gl_.DeleteBuffers(1, &vertexBuffer_);
  if (vertexArray_) gl_.DeleteVertexArrays(1, &vertexArray_);
  if (program_) gl_.DeleteProgram(program_);
}

bool Renderer::fail(const std::string& message) {
  error_ = message;
  return false;
}

bool Renderer::ensureFramebuffer(int width, int height) {
  if (framebuffer_ && width == framebufferWidth_ && height == framebufferHeight_) return true;
  GLint maxSize = 0;
  gl_.GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
  if (width > maxSize || height > maxSize) {
    return fail("Renderer: " + size(width, height) + " is larger than this context allows (" +
                std::to_string(maxSize) + " pixels a side)");
  }
  if (!framebuffer_) gl_.GenFramebuffers(1, &framebuffer_);
  if (!colorBuffer_) gl_.GenRenderbuffers(1, &colorBuffer_);
  gl_.BindRenderbuffer(GL_RENDERBUFFER, colorBuffer_);
  gl_.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  gl_.BindRenderbuffer(GL_RENDERBUFFER, 0);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colorBuffer_);
  const GLenum status = gl_.CheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    framebufferWidth_ = framebufferHeight_ = 0;
    return fail("Renderer: the " + size(width, height) + " offscreen framebuffer is incomplete (" +
                glErrorName(status) + ")");
  }
  framebufferWidth_ = width;
  framebufferHeight_ = height;
  return true;
}

bool Renderer::draw(const Snapshot& snapshot, int width, int height, const RenderOptions& options,
                    int left) {
  if (program_ == 0 || vertexArray_ == 0) {
    if (error_.empty()) error_ = "Renderer: not initialised";
    return false;
  }
  error_.clear();
  if (width <= 0 || height <= 0) return fail("Renderer: invalid size " + size(width, height));

  const std::vector<Vertex> vertices = buildGeometry(snapshot, width, height, options);

  // State that changes pixels is set here, whatever the caller (e.g. ImGui) left behind.
  // The scissor keeps the clear inside the viewport (two views side by side in one window).
  gl_.Viewport(left, 0, width, height);
  gl_.Scissor(left, 0, width, height);
  gl_.Enable(GL_SCISSOR_TEST);
  gl_.Disable(GL_BLEND);
  gl_.Disable(GL_DEPTH_TEST);
  gl_.Disable(GL_STENCIL_TEST);
  gl_.Disable(GL_CULL_FACE);
  gl_.Disable(GL_MULTISAMPLE);
  gl_.Disable(GL_FRAMEBUFFER_SRGB);
  const Rgba bg = palette::kBackground;
  gl_.ClearColor(bg.r / 255.0f, bg.g / 255.0f, bg.b / 255.0f, 1.0f);
  gl_.Clear(GL_COLOR_BUFFER_BIT);

  gl_.UseProgram(program_);
  gl_.BindVertexArray(vertexArray_);
  gl_.BindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
  gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
                 vertices.empty() ? nullptr : vertices.data(), GL_STREAM_DRAW);
  // One draw call: OpenGL paints triangles in order, so later ones cover earlier ones.
  if (!vertices.empty()) gl_.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
  gl_.BindVertexArray(0);
  gl_.BindBuffer(GL_ARRAY_BUFFER, 0);
  gl_.UseProgram(0);
  gl_.Disable(GL_SCISSOR_TEST);
  if (GLenum e = gl_.GetError(); e != GL_NO_ERROR) {
    return fail("Renderer: drawing failed with " + glErrorName(e));
  }
  return true;
}

Image Renderer::render(const Snapshot& snapshot, int width, int height,
                       const RenderOptions& options) {
  if (program_ == 0) {
    if (error_.empty()) error_ = "Renderer: not initialised";
    return Image();
  }
  error_.clear();
  if (width <= 0 || height <= 0) {
    fail("Renderer: invalid size " + size(width, height));
    return Image();
  }
  if (!context_.makeCurrent()) {
    fail("Renderer: " + context_.error());
    return Image();
  }
  GLint previous = 0;
  gl_.GetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
  Image image;
  if (ensureFramebuffer(width, height)) {
    gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    if (draw(snapshot, width, height, options)) {
      // Read back, then flip: OpenGL's rows go bottom-up, an Image's top-down.
      std::vector<std::uint8_t> rows(static_cast<size_t>(width) * height * 4);
      gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
      gl_.ReadBuffer(GL_COLOR_ATTACHMENT0);
      gl_.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
      if (GLenum e = gl_.GetError(); e != GL_NO_ERROR) {
        fail("Renderer: reading the pixels back failed with " + glErrorName(e));
      } else {
        image.width = width;
        image.height = height;
        image.pixels.resize(rows.size());
        const size_t stride = static_cast<size_t>(width) * 4;
        for (int y = 0; y < height; ++y) {
          std::memcpy(&image.pixels[y * stride], &rows[(height - 1 - y) * stride], stride);
        }
      }
    }
  }
  gl_.BindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous));
  return image;
}

}  // namespace a6
