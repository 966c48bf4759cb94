// The OSMesa backend: Mesa's off-screen software renderer (llvmpipe), Mesa 22.3 in Debian 12.
// Removed from Mesa 25.1: the EGL backend takes over there.
#include <GL/osmesa.h>

#include <vector>

#include "contexts/headless_backends.h"

namespace a6::detail {
namespace {

class OSMesaGLContext : public GLContext {
 public:
  OSMesaGLContext(OSMesaContext context, int width, int height)
      : context_(context),
        width_(width),
        height_(height),
        buffer_(static_cast<size_t>(width) * static_cast<size_t>(height) * 4) {}

  ~OSMesaGLContext() override {
    if (OSMesaGetCurrentContext() == context_) OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(context_);
  }

  bool makeCurrent() override {
    // The buffer is only the context's default surface; the renderer draws into an FBO.
    if (OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_)) {
      return true;
    }
    error_ = "OSMesa: OSMesaMakeCurrent failed for a " + std::to_string(width_) + "x" +
             std::to_string(height_) + " buffer";
    return false;
  }

  GLProc getProcAddress(const char* name) const override {
    return reinterpret_cast<GLProc>(OSMesaGetProcAddress(name));
  }
  int width() const override { return width_; }
  int height() const override { return height_; }
  std::string backend() const override { return "osmesa"; }

  void describe() { readDescription(); }

 private:
  OSMesaContext context_;
  int width_, height_;
  std::vector<unsigned char> buffer_;
};

}  // namespace

ContextResult makeOSMesaContext(int width, int height) {
  // A 3.3 core profile, no depth, stencil or accumulation buffers: the renderer needs none.
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            0,
                            OSMESA_STENCIL_BITS,
                            0,
                            OSMESA_ACCUM_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  OSMesaContext context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (context == nullptr) {
    return {nullptr,
            "OSMesa: could not create a 3.3 core context: is libosmesa6 installed (Mesa 22.3 or "
            "older; OSMesa is gone from Mesa 25.1, use the EGL backend there)?"};
  }
  auto result = std::make_unique<OSMesaGLContext>(context, width, height);
  if (!result->makeCurrent()) return {nullptr, result->error()};
  result->describe();
  return {std::move(result), ""};
}

}  // namespace a6::detail
