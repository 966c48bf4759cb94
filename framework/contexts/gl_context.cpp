#include "contexts/gl_context.h"

#include "contexts/headless_backends.h"

namespace a6 {

void GLContext::readDescription() {
  // glGetString by hand: the GL loader needs a context, and this runs while making one.
  using GetString = const unsigned char* (*)(unsigned int);
  constexpr unsigned int kRenderer = 0x1F01, kVersion = 0x1F02;  // GL_RENDERER, GL_VERSION
  auto getString = reinterpret_cast<GetString>(getProcAddress("glGetString"));
  auto text = [&](unsigned int name) -> std::string {
    const unsigned char* s = getString ? getString(name) : nullptr;
    return s ? reinterpret_cast<const char*>(s) : "?";
  };
  renderer_ = text(kRenderer);
  version_ = text(kVersion);
  description_ = renderer_ + "; OpenGL " + version_;
}

const char* toString(HeadlessBackend backend) {
  switch (backend) {
    case HeadlessBackend::OSMesa:
      return "osmesa";
    case HeadlessBackend::EGL:
      return "egl";
    case HeadlessBackend::Auto:
      break;
  }
  return "auto";
}

bool parseHeadlessBackend(const std::string& text, HeadlessBackend* backend) {
  for (HeadlessBackend b : {HeadlessBackend::Auto, HeadlessBackend::OSMesa, HeadlessBackend::EGL}) {
    if (text == toString(b)) {
      *backend = b;
      return true;
    }
  }
  return false;
}

std::string availableHeadlessBackends() {
  std::string names;
#ifdef A6_HAVE_OSMESA
  names += "osmesa";
#endif
#ifdef A6_HAVE_EGL
  names += names.empty() ? "egl" : " egl";
#endif
  return names.empty() ? "none" : names;
}

namespace {

ContextResult makeOSMesa(int width, int height) {
#ifdef A6_HAVE_OSMESA
  return detail::makeOSMesaContext(width, height);
#else
  (void)width, (void)height;
  return {nullptr,
          "OSMesa: not built in (pkg-config found no 'osmesa' at configure time): install "
          "libosmesa6-dev and re-run cmake, or use the EGL backend"};
#endif
}

ContextResult makeEGL(int width, int height) {
#ifdef A6_HAVE_EGL
  return detail::makeEGLContext(width, height);
#else
  (void)width, (void)height;
  return {nullptr,
          "EGL: not built in (pkg-config found no 'egl' at configure time): install libegl-dev "
          "and re-run cmake, or use the OSMesa backend"};
#endif
}

}  // namespace

ContextResult makeHeadlessContext(int width, int height, HeadlessBackend backend) {
  if (width <= 0 || height <= 0) {
    return {nullptr, "headless GL: invalid size " + std::to_string(width) + "x" +
                         std::to_string(height) + " (both must be > 0)"};
  }
  switch (backend) {
    case HeadlessBackend::OSMesa:
      return makeOSMesa(width, height);
    case HeadlessBackend::EGL:
      return makeEGL(width, height);
    case HeadlessBackend::Auto:
      break;
  }
  // OSMesa first: always llvmpipe, the renderer the golden images are made with.
  ContextResult osmesa = makeOSMesa(width, height);
  if (osmesa) return osmesa;
  ContextResult egl = makeEGL(width, height);
  if (egl) return egl;
  return {nullptr, "no headless OpenGL 3.3 context could be created:\n  " + osmesa.error + "\n  " +
                       egl.error};
}

}  // namespace a6
