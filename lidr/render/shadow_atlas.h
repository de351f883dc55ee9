#pragma once
// Shadow maps of spot and point lights, all in one depth texture (issue 30; the paper's "shadows are harder to
// support"). Each shadow-casting spot light gets a square tile of the atlas holding the opaque scene's depth seen
// from the light: a perspective view down the cone's axis whose field of view is the outer cone (up to
// kMaxShadowConeAngle), from a near plane at a hundredth of the range to the range; a point light gets six tiles,
// the faces of a cube around it (90-degree views along +x, -x, +y, -y, +z, -z). A map is drawn again only
// when its light changed or a scene change (GpuScene::changedNear) touched the light's range: a static scene
// draws each map once. Closed meshes cast from the side facing the light (GpuScene::draw's inner-side culling
// seen from the light). This is the atlas alone: the lookups that use it (the volume pass's test and the forward
// pass's, doc/architecture.md "Shadows") come next.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "lidr/base/image.h"
#include "lidr/gl/gl_info.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/render/gpu_scene.h"
#include "lidr/render/shadow_settings.h"
#include "lidr/scene/camera.h"
#include "lidr/scene/scene.h"

namespace lidr {

// The widest outer cone one perspective map covers: 80 degrees, a 160-degree field of view.
constexpr float kMaxShadowConeAngle = 1.3962634f;

// The camera a spot light's map is drawn with (tile x tile pixels). Throws lidr::Error for a point light, a cone
// wider than kMaxShadowConeAngle, a range that is not positive or a direction of length 0.
CameraMatrices spotShadowCamera(const PointLight& spot, int tileSize);
// Face f (0..5: +x, -x, +y, -y, +z, -z) of a point light's cube of maps. Throws lidr::Error for a spot light, a
// face outside 0..5 or a range that is not positive.
CameraMatrices pointShadowCamera(const PointLight& light, int face, int tileSize);
// Tiles a light's maps take: 1 for a spot light, 6 for a point light.
int shadowTiles(const PointLight& light);

class ShadowAtlas {
public:
    // Throws lidr::Error for sizes that are not powers of two with tileSize <= size, a size over the context's
    // GL_MAX_TEXTURE_SIZE, or a slope bias outside [0, 64]. Without depth textures (ES 2.0 without
    // OES_depth_texture) or with options.packedDepth the atlas is RGBA8 holding 24-bit depths (packed()).
    ShadowAtlas(const GlInfo& info, const ShadowAtlasOptions& options = {});

    int capacity() const { return perRow_ * perRow_; }  // tiles
    int tileSize() const { return options_.tileSize; }
    int size() const { return options_.size; }

    struct Slot {
        int light = -1;            // index into the lights given to update()
        int face = 0;              // a point light's cube face (0..5: +x, -x, +y, -y, +z, -z); 0 for a spot
        glm::ivec4 rect{0};        // x, y, width, height in atlas texels
        CameraMatrices camera;     // the map's view (spotShadowCamera)
        glm::mat4 worldToAtlas{1.0f};  // world -> (atlas u, v, window depth) in [0, 1], w the perspective divisor
    };
    // Gives lights[casters[i]] the next shadowTiles() slots in order (spot lights within kMaxShadowConeAngle, point
    // lights) and draws the maps whose light changed or whose range a scene change touched since they were
    // drawn. Returns how many maps (tiles) it drew. Throws lidr::Error (before drawing) for more tiles than the
    // atlas holds or a caster that cannot have a map. The atlas's framebuffer is left bound.
    int update(const GpuScene& scene, const std::vector<PointLight>& lights, const std::vector<int>& casters);
    const std::vector<Slot>& slots() const { return slots_; }
    long mapsDrawnTotal() const { return mapsDrawn_; }

    const gl::Texture& depthTexture() const { return depth_; }
    const gl::Texture& texture() const { return depth_; }  // what lookups sample (shadow_lookup.glsl)
    bool packed() const { return packed_; }  // an RGBA8 atlas holding 24-bit depth (LIDR_SHADOW_PACKED)
    // Window depth of every atlas texel, rows bottom to top (tests and the debug view). Throws
    // lidr::UnsupportedError on OpenGL ES 2.0 for a depth-texture atlas (ES reads no depth back).
    std::vector<float> readDepth() const;
    // The atlas as a picture (the viewer's and the page's debug view): each texel's distance from its light as a
    // fraction of the range, near white to far dark, empty texels black; at most maxSide pixels a side (the
    // nearest of each block of texels kept), rows top to bottom. Throws as readDepth does.
    ImageRGBA8 image(int maxSide = 1024) const;

private:
    struct Drawn {  // what a slot's map was drawn for
        glm::vec4 posRange{0.0f}, directionCone{0.0f};
        uint64_t sceneVersion = 0;
        bool valid = false;
    };
    ShadowAtlasOptions options_;
    int perRow_ = 0;
    gl::Texture depth_;  // the depth texture, or the packed RGBA8 one
    gl::Renderbuffer depthBuffer_;  // packed: the depth test's buffer
    gl::Framebuffer framebuffer_;
    gl::Program program_;
    std::vector<Slot> slots_;
    std::vector<Drawn> drawn_;
    long mapsDrawn_ = 0;
    // The slope bias is computed in the map's shader (shadow_depth.frag) wherever it can write the depth: polygon
    // offset's slope is the implementation's estimate, and softpipe's left acne where llvmpipe's did not. ES 2.0's
    // depth-texture maps keep polygon offset (gl_FragDepth needs EXT_frag_depth there).
    bool slopeInShader() const { return packed_ || !gles_; }
    bool packed_ = false, gles_ = false;
};

}  // namespace lidr
