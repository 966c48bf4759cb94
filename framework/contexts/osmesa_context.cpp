// The OSMesa backend: Mesa's off-screen software renderer (llvmpipe), Mesa 22.3 in Debian 12.
// Removed from Mesa 25.1: the EGL backend takes over there. libOSMesa is loaded at run time
// (dlopen), never linked, so that the same binaries start where it is missing and Auto picks EGL.
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <string>
#include <vector>

#include "contexts/headless_backends.h"

namespace a6::detail {
namespace {

// The five OSMesa functions we call, from libOSMesa as found at run time.
struct OSMesaApi {
  decltype(&::OSMesaCreateContextAttribs) createContextAttribs = nullptr;
  decltype(&::OSMesaMakeCurrent) makeCurrent = nullptr;
  decltype(&::OSMesaGetCurrentContext) getCurrentContext = nullptr;
  decltype(&::OSMesaDestroyContext) destroyContext = nullptr;
  decltype(&::OSMesaGetProcAddress) getProcAddress = nullptr;
  std::string error;  ///< why OSMesa cannot be used here, or ""
};

template <class Function>
void bind(void* library, const char* name, Function& function, std::string& error) {
  function = reinterpret_cast<Function>(dlsym(library, name));
  if (function == nullptr && error.empty()) error = std::string("OSMesa: libOSMesa has no ") + name;
}

// Loaded once; the library stays loaded for the life of the process.
const OSMesaApi& osmesa() {
  static const OSMesaApi api = [] {
    OSMesaApi a;
    void* library = nullptr;
    for (const char* name : {"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"}) {
      library = dlopen(name, RTLD_NOW | RTLD_LOCAL);
      if (library != nullptr) break;
    }
    if (library == nullptr) {
      a.error =
          "OSMesa: libOSMesa is not installed here (Mesa 25.1 and later have none): the EGL "
          "backend is the one to use";
      return a;
    }
    bind(library, "OSMesaCreateContextAttribs", a.createContextAttribs, a.error);
    bind(library, "OSMesaMakeCurrent", a.makeCurrent, a.error);
    bind(library, "OSMesaGetCurrentContext", a.getCurrentContext, a.error);
    bind(library, "OSMesaDestroyContext", a.destroyContext, a.error);
    bind(library, "OSMesaGetProcAddress", a.getProcAddress, a.error);
    return a;
  }();
  return api;
}

class OSMesaGLContext : public GLContext {
 public:
  OSMesaGLContext(OSMesaContext context, int width, int height)
      : context_(context),
        width_(width),
        height_(height),
        buffer_(static_cast<size_t>(width) * static_cast<size_t>(height) * 4) {}

  ~OSMesaGLContext() override {
    if (osmesa().getCurrentContext() == context_) {
      osmesa().makeCurrent(nullptr, nullptr, 0, 0, 0);
    }
    osmesa().destroyContext(context_);
  }

  bool makeCurrent() override {
    // The buffer is only the context's default surface; the renderer draws into an FBO.
    if (osmesa().makeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_)) {
      return true;
    }
    error_ = "OSMesa: OSMesaMakeCurrent failed for a " + std::to_string(width_) + "x" +
             std::to_string(height_) + " buffer";
    return false;
  }

  GLProc getProcAddress(const char* name) const override {
    return reinterpret_cast<GLProc>(osmesa().getProcAddress(name));
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
  if (!osmesa().error.empty()) return {nullptr, osmesa().error};
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
  OSMesaContext context = osmesa().createContextAttribs(attributes, nullptr);
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
