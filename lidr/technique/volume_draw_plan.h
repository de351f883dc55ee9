#pragma once
// Which state for which draw of the light-volume pass, decided on the CPU: planVolumeDraw turns one sub-pass of
// a packing scheme (VolumeDraw), the volume test, a few facts per light and the context's capabilities into
// the list of draw steps, each with its RenderState. No GL call here, so the plan is unit-tested without a
// context (tests/test_volume_draw_plan.cpp); LightVolumePass executes it through the StateCache.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "lidr/base/gl_types.h"
#include "lidr/gl/gl_state.h"

namespace lidr {

enum class VolumeTest {
    BackFace,      // back faces, depth GEQUAL: cheap; also marks surfaces in front of a light (wastes slots)
    ExactStencil,  // per light: front faces mark the pixels in front of the volume in stencil, then back
                   // faces GEQUAL where unmarked: exactly the surfaces inside the volume
    FrontFace,     // front faces, depth LEQUAL: every light whose volume crosses the eye ray in front of the
                   // opaque surface, so transparent surfaces and MSAA edge samples in front find their lights
    // The shader tests: the fragment shader reads a copy of the pre-pass depth and discards what the light's
    // true sphere does not reach, so the stencil sees real marks only; lights go in batches of many per draw.
    Sphere,        // the surface point lies inside the sphere: exactly the lights that shade the pixel
    SphereRay,     // the eye ray between the near plane and the surface meets the sphere: the front-face lists
                   // of transparent layers (and, before sphere-span, of MSAA edge samples)
    SphereSpan,    // MSAA: the eye ray between the nearest and the farthest surface the pixel's samples shade
                   // meets the sphere (DepthSpanPass): `sphere` on interior pixels, the edge samples' surfaces on
                   // edge pixels
};
// True for the tests decided in the fragment shader (they need the pre-pass depth as a texture).
inline bool isShaderVolumeTest(VolumeTest t) {
    return t == VolumeTest::Sphere || t == VolumeTest::SphereRay || t == VolumeTest::SphereSpan;
}
// True for the tests that mark every light crossing the eye ray before the surface (front-face lists).
inline bool isFrontFaceVolumeTest(VolumeTest t) { return t == VolumeTest::FrontFace || t == VolumeTest::SphereRay; }
const char* volumeTestName(VolumeTest t);
VolumeTest parseVolumeTest(const std::string& name);  // "backface", "exact", "frontface", "sphere", "sphere-ray", "sphere-span"

// One sub-pass of a packing scheme: which targets, how to blend, and how stencil limits the writes.
struct VolumeDraw {
    std::string name = "light-volumes";
    int firstTarget = 0, targetCount = 1;  // written together (draw buffers) when targetCount > 1
    glm::bvec4 colorMask{true, true, true, true};
    bool blend = false;
    GLenum blendEquation = glc::kFuncAdd;
    GLenum blendSrc = glc::kOne, blendDst = glc::kZero;
    glm::vec4 blendColor{0.0f};
    // Stencil rank window. rankCount > 0: a light writes only where it is the rankFirst-th ..
    // (rankFirst + rankCount - 1)-th light (0-based, in draw order) to mark the pixel in this draw. rankCount is
    // a power of two and rankFirst a multiple of it: the test is a masked GL_EQUAL on the count. rankCount 0:
    // every marking light writes. Either way the stencil counts every light that marks the pixel (saturating),
    // so lights past the window are counted, not written.
    int rankFirst = 0, rankCount = 0;
    bool restartCount = false;  // clear the count first: a further pass over the same lights ranks them anew
    bool writesColor() const { return colorMask.r || colorMask.g || colorMask.b || colorMask.a; }
};

// What the plan needs to know about one light, from the light and the camera (the pass's geometry says).
struct VolumeLightFacts {
    bool reachesFarPlane = false;   // the drawn volume reaches the far plane
    bool reachesNearPlane = false;  // the drawn volume reaches in front of the near plane (front-face test)
    int detail = 0;                 // the volume mesh drawn (LightVolumePass::detailFor)
};

// What the plan needs to know about the pass and the context.
struct VolumePlanContext {
    VolumeTest test = VolumeTest::BackFace;
    bool depthClamp = false;  // ARB/NV_depth_clamp
    bool gles = false;        // OpenGL ES: gl_FragData[i] goes to COLOR_ATTACHMENTi only
    bool drawBuffers = true;  // more than one draw buffer (ES 2.0: EXT_draw_buffers); false: none are set
    int batchSize = 1;        // lights per draw of the shader tests, for this draw's target count
    bool screenTiles = false; // the shader tests draw screen quads over tiles (VolumeGeometry::drawsScreenTiles):
                              // no depth pre-test, the tiles were culled by depth on the CPU
    glm::ivec4 scissor{-1};   // x, y, width, height; z < 0: none
};

// True where a light is drawn without its depth test: the stencil tests without depth clamp pull a volume that
// reaches the far plane onto it, so it marks its whole screen footprint.
inline bool volumeMarksWholeFootprint(VolumeTest test, bool depthClamp, bool reachesFarPlane) {
    return !depthClamp && !isShaderVolumeTest(test) && reachesFarPlane;
}

enum class VolumeStepRole {
    Mark,    // exact test: front faces behind the surface set stencil bit 7 (the surface lies in front)
    Write,   // the volume test proper: writes the index colours (and counts, where no Count step follows)
    Count,   // no colour: counts the light in stencil (after a windowed Write, or the exact test's)
    Unmark,  // exact test: clears bit 7 for the next light
};
const char* volumeStepRoleName(VolumeStepRole r);

enum class VolumeProgram {
    PerLight,  // one light per draw (the stencil tests): light_volume.vert/.frag
    Batch,     // the shader tests' batches: light_volume_batch.vert, light_volume_sphere.frag
};

// One draw call.
struct VolumeStep {
    VolumeStepRole role = VolumeStepRole::Write;
    int state = 0;                       // index into VolumeDrawPlan::states
    int firstLight = 0, lightCount = 1;  // the lights drawn (a batch: several, in order)
    bool loadLights = true;              // the first step of these lights: their uniforms are set before it
    bool clampToFar = false;             // vertices past the far plane are pulled onto it (no depth clamp)
    int detail = 0;                      // the volume mesh (PerLight)
};

struct VolumeDrawPlan {
    bool restartCount = false;       // clear the stencil before the first step
    int framebufferFrom = -1;        // >= 0: bind IndexTargets::framebufferFrom(n) (OpenGL ES); -1: keep the pass's
    std::vector<GLenum> drawBuffers;  // set before the steps; empty: left as they are
    VolumeProgram program = VolumeProgram::PerLight;
    int programTargets = 1;          // the program's LIDR_DRAW_TARGETS
    int countBits = 0;               // stencil bits that count lights per pixel after this draw
    std::vector<RenderState> states;  // the distinct states, in first use order
    std::vector<VolumeStep> steps;    // in draw order
    const RenderState& stateOf(const VolumeStep& s) const { return states[size_t(s.state)]; }
};

// The plan of one sub-pass over lights with these facts (in draw order). Throws lidr::Error for a rank window
// that is not a power of two, aligned and below 64.
VolumeDrawPlan planVolumeDraw(const VolumeDraw& d, const VolumePlanContext& context,
                              const std::vector<VolumeLightFacts>& lights);

}  // namespace lidr
