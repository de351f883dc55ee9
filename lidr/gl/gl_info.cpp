#include "lidr/gl/gl_info.h"

#include <sstream>

namespace lidr {

std::string GlInfo::summary() const {
    std::ostringstream s;
    s << "backend " << backend << ", GL " << version << ", renderer " << renderer << ", GLSL " << glslVersion
      << ", FBO " << (framebufferObject ? "yes" : "no") << ", float textures " << (textureFloat ? "yes" : "no")
      << ", timer queries " << (timerQuery ? "yes" : "no") << ", max samples " << maxSamples;
    return s.str();
}

}  // namespace lidr
