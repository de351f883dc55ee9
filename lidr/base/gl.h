#pragma once
// The one include for GL in lidr: GLEW's loader (Debian's GLX build, also used under EGL; see context.cpp).
#include <GL/glew.h>
