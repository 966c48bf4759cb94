#include "contexts/gl_functions.h"

#include <cstdio>

namespace a6 {

std::string GLFunctions::load(const GLContext& context) {
  std::string missing;
  // Each name is looked up with its "gl" prefix; a missing one is named, the rest still load.
#define A6_GL_LOAD(type, name)                                             \
  this->name = reinterpret_cast<type>(context.getProcAddress("gl" #name)); \
  if (this->name == nullptr) missing += std::string(missing.empty() ? "" : ", ") + "gl" #name;
  A6_GL_FUNCTIONS(A6_GL_LOAD)
#undef A6_GL_LOAD
  if (missing.empty()) return "";
  return "OpenGL: the " + context.backend() + " context (" + context.description() + ") lacks " +
         missing + ": the renderer needs an OpenGL 3.3 core context";
}

std::string glErrorName(unsigned int code) {
  switch (code) {
    case GL_NO_ERROR:
      return "GL_NO_ERROR";
    case GL_INVALID_ENUM:
      return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
      return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
      return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
      return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
      return "GL_OUT_OF_MEMORY";
    default: {
      char text[32];
      std::snprintf(text, sizeof text, "GL error 0x%04X", code);
      return text;
    }
  }
}

}  // namespace a6
