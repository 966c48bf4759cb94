// Our one OpenGL loader: exactly the GL 3.3 core functions the renderer and the viewer call,
// loaded by name from the context that will run them.
//
// Why our own: Debian's GLEW and libepoxy fail under OSMesa, and there is no glad package.
// Why a struct and not global pointers: two contexts from two libraries (OSMesa and EGL) may hand
// out different entry points, so each user keeps the table of its own context.
//
// To use one more GL function: add it to A6_GL_FUNCTIONS (type from <GL/glcorearb.h>, name
// without the "gl" prefix), then call it as gl.Name(...).
#pragma once

// <GL/gl.h> declares GL 1.x without the PFN...PROC types used below; once it is in, the core
// header adds nothing.
#if defined(__gl_h_) && !defined(__gl_glcorearb_h_)
#error \
    "<GL/gl.h> was included before contexts/gl_functions.h: include our headers first, or \
define GLFW_INCLUDE_NONE before <GLFW/glfw3.h>"
#endif
#include <GL/glcorearb.h>

#include <string>

#include "contexts/gl_context.h"

// X(type, name): PFNGL...PROC from <GL/glcorearb.h>, and the GL name without its "gl" prefix.
#define A6_GL_FUNCTIONS(X)                                     \
  /* state, clearing, reading back */                          \
  X(PFNGLGETERRORPROC, GetError)                               \
  X(PFNGLGETSTRINGPROC, GetString)                             \
  X(PFNGLGETINTEGERVPROC, GetIntegerv)                         \
  X(PFNGLENABLEPROC, Enable)                                   \
  X(PFNGLDISABLEPROC, Disable)                                 \
  X(PFNGLVIEWPORTPROC, Viewport)                               \
  X(PFNGLSCISSORPROC, Scissor)                                 \
  X(PFNGLCLEARCOLORPROC, ClearColor)                           \
  X(PFNGLCLEARPROC, Clear)                                     \
  X(PFNGLPIXELSTOREIPROC, PixelStorei)                         \
  X(PFNGLREADBUFFERPROC, ReadBuffer)                           \
  X(PFNGLREADPIXELSPROC, ReadPixels)                           \
  X(PFNGLFINISHPROC, Finish)                                   \
  /* shaders and programs */                                   \
  X(PFNGLCREATESHADERPROC, CreateShader)                       \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                       \
  X(PFNGLCOMPILESHADERPROC, CompileShader)                     \
  X(PFNGLGETSHADERIVPROC, GetShaderiv)                         \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)               \
  X(PFNGLDELETESHADERPROC, DeleteShader)                       \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                     \
  X(PFNGLATTACHSHADERPROC, AttachShader)                       \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                         \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                       \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)             \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                     \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                           \
  /* vertex data */                                            \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                 \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                 \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)           \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                           \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                           \
  X(PFNGLBUFFERDATAPROC, BufferData)                           \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                     \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)         \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray) \
  X(PFNGLDRAWARRAYSPROC, DrawArrays)                           \
  /* offscreen framebuffers */                                 \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                 \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                 \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer) \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)   \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)           \
  X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)               \
  X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)               \
  X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)         \
  X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)

namespace a6 {

/// The GL functions of one context. Call them as gl.Clear(GL_COLOR_BUFFER_BIT).
struct GLFunctions {
#define A6_GL_DECLARE(type, name) type name = nullptr;
  A6_GL_FUNCTIONS(A6_GL_DECLARE)
#undef A6_GL_DECLARE

  /// Loads every function from `context`. Returns an empty string on success, otherwise a
  /// message naming each missing function; the table is then unusable.
  std::string load(const GLContext& context);
};

/// A readable name for a glGetError() code, e.g. "GL_INVALID_OPERATION".
std::string glErrorName(unsigned int code);

}  // namespace a6
