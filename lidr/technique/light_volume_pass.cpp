#include "lidr/technique/light_volume_pass.h"
#include "lidr/base/gl.h"

#include <algorithm>

#include <glm/gtc/type_ptr.hpp>

#include "lidr/base/error.h"
#include "lidr/gl/shader_source.h"

namespace lidr {

IndexTargets::IndexTargets(int count, int width, int height, const gl::Renderbuffer& depthStencil, int samples)
    : width_(width), height_(height), samples_(samples) {
    if (count < 1 || count > kMaxIndexTargets)
        throw Error("index target count must be 1.." + std::to_string(kMaxIndexTargets));
    fbo_ = gl::Framebuffer::create();
    for (int i = 0; i < count; ++i) {
        textures_.push_back(samples > 0 ? gl::Texture::create2DMultisample(GL_RGBA8, width, height, samples)
                                        : gl::Texture::create2D(GL_RGBA8, width, height, GL_RGBA, GL_UNSIGNED_BYTE));
        fbo_.attachTexture(GL_COLOR_ATTACHMENT0 + i, textures_.back());
    }
    fbo_.attachRenderbuffer(GL_DEPTH_STENCIL_ATTACHMENT, depthStencil);
    fbo_.checkComplete("light-index targets");
    if (currentContextIsGles()) {
        for (int first = 1; first < count; ++first) {
            gl::Framebuffer f = gl::Framebuffer::create();
            for (int i = first; i < count; ++i) f.attachTexture(GL_COLOR_ATTACHMENT0 + (i - first), textures_[size_t(i)]);
            f.attachRenderbuffer(GL_DEPTH_STENCIL_ATTACHMENT, depthStencil);
            f.checkComplete("light-index targets from a later one (OpenGL ES)");
            fromFbos_.push_back(std::move(f));
        }
    }
    StateCache::current().bindFramebuffer(0);
}

const gl::Framebuffer& IndexTargets::framebufferFrom(int first) const {
    if (first == 0 || fromFbos_.empty()) return fbo_;
    return fromFbos_.at(size_t(first - 1));
}

size_t IndexTargets::bytes() const { return size_t(count()) * width_ * height_ * 4 * std::max(samples_, 1); }

LightVolumePass::LightVolumePass(const GlInfo& info, VolumeTest test, bool volumeDetail)
    : test_(test), depthClamp_(info.depthClamp), gles_(info.gles), coarsest_(volumeDetail ? 0 : kDetailLevels - 1) {
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
    vertices_ = gl::Buffer::create(GL_ARRAY_BUFFER, positions.data(), positions.size() * sizeof(glm::vec3));
    indices_ = gl::Buffer::create(GL_ELEMENT_ARRAY_BUFFER, indices.data(), indices.size() * sizeof(uint16_t));
    maxDrawTargets_ = std::min(kMaxIndexTargets, info.drawBuffers ? std::max(1, info.maxDrawBuffers) : 1);
    programs_.resize(kMaxIndexTargets);
    listPrograms_.resize(kMaxIndexTargets);
    batchPrograms_.resize(kMaxIndexTargets);
    if (isShaderVolumeTest(test)) {
        // The shader decides, so the volume need only enclose the sphere: the icosahedron (vertices at 1.26 x
        // the radius) beat the 80- and 320-face meshes on the room (volume pass 32 / 40 / 70 ms, llvmpipe):
        // its extra fill costs less than their vertices (doc/benchmarks.md).
        const LightVolumeMesh& mesh = meshes_[batchLevel_];
        const int byUniforms = (info.maxVertexUniformVectors - kReservedVertexUniforms) / 2;  // one target
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
    }
}

int LightVolumePass::batchFor(int targetCount) const {
    return std::max(1, std::min(batch_, (maxVertexUniformVectors_ - kReservedVertexUniforms) / (1 + targetCount)));
}

const gl::Program& LightVolumePass::batchProgramFor(int targetCount) const {
    if (targetCount != 1 && targetCount != 2 && targetCount != 4)
        throw Error("the sphere volume tests write 1, 2 or 4 index targets per draw, not " + std::to_string(targetCount));
    if (targetCount > maxDrawTargets_)
        throw UnsupportedError("writing " + std::to_string(targetCount) +
                               " index targets at once needs that many draw buffers");
    gl::Program& p = batchPrograms_[size_t(targetCount - 1)];
    if (!p) {
        ShaderDefines defs = {{"LIDR_DRAW_TARGETS", std::to_string(targetCount)},
                              {"LIDR_BATCH", std::to_string(batchFor(targetCount))}};
        if (test_ == VolumeTest::SphereRay) defs.push_back({"LIDR_SPHERE_RAY", "1"});
        p = gl::Program::create(std::string(volumeTestName(test_)) + "-volumes-" + std::to_string(targetCount),
                                buildShaderSource("light_volume_batch.vert", defs),
                                buildShaderSource("light_volume_sphere.frag", defs),
                                {{"aPosition", gl::kPosition}, {"aSlot", gl::kVolumeSlot}});
    }
    return p;
}

const gl::Program& LightVolumePass::programFor(int targetCount) const {
    if (targetCount < 1 || targetCount > maxDrawTargets_)
        throw UnsupportedError("writing " + std::to_string(targetCount) +
                               " index targets at once needs that many draw buffers");
    gl::Program& p = (listSource_ ? listPrograms_ : programs_)[size_t(targetCount - 1)];
    if (!p) {
        const std::string base = listSource_ ? "pixel_list_volume" : "light_volume";
        const ShaderDefines defs = {{"LIDR_DRAW_TARGETS", std::to_string(targetCount)}};
        p = gl::Program::create(base + "-" + std::to_string(targetCount), buildShaderSource(base + ".vert", defs),
                                buildShaderSource(base + ".frag", defs), {{"aPosition", gl::kPosition}});
    }
    return p;
}

void LightVolumePass::begin(const IndexTargets& targets, const CameraMatrices& camera, const gl::Texture* depth) {
    if (isShaderVolumeTest(test_) && !listSource_ && !(depth && *depth))
        throw Error(std::string("the ") + volumeTestName(test_) + " volume test needs the pre-pass depth as a texture");
    depth_ = depth;
    if (listSource_ && !quad_) {
        // Two clockwise triangles over the whole target: back faces, as the volume test draws them.
        const float q[] = {-1, -1, 0, -1, 1, 0, 1, 1, 0, -1, -1, 0, 1, 1, 0, 1, -1, 0};
        quad_ = gl::Buffer::create(GL_ARRAY_BUFFER, q, sizeof(q));
    }
    targets_ = &targets;
    camera_ = camera;
    drawCalls_ = 0;
    PassDescription pass{targets.framebuffer().id(), glm::ivec4(0, 0, targets.width(), targets.height()), {}, {}};
    // OpenGL ES without EXT_draw_buffers draws to COLOR_ATTACHMENT0 only: its draw buffers are left as they are.
    if (!gles_ || maxDrawTargets_ > 1)
        for (int i = 0; i < targets.count(); ++i) pass.drawBuffers.push_back(GL_COLOR_ATTACHMENT0 + i);
    pass.clear.color = pass.clear.stencil = true;  // index 0 (the null light) everywhere, no light counted
    StateCache::current().beginPass(pass);
    if (isShaderVolumeTest(test_) && !listSource_) {
        glBindBuffer(GL_ARRAY_BUFFER, batchVertices_.id());
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, batchIndices_.id());
        glEnableVertexAttribArray(gl::kPosition);
        glVertexAttribPointer(gl::kPosition, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec4), nullptr);
        glEnableVertexAttribArray(gl::kVolumeSlot);
        glVertexAttribPointer(gl::kVolumeSlot, 1, GL_FLOAT, GL_FALSE, sizeof(glm::vec4),
                              reinterpret_cast<const void*>(3 * sizeof(float)));
    } else {
        glBindBuffer(GL_ARRAY_BUFFER, listSource_ ? quad_.id() : vertices_.id());
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
        glEnableVertexAttribArray(gl::kPosition);
        glVertexAttribPointer(gl::kPosition, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    }
    checkGl("light-volume pass begin");
}

