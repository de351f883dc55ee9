#include "lidr/render/depth_prepass.h"
#include "lidr/base/gl.h"

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/shader_source.h"

namespace lidr {

const std::vector<std::pair<std::string, GLuint>>& geometryAttributes() {
    static const std::vector<std::pair<std::string, GLuint>> attributes = {
        {"aPosition", gl::kPosition}, {"aNormal", gl::kNormal}, {"aTexCoord", gl::kTexCoord},
        {"aTexCoord1", gl::kTexCoord1}, {"aTangent", gl::kTangent}};  // the last two: material variants only
    return attributes;
}

void DepthEmulation::apply(ShaderDefines& defines, ShaderIncludes& includes) const {
    if (bits == 0) return;
    if (bits != 16) throw Error("emulated depth precision is 16 bits, not " + std::to_string(bits));
    defines.push_back({"LIDR_DEPTH_STEPS", "65535.0"});
    includes.push_back({"lidr_depth.glsl", "lidr_depth_emulated.glsl"});
}

DepthPrepass::DepthPrepass(DepthEmulation depth) {
    ShaderDefines defines;
    ShaderIncludes includes;
    depth.apply(defines, includes);
    program_ = gl::Program::create("depth-prepass", buildShaderSource("geometry.vert"),
                                   buildShaderSource("depth_only.frag", defines, includes), geometryAttributes());
}

void drawOpaqueDepth(const gl::Program& program, const GpuScene& scene, const CameraMatrices& camera, float slopeBias,
                     bool colorWrites) {
    StateCache& cache = StateCache::current();
    RenderState s;
    s.polygonOffset = slopeBias > 0.0f;
    s.polygonOffsetFactorUnits = glm::vec2(slopeBias, 0.0f);
    s.depthTest = true;
    s.depthFunc = GL_LESS;
    s.depthWrite = true;
    s.colorMask = glm::bvec4(colorWrites);
    cache.apply(s);
    program.use();
    program.set("uViewProj", camera.viewProjection);
    scene.draw(program, DrawFilter::Opaque, false, &camera);
    cache.apply(RenderState{});
}

void DepthPrepass::run(const GpuScene& scene, const CameraMatrices& camera) const {
    ClearAction clear;
    clear.depth = clear.stencil = true;
    StateCache::current().clear(clear);
    drawOpaqueDepth(program_, scene, camera);
    checkGl("depth pre-pass");
}

}  // namespace lidr
