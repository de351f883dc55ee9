#include "lidr/technique/volume_draw_plan.h"
#include "lidr/base/gl.h"  // GL enum values only: nothing here calls GL

#include <algorithm>
#include <utility>

#include "lidr/base/error.h"

namespace lidr {

const char* volumeTestName(VolumeTest t) {
    switch (t) {
    case VolumeTest::BackFace: return "backface";
    case VolumeTest::ExactStencil: return "exact";
    case VolumeTest::FrontFace: return "frontface";
    case VolumeTest::Sphere: return "sphere";
    case VolumeTest::SphereRay: return "sphere-ray";
    case VolumeTest::SphereSpan: return "sphere-span";
    }
    return "?";
}

VolumeTest parseVolumeTest(const std::string& name) {
    if (name == "backface" || name == "back-face") return VolumeTest::BackFace;
    if (name == "exact" || name == "exact-stencil") return VolumeTest::ExactStencil;
    if (name == "frontface" || name == "front-face") return VolumeTest::FrontFace;
    if (name == "sphere") return VolumeTest::Sphere;
    if (name == "sphere-ray") return VolumeTest::SphereRay;
    if (name == "sphere-span") return VolumeTest::SphereSpan;
    throw Error("unknown volume test '" + name + "' (valid: backface, exact, frontface, sphere, sphere-ray, sphere-span)");
}

const char* volumeStepRoleName(VolumeStepRole r) {
    switch (r) {
    case VolumeStepRole::Mark: return "mark";
    case VolumeStepRole::Write: return "write";
    case VolumeStepRole::Count: return "count";
    case VolumeStepRole::Unmark: return "unmark";
    }
    return "?";
}

namespace {

// How a step's depth test differs from its role's state.
enum Depth {
    kAsTested,   // the role's own depth test
    kNoDepth,    // depth ALWAYS (stencil tests) or off (shader tests): the far plane, the near plane
    kFrontFace,  // front faces, LEQUAL: the front-face test proper
    kDepthVariants
};
constexpr int kRoles = 4;

// Back faces, depth GEQUAL (test off), the draw's colour and blend state, stencil on, the scissor.
RenderState backFaceState(const VolumeDraw& d, const VolumePlanContext& c) {
    RenderState s;
    s.depthFunc = GL_GEQUAL;
    s.depthClamp = c.depthClamp;  // back faces past the far plane still mark the pixels in front of them
    s.cull = true;
    s.cullFace = GL_FRONT;
    s.colorMask = d.colorMask;
    s.blend = d.blend;
    s.blendEquation = d.blendEquation;
    s.blendSrcRgb = s.blendSrcAlpha = d.blendSrc;
    s.blendDstRgb = s.blendDstAlpha = d.blendDst;
    s.blendColor = d.blendColor;
    s.stencilTest = true;
    s.scissor = c.scissor.z >= 0;
    s.scissorBox = c.scissor;
    return s;
}

void checkRankWindow(const VolumeDraw& d) {
    if (d.rankCount < 0 || (d.rankCount & (d.rankCount - 1)) != 0 || d.rankCount > 64 ||
        (d.rankCount > 0 && d.rankFirst % d.rankCount != 0) || d.rankFirst < 0 || d.rankFirst + d.rankCount > 64)
        throw Error("volume draw '" + d.name + "': a rank window is a power of two, aligned, below 64");
}

// The base state of each role, and the states actually used, each added once.
struct StateTable {
    RenderState base[kRoles];
    int index[kRoles][kDepthVariants];
    bool shaderTest = false;
    std::vector<RenderState>* states = nullptr;