int LightVolumePass::detailFor(const VolumeLight& l) const {
    const int finest = kDetailLevels - 1;
    if (isShaderVolumeTest(test_)) return batchLevel_;
    if (coarsest_ == finest) return finest;
    // Projected radius in pixels: focal length (pixels) x tan of the sphere's angular radius, stretched by
    // 1 / cos^2 of its angle off the view axis (how a perspective projection widens off-centre spheres).
    // Near, behind or far off-axis: the finest volume.
    const glm::vec3 toCentre = glm::vec3(l.posRadius) - camera_.eye;
    const float distance = glm::length(toCentre), radius = l.posRadius.w;
    if (!(distance - radius * meshes_[0].outsideRadius > camera_.nearPlane * 1.5f)) return finest;
    const float cosOff = glm::dot(toCentre, camera_.forward) / distance;
    if (!(cosOff > 0.2f)) return finest;
    const float focal = camera_.projection[1][1] * 0.5f * float(camera_.height);
    const float sinA = radius / distance;
    const float pixels = focal * sinA / std::sqrt(std::max(1e-6f, 1.0f - sinA * sinA)) / (cosOff * cosOff);
    // The coarsest volume whose reach past the finest one's stays under a pixel.
    for (int level = coarsest_; level < finest; ++level)
        if ((meshes_[level].outsideRadius - meshes_[finest].outsideRadius) * pixels <= 1.0f) return level;
    return finest;
}

