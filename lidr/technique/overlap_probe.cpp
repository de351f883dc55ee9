#include "lidr/technique/overlap_probe.h"
#include "lidr/base/gl.h"

#include "lidr/base/error.h"
#include "lidr/gl/shader_source.h"
#include "lidr/render/depth_prepass.h"

namespace lidr {

constexpr std::array<int, OverlapProbe::kThresholds> OverlapProbe::kThreshold;

OverlapProbe::OverlapProbe(const GlInfo&, DepthEmulation depth) {
    // Occlusion queries are GL 1.5 core, inside lidr's GL 2.1 floor.
    program_ = gl::Program::create("overlap-probe", buildShaderSource("fullscreen.vert"),
                                   buildShaderSource("overlap_probe.frag"), {{"aPosition", gl::kPosition}});
    ShaderDefines defines;
    ShaderIncludes includes;
    depth.apply(defines, includes);  // the meshes are depth-tested against the pre-pass
    meshProgram_ = gl::Program::create("overlap-probe-meshes", buildShaderSource("geometry.vert"),
                                       buildShaderSource("overlap_probe.frag", defines, includes),
                                       geometryAttributes());
    triangle_ = FullScreenTriangle::create();
    for (gl::Object& q : queries_) q = gl::Object(gl::Kind::Query);
    checkGl("OverlapProbe");
}

RenderState OverlapProbe::stateFor(const glm::ivec4* scissor) const {
    if (!program_) throw Error("OverlapProbe used before it was created");
    RenderState s;
    s.colorMask = glm::bvec4(false);
    s.stencilTest = true;
    s.stencil.func = GL_LESS;  // passes where ref < count, i.e. count > threshold
    s.stencil.readMask = 0xFF;
    s.stencil.writeMask = 0;
    if (scissor) {
        s.scissor = true;
        s.scissorBox = *scissor;
    }
    return s;
}

unsigned OverlapProbe::aroundBudget(int budget) {
    unsigned m = 0;
    for (int i = 0; i < kThresholds; ++i)
        if (kThreshold[size_t(i)] == budget || 2 * kThreshold[size_t(i)] == budget) m |= 1u << i;
    return m;
}

unsigned OverlapProbe::atBudget(int budget) {
    unsigned m = 0;
    for (int i = 0; i < kThresholds; ++i)
        if (kThreshold[size_t(i)] == budget) m |= 1u << i;
    return m;
}

unsigned OverlapProbe::aboveBudget(int budget) {
    unsigned m = 0;
    for (int i = 0; i < kThresholds; ++i)
        if (kThreshold[size_t(i)] > budget) m |= 1u << i;
    return m;
}

void OverlapProbe::issueOverMeshes(const GpuScene& scene, DrawFilter filter, const CameraMatrices& camera,
                                   unsigned which, const glm::ivec4* scissor) {
    RenderState s = stateFor(scissor);
    knownZero_ = 0;
    s.depthTest = true;
    s.depthFunc = GL_LEQUAL;  // visible in front of the opaque depth; several layers may count a pixel twice,
                              // which changes no zero
    meshProgram_.use();
    meshProgram_.set("uViewProj", camera.viewProjection);
    for (int i = 0; i < kThresholds; ++i) {
        if (!(which & (1u << i))) continue;
        s.stencil.ref = kThreshold[size_t(i)];
        StateCache::current().apply(s);
        glBeginQuery(GL_SAMPLES_PASSED, queries_[size_t(i)].id());
        scene.draw(meshProgram_, filter, false);
        glEndQuery(GL_SAMPLES_PASSED);
        ++drawCalls_;
    }
    StateCache::current().apply(RenderState{});
    issued_ = which;
    checkGl("OverlapProbe::issueOverMeshes");
}

void OverlapProbe::issue(unsigned which, const glm::ivec4* scissor) {
    Areas areas;
    areas.fill(scissor ? *scissor : glm::ivec4(0, 0, -1, -1));
    issue(which, areas);
}

void OverlapProbe::issue(unsigned which, const Areas& areas) {
    RenderState s = stateFor(nullptr);
    program_.use();
    triangle_.bind();
    knownZero_ = 0;
    for (int i = 0; i < kThresholds; ++i) {
        if (!(which & (1u << i))) continue;
        const glm::ivec4& area = areas[size_t(i)];
        if (area.z == 0 || area.w == 0) {
            knownZero_ |= 1u << i;
            continue;
        }
        s.scissor = area.z > 0;
        s.scissorBox = s.scissor ? area : glm::ivec4(0);
        s.stencil.ref = kThreshold[size_t(i)];
        StateCache::current().apply(s);
        glBeginQuery(GL_SAMPLES_PASSED, queries_[size_t(i)].id());
        StateCache::current().drawArrays(GL_TRIANGLES, 0, 3);
        glEndQuery(GL_SAMPLES_PASSED);
        ++drawCalls_;
    }
    triangle_.unbind();
    // The default state again (scissor off): a blit after it, such as the MSAA resolve, is scissored too.
    StateCache::current().apply(RenderState{});
    issued_ = which;
    checkGl("OverlapProbe::issue");
}

std::array<long, OverlapProbe::kThresholds> OverlapProbe::pixelsAbove() const {
    if (!issued_) throw Error("OverlapProbe: no measurement issued");
    std::array<long, kThresholds> above{};
    for (int i = 0; i < kThresholds; ++i) {
        above[size_t(i)] = -1;
        if (!(issued_ & (1u << i))) continue;
        if (knownZero_ & (1u << i)) {
            above[size_t(i)] = 0;
            continue;
        }
        GLuint n = 0;
        glGetQueryObjectuiv(queries_[size_t(i)].id(), GL_QUERY_RESULT, &n);
        above[size_t(i)] = static_cast<long>(n);
    }
    checkGl("OverlapProbe::pixelsAbove");
    return above;
}

void OverlapProbe::merge(std::array<long, kThresholds>& into, const std::array<long, kThresholds>& more) {
    for (size_t i = 0; i < into.size(); ++i)
        if (more[i] >= 0) into[i] = more[i];
}

int OverlapProbe::smallestBudget(const std::array<long, kThresholds>& above) {
    for (int i = 0; i < kThresholds; ++i)
        if (above[size_t(i)] == 0) return kThreshold[size_t(i)];
    return above[size_t(kThresholds - 1)] > 0 ? 0 : -1;
}

}  // namespace lidr
