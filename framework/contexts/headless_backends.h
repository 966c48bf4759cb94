// Internal: the headless backends behind makeHeadlessContext(). Each is compiled only when its
// library was found at configure time (A6_HAVE_OSMESA, A6_HAVE_EGL).
#pragma once

#include "contexts/gl_context.h"

namespace a6::detail {

ContextResult makeOSMesaContext(int width, int height);
ContextResult makeEGLContext(int width, int height);

}  // namespace a6::detail
