#include "lidr/technique/light_volume_geometry.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <cstring>
#include <cmath>
#include <string>

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/shader_source.h"
#include "lidr/scene/sphere_bounds.h"

namespace lidr {

LightVolumeGeometry::LightVolumeGeometry(const GlInfo& info, VolumeTest test, bool volumeDetail, DepthEmulation depth,
                                         bool depthSpans, int spanSamples)
    : test_(test), coarsest_(volumeDetail ? 0 : kDetailLevels - 1),
      readsSpans_(test == VolumeTest::SphereSpan || (test == VolumeTest::SphereRay && depthSpans)),
      spanSamples_(readsSpans_ ? spanSamples : 0) {
    uploadMeshes();
    programs_ = DrawTargetPrograms(info, [depth](int targetCount) {
        ShaderDefines defs = {{"LIDR_DRAW_TARGETS", std::to_string(targetCount)}};
        const std::string vertex = buildShaderSource("light_volume.vert", defs);
        ShaderIncludes includes;
        depth.apply(defs, includes);
        return gl::Program::create("light_volume-" + std::to_string(targetCount), vertex,
                                   buildShaderSource("light_volume.frag", defs, includes),
                                   {{"aPosition", gl::kPosition}});
    });
    if (isShaderVolumeTest(test)) setUpBatches(info, test, depth);
}

void LightVolumeGeometry::uploadMeshes() {
    std::vector<glm::vec3> positions;
    std::vector<uint16_t> indices;
    for (int level = 0; level < kDetailLevels; ++level) {
        meshes_[level] = makeLightVolumeMesh(level);
        const auto base = static_cast<uint16_t>(positions.size());  // GL 2.1 has no base vertex: offset here
        firstIndex_[level] = static_cast<GLsizei>(indices.size());
        indexCount_[level] = static_cast<GLsizei>(meshes_[level].indices.size());
        positions.insert(positions.end(), meshes_[level].positions.begin(), meshes_[level].positions.end());
        for (uint16_t i : meshes_[level].indices) indices.push_back(static_cast<uint16_t>(base + i));
    }
    {
        // A spot light's cone mesh (stencil and front-face tests), placed per light by light_volume.vert.
        const LightVolumeMesh spot = makeSpotVolumeMesh();
        const auto base = static_cast<uint16_t>(positions.size());
        firstIndex_[kSpotDetail] = static_cast<GLsizei>(indices.size());
        indexCount_[kSpotDetail] = static_cast<GLsizei>(spot.indices.size());
        positions.insert(positions.end(), spot.positions.begin(), spot.positions.end());
        for (uint16_t i : spot.indices) indices.push_back(static_cast<uint16_t>(base + i));
    }
    vertices_ = gl::Buffer::create(GL_ARRAY_BUFFER, positions.data(), positions.size() * sizeof(glm::vec3));
    indices_ = gl::Buffer::create(GL_ELEMENT_ARRAY_BUFFER, indices.data(), indices.size() * sizeof(uint16_t));
}

void LightVolumeGeometry::setUpBatches(const GlInfo& info, VolumeTest test, DepthEmulation depth) {
    // The shader decides, so the volume need only enclose the sphere: the icosahedron (vertices at 1.26 x
    // the radius) beat the 80- and 320-face meshes on the room (volume pass 32 / 40 / 70 ms, llvmpipe):
    // its extra fill costs less than their vertices (doc/benchmarks.md).
    const LightVolumeMesh& mesh = meshes_[batchLevel_];
    // Per light: its sphere, its cone and one index colour per target.
    const int byUniforms = (info.maxVertexUniformVectors - kReservedVertexUniforms) / 3;  // one target
    batch_ = std::max(1, std::min({kMaxBatch, byUniforms, int(65535 / mesh.positions.size())}));
    std::vector<glm::vec4> copies;
    std::vector<uint16_t> copyIndices;
    copies.reserve(mesh.positions.size() * size_t(batch_));
    copyIndices.reserve(mesh.indices.size() * size_t(batch_));
    for (int slot = 0; slot < batch_; ++slot) {
        const auto base = static_cast<uint16_t>(copies.size());
        for (const glm::vec3& p : mesh.positions) copies.emplace_back(p, float(slot));
        for (uint16_t i : mesh.indices) copyIndices.push_back(static_cast<uint16_t>(base + i));
    }
    batchCopyIndices_ = static_cast<GLsizei>(mesh.indices.size());
    batchVertices_ = gl::Buffer::create(GL_ARRAY_BUFFER, copies.data(), copies.size() * sizeof(glm::vec4));
    batchIndices_ = gl::Buffer::create(GL_ELEMENT_ARRAY_BUFFER, copyIndices.data(), copyIndices.size() * sizeof(uint16_t));
    maxVertexUniformVectors_ = info.maxVertexUniformVectors;
    // By value: the geometry moves with its pass.
    const int uniforms = maxVertexUniformVectors_;
    auto programs = [info, test, depth, batch = batch_, uniforms, spans = readsSpans_,
                     samples = spanSamples_](bool screenTiles, bool cones, const ShaderDefines& shadow) {
        return DrawTargetPrograms(info, [test, depth, batch, uniforms, spans, samples, screenTiles, cones,
                                         shadow](int targetCount) {
            if (targetCount != 1 && targetCount != 2 && targetCount != 4)
                throw Error("the sphere volume tests write 1, 2 or 4 index targets per draw, not " +
                            std::to_string(targetCount));
            ShaderDefines defs = {{"LIDR_DRAW_TARGETS", std::to_string(targetCount)},
                                  {"LIDR_BATCH", std::to_string(batchFor(batch, uniforms, targetCount,
                                                                         !shadow.empty()))}};
            if (test == VolumeTest::SphereRay) defs.push_back({"LIDR_SPHERE_RAY", "1"});
            if (spans && samples > 0) defs.push_back({"LIDR_SPAN_SAMPLES", std::to_string(samples)});
            if (spans && samples == 0) defs.push_back({"LIDR_DEPTH_SPAN", "1"});
            if (screenTiles) defs.push_back({"LIDR_SCREEN_TILES", "1"});
            if (cones) defs.push_back({"LIDR_SPOT_CONES", "1"});
            defs.insert(defs.end(), shadow.begin(), shadow.end());
            const std::string vertex = buildShaderSource("light_volume_batch.vert", defs);
            ShaderIncludes includes;
            depth.apply(defs, includes);
            const std::string fragment = buildShaderSource("light_volume_sphere.frag", defs, includes);
            return gl::Program::create(std::string(volumeTestName(test)) + (screenTiles ? "-tiles-" : "-volumes-") +
                                           (cones ? "cones-" : "") + (shadow.empty() ? "" : "shadows-") +
                                           std::to_string(targetCount),
                                       vertex, samples > 0 ? perSampleGlsl150(fragment, false) : fragment,
                                       {{"aPosition", gl::kPosition}, {"aSlot", gl::kVolumeSlot}});
        });
    };
    // Each with and without the cone test: a draw of point lights alone skips its varying and arithmetic
    // (+8 % volume-pass instructions on hall-1024, callgrind). Compiled on first use.
    for (int cones = 0; cones < 2; ++cones) batchPrograms_[cones] = programs(false, cones == 1, {});
    if (test == VolumeTest::Sphere || test == VolumeTest::SphereSpan) {
        for (int cones = 0; cones < 2; ++cones) tilePrograms_[cones] = programs(true, cones == 1, {});
        makePrograms_ = programs;
        tileQuads_ = gl::Buffer::create(GL_ARRAY_BUFFER, nullptr, 0, GL_STREAM_DRAW);
    }
}

int LightVolumeGeometry::batchFor(int batch, int maxVertexUniformVectors, int targetCount, bool shadowed) {
    const int vectors = maxVertexUniformVectors - kReservedVertexUniforms;
    // Shadowed: n lights take n (2 + targets) vectors and ceil(n / 4) of tiles.
    const int lights = shadowed ? (4 * vectors - 3) / (4 * (2 + targetCount) + 1) : vectors / (2 + targetCount);
    return std::max(1, std::min(batch, lights));
}

int LightVolumeGeometry::batchFor(int targetCount) const {
    return batchFor(batch_, maxVertexUniformVectors_, targetCount);
}

int LightVolumeGeometry::batchFor(int targetCount, bool shadowed) const {
    return batchFor(batch_, maxVertexUniformVectors_, targetCount, shadowed);
}

bool LightVolumeGeometry::shadowedDraw(const std::vector<VolumeLight>& lights) const {
    return shadowMaps_ && shadowMaps_->active() && makePrograms_ &&
           std::any_of(lights.begin(), lights.end(), [](const VolumeLight& l) { return l.shadowTile >= 0; });
}

const SpotVolumeShape* LightVolumeGeometry::spotShapeOf(const VolumeLight& l, glm::vec3* axis) const {
    // The cone as the shading takes it (lidr::spotCone): axis x scale, -cos(outer) x scale; a point light's is
    // (0, 0, 0, 1).
    const float scale = glm::length(glm::vec3(l.cone));
    if (!(scale > 0.0f)) return nullptr;
    if (axis) *axis = glm::vec3(l.cone) / scale;
    const float cosOuter = std::clamp(-l.cone.w / scale, 0.0f, 1.0f);
    auto it = spotShapes_.find(cosOuter);
    if (it == spotShapes_.end()) it = spotShapes_.emplace(cosOuter, spotVolumeShape(std::acos(cosOuter))).first;
    return &it->second;
}

int LightVolumeGeometry::detailFor(const VolumeLight& l, const CameraMatrices& camera) const {
    const int finest = kDetailLevels - 1;
    if (isShaderVolumeTest(test_)) return batchLevel_;
    if (spotShapeOf(l)) return kSpotDetail;
    if (coarsest_ == finest) return finest;
    // Projected radius in pixels: focal length (pixels) x tan of the sphere's angular radius, stretched by
    // 1 / cos^2 of its angle off the view axis (how a perspective projection widens off-centre spheres).
    // Near, behind or far off-axis: the finest volume.
    const glm::vec3 toCentre = glm::vec3(l.posRadius) - camera.eye;
    const float distance = glm::length(toCentre), radius = l.posRadius.w;
    if (!(distance - radius * meshes_[0].outsideRadius > camera.nearPlane * 1.5f)) return finest;
    const float cosOff = glm::dot(toCentre, camera.forward) / distance;
    if (!(cosOff > 0.2f)) return finest;
    const float focal = camera.projection[1][1] * 0.5f * float(camera.height);
    const float sinA = radius / distance;
    const float pixels = focal * sinA / std::sqrt(std::max(1e-6f, 1.0f - sinA * sinA)) / (cosOff * cosOff);
    // The coarsest volume whose reach past the finest one's stays under a pixel.
    for (int level = coarsest_; level < finest; ++level)
        if ((meshes_[level].outsideRadius - meshes_[finest].outsideRadius) * pixels <= 1.0f) return level;
    return finest;
}

float LightVolumeGeometry::outsideRadiusFor(const VolumeLight& light, const CameraMatrices& camera) const {
    // The shader tests mark exactly what the sphere (times kSphereRadiusScale) reaches, whatever mesh is drawn.
    if (isShaderVolumeTest(test_)) return kSphereRadiusScale;
    if (const SpotVolumeShape* spot = spotShapeOf(light)) return spot->capScale;  // the cone mesh's cap
    return meshes_[size_t(detailFor(light, camera))].outsideRadius;
}

bool LightVolumeGeometry::reachesFarPlane(const VolumeLight& l, const CameraMatrices& camera) const {
    // The mesh drawn: the sphere tests' batch mesh reaches past what they mark, a spot's cone mesh to its cap.
    const int detail = detailFor(l, camera);
    const float outside = detail == kSpotDetail ? spotShapeOf(l)->capScale : meshes_[size_t(detail)].outsideRadius;
    return glm::dot(glm::vec3(l.posRadius) - camera.eye, camera.forward) + l.posRadius.w * outside >=
           camera.farPlane * 0.999f;
}

VolumeLightFacts LightVolumeGeometry::factsFor(const VolumeLight& l, const CameraMatrices& camera) const {
    VolumeLightFacts f;
    f.detail = detailFor(l, camera);
    f.reachesFarPlane = reachesFarPlane(l, camera);
    // A volume reaching in front of the near plane (or holding the camera) has its front faces clipped there.
    if (test_ == VolumeTest::FrontFace)
        f.reachesNearPlane = glm::dot(glm::vec3(l.posRadius) - camera.eye, camera.forward) -
                                 l.posRadius.w * outsideRadiusFor(l, camera) <=
                             camera.nearPlane * 1.001f;
    return f;
}

void LightVolumeGeometry::begin(const CameraMatrices& camera, glm::ivec2 targetSize, const gl::Texture* depth) {
    if (isShaderVolumeTest(test_) && !(depth && *depth))
        throw Error(std::string("the ") + volumeTestName(test_) + " volume test needs the pre-pass depth as a texture");
    camera_ = camera;
    targetSize_ = targetSize;
    depth_ = depth;
    tileQuadPixels_ = 0;
    tileStepLights_ = 0;
    if (drawsScreenTiles()) {
        glBindBuffer(GL_ARRAY_BUFFER, tileQuads_.id());  // attributes set per step (the data is re-specified)
        glEnableVertexAttribArray(gl::kPosition);
        glEnableVertexAttribArray(gl::kVolumeSlot);
    } else if (isShaderVolumeTest(test_)) {
        glBindBuffer(GL_ARRAY_BUFFER, batchVertices_.id());
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, batchIndices_.id());
        glEnableVertexAttribArray(gl::kPosition);
        glVertexAttribPointer(gl::kPosition, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec4), nullptr);
        glEnableVertexAttribArray(gl::kVolumeSlot);
        glVertexAttribPointer(gl::kVolumeSlot, 1, GL_FLOAT, GL_FALSE, sizeof(glm::vec4),
                              reinterpret_cast<const void*>(3 * sizeof(float)));
    } else {
        glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
        glEnableVertexAttribArray(gl::kPosition);
        glVertexAttribPointer(gl::kPosition, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    }
}

