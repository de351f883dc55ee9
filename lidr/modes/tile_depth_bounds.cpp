#include "lidr/modes/tile_depth_bounds.h"
#include "lidr/base/gl.h"

#include "lidr/render/depth_prepass.h"
#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/shader_source.h"

namespace lidr {

const char* depthReductionFormatName(DepthReductionFormat f) {
    return f == DepthReductionFormat::Float32 ? "float32" : "packed-rgba8";
}

namespace {
constexpr double kDepthUnits = 16777215.0;  // 2^24 - 1, the packed path's depth scale

gl::Texture colorTexture(DepthReductionFormat f, int w, int h) {
    if (f == DepthReductionFormat::Float32) return gl::Texture::create2D(GL_RGBA32F_ARB, w, h, GL_RGBA, GL_FLOAT);
    return gl::Texture::create2D(GL_RGBA8, w, h, GL_RGBA, GL_UNSIGNED_BYTE);
}

gl::Framebuffer colorFbo(const gl::Texture& t) {
    gl::Framebuffer f = gl::Framebuffer::create();
    f.attachTexture(GL_COLOR_ATTACHMENT0, t);
    return f;
}

bool complete(const gl::Framebuffer& f) {
    f.bind();
    return glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}
}  // namespace

TileDepthBounds::TileDepthBounds(const GlInfo& info, int width, int height, int tileSize,
                                 const gl::Renderbuffer& depthStencil, bool forcePacked, bool halfZ,
                                 const RenderTargets* msaa)
    : format_(info.textureFloat && !forcePacked ? DepthReductionFormat::Float32 : DepthReductionFormat::PackedRGBA8),
      width_(width),
      height_(height),
      halfZ_(halfZ && !msaa) {
    const LightGrid shape(width, height, tileSize);  // validates the tile size
    tilesX_ = shape.tilesX();
    tilesY_ = shape.tilesY();
    createTargets(depthStencil);
    if (format_ == DepthReductionFormat::Float32 && !(complete(chains_[0].columnsFbo) && complete(chains_[0].tilesFbo))) {
        // ARB_texture_float makes float textures, not necessarily float render targets: fall back.
        format_ = DepthReductionFormat::PackedRGBA8;
        createTargets(depthStencil);
    }
    if (msaa) {
        if (format_ != DepthReductionFormat::Float32)
            throw UnsupportedError("tile depth bounds under MSAA reduce the samples' depth spans in float targets");
        spans_ = std::make_unique<DepthSpanPass>(info, *msaa, true);
    }
    prepassFbo_.checkComplete("tile pre-Z");
    for (const std::vector<Chain>* chains : {&chains_, &splitChains_})
        for (const Chain& c : *chains) {
            c.columnsFbo.checkComplete("tile depth reduction (columns)");
            c.tilesFbo.checkComplete("tile depth reduction (tiles)");
        }
    StateCache::current().bindFramebuffer(0);

    prepassProgram_ = gl::Program::create("tile-prez", buildShaderSource("geometry.vert"),
                                          buildShaderSource("depth_to_color.frag"), geometryAttributes());
    const bool packed = format_ == DepthReductionFormat::PackedRGBA8;
    for (size_t c = 0; c < chains_.size(); ++c) {
        for (int vertical = 0; vertical < 2; ++vertical) {
            ShaderDefines d;
            d.push_back({"LIDR_INPUT_PACKED", packed || !vertical ? "1" : "0"});  // the depth copy is packed
            d.push_back({"LIDR_OUTPUT_PACKED", packed ? "1" : "0"});
            d.push_back({"LIDR_REDUCE_COUNT", std::to_string(tileSize)});
            d.push_back({"LIDR_REDUCE_VERTICAL", std::to_string(vertical)});
            d.push_back({"LIDR_REDUCE_MAX", c == 1 ? "1" : "0"});
            d.push_back({"LIDR_INPUT_SPANS", spans_ && !vertical ? "1" : "0"});
            gl::Program p = gl::Program::create("tile-depth-reduce", buildShaderSource("fullscreen.vert"),
                                                buildShaderSource("tile_depth_reduce.frag", d),
                                                {{"aPosition", gl::kPosition}});
            (vertical ? vertical_ : horizontal_).push_back(std::move(p));
        }
    }
    for (size_t c = 0; c < splitChains_.size(); ++c) {
        ShaderDefines d;
        d.push_back({"LIDR_OUTPUT_PACKED", packed ? "1" : "0"});
        d.push_back({"LIDR_REDUCE_COUNT", std::to_string(tileSize)});
        d.push_back({"LIDR_SPLIT_NEAR_MAX", c == 1 ? "1" : "0"});
        splitHorizontal_.push_back(gl::Program::create("tile-depth-split", buildShaderSource("fullscreen.vert"),
                                                       buildShaderSource("tile_depth_split.frag", d),
                                                       {{"aPosition", gl::kPosition}}));
        // The vertical step is the plain reduction: min of the far mins (R), max of the near maxes (G).
        ShaderDefines v = {{"LIDR_INPUT_PACKED", packed ? "1" : "0"}, {"LIDR_OUTPUT_PACKED", packed ? "1" : "0"},
                           {"LIDR_REDUCE_COUNT", std::to_string(tileSize)}, {"LIDR_REDUCE_VERTICAL", "1"},
                           {"LIDR_REDUCE_MAX", c == 1 ? "1" : "0"}};
        splitVertical_.push_back(gl::Program::create("tile-depth-split-reduce", buildShaderSource("fullscreen.vert"),
                                                     buildShaderSource("tile_depth_reduce.frag", v),
                                                     {{"aPosition", gl::kPosition}}));
    }
    triangle_ = FullScreenTriangle::create();
    checkGl("TileDepthBounds");
}

void TileDepthBounds::createTargets(const gl::Renderbuffer& depthStencil) {
    // The full-size copy is always packed RGBA8 (4 bytes a pixel); the small reduced ones use the format.
    depthCopy_ = colorTexture(DepthReductionFormat::PackedRGBA8, width_, height_);
    prepassFbo_ = colorFbo(depthCopy_);
    prepassFbo_.attachRenderbuffer(GL_DEPTH_STENCIL_ATTACHMENT, depthStencil);
    chains_.clear();
    splitChains_.clear();
    const int chainCount = format_ == DepthReductionFormat::Float32 ? 1 : 2;
    for (int c = 0; c < chainCount; ++c) {
        chains_.push_back(makeChain());
        if (halfZ_) splitChains_.push_back(makeChain());
    }
    StateCache::current().bindFramebuffer(0);
    checkGl("TileDepthBounds targets");
}

TileDepthBounds::Chain TileDepthBounds::makeChain() const {
    Chain chain;
    chain.columns = colorTexture(format_, tilesX_, height_);
    chain.columnsFbo = colorFbo(chain.columns);
    chain.tiles = colorTexture(format_, tilesX_, tilesY_);
    chain.tilesFbo = colorFbo(chain.tiles);
    return chain;
}

size_t TileDepthBounds::bytes() const {
    const size_t texel = format_ == DepthReductionFormat::Float32 ? 16 : 4;
    return 4 * size_t(width_) * height_ +
           texel * (chains_.size() + splitChains_.size()) * (size_t(tilesX_) * height_ + size_t(tilesX_) * tilesY_);
}

void TileDepthBounds::prepass(const GpuScene& scene, const CameraMatrices& camera) const {
    StateCache& cache = StateCache::current();
    ClearAction clear;
    clear.color = clear.depth = clear.stencil = true;
    clear.colorValue = glm::vec4(1.0f);  // depth 1 (the far plane) in both formats
    cache.beginPass({prepassFbo_.id(), glm::ivec4(0, 0, width_, height_), {GL_COLOR_ATTACHMENT0}, clear});
    RenderState s;
    s.depthTest = true;
    s.depthFunc = GL_LESS;
    s.depthWrite = true;
    cache.apply(s);
    prepassProgram_.use();
    prepassProgram_.set("uViewProj", camera.viewProjection);
    scene.draw(prepassProgram_, DrawFilter::Opaque, false, &camera);
    cache.apply(RenderState{});
    checkGl("tile pre-Z");
}

void TileDepthBounds::samples(const GpuScene& scene, const CameraMatrices& camera) const {
    if (spans_) spans_->run(scene, camera, depthCopy_);
}

void TileDepthBounds::runPass(const gl::Program& program, const gl::Texture& input, const gl::Framebuffer& output,
                              int outW, int outH) const {
    StateCache::current().beginPass({output.id(), glm::ivec4(0, 0, outW, outH), {GL_COLOR_ATTACHMENT0}, {}});
    program.use();
    input.bind(gl::kUnitReductionInput);
    program.set("uInput", gl::kUnitReductionInput);
    program.set("uInputSize", glm::vec2(float(input.width()), float(input.height())));
    StateCache::current().drawArrays(GL_TRIANGLES, 0, 3);
}

std::vector<float> TileDepthBounds::readChain(const Chain& chain, int component) const {
    const size_t tiles = size_t(tilesX_) * tilesY_;
    std::vector<float> out(tiles);
    chain.tilesFbo.bind();
    readFromColorAttachment0();
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    if (format_ == DepthReductionFormat::Float32) {
        std::vector<float> texels(tiles * 4);
        glReadPixels(0, 0, tilesX_, tilesY_, GL_RGBA, GL_FLOAT, texels.data());
        for (size_t t = 0; t < tiles; ++t) out[t] = texels[t * 4 + component];
    } else {
        std::vector<uint8_t> texels(tiles * 4);
        glReadPixels(0, 0, tilesX_, tilesY_, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
        for (size_t t = 0; t < tiles; ++t) {
            const uint32_t v = (uint32_t(texels[t * 4]) << 16) | (uint32_t(texels[t * 4 + 1]) << 8) | texels[t * 4 + 2];
            out[t] = float(double(v) / kDepthUnits);
        }
    }
    return out;
}

std::vector<TileDepthRange> TileDepthBounds::reduce() const {
    StateCache::current().apply(RenderState{});
    triangle_.bind();
    for (size_t c = 0; c < chains_.size(); ++c) {
        if (spans_) {
            horizontal_[c].use();
            spans_->texture().bind(gl::kUnitTileDepthMin);  // free until half-Z, which MSAA goes without
            horizontal_[c].set("uSpans", gl::kUnitTileDepthMin);
            horizontal_[c].set("uSpanBoundScale", spans_->boundScale());
        }
        runPass(horizontal_[c], depthCopy_, chains_[c].columnsFbo, tilesX_, height_);
        runPass(vertical_[c], chains_[c].columns, chains_[c].tilesFbo, tilesX_, tilesY_);
    }
    for (size_t c = 0; c < splitChains_.size(); ++c) {  // half-Z: needs the min/max tiles just reduced
        const gl::Program& p = splitHorizontal_[c];
        p.use();
        chains_[0].tiles.bind(gl::kUnitTileDepthMin);
        p.set("uTileMin", gl::kUnitTileDepthMin);
        if (chains_.size() > 1) {
            chains_[1].tiles.bind(gl::kUnitTileDepthMax);
            p.set("uTileMax", gl::kUnitTileDepthMax);
        }
        p.set("uTileGridSize", glm::vec2(float(tilesX_), float(tilesY_)));
        runPass(p, depthCopy_, splitChains_[c].columnsFbo, tilesX_, height_);
        runPass(splitVertical_[c], splitChains_[c].columns, splitChains_[c].tilesFbo, tilesX_, tilesY_);
    }
    triangle_.unbind();
    StateCache::current().unbindTextures({gl::kUnitTileDepthMax, gl::kUnitTileDepthMin, gl::kUnitReductionInput});

    // Read back with GL's bottom-up rows: tile (x, y) lands at y * tilesX + x, as LightGrid counts tiles.
    const bool packed = format_ == DepthReductionFormat::PackedRGBA8;
    const std::vector<float> mins = readChain(chains_[0], 0);
    const std::vector<float> maxs = readChain(chains_[packed ? 1 : 0], packed ? 0 : 1);
    std::vector<TileDepthRange> out(mins.size());
    for (size_t t = 0; t < out.size(); ++t) out[t].minDepth = mins[t], out[t].maxDepth = maxs[t];
    if (halfZ_) {
        const std::vector<float> farMins = readChain(splitChains_[0], 0);
        const std::vector<float> nearMaxs = readChain(splitChains_[packed ? 1 : 0], packed ? 0 : 1);
        for (size_t t = 0; t < out.size(); ++t) {
            out[t].split = true;
            out[t].farMinDepth = farMins[t];
            out[t].nearMaxDepth = nearMaxs[t];
        }
    }
    StateCache::current().bindFramebuffer(0);
    checkGl("tile depth reduction");
    return out;
}

}  // namespace lidr