    explicit StateTable(std::vector<RenderState>& used) : states(&used) {
        for (auto& row : index) std::fill(std::begin(row), std::end(row), -1);
    }
    RenderState& of(VolumeStepRole role) { return base[int(role)]; }
    int use(VolumeStepRole role, Depth depth) {
        int& i = index[int(role)][depth];
        if (i >= 0) return i;
        RenderState s = base[int(role)];
        if (depth == kNoDepth && shaderTest) {
            s.depthTest = false;  // the shader decides; vertices pulled onto the far plane break the pre-test
        } else if (depth == kNoDepth) {
            s.depthFunc = GL_ALWAYS;
        } else if (depth == kFrontFace) {
            s.depthFunc = GL_LEQUAL;
            s.cullFace = GL_BACK;
        }
        i = int(states->size());
        states->push_back(s);
        return i;
    }
};

// The rank window: (count & ~(rankCount - 1)) == rankFirst. GL_INCR saturates at the top of the count, and a
// saturated count never matches a window below 64, so no number of lights wraps into a window.
struct RankWindow {
    bool on;
    GLuint mask;
    explicit RankWindow(const VolumeDraw& d)
        : on(d.rankCount > 0), mask(d.rankCount > 0 ? (~GLuint(d.rankCount - 1)) & 0xFFu : 0xFFu) {}
};

// Where the draw writes: its targets' draw buffers (OpenGL ES: from attachment 0 of a framebuffer that starts at
// firstTarget).
void planTargets(const VolumeDraw& d, const VolumePlanContext& c, VolumeDrawPlan& plan) {
    plan.restartCount = d.restartCount;
    plan.programTargets = d.targetCount;
    if (c.gles) {  // gl_FragData[i] goes to COLOR_ATTACHMENTi only: the targets from firstTarget on start at 0
        plan.framebufferFrom = d.firstTarget;
        if (c.drawBuffers)
            for (int i = 0; i < d.targetCount; ++i) plan.drawBuffers.push_back(GL_COLOR_ATTACHMENT0 + i);
    } else {
        for (int i = 0; i < d.targetCount; ++i) plan.drawBuffers.push_back(GL_COLOR_ATTACHMENT0 + d.firstTarget + i);
    }
}

// The shader tests (sphere, sphere-ray, sphere-span): lights in batches, one step a batch.
void planShaderTest(const VolumeDraw& d, const VolumePlanContext& c, const std::vector<VolumeLightFacts>& lights,
                    const RankWindow& window, StateTable& table, VolumeDrawPlan& plan) {
    // Back faces of the enclosing mesh cover every pixel whose eye ray meets the sphere past the near plane,
    // once per light. Only fragments the shader keeps reach the stencil, so every stencil outcome counts the
    // light (INCR on stencil fail, depth fail and pass) and the rank window decides the colour write alone:
    // one draw does what the stencil tests need a count draw for.
    plan.program = VolumeProgram::Batch;
    plan.countBits = 8;
    table.shaderTest = true;
    RenderState& st = table.of(VolumeStepRole::Write);
    st = backFaceState(d, c);
    // Sphere: depth GEQUAL is a cheap pre-test (a surface inside the sphere lies in front of the mesh's back
    // face), so fragments behind the surface skip the stencil; the ray and span tests need every fragment (a
    // span's far end may lie behind the single-sample depth the pass tests against).
    st.depthTest = c.test == VolumeTest::Sphere && !c.screenTiles;
    st.stencil.func = window.on ? GL_EQUAL : GL_ALWAYS;
    st.stencil.ref = d.rankFirst;
    st.stencil.readMask = window.mask;
    st.stencil.stencilFail = st.stencil.depthFail = st.stencil.depthPass = GL_INCR;  // saturates at 255
    st.stencil.writeMask = 0xFF;
    const int batch = std::max(1, c.batchSize);
    for (size_t first = 0; first < lights.size(); first += size_t(batch)) {
        VolumeStep step;
        step.firstLight = int(first);
        step.lightCount = int(std::min(lights.size() - first, size_t(batch)));
        for (int i = 0; i < step.lightCount; ++i)
            step.clampToFar = step.clampToFar || (!c.depthClamp && lights[first + size_t(i)].reachesFarPlane);
        step.state = table.use(VolumeStepRole::Write, step.clampToFar ? kNoDepth : kAsTested);
        plan.steps.push_back(step);
    }
}

// The exact test's mark and unmark states, the write and count states reading them (plan.countBits 7).
void setExactStates(const VolumeDraw& d, const VolumePlanContext& c, const RankWindow& window, StateTable& table,
                    VolumeDrawPlan& plan) {
    RenderState& inside = table.of(VolumeStepRole::Write);
    RenderState& count = table.of(VolumeStepRole::Count);
    // Bit 7 marks "this pixel's surface lies in front of the volume" for the current light only;
    // bits 0..6 count the lights that really contain the surface.
    RenderState& mark = table.of(VolumeStepRole::Mark);
    mark.depthTest = true;
    mark.depthFunc = GL_GREATER;  // front face behind the surface: surface in front of the light
    mark.depthClamp = c.depthClamp;
    mark.cull = true;
    mark.cullFace = GL_BACK;
    mark.colorMask = glm::bvec4(false);
    mark.stencilTest = true;
    mark.stencil.func = GL_ALWAYS;
    mark.stencil.ref = 0x80;
    mark.stencil.depthPass = GL_REPLACE;
    mark.stencil.writeMask = 0x80;
    mark.scissor = c.scissor.z >= 0;
    mark.scissorBox = c.scissor;
    table.of(VolumeStepRole::Unmark) = mark;
    table.of(VolumeStepRole::Unmark).stencil.ref = 0;
    // Marked pixels hold >= 128, so "128 > stencil" and the masked window (bit 7 in its mask) reject them.
    inside.stencil.func = window.on ? GL_EQUAL : GL_GREATER;
    inside.stencil.ref = window.on ? d.rankFirst : 0x80;
    inside.stencil.readMask = window.mask;
    inside.stencil.writeMask = 0;
    count = inside;
    count.colorMask = glm::bvec4(false);
    count.blend = false;
    count.stencil.func = GL_GREATER;
    count.stencil.ref = 0x7F;  // saturate the 7-bit count at 127
    count.stencil.readMask = 0xFF;
    count.stencil.depthPass = GL_INCR;
    count.stencil.writeMask = 0x7F;
    plan.countBits = 7;
}

// The stencil tests' states (back faces, cull front, at or behind the surface); returns whether the count is a
// draw of its own (a rank window without the exact test).
bool setStencilTestStates(const VolumeDraw& d, const VolumePlanContext& c, const RankWindow& window, StateTable& table,
                          VolumeDrawPlan& plan) {
    RenderState& inside = table.of(VolumeStepRole::Write);
    inside = backFaceState(d, c);
    inside.depthTest = true;
    if (c.test == VolumeTest::ExactStencil) {
        setExactStates(d, c, window, table, plan);
        return false;
    }
    // The stencil test comes BEFORE the depth test: a fragment the window rejects never reaches the depth
    // test, so "GL_INCR on stencil fail" would count lights whose back face lies in front of the surface
    // (lights that do not mark the pixel), and later passes would rank differently from earlier ones (one
    // light taken twice, another never). With a window, each light is therefore drawn twice: the colour draw
    // tests the window and leaves the stencil alone, then the count draw (no colour) counts depth passes.
    inside.stencil.func = window.on ? GL_EQUAL : GL_ALWAYS;
    inside.stencil.ref = d.rankFirst;
    inside.stencil.readMask = window.mask;
    plan.countBits = 8;
    if (!window.on) {
        inside.stencil.depthPass = GL_INCR;
        return false;
    }
    inside.stencil.writeMask = 0;
    RenderState& count = table.of(VolumeStepRole::Count);
    count = inside;
    count.colorMask = glm::bvec4(false);
    count.blend = false;
    count.stencil.func = GL_ALWAYS;
    count.stencil.depthPass = GL_INCR;  // saturates at 255
    count.stencil.writeMask = 0xFF;
    return true;
}

// The stencil tests' steps: per light, mark, write, count and unmark (exact), or write then count (a rank
// window), or one write.
void planStencilTest(const VolumeDraw& d, const VolumePlanContext& c, const std::vector<VolumeLightFacts>& lights,
                     bool separateCount, StateTable& table, VolumeDrawPlan& plan) {
    const bool exact = c.test == VolumeTest::ExactStencil;
    plan.steps.reserve(lights.size() * (exact ? 4 : separateCount ? 2 : 1));
    for (size_t i = 0; i < lights.size(); ++i) {
        const VolumeLightFacts& l = lights[i];
        // Without depth clamp, a back face beyond the far plane would be clipped and would not mark the pixels
        // in front of it: such lights are pulled onto the far plane in the vertex shader and skip the depth
        // test (conservative: the whole footprint is marked).
        const bool clampToFar = volumeMarksWholeFootprint(c.test, c.depthClamp, l.reachesFarPlane);
        Depth depth = clampToFar ? kNoDepth : kAsTested;
        // Front-face test: front faces at or before the surface. A volume reaching in front of the near plane
        // (or holding the camera) has its front faces clipped there; it is drawn by its back faces without a
        // depth test instead, which marks every ray that is inside the volume anywhere past the near plane.
        if (c.test == VolumeTest::FrontFace) depth = l.reachesNearPlane ? kNoDepth : kFrontFace;
        bool load = true;
        auto add = [&](VolumeStepRole role, Depth dv) {
            VolumeStep step;
            step.role = role;
            step.state = table.use(role, dv);
            step.firstLight = int(i);
            step.loadLights = std::exchange(load, false);
            step.clampToFar = clampToFar;
            step.detail = l.detail;
            plan.steps.push_back(step);
        };
        if (exact) {
            add(VolumeStepRole::Mark, kAsTested);
            add(VolumeStepRole::Write, depth);
            add(VolumeStepRole::Count, depth);
            add(VolumeStepRole::Unmark, kAsTested);
        } else if (separateCount) {
            if (d.writesColor()) add(VolumeStepRole::Write, depth);
            add(VolumeStepRole::Count, depth);
        } else {
            add(VolumeStepRole::Write, depth);
        }
    }
}

}  // namespace

VolumeDrawPlan planVolumeDraw(const VolumeDraw& d, const VolumePlanContext& c,
                              const std::vector<VolumeLightFacts>& lights) {
    checkRankWindow(d);
    VolumeDrawPlan plan;
    planTargets(d, c, plan);
    StateTable table(plan.states);
    const RankWindow window(d);
    if (isShaderVolumeTest(c.test)) {
        planShaderTest(d, c, lights, window, table, plan);
    } else {
        const bool separateCount = setStencilTestStates(d, c, window, table, plan);
        planStencilTest(d, c, lights, separateCount, table, plan);
    }
    return plan;
}

}  // namespace lidr