float LightVolumePass::outsideRadiusFor(const VolumeLight& light) const {
    // The shader tests mark exactly what the sphere (times kSphereRadiusScale) reaches, whatever mesh is drawn.
    if (isShaderVolumeTest(test_) && !listSource_) return kSphereRadiusScale;
    return meshes_[size_t(detailFor(light))].outsideRadius;
}

bool LightVolumePass::reachesFarPlane(const VolumeLight& l) const {
    return glm::dot(glm::vec3(l.posRadius) - camera_.eye, camera_.forward) +
               l.posRadius.w * meshes_[size_t(detailFor(l))].outsideRadius >=
           camera_.farPlane * 0.999f;
}

bool LightVolumePass::marksWholeFootprint(const VolumeLight& l) const {
    return !listSource_ && volumeMarksWholeFootprint(test_, depthClamp_, reachesFarPlane(l));
}

// The test hook's colour table: row block t (rows t*R .. t*R+R-1, R = rows per target) holds target t's colour
// of index i at texel (i mod 256, t*R + i/256), exactly the bytes the colors callback asks for.
void LightVolumePass::uploadColorTable(const VolumeDraw& d, const std::function<IndexColors(uint32_t)>& colors) {
    const int rows = static_cast<int>(listSource_->maxIndex / 256 + 1);
    const int height = rows * d.targetCount;
    std::vector<uint8_t> texels(size_t(256) * height * 4, 0);
    for (uint32_t i = 0; i <= listSource_->maxIndex; ++i) {
        const IndexColors c = colors(i);
        for (int t = 0; t < d.targetCount; ++t)
            for (int ch = 0; ch < 4; ++ch) {
                const float v = std::clamp(c[t][ch], 0.0f, 1.0f) * 255.0f;
                texels[((size_t(t) * rows + i / 256) * 256 + i % 256) * 4 + ch] = static_cast<uint8_t>(std::lround(v));
            }
    }
    colorTable_ = gl::Texture::create2D(GL_RGBA8, 256, height, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
}

void LightVolumePass::draw(const VolumeDraw& d, const std::vector<VolumeLight>& lights,
                           const std::function<IndexColors(uint32_t)>& colors) {
    if (!targets_) throw Error("LightVolumePass::draw outside begin/end");
    if (d.firstTarget < 0 || d.firstTarget + d.targetCount > targets_->count())
        throw Error("volume draw '" + d.name + "' addresses index targets outside the frame's set");
    if (isShaderVolumeTest(test_) && listSource_) throw Error("pixel lists stand in for the stencil tests' volumes");
    std::vector<VolumeLightFacts> facts;
    facts.reserve(lights.size());
    for (const VolumeLight& l : lights) facts.push_back(factsFor(l));
    VolumePlanContext context;
    context.test = test_;
    context.depthClamp = depthClamp_;
    context.gles = gles_;
    context.drawBuffers = maxDrawTargets_ > 1;
    context.batchSize = isShaderVolumeTest(test_) ? batchFor(d.targetCount) : 1;
    context.scissor = scissor_;
    const VolumeDrawPlan plan = planVolumeDraw(d, context, facts);

    StateCache& cache = StateCache::current();  // sets per step only what differs from the last
    if (plan.restartCount) {
        ClearAction clear;
        clear.stencil = true;
        cache.clear(clear);
    }
    if (plan.framebufferFrom >= 0) targets_->framebufferFrom(plan.framebufferFrom).bind();
    if (!plan.drawBuffers.empty()) cache.setDrawBuffers(plan.drawBuffers);
    beginSteps(d, plan, colors);
    for (const VolumeStep& step : plan.steps) {
        cache.apply(plan.stateOf(step));
        drawStep(step, lights, colors);
    }
    countBits_ = plan.countBits;
    checkGl(("light-volume draw '" + d.name + "'").c_str());
}

VolumeLightFacts LightVolumePass::factsFor(const VolumeLight& l) const {
    VolumeLightFacts f;
    if (listSource_) return f;
    f.detail = detailFor(l);
    f.reachesFarPlane = reachesFarPlane(l);
    // A volume reaching in front of the near plane (or holding the camera) has its front faces clipped there.
    if (test_ == VolumeTest::FrontFace)
        f.reachesNearPlane = glm::dot(glm::vec3(l.posRadius) - camera_.eye, camera_.forward) -
                                 l.posRadius.w * outsideRadiusFor(l) <=
                             camera_.nearPlane * 1.001f;
    return f;
}

void LightVolumePass::beginSteps(const VolumeDraw& d, const VolumeDrawPlan& plan,
                                 const std::function<IndexColors(uint32_t)>& colors) {
    stepProgram_ = plan.program;
    stepTargets_ = plan.programTargets;
    if (plan.program == VolumeProgram::Batch) {
        const gl::Program& program = batchProgramFor(plan.programTargets);
        program.use();
        program.set("uViewProj", camera_.viewProjection);
        program.set("uView", camera_.view);
        // Window depth d to distance in front of the eye, for lidr's perspective projections (P[2][3] = -1):
        // z_ndc = 2d - 1 = (P22 z_view + P32) / -z_view, so distance = -z_view = (P32 / 2) / (d + (P22 - 1) / 2).
        const glm::mat4& P = camera_.projection;
        if (P[2][3] != -1.0f || P[3][3] != 0.0f) throw Error("the sphere volume tests need a perspective projection");
        program.set("uDepthToDistance", glm::vec2(0.5f * P[3][2], 0.5f * (P[2][2] - 1.0f)));
        program.set("uNearPlane", camera_.nearPlane);
        program.set("uInvTargetSize", glm::vec2(1.0f / targets_->width(), 1.0f / targets_->height()));
        program.set("uRadiusScale", kSphereRadiusScale);
        program.set("uDepthMargin", kSphereDepthSteps / 16777215.0f);  // steps of DEPTH_COMPONENT24
        program.set("uDepth", gl::kUnitDepthCopy);
        depth_->bind(gl::kUnitDepthCopy);
        lightsUniform_ = program.uniform<glm::vec4>("uLights");
        colorsUniform_ = program.uniform<glm::vec4>("uIndexColors");
        clampUniform_ = program.uniform<float>("uClampToFar");
        const size_t batch = size_t(batchFor(plan.programTargets));
        lightData_.resize(batch);
        colorData_.resize(batch * size_t(plan.programTargets));
        return;
    }
    const gl::Program& program = programFor(plan.programTargets);
    program.use();
    if (listSource_) {  // the pixel-list quads are in clip space
        uploadColorTable(d, colors);
        colorTable_.bind(gl::kUnitPixelListColors);
        program.set("uStepIndices", gl::kUnitPixelListStep);
        program.set("uColorTable", gl::kUnitPixelListColors);
        program.set("uInvTargetSize", glm::vec2(1.0f / targets_->width(), 1.0f / targets_->height()));
        program.set("uTableRowsPerTarget", float(listSource_->maxIndex / 256 + 1));
        program.set("uTableHeight", float((listSource_->maxIndex / 256 + 1) * d.targetCount));
        return;
    }
    program.set("uViewProj", camera_.viewProjection);
    // Per light: looked up once per draw, set through typed handles.
    lightsUniform_ = program.uniform<glm::vec4>("uLightPosRadius");
    colorsUniform_ = program.uniform<glm::vec4>("uIndexColor");
    clampUniform_ = program.uniform<float>("uClampToFar");
}

void LightVolumePass::drawStep(const VolumeStep& step, const std::vector<VolumeLight>& lights,
                               const std::function<IndexColors(uint32_t)>& colors) {
    StateCache& cache = StateCache::current();
    if (listSource_) {
        const size_t index = lights[size_t(step.firstLight)].index;
        if (index == 0 || index - 1 >= listSource_->steps.size()) throw Error("pixel-list step out of range");
        listSource_->steps[index - 1]->bind(gl::kUnitPixelListStep);
        cache.drawArrays(GL_TRIANGLES, 0, 6);
        ++drawCalls_;
        return;
    }
    const int targets = stepTargets_;
    const bool batch = stepProgram_ == VolumeProgram::Batch;
    if (step.loadLights) {
        if (batch) {
            for (int i = 0; i < step.lightCount; ++i) {
                const VolumeLight& l = lights[size_t(step.firstLight + i)];
                lightData_[size_t(i)] = l.posRadius;
                const IndexColors c = colors(l.index);
                for (int t = 0; t < targets; ++t) colorData_[size_t(i * targets + t)] = c[size_t(t)];
            }
            lightsUniform_.setArray(lightData_.data(), step.lightCount);
            colorsUniform_.setArray(colorData_.data(), step.lightCount * targets);
        } else {
            const VolumeLight& l = lights[size_t(step.firstLight)];
            lightsUniform_.set(l.posRadius);
            const IndexColors c = colors(l.index);
            colorsUniform_.setArray(c.data(), targets);
        }
        clampUniform_.set(step.clampToFar ? 1.0f : 0.0f);
    }
    if (batch) {
        cache.drawElements(GL_TRIANGLES, GLsizei(step.lightCount) * batchCopyIndices_, GL_UNSIGNED_SHORT, nullptr);
    } else {
        cache.drawElements(GL_TRIANGLES, indexCount_[step.detail], GL_UNSIGNED_SHORT,
                           reinterpret_cast<const void*>(size_t(firstIndex_[step.detail]) * sizeof(uint16_t)));
    }
    ++drawCalls_;
}

void LightVolumePass::end() {
    if (isShaderVolumeTest(test_)) glDisableVertexAttribArray(gl::kVolumeSlot);
    glDisableVertexAttribArray(gl::kPosition);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    StateCache::current().apply(RenderState{});
    targets_ = nullptr;
    checkGl("light-volume pass end");
}

}  // namespace lidr
