#include "lidr/render/shadow_atlas.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/shader_source.h"
#include "lidr/base/image.h"
#include "lidr/render/depth_prepass.h"

namespace lidr {

namespace {
bool powerOfTwo(int v) { return v > 0 && (v & (v - 1)) == 0; }
}  // namespace

CameraMatrices spotShadowCamera(const PointLight& spot, int tileSize) {
    if (!spot.isSpot()) throw Error("shadow map: the light is not a spot light (a point light has six maps: pointShadowCamera)");
    if (!(spot.outerConeAngle <= kMaxShadowConeAngle))
        throw Error("shadow map: the spot light's outer cone of " + std::to_string(glm::degrees(spot.outerConeAngle)) +
                    " degrees is wider than one map covers (" + std::to_string(glm::degrees(kMaxShadowConeAngle)) + ")");
    if (!(spot.radius > 0.0f) || !std::isfinite(spot.radius)) throw Error("shadow map: the light's range must be positive");
    const float length = glm::length(spot.direction);
    if (!(length > 0.0f) || !std::isfinite(length)) throw Error("shadow map: the spot light's direction has no length");
    CameraMatrices m;
    m.eye = spot.position;
    m.forward = spot.direction / length;
    // Any up vector not along the axis: the map's roll does not matter.
    const glm::vec3 up = std::abs(m.forward.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    m.view = glm::lookAt(m.eye, m.eye + m.forward, up);
    m.nearPlane = spot.radius * 0.01f;
    m.farPlane = spot.radius;
    m.projection = glm::perspective(2.0f * spot.outerConeAngle, 1.0f, m.nearPlane, m.farPlane);
    m.viewProjection = m.projection * m.view;
    m.inverseViewProjection = glm::inverse(m.viewProjection);
    m.width = m.height = tileSize;
    return m;
}

CameraMatrices pointShadowCamera(const PointLight& light, int face, int tileSize) {
    if (light.isSpot()) throw Error("shadow map: a spot light has one map, not a cube of six");
    if (face < 0 || face > 5) throw Error("shadow map: cube face " + std::to_string(face) + " is not in 0..5");
    if (!(light.radius > 0.0f) || !std::isfinite(light.radius)) throw Error("shadow map: the light's range must be positive");
    static const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const glm::vec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    CameraMatrices m;
    m.eye = light.position;
    m.forward = axes[face];
    m.view = glm::lookAt(m.eye, m.eye + m.forward, ups[face]);
    // Every point of the range lies in front of one face at a view depth of at most the range.
    m.nearPlane = light.radius * 0.01f;
    m.farPlane = light.radius;
    m.projection = glm::perspective(glm::radians(90.0f), 1.0f, m.nearPlane, m.farPlane);
    m.viewProjection = m.projection * m.view;
    m.inverseViewProjection = glm::inverse(m.viewProjection);
    m.width = m.height = tileSize;
    return m;
}

int shadowTiles(const PointLight& light) { return light.isSpot() ? 1 : 6; }

ShadowAtlas::ShadowAtlas(const GlInfo& info, const ShadowAtlasOptions& options) : options_(options) {
    if (!powerOfTwo(options.size) || !powerOfTwo(options.tileSize) || options.tileSize > options.size || options.tileSize < 16)
        throw Error("shadow atlas: size " + std::to_string(options.size) + " and tile size " + std::to_string(options.tileSize) +
                    " must be powers of two with 16 <= tile size <= size");
    if (!(options.slopeBias >= 0.0f && options.slopeBias <= 64.0f))
        throw Error("shadow atlas: slope bias " + std::to_string(options.slopeBias) + " must be in [0, 64] (texels)");
    if (info.maxTextureSize > 0 && options.size > info.maxTextureSize)
        throw Error("shadow atlas: size " + std::to_string(options.size) + " is over this context's GL_MAX_TEXTURE_SIZE of " +
                    std::to_string(info.maxTextureSize));
    perRow_ = options.size / options.tileSize;
    packed_ = options.packedDepth || !info.depthTexture;
    gles_ = info.gles;
    framebuffer_ = gl::Framebuffer::create();
    if (packed_) {
        // Each texel's 24-bit window depth in RGB (shadow_depth.frag), a depth renderbuffer for the test: 16 bits
        // on ES 2.0 (all it guarantees) can let a farther surface win where two lie within 2^-16 of each other.
        depth_ = gl::Texture::create2D(GL_RGBA8, options.size, options.size, GL_RGBA, GL_UNSIGNED_BYTE);
        depthBuffer_ = gl::Renderbuffer::create(info.gles ? GL_DEPTH_COMPONENT16 : GL_DEPTH_COMPONENT24, options.size,
                                                options.size);
        framebuffer_.attachTexture(GL_COLOR_ATTACHMENT0, depth_);
        framebuffer_.attachRenderbuffer(GL_DEPTH_ATTACHMENT, depthBuffer_);
    } else {
        depth_ = gl::Texture::create2D(info.gles ? GL_DEPTH_COMPONENT : GL_DEPTH_COMPONENT24, options.size, options.size,
                                       GL_DEPTH_COMPONENT, GL_UNSIGNED_INT);
        framebuffer_.attachTexture(GL_DEPTH_ATTACHMENT, depth_);
        if (!info.gles) {
            // No colour: GL 2.1's FBO completeness wants the draw and read buffers to be NONE (framebuffer state).
            glDrawBuffer(GL_NONE);
            glReadBuffer(GL_NONE);
        }
    }
    framebuffer_.checkComplete("shadow atlas");
    {  // tiles no light has used yet read as empty (depth 1), in the debug view too
        PassDescription pass;
        pass.framebuffer = framebuffer_.id();
        pass.viewport = glm::ivec4(0, 0, options.size, options.size);
        pass.clear.depth = true;
        pass.clear.color = packed_;
        pass.clear.colorValue = glm::vec4(1.0f);
        StateCache::current().beginPass(pass);
    }
    if (slopeInShader()) {
        ShaderDefines defines;
        if (packed_) defines.push_back({"LIDR_SHADOW_PACKED", "1"});
        program_ = gl::Program::create(packed_ ? "shadow-depth-packed" : "shadow-depth", buildShaderSource("geometry.vert"),
                                       buildShaderSource("shadow_depth.frag", defines), geometryAttributes());
    } else {
        program_ = gl::Program::create("shadow-depth-offset", buildShaderSource("geometry.vert"),
                                       buildShaderSource("depth_only.frag"), geometryAttributes());
    }
    checkGl("shadow atlas");
}

int ShadowAtlas::update(const GpuScene& scene, const std::vector<PointLight>& lights, const std::vector<int>& casters) {
    std::vector<Slot> slots;
    for (const int light : casters) {
        if (light < 0 || size_t(light) >= lights.size())
            throw Error("shadow atlas: caster " + std::to_string(light) + " is not one of the " + std::to_string(lights.size()) + " lights");
        for (int face = 0; face < shadowTiles(lights[size_t(light)]); ++face) {
            Slot s;
            s.light = light;
            s.face = face;
            const PointLight& l = lights[size_t(light)];
            s.camera = l.isSpot() ? spotShadowCamera(l, options_.tileSize) : pointShadowCamera(l, face, options_.tileSize);
            slots.push_back(s);  // throws above for lights without a map
        }
    }
    if (slots.size() > size_t(capacity()))
        throw Error("shadow atlas: the shadow-casting lights need " + std::to_string(slots.size()) + " maps (a spot light 1, a point light 6), the atlas holds " +
                    std::to_string(capacity()) + " (" + std::to_string(options_.size) + " / " +
                    std::to_string(options_.tileSize) + " squared)");
    for (size_t i = 0; i < slots.size(); ++i) {
        Slot& s = slots[i];
        s.rect = glm::ivec4(int(i) % perRow_ * options_.tileSize, int(i) / perRow_ * options_.tileSize, options_.tileSize,
                            options_.tileSize);
        // NDC -> the tile's texels in [0, 1] of the atlas; depth -> window depth.
        const float scale = float(options_.tileSize) / float(options_.size);
        glm::mat4 toAtlas(1.0f);
        toAtlas[0][0] = toAtlas[1][1] = 0.5f * scale;
        toAtlas[2][2] = 0.5f;
        toAtlas[3] = glm::vec4(float(s.rect.x) / float(options_.size) + 0.5f * scale,
                               float(s.rect.y) / float(options_.size) + 0.5f * scale, 0.5f, 1.0f);
        s.worldToAtlas = toAtlas * s.camera.viewProjection;
    }
    drawn_.resize(slots.size());
    StateCache& cache = StateCache::current();
    int drawnNow = 0;
    for (size_t i = 0; i < slots.size(); ++i) {
        const PointLight& l = lights[size_t(slots[i].light)];
        const glm::vec4 posRange(l.position, l.radius);
        const glm::vec4 directionCone = l.isSpot() ? glm::vec4(l.direction, l.outerConeAngle) : glm::vec4(0.0f, 0.0f, 0.0f, -1.0f - float(slots[i].face));  // outer > 0 for spots
        Drawn& d = drawn_[i];
        const bool same = d.valid && d.posRange == posRange && d.directionCone == directionCone &&
                          !scene.changedNear(l.position, l.radius, d.sceneVersion);
        if (same) continue;
        PassDescription pass;
        pass.framebuffer = framebuffer_.id();
        pass.viewport = slots[i].rect;
        pass.clear.depth = true;
        pass.clear.color = packed_;  // packed: 1.0 is (255, 255, 255)
        pass.clear.colorValue = glm::vec4(1.0f);
        pass.clear.region = slots[i].rect;
        cache.beginPass(pass);
        if (slopeInShader()) {  // the shader adds the slope bias (shadow_depth.frag); no polygon offset
            program_.use();
            program_.set("uSlopeBias", options_.slopeBias);
        }
        drawOpaqueDepth(program_, scene, slots[i].camera, slopeInShader() ? 0.0f : options_.slopeBias, packed_);
        d = {posRange, directionCone, scene.version(), true};
        ++drawnNow;
    }
    checkGl("shadow atlas: maps");
    slots_ = std::move(slots);
    mapsDrawn_ += drawnNow;
    return drawnNow;
}

ImageRGBA8 ShadowAtlas::image(int maxSide) const {
    const std::vector<float> depth = readDepth();
    const int n = options_.size;
    const int step = (n + std::max(maxSide, 1) - 1) / std::max(maxSide, 1);
    const int side = n / step;
    ImageRGBA8 out(side, side);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            float nearest = 1.0f;
            for (int j = 0; j < step; ++j)
                for (int i = 0; i < step; ++i)
                    nearest = std::min(nearest, depth[size_t(y * step + j) * size_t(n) + size_t(x * step + i)]);
            // Window depth z -> distance / range = 0.01 / (1 - 0.99 z) (near plane at a hundredth of the range).
            const float fraction = nearest >= 1.0f ? 1.0f : std::min(1.0f, 0.01f / std::max(1.0f - 0.99f * nearest, 1e-6f));
            const auto v = static_cast<uint8_t>(std::lround((1.0f - fraction) * 255.0f));
            uint8_t* p = out.at(x, side - 1 - y);  // the atlas's rows are bottom to top
            p[0] = p[1] = p[2] = v;
            p[3] = 255;
        }
    return out;
}

std::vector<float> ShadowAtlas::readDepth() const {
    StateCache& cache = StateCache::current();
    PassDescription pass;
    pass.framebuffer = framebuffer_.id();
    pass.viewport = glm::ivec4(0, 0, options_.size, options_.size);
    cache.beginPass(pass);
    if (packed_) {
        std::vector<uint8_t> bytes(size_t(options_.size) * size_t(options_.size) * 4);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, options_.size, options_.size, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
        checkGl("shadow atlas: read-back");
        std::vector<float> rows(bytes.size() / 4);  // glReadPixels' rows are bottom to top already
        for (size_t i = 0; i < rows.size(); ++i)
            rows[i] = float(double((uint32_t(bytes[i * 4]) << 16) | (uint32_t(bytes[i * 4 + 1]) << 8) | bytes[i * 4 + 2]) /
                            16777215.0);
        return rows;
    }
    if (gles_) throw UnsupportedError("shadow atlas: OpenGL ES 2.0 cannot read a depth texture back (a packed atlas can)");
    const ImageFloat image = lidr::readDepth(options_.size, options_.size);
    // readDepth gives rows top to bottom (an image); the atlas's rows are kept bottom to top like GL's.
    std::vector<float> rows(image.pixels.size());
    for (int y = 0; y < options_.size; ++y)
        for (int x = 0; x < options_.size; ++x)
            rows[size_t(y) * size_t(options_.size) + size_t(x)] =
                image.pixels[size_t(options_.size - 1 - y) * size_t(options_.size) + size_t(x)];
    return rows;
}

}  // namespace lidr