void LightVolumeGeometry::end() {
    if (isShaderVolumeTest(test_)) glDisableVertexAttribArray(gl::kVolumeSlot);
    glDisableVertexAttribArray(gl::kPosition);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

void LightVolumeGeometry::beginSteps(const VolumeDraw& d, const VolumeDrawPlan& plan, const IndexColorsFor&) {
    program_ = plan.program;
    targets_ = plan.programTargets;
    if (plan.program == VolumeProgram::PerLight) {
        const gl::Program& program = programs_.get(plan.programTargets);
        program.use();
        program.set("uViewProj", camera_.viewProjection);
        // Per light: looked up once per draw, set through typed handles.
        lightsUniform_ = program.uniform<glm::vec4>("uLightPosRadius");
        spotUniform_ = program.uniform<glm::vec4>("uSpotVolume");
        colorsUniform_ = program.uniform<glm::vec4>("uIndexColor");
        clampUniform_ = program.uniform<float>("uClampToFar");
        return;
    }
    const gl::Program* chosen = nullptr;
    if (shadowDraw_) {
        const ShaderDefines shadow = shadowMaps_->defines(shadowSettings_);
        std::string key = std::string(drawsScreenTiles() ? "tiles" : "volumes") + (spotCones_ ? "-cones" : "");
        for (const auto& d : shadow) key += " " + d.first + "=" + d.second;
        auto found = shadowPrograms_.find(key);
        if (found == shadowPrograms_.end())
            found = shadowPrograms_.emplace(key, makePrograms_(drawsScreenTiles(), spotCones_, shadow)).first;
        chosen = &found->second.get(plan.programTargets);
    } else {
        chosen = &(drawsScreenTiles() ? tilePrograms_ : batchPrograms_)[spotCones_ ? 1 : 0].get(plan.programTargets);
    }
    const gl::Program& program = *chosen;
    program.use();
    if (shadowDraw_) {
        program.set("uInvView", glm::inverse(camera_.view));
        shadowMaps_->bind(program, shadowSettings_);
        shadowTilesUniform_ = program.uniform<glm::vec4>("uShadowTiles");
    }
    program.set("uViewProj", camera_.viewProjection);
    program.set("uView", camera_.view);
    program.set("uProjection", camera_.projection);
    // A rank window from rank k on writes only where more than k lights mark a pixel; its count is not the
    // one left for the probe (rankWindowDraw draws rank 0 last, over every tile).
    skipTilesUpTo_ = d.rankCount > 0 ? d.rankFirst : 0;
    // Window depth d to distance in front of the eye, for lidr's perspective projections (P[2][3] = -1):
    // z_ndc = 2d - 1 = (P22 z_view + P32) / -z_view, so distance = -z_view = (P32 / 2) / (d + (P22 - 1) / 2).
    const glm::mat4& P = camera_.projection;
    if (P[2][3] != -1.0f || P[3][3] != 0.0f) throw Error("the sphere volume tests need a perspective projection");
    program.set("uDepthToDistance", glm::vec2(0.5f * P[3][2], 0.5f * (P[2][2] - 1.0f)));
    program.set("uNearPlane", camera_.nearPlane);
    program.set("uInvTargetSize", 1.0f / glm::vec2(targetSize_));
    program.set("uRadiusScale", kSphereRadiusScale);
    program.set("uDepthMargin", kSphereDepthSteps / depthUnits_);  // steps of the pre-pass depth buffer
    program.set("uDepth", gl::kUnitDepthCopy);
    depth_->bind(gl::kUnitDepthCopy);
    if (spanSamples_) {
        if (!(depthSpans_ && depthSpans_->storesSamples() && depthSpans_->samples() == spanSamples_))
            throw Error(std::string("the ") + volumeTestName(test_) + " volume test needs the frame's MSAA sample "
                        "distances of " + std::to_string(spanSamples_) + " samples");
        // Four samples a texel: units kUnitDepthSpans and the one after it (the moments' side unit, unused here).
        static_assert(gl::kUnitDepthSpanSides == gl::kUnitDepthSpans + 1);
        for (int t = 0; t < depthSpans_->packedTextureCount(); ++t) {
            program.set(("uLidrSampleDistances" + std::to_string(t)).c_str(), gl::kUnitDepthSpans + t);
            depthSpans_->packedTexture(t).bind(gl::kUnitDepthSpans + t);
        }
    } else if (readsSpans_) {
        if (!(depthSpans_ && *depthSpans_ && depthSpans_->hasSides()))
            throw Error(std::string("the ") + volumeTestName(test_) + " volume test needs the frame's MSAA depth spans");
        program.set("uDepthSpan", gl::kUnitDepthSpans);
        program.set("uSpanBoundScale", depthSpans_->boundScale());
        program.set("uSpanSides", gl::kUnitDepthSpanSides);
        program.set("uSpanSamples", float(depthSpans_->samples()));
        program.set("uSpanMomentScale", depthSpans_->momentScale());
        program.set("uSpanRounding", depthSpans_->sideRounding());
        program.set("uSpanSideMargin", DepthSpanPass::kSideMargin);
        depthSpans_->texture().bind(gl::kUnitDepthSpans);
        depthSpans_->sideTexture().bind(gl::kUnitDepthSpanSides);
    }
    lightsUniform_ = program.uniform<glm::vec4>("uLights");
    conesUniform_ = program.uniform<glm::vec4>("uCones");
    colorsUniform_ = program.uniform<glm::vec4>("uIndexColors");
    clampUniform_ = program.uniform<float>("uClampToFar");
    const size_t batch = size_t(batchFor(plan.programTargets, shadowDraw_));
    shadowTileData_.resize((batch + 3) / 4);
    lightData_.resize(batch);
    coneData_.resize(batch);
    colorData_.resize(batch * size_t(plan.programTargets));
}

void LightVolumeGeometry::drawStep(const VolumeStep& step, const std::vector<VolumeLight>& lights,
                                   const IndexColorsFor& colors) {
    const bool batch = program_ == VolumeProgram::Batch;
    if (step.loadLights) {
        if (batch) {
            for (int i = 0; i < step.lightCount; ++i) {
                const VolumeLight& l = lights[size_t(step.firstLight + i)];
                lightData_[size_t(i)] = l.posRadius;
                coneData_[size_t(i)] = l.cone;
                const IndexColors c = colors(l.index);
                for (int t = 0; t < targets_; ++t) colorData_[size_t(i * targets_ + t)] = c[size_t(t)];
            }
            lightsUniform_.setArray(lightData_.data(), step.lightCount);
            conesUniform_.setArray(coneData_.data(), step.lightCount);
            colorsUniform_.setArray(colorData_.data(), step.lightCount * targets_);
            if (shadowDraw_) {
                for (int i = 0; i < step.lightCount; ++i)
                    shadowTileData_[size_t(i / 4)][i % 4] = float(lights[size_t(step.firstLight + i)].shadowTile);
                shadowTilesUniform_.setArray(shadowTileData_.data(), (step.lightCount + 3) / 4);
            }
        } else {
            const VolumeLight& l = lights[size_t(step.firstLight)];
            glm::vec3 axis(0.0f);
            if (const SpotVolumeShape* spot = spotShapeOf(l, &axis)) {
                lightsUniform_.set(glm::vec4(glm::vec3(l.posRadius), l.posRadius.w * spot->capScale));
                spotUniform_.set(glm::vec4(axis, spot->rimAngle));
            } else {
                lightsUniform_.set(l.posRadius);
                spotUniform_.set(glm::vec4(0.0f));
            }
            const IndexColors c = colors(l.index);
            colorsUniform_.setArray(c.data(), targets_);
        }
        clampUniform_.set(step.clampToFar ? 1.0f : 0.0f);
    }
    StateCache& cache = StateCache::current();
    if (batch && drawsScreenTiles()) {
        cullToTiles(lights);
        drawTileQuads(step);
    } else if (batch) {
        cache.drawElements(GL_TRIANGLES, GLsizei(step.lightCount) * batchCopyIndices_, GL_UNSIGNED_SHORT, nullptr);
    } else {
        cache.drawElements(GL_TRIANGLES, indexCount_[step.detail], GL_UNSIGNED_SHORT,
                           reinterpret_cast<const void*>(size_t(firstIndex_[step.detail]) * sizeof(uint16_t)));
    }
}

size_t LightVolumeGeometry::SphereHash::operator()(const SphereKey& k) const {
    // The floats' bits mixed (std::hash<float> runs a byte hash per float: a tenth of the light-table pass on
    // the hall); + 0.0f makes -0 into +0, which compare equal.
    uint64_t h = 0;
    for (int i = 0; i < 4; ++i) {
        const float v = k.posRadius[i] + 0.0f;
        uint32_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        h = (h ^ bits) * 0x9E3779B97F4A7C15ull;
        h ^= h >> 29;
    }
    return size_t(h);
}

void LightVolumeGeometry::setTiles(const VolumeTiles* tiles, const CameraMatrices& camera) {
    if (tiles && test_ != VolumeTest::Sphere && test_ != VolumeTest::SphereSpan)
        throw Error("tile-culled light volumes are the sphere and sphere-span tests'");
    tiles_ = tiles;
    camera_ = camera;
    sphereTiles_.clear();  // a new frame's tiles
    tiledLights_.clear();
    tiledRegions_.clear();
    regions_ = IndexRegions{};
}

const LightVolumeGeometry::SphereTiles& LightVolumeGeometry::tilesOf(const glm::vec4& posRadius) {
    auto [it, added] = sphereTiles_.try_emplace(SphereKey{posRadius});
    SphereTiles& result = it->second;
    if (!added) return result;
    std::vector<TileReach>& tiles = result.tiles;
    const glm::vec3 centre(posRadius);
    const float radius = posRadius.w * kSphereRadiusScale;
    glm::ivec4 rect;  // pixels, inclusive, y up
    float nearDepth = 0.0f, farDepth = 1.0f;
    if (!spherePixelRect(camera_, centre, radius, rect) ||
        !VolumeTiles::sphereDepthSpan(camera_, centre, radius, nearDepth, farDepth))
        return result;
    result.rect = rect;
    const glm::vec3 viewCentre(camera_.view * glm::vec4(centre, 1.0f));
    const int size = tiles_->tileSize(), tilesX = tiles_->tilesX(), tilesY = tiles_->tilesY();
    const int tx0 = rect.x / size, tx1 = std::min(rect.z / size, tilesX - 1);
    const int ty0 = rect.y / size, ty1 = std::min(rect.w / size, tilesY - 1);
    for (int ty = ty0; ty <= ty1; ++ty)
        for (int tx = tx0; tx <= tx1; ++tx) {
            const int t = ty * tilesX + tx;
            const uint32_t slices = tiles_->slicesReached(t, viewCentre, radius, nearDepth, farDepth);
            if (slices) tiles.push_back({t, slices});
        }
    return result;
}

bool LightVolumeGeometry::sphereReachesTiles(const glm::vec4& posRadius) {
    if (!tiles_) throw Error("sphereReachesTiles without tiles");
    return !tilesOf(posRadius).tiles.empty();
}

uint32_t LightVolumeGeometry::sphereRegions(const glm::vec4& posRadius, const IndexRegions& regions) {
    if (!tiles_) throw Error("sphereRegions without tiles");
    uint32_t reached = 0;
    for (const TileReach& r : tilesOf(posRadius).tiles) reached |= 1u << regions.regionOfTile(r.tile);
    return reached;
}

void LightVolumeGeometry::cullToTiles(const std::vector<VolumeLight>& lights) {
    bool same = tiledLights_.size() == lights.size();
    for (size_t i = 0; same && i < lights.size(); ++i)
        same = lights[i].posRadius == tiledLights_[i] && lights[i].region == tiledRegions_[i];
    if (same) return;  // the frame's earlier draw (another rank window) gathered these lights already
    tiledLights_.clear();
    tiledRegions_.clear();
    lightTiles_.clear();
    const size_t tiles = size_t(tiles_->tileCount());
    sliceCounts_.assign(tiles * 32, 0);
    for (const VolumeLight& l : lights) {
        tiledLights_.push_back(l.posRadius);
        tiledRegions_.push_back(l.region);
        lightTiles_.push_back(&tilesOf(l.posRadius));
        // Per run of slices one pixel's depth span may cover (VolumeTiles::candidateWindows): a light reaching any
        // slice of it may mark that pixel.
        for (const TileReach& r : lightTiles_.back()->tiles)
            for (uint32_t bits = tileInRegion(r.tile, l.region) ? VolumeTiles::candidateWindows(r.slices, tiles_->sliceSpan(r.tile)) : 0u;
                 bits; bits &= bits - 1) {
                uint8_t& n = sliceCounts_[size_t(r.tile) * 32 + size_t(__builtin_ctz(bits))];
                if (n < 255) ++n;
            }
    }
    tileCandidates_.assign(tiles, 0);
    for (size_t t = 0; t < tiles; ++t)
        tileCandidates_[t] = *std::max_element(sliceCounts_.begin() + t * 32, sliceCounts_.begin() + (t + 1) * 32);
}

glm::ivec4 LightVolumeGeometry::candidateArea(int count) const {
    if (!tiles_ || tiledLights_.empty() || tileCandidates_.size() != size_t(tiles_->tileCount())) return {0, 0, -1, -1};
    const int tilesX = tiles_->tilesX(), size = tiles_->tileSize();
    int x0 = tilesX, y0 = tiles_->tilesY(), x1 = -1, y1 = -1;
    for (size_t t = 0; t < tileCandidates_.size(); ++t) {
        if (tileCandidates_[t] <= count) continue;
        const int tx = int(t) % tilesX, ty = int(t) / tilesX;
        x0 = std::min(x0, tx), x1 = std::max(x1, tx), y0 = std::min(y0, ty), y1 = std::max(y1, ty);
    }
    if (x1 < 0) return {0, 0, 0, 0};
    const int px0 = x0 * size, py0 = y0 * size;
    return {px0, py0, std::min((x1 + 1) * size, targetSize_.x) - px0, std::min((y1 + 1) * size, targetSize_.y) - py0};
}

void LightVolumeGeometry::drawTileQuads(const VolumeStep& step) {
    // Window pixel (x, y) -> its point at NDC depth 0 in view space (a plane, so the eye ray interpolates
    // exactly across a quad; the near plane itself would be clipped by rounding).
    const glm::mat4 inverseProjection = glm::inverse(camera_.projection);
    auto nearPoint = [&](int x, int y) {
        const glm::vec4 ndc(2.0f * float(x) / float(targetSize_.x) - 1.0f, 2.0f * float(y) / float(targetSize_.y) - 1.0f,
                            0.0f, 1.0f);
        const glm::vec4 v = inverseProjection * ndc;
        return glm::vec3(v) / v.w;
    };
    tileVertices_.clear();
    tileStepLights_ += step.lightCount;
    const int tilesX = tiles_->tilesX(), size = tiles_->tileSize();
    for (int slot = 0; slot < step.lightCount; ++slot) {
        const SphereTiles& sphere = *lightTiles_[size_t(step.firstLight + slot)];
        const int region = tiledRegions_[size_t(step.firstLight + slot)];
        const std::vector<TileReach>& tiles = sphere.tiles;
        for (size_t k = 0; k < tiles.size();) {
            // A run of kept tiles along one row (and within the entry's region) becomes one quad.
            const int first = tiles[k].tile;
            if (tileCandidates_[size_t(first)] <= skipTilesUpTo_ || !tileInRegion(first, region)) {
                ++k;
                continue;
            }
            int last = first;
            while (k + 1 < tiles.size() && tiles[k + 1].tile == last + 1 && (last + 1) % tilesX != 0 &&
                   tileCandidates_[size_t(last + 1)] > skipTilesUpTo_ && tileInRegion(last + 1, region))
                last = tiles[++k].tile;
            ++k;
            // The run's pixels, clipped to the sphere's own rectangle (inclusive there, exclusive here).
            const glm::ivec4& r = sphere.rect;
            const int y0 = std::max((first / tilesX) * size, r.y), y1 = std::min({(first / tilesX + 1) * size, r.w + 1, targetSize_.y});
            const int x0 = std::max((first % tilesX) * size, r.x), x1 = std::min({(last % tilesX + 1) * size, r.z + 1, targetSize_.x});
            if (x1 <= x0 || y1 <= y0) continue;
            tileQuadPixels_ += long(x1 - x0) * long(y1 - y0);
            const glm::vec3 a = nearPoint(x0, y0), b = nearPoint(x1, y0), c = nearPoint(x1, y1), d = nearPoint(x0, y1);
            // Clockwise on screen: the pass's state culls front faces (it draws a volume's back faces).
            for (const glm::vec3& p : {a, d, c, a, c, b}) tileVertices_.emplace_back(p, float(slot));
        }
    }
    if (tileVertices_.empty()) return;
    glBindBuffer(GL_ARRAY_BUFFER, tileQuads_.id());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(tileVertices_.size() * sizeof(glm::vec4)), tileVertices_.data(),
                 GL_STREAM_DRAW);
    glVertexAttribPointer(gl::kPosition, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec4), nullptr);
    glVertexAttribPointer(gl::kVolumeSlot, 1, GL_FLOAT, GL_FALSE, sizeof(glm::vec4),
                          reinterpret_cast<const void*>(3 * sizeof(float)));
    StateCache::current().drawArrays(GL_TRIANGLES, 0, GLsizei(tileVertices_.size()));
}

}  // namespace lidr
