// lidr inside a program's own GL context (doc/embedding.md): the caller's GL state survives render() in every
// mode and FramePresenter::present(); currentContextGlInfo() reads the current context; presenting copies the
// frame into the caller's FBO pixel for pixel; a material shader of the program's own reads the light lists
// (lidr_lights.glsl) and gets exactly the lists the packing scheme's CPU model decodes from the index targets.
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include "gl_test_context.h"
#include "lidr/base/gl.h"
#include "lidr/base/error.h"
#include "lidr/gl/bindings.h"
#include "lidr/gl/gl_state.h"
#include "lidr/lidr.h"
#include "lidr/modes/auto_mode_renderer.h"
#include "lidr/eval/light_coverage.h"
#include "render_helpers.h"

using namespace lidr;
using namespace lidr::test;

namespace {

// Every piece of GL state a renderer could touch that the caller may care about, read straight from GL
// (independently of SavedGlState), as named lists of numbers.
using StateList = std::vector<std::pair<std::string, std::vector<double>>>;

StateList readGlState() {
    StateList s;
    auto ints = [&](const std::string& name, GLenum e, int n = 1) {
        GLint v[16] = {};
        glGetIntegerv(e, v);
        s.push_back({name, std::vector<double>(v, v + n)});
    };
    auto floats = [&](const std::string& name, GLenum e, int n = 1) {
        GLfloat v[16] = {};
        glGetFloatv(e, v);
        s.push_back({name, std::vector<double>(v, v + n)});
    };
    auto enabled = [&](const std::string& name, GLenum e) { s.push_back({name, {double(glIsEnabled(e))}}); };
    if (testGl().major >= 3) ints("vertex array", GL_VERTEX_ARRAY_BINDING);
    ints("program", GL_CURRENT_PROGRAM);
    ints("active texture", GL_ACTIVE_TEXTURE);
    GLint active = 0, units = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &units);
    for (int i = 0; i < std::min(units, SavedGlState::kMaxTextureUnits); ++i) {
        glActiveTexture(GL_TEXTURE0 + i);
        ints("texture 2D unit " + std::to_string(i), GL_TEXTURE_BINDING_2D);
        ints("cube map unit " + std::to_string(i), GL_TEXTURE_BINDING_CUBE_MAP);  // the environment light's
    }
    glActiveTexture(active);
    for (GLenum e : {GL_PACK_ALIGNMENT, GL_UNPACK_ALIGNMENT, GL_PACK_ROW_LENGTH, GL_UNPACK_ROW_LENGTH, GL_PACK_SKIP_ROWS,
                     GL_PACK_SKIP_PIXELS, GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS})
        ints("pixel store " + std::to_string(e), e);
    ints("viewport", GL_VIEWPORT, 4);
    ints("scissor box", GL_SCISSOR_BOX, 4);
    enabled("blend", GL_BLEND);
    enabled("depth test", GL_DEPTH_TEST);
    enabled("stencil test", GL_STENCIL_TEST);
    enabled("cull face", GL_CULL_FACE);
    enabled("scissor test", GL_SCISSOR_TEST);
    enabled("polygon offset fill", GL_POLYGON_OFFSET_FILL);
    enabled("color logic op", GL_COLOR_LOGIC_OP);
    enabled("sample alpha to coverage", GL_SAMPLE_ALPHA_TO_COVERAGE);
    ints("polygon mode", GL_POLYGON_MODE, 2);
    if (testGl().depthClamp) enabled("depth clamp", GL_DEPTH_CLAMP);
    ints("depth func", GL_DEPTH_FUNC);
    ints("depth mask", GL_DEPTH_WRITEMASK);
    floats("depth clear", GL_DEPTH_CLEAR_VALUE);
    for (GLenum e : {GL_STENCIL_FUNC, GL_STENCIL_REF, GL_STENCIL_VALUE_MASK, GL_STENCIL_FAIL, GL_STENCIL_PASS_DEPTH_FAIL,
                     GL_STENCIL_PASS_DEPTH_PASS, GL_STENCIL_WRITEMASK, GL_STENCIL_BACK_FUNC, GL_STENCIL_BACK_REF,
                     GL_STENCIL_BACK_VALUE_MASK, GL_STENCIL_BACK_FAIL, GL_STENCIL_BACK_PASS_DEPTH_FAIL,
                     GL_STENCIL_BACK_PASS_DEPTH_PASS, GL_STENCIL_BACK_WRITEMASK, GL_STENCIL_CLEAR_VALUE})
        ints("stencil " + std::to_string(e), e);
    for (GLenum e : {GL_BLEND_EQUATION_RGB, GL_BLEND_EQUATION_ALPHA, GL_BLEND_SRC_RGB, GL_BLEND_DST_RGB,
                     GL_BLEND_SRC_ALPHA, GL_BLEND_DST_ALPHA})
        ints("blend " + std::to_string(e), e);
    floats("blend color", GL_BLEND_COLOR, 4);
    floats("clear color", GL_COLOR_CLEAR_VALUE, 4);
    ints("color mask", GL_COLOR_WRITEMASK, 4);
    ints("cull face mode", GL_CULL_FACE_MODE);
    ints("front face", GL_FRONT_FACE);
    ints("draw framebuffer", GL_FRAMEBUFFER_BINDING);
    if (testGl().major >= 3) ints("read framebuffer", GL_READ_FRAMEBUFFER_BINDING);
    ints("renderbuffer", GL_RENDERBUFFER_BINDING);
    ints("draw buffer", GL_DRAW_BUFFER);
    ints("read buffer", GL_READ_BUFFER);
    ints("array buffer", GL_ARRAY_BUFFER_BINDING);
    ints("element array buffer", GL_ELEMENT_ARRAY_BUFFER_BINDING);
    if (!testGl().gles) {  // pixel buffers: GL 2.1 core, not in ES 2.0
        ints("pixel pack buffer", GL_PIXEL_PACK_BUFFER_BINDING);
        ints("pixel unpack buffer", GL_PIXEL_UNPACK_BUFFER_BINDING);
    }
    for (GLuint a = 0; a < 8; ++a) {
        for (GLenum e : {GL_VERTEX_ATTRIB_ARRAY_ENABLED, GL_VERTEX_ATTRIB_ARRAY_SIZE, GL_VERTEX_ATTRIB_ARRAY_TYPE,
                         GL_VERTEX_ATTRIB_ARRAY_STRIDE, GL_VERTEX_ATTRIB_ARRAY_NORMALIZED,
                         GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING}) {
            GLint v = 0;
            glGetVertexAttribiv(a, e, &v);
            s.push_back({"attribute " + std::to_string(a) + " " + std::to_string(e), {double(v)}});
        }
        void* p = nullptr;
        glGetVertexAttribPointerv(a, GL_VERTEX_ATTRIB_ARRAY_POINTER, &p);
        s.push_back({"attribute " + std::to_string(a) + " pointer", {double(reinterpret_cast<uintptr_t>(p))}});
    }
    REQUIRE(glGetError() == GL_NO_ERROR);
    return s;
}

// The program's own GL objects and a state far from every default, as an application would leave it
// before handing the frame to lidr (and expect back after).
struct CallerState {
    gl::Texture textures[2], target, cube;
    gl::Framebuffer fbo;
    gl::Renderbuffer renderbuffer;
    gl::Buffer vertices, elements;
    gl::Program program;
    GLuint vao = 0;

    CallerState() {
        for (auto& t : textures) t = gl::Texture::create2D(GL_RGBA8, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE);
        const uint8_t texel[4] = {};
        cube = gl::Texture::createCube(GL_RGBA8, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, [&](int, int) { return texel; }, 0.0f);
        target = gl::Texture::create2D(GL_RGBA8, 32, 32, GL_RGBA, GL_UNSIGNED_BYTE);
        fbo = gl::Framebuffer::create();
        fbo.bind();
        fbo.attachTexture(GL_COLOR_ATTACHMENT0, target);
        renderbuffer = gl::Renderbuffer::create(GL_DEPTH24_STENCIL8, 8, 8);
        const float data[16] = {};
        vertices = gl::Buffer::create(GL_ARRAY_BUFFER, data, sizeof data);
        const unsigned short indices[3] = {0, 1, 2};
        elements = gl::Buffer::create(GL_ELEMENT_ARRAY_BUFFER, indices, sizeof indices);
        program = gl::Program::create("caller", "#version 120\nattribute vec4 p;\nvoid main() { gl_Position = p; }\n",
                                      "#version 120\nvoid main() { gl_FragColor = vec4(1.0); }\n", {{"p", 0}});
        // The caller's attributes in a VAO of its own where there are VAOs (the GL 2.1 run: in the default one).
        if (testGl().major >= 3) {
            glGenVertexArrays(1, &vao);
            glBindVertexArray(vao);
        }
        set();
    }
    ~CallerState() {  // back to GL's defaults for the tests that follow
        for (GLuint a : {0u, 2u}) glDisableVertexAttribArray(a);
        if (vao) {
            glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
            glBindVertexArray(0);
            glDeleteVertexArrays(1, &vao);
        }
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
        if (!testGl().gles) {
            glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
            glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        }
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        glUseProgram(0);
        GLint units = 0;
        glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &units);
        for (int i = 0; i < std::min(units, SavedGlState::kMaxTextureUnits); ++i) {
            glActiveTexture(GL_TEXTURE0 + i);
            glBindTexture(GL_TEXTURE_2D, 0);
            glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
        }
        glActiveTexture(GL_TEXTURE0);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glPixelStorei(GL_PACK_ROW_LENGTH, 0);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
        glPixelStorei(GL_PACK_SKIP_ROWS, 0);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
        glDisable(GL_COLOR_LOGIC_OP);
        glLogicOp(GL_COPY);
        glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        applyRenderState(RenderState{});
        glDisable(GL_POLYGON_OFFSET_FILL);
        glDisable(GL_SCISSOR_TEST);
        glStencilMask(0xFF);
        glStencilFunc(GL_ALWAYS, 0, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ZERO);
        glBlendColor(0.0f, 0.0f, 0.0f, 0.0f);
        glClearDepth(1.0);
        glClearStencil(0);
        glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
        glCullFace(GL_BACK);
        glFrontFace(GL_CCW);
        glDepthFunc(GL_LESS);
    }
    void set() const {
        program.use();
        GLint units = 0;
        glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &units);
        for (int i = 0; i < std::min(units, SavedGlState::kMaxTextureUnits); ++i) {
            textures[i % 2].bind(i);
            cube.bind(i);
        }
        glActiveTexture(GL_TEXTURE5);
        glPixelStorei(GL_PACK_ALIGNMENT, 2);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
        glPixelStorei(GL_PACK_ROW_LENGTH, 7);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, 9);
        glPixelStorei(GL_PACK_SKIP_ROWS, 1);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
        glEnable(GL_COLOR_LOGIC_OP);
        glLogicOp(GL_XOR);
        glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
        glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
        glViewport(3, 5, 17, 19);
        glScissor(1, 2, 30, 28);
        glEnable(GL_SCISSOR_TEST);
        glEnable(GL_BLEND);
        glBlendEquationSeparate(GL_FUNC_SUBTRACT, GL_MAX);
        glBlendFuncSeparate(GL_SRC_COLOR, GL_DST_ALPHA, GL_ONE_MINUS_DST_COLOR, GL_CONSTANT_ALPHA);
        glBlendColor(0.1f, 0.2f, 0.3f, 0.4f);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_GEQUAL);
        glDepthMask(GL_FALSE);
        glClearDepth(0.25);
        glEnable(GL_STENCIL_TEST);
        glStencilFuncSeparate(GL_FRONT, GL_LESS, 3, 0x0F);
        glStencilFuncSeparate(GL_BACK, GL_GREATER, 5, 0xF0);
        glStencilOpSeparate(GL_FRONT, GL_INCR, GL_DECR, GL_INVERT);
        glStencilOpSeparate(GL_BACK, GL_REPLACE, GL_ZERO, GL_INCR_WRAP);
        glStencilMaskSeparate(GL_FRONT, 0x3C);
        glStencilMaskSeparate(GL_BACK, 0xC3);
        glClearStencil(7);
        glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
        glClearColor(0.5f, 0.25f, 0.75f, 0.125f);
        glEnable(GL_CULL_FACE);
        glCullFace(GL_FRONT);
        glFrontFace(GL_CW);
        glEnable(GL_POLYGON_OFFSET_FILL);
        fbo.bind();
        glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer.id());
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, elements.id());
        glBindBuffer(GL_ARRAY_BUFFER, vertices.id());
        glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 8, reinterpret_cast<void*>(8));
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, 4, nullptr);
        glEnableVertexAttribArray(2);
        glBindBuffer(GL_ARRAY_BUFFER, elements.id());  // a different buffer bound than the attributes use
        // Pixel buffers the program reads back into and uploads from: lidr's read-backs and light-table uploads
        // would go to and come from them (a GL error, or the wrong light table).
        glBindBuffer(GL_PIXEL_PACK_BUFFER, vertices.id());
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, elements.id());
        REQUIRE(glGetError() == GL_NO_ERROR);
    }
};

void requireSameState(const StateList& before, const StateList& after) {
    REQUIRE(before.size() == after.size());
    for (size_t i = 0; i < before.size(); ++i) {
        INFO(before[i].first);
        CHECK(before[i].second == after[i].second);
    }
}

Scene litFloorScene() {
    Scene scene = floorScene();
    for (int i = 0; i < 12; ++i) {
        const float x = -9.0f + 1.6f * float(i), z = (i % 3 - 1) * 3.0f;
        scene.lights.push_back(light({x, 0.6f, z}, 2.5f + 0.5f * float(i % 4),
                                     {0.4f + 0.05f * float(i % 5), 0.6f, 0.9f - 0.05f * float(i % 7)}));
    }
    return scene;
}

// The lit floor with its lights and shading at time 0: the frame most tests here render.
struct LitFloorFrame {
    Scene scene;
    std::vector<PointLight> lights;
    ShadingParameters shading;
};

LitFloorFrame litFloorFrame() {
    Scene scene = litFloorScene();
    std::vector<PointLight> lights = scene.lightsAt(0.0f);
    const ShadingParameters shading{scene.ambient, scene.backgroundColor};
    return {std::move(scene), std::move(lights), shading};
}

// A renderer of `mode` built as a program embedding lidr builds it: with no GL error pending (the test's own GL
// calls left none), and around the constructor, which may bind what it creates, the program's GL state kept.
std::unique_ptr<Renderer> buildKeepingState(const std::string& mode, const Scene& scene) {
    REQUIRE(glGetError() == GL_NO_ERROR);
    RenderModeOptions options;
    options.mode = mode;
    const SavedGlState keep;
    return createRenderer(options, testGl(), scene, scene.width, scene.height);
}

}  // namespace

TEST_CASE("currentContextGlInfo reads the context current on this thread", "[embed][every-gl]") {
    testContext();
    const GlInfo info = currentContextGlInfo("caller");
    CHECK(info.backend == "caller");
    CHECK(info.version == testGl().version);
    CHECK(info.renderer == testGl().renderer);
    CHECK(info.framebufferObject == testGl().framebufferObject);
    CHECK(info.textureFloat == testGl().textureFloat);
    CHECK(info.maxSamples == testGl().maxSamples);
    CHECK(info.maxVertexUniformVectors == testGl().maxVertexUniformVectors);
}

// [desktop-state]: the caller's state set here is desktop GL's (glClearDepth, polygon mode, logic op...).
TEST_CASE("every mode's render() and present() leave the caller's GL state as found", "[embed][desktop-state][every-gl]") {
    testContext();
    const auto [scene, lights, floorShading] = litFloorFrame();
    ShadingParameters shading = floorShading;
    shading.environment.map = defaultEnvironment();  // its cube and table bound on units 17 and 18 (or 6 and 7)
    for (const std::string& mode : renderModeNames()) {
        INFO("mode " << mode);
        const std::unique_ptr<Renderer> renderer = buildKeepingState(mode, scene);
        FramePresenter presenter;
        const CallerState caller;
        const StateList before = readGlState();
        renderer->render(scene.camera, lights, shading);
        requireSameState(before, readGlState());
        presenter.present(renderer->targets(), caller.fbo.id(), 2, 3, 20, 21);
        requireSameState(before, readGlState());
        renderer->render(scene.camera, lights, shading);  // a second frame starts from the caller's state too
        requireSameState(before, readGlState());
    }
    CHECK(glGetError() == GL_NO_ERROR);
}

// The web page's sequence (doc/web.md, "Fixed: GL_INVALID_OPERATION after the depth read-back"): the program
// draws with a buffer of its own outside render() and leaves an attribute disabled but naming it at an offset;
// a frame saves and restores that; the program deletes the buffer (GL unbinds it from the attribute, the offset
// stays); the first frame of a renderer built afterwards must leave no GL error and the attribute as the
// program left it: no buffer, disabled, and, these contexts having client-side arrays, the offset as it was.
// (WebGL has none and refused that offset back; SavedGlState puts it back as 0 there, which web.chromium checks.)
TEST_CASE("a frame after the caller deleted the buffer its attribute named: no GL error, the attribute as left",
          "[embed][every-gl]") {
    testContext();
    const auto [scene, lights, shading] = litFloorFrame();
    const std::string mode = GENERATE(as<std::string>(), "lidr", "forward-multipass", "forward-brute");
    if (!takeRow(mode == "lidr")) return;
    DYNAMIC_SECTION(mode) {
        auto attribute = [](GLenum what) {
            GLint v = -1;
            glGetVertexAttribiv(gl::kNormal, what, &v);
            return v;
        };
        auto offset = [] {
            void* p = nullptr;
            glGetVertexAttribPointerv(gl::kNormal, GL_VERTEX_ATTRIB_ARRAY_POINTER, &p);
            return reinterpret_cast<uintptr_t>(p);
        };
        std::unique_ptr<Renderer> first = buildKeepingState(mode, scene);
        {
            const float data[16] = {};
            const gl::Buffer own = gl::Buffer::create(GL_ARRAY_BUFFER, data, sizeof data);
            glBindBuffer(GL_ARRAY_BUFFER, own.id());
            glVertexAttribPointer(gl::kNormal, 3, GL_FLOAT, GL_FALSE, 32, reinterpret_cast<const void*>(12));
            glBindBuffer(GL_ARRAY_BUFFER, 0);
            first->render(scene.camera, lights, shading);
            REQUIRE(attribute(GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING) == GLint(own.id()));
        }  // the buffer is deleted here, the renderer and its scene after it (the page's scene change)
        first.reset();
        REQUIRE(attribute(GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING) == 0);
        REQUIRE(offset() == 12);
        const std::unique_ptr<Renderer> second = buildKeepingState(mode, scene);
        for (int frame = 0; frame < 2; ++frame) {
            INFO("frame " << frame << " of the renderer built after the deletion");
            second->render(scene.camera, lights, shading);
            CHECK(glGetError() == GL_NO_ERROR);
            CHECK(attribute(GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING) == 0);
            CHECK(attribute(GL_VERTEX_ATTRIB_ARRAY_ENABLED) == 0);
            CHECK(offset() == 12);
        }
        glVertexAttribPointer(gl::kNormal, 4, GL_FLOAT, GL_FALSE, 0, nullptr);  // GL's default for the next tests
    }
}

TEST_CASE("a frame after the caller deleted its current program: no GL error, no program current after",
          "[embed][every-gl]") {
    // GL keeps a program deleted while current until another replaces it; render() replaces it, so giving it
    // back would be GL_INVALID_VALUE (found when a shadow atlas was destroyed with its program current).
    testContext();
    const auto [scene, lights, shading] = litFloorFrame();
    const std::string mode = GENERATE(as<std::string>(), "lidr", "forward-multipass", "forward-brute");
    if (!takeRow(mode == "lidr")) return;
    DYNAMIC_SECTION(mode) {
        const std::unique_ptr<Renderer> renderer = buildKeepingState(mode, scene);
        {
            const gl::Program own = gl::Program::create(
                "caller", "#version 120\nattribute vec4 p;\nvoid main() { gl_Position = p; }\n",
                "#version 120\nvoid main() { gl_FragColor = vec4(1.0); }\n", {{"p", 0}});
            own.use();
        }  // deleted while current
        for (int frame = 0; frame < 2; ++frame) {
            INFO("frame " << frame);
            renderer->render(scene.camera, lights, shading);
            CHECK(glGetError() == GL_NO_ERROR);
            GLint current = -1;
            glGetIntegerv(GL_CURRENT_PROGRAM, &current);
            CHECK(current == 0);
        }
    }
}

TEST_CASE("FramePresenter copies the frame into the caller's framebuffer pixel for pixel", "[embed][every-gl]") {
    testContext();
    const Scene scene = litFloorScene();
    LidrRenderer renderer(testGl(), scene, LidrOptions{}, scene.width, scene.height);
    renderer.render(scene.camera, scene.lightsAt(0.0f), {scene.ambient, scene.backgroundColor});
    const ImageRGBA8 frame = renderer.targets().readColor();
    const int w = scene.width, h = scene.height;
    gl::Texture color = gl::Texture::create2D(GL_RGBA8, w + 10, h + 6, GL_RGBA, GL_UNSIGNED_BYTE);
    gl::Framebuffer fbo = gl::Framebuffer::create();
    fbo.bind();
    fbo.attachTexture(GL_COLOR_ATTACHMENT0, color);
    fbo.checkComplete("caller FBO");
    glViewport(0, 0, w + 10, h + 6);
    glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    FramePresenter presenter;
    presenter.present(renderer.targets(), fbo.id(), 7, 2, w, h);
    fbo.bind();
    const ImageRGBA8 all = readPixelsRGBA8(w + 10, h + 6);  // top to bottom, like readColor
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    long differing = 0, outside = 0;
    for (int y = 0; y < h + 6; ++y)
        for (int x = 0; x < w + 10; ++x) {
            const uint8_t* p = &all.pixels[(size_t(y) * (w + 10) + x) * 4];
            const int fx = x - 7, fyBottom = (h + 6 - 1 - y) - 2;  // frame pixel, rows counted from the bottom
            if (fx < 0 || fx >= w || fyBottom < 0 || fyBottom >= h) {
                outside += !(p[0] == 0 && p[1] == 0 && p[2] == 255 && p[3] == 255);
                continue;
            }
            const uint8_t* q = &frame.pixels[(size_t(h - 1 - fyBottom) * w + fx) * 4];
            differing += !(p[0] == q[0] && p[1] == q[1] && p[2] == q[2] && p[3] == q[3]);
        }
    CHECK(differing == 0);
    CHECK(outside == 0);
    CHECK_THROWS_WITH(presenter.present(renderer.targets(), fbo.id(), 0, 0, 0, 4), Catch::Contains("empty"));
}

TEST_CASE("a material shader of the program's own iterates exactly the lights the index lists hold", "[embed][every-gl]") {
    testContext();
    const Scene scene = litFloorScene();
    const std::vector<PointLight> lights = scene.lightsAt(0.0f);
    // Red: how many lights this pixel's list holds; green: the first light's index.
    const std::string countShader = R"(#version 120
#include "lidr_lights.glsl"
void main() {
    float count = 0.0, first = 0.0;
    LidrLight light;
    lidrBeginLights();
    for (int i = 0; i < LIDR_MAX_LIGHTS; ++i) {
        if (!lidrNextLight(light)) break;
        if (count < 0.5) first = light.index;
        count += 1.0;
    }
    gl_FragColor = vec4(count / 255.0, first / 255.0, 0.0, 1.0);
}
)";
    const PackingSchemeKind scheme = GENERATE(from_range(packingSchemes()));
    DYNAMIC_SECTION(packingSchemeName(scheme)) {
        LidrOptions o;
        o.packing = {scheme, 4, 8};
        o.materialShader = countShader;
        LidrRenderer renderer(testGl(), scene, o, scene.width, scene.height);
        renderer.render(scene.camera, lights, {scene.ambient, scene.backgroundColor});
        const ImageRGBA8 image = renderer.targets().readColor();
        const std::vector<ImageRGBA8> targets = renderer.readIndexTargets();
        const int n = renderer.scheme().targetCount();
        std::vector<uint8_t> texels(size_t(n) * 4);
        long mismatches = 0, lit = 0;
        for (size_t p = 0; p < size_t(scene.width) * scene.height; ++p) {
            for (int t = 0; t < n; ++t) std::copy_n(&targets[size_t(t)].pixels[p * 4], 4, &texels[size_t(t) * 4]);
            int count = 0, first = 0;
            for (uint32_t index : renderer.scheme().decodePixel(texels.data())) {
                if (index == 0) continue;
                if (count == 0) first = int(index);
                ++count;
            }
            lit += count > 0;
            mismatches += !(image.pixels[p * 4] == count && image.pixels[p * 4 + 1] == first);
        }
        CHECK(mismatches == 0);
        CHECK(lit > scene.width * scene.height / 10);  // the lights reach a good part of the floor
    }
}

TEST_CASE("a toon material through lidr_lights.glsl matches the CPU on the lit floor", "[embed][every-gl]") {
    testContext();
    // One light straight above a flat floor: every floor pixel's light count and toon band follow from its
    // distance to the light alone, which the CPU computes from the depth buffer.
    Scene scene = floorScene();
    scene.lights.push_back(light({1.0f, 0.5f, 3.0f}, 4.0f, glm::vec3(1.0f)));
    const std::string toon = toonMaterialShader(100);
    LidrOptions o;
    o.materialShader = toon;
    LidrRenderer renderer(testGl(), scene, o, scene.width, scene.height);
    const std::vector<PointLight> lights = scene.lightsAt(0.0f);
    renderer.render(scene.camera, lights, {scene.ambient, scene.backgroundColor});
    const ImageRGBA8 image = renderer.targets().readColor();
    const ImageFloat depth = renderer.targets().readDepth();
    const CameraMatrices cam = cameraMatrices(scene.camera, scene.width, scene.height);
    long checked = 0, wrong = 0;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
            const size_t p = size_t(y) * scene.width + x;
            const float z = depth.pixels[p];
            if (z >= 1.0f) continue;
            const glm::vec3 surface = unprojectPixel(cam, x, y, z);
            const glm::vec3 d = lights[0].position - surface;
            const float a = 1.0f - glm::dot(d, d) / (lights[0].radius * lights[0].radius);
            if (std::abs(a) < 0.02f || std::abs(a - 0.5f) < 0.02f) continue;  // depth precision at a band edge
            const int band = a > 0.5f ? 2 : (a > 0.0f ? 1 : 0);
            ++checked;
            wrong += image.pixels[p * 4] != band * 100;
        }
    CHECK(wrong == 0);
    CHECK(checked > scene.width * scene.height / 4);
}

TEST_CASE("a material shader that does not compile is an error naming it", "[embed][bad-input][every-gl]") {
    testContext();
    const Scene scene = litFloorScene();
    LidrOptions o;
    o.materialShader = "#version 120\n#include \"lidr_lights.glsl\"\nvoid main() { gl_FragColor = vec4(oops); }\n";
    CHECK_THROWS_WITH(LidrRenderer(testGl(), scene, o, scene.width, scene.height),
                      Catch::Contains("material shader") && Catch::Contains("oops"));
    o.materialShader = "#version 120\n#include \"no_such_file.glsl\"\nvoid main() {}\n";
    CHECK_THROWS_WITH(LidrRenderer(testGl(), scene, o, scene.width, scene.height), Catch::Contains("no_such_file.glsl"));
}

TEST_CASE("timing is off by default: no timer queries, no pass times, in every mode", "[embed][timing][modes][every-gl]") {
    testContext();
    const Scene scene = litFloorScene();
    const std::vector<PointLight> lights = scene.lightsAt(0.0f);
    for (const std::string& mode : renderModeNames()) {
        if (!takeRow(mode != "auto")) continue;  // auto's trial frames are its candidates' frames
        INFO("mode " << mode);
        RenderModeOptions options;
        options.mode = mode;
        options.timingMethod = testGl().timerQuery ? TimingMethod::GpuQueries : TimingMethod::Auto;
        std::unique_ptr<Renderer> renderer = createRenderer(options, testGl(), scene, scene.width, scene.height);
        renderer->render(scene.camera, lights, {scene.ambient, scene.backgroundColor});
        // The auto mode's candidates each draw their first frames while it measures: past that, as the others.
        auto* autoMode = dynamic_cast<AutoModeRenderer*>(renderer.get());
        while (autoMode && autoMode->measuring())
            renderer->render(scene.camera, lights, {scene.ambient, scene.backgroundColor});
        // LIDR's second frame may give up tiles its first measured as not worth their read-back and draw the
        // volume meshes, whose program is compiled on first use (doc/architecture.md, "Tiles only where they pay").
        renderer->render(scene.camera, lights, {scene.ambient, scene.backgroundColor});
        const int objects = gl::liveGlObjects();
        for (int frame = 0; frame < 3; ++frame) {
            const FrameStats& stats = renderer->render(scene.camera, lights, {scene.ambient, scene.backgroundColor});
            CHECK(stats.passes.empty());
        }
        CHECK(gl::liveGlObjects() == objects);  // nothing created per frame, no query objects
    }
}

TEST_CASE("GPU pass times arrive a frame or more later without waiting, from a ring of queries", "[embed][timing][every-gl]") {
    testContext();
    if (!testGl().timerQuery) {
        WARN("no timer queries in this context: skipped");
        return;
    }
    const auto [scene, lights, shading] = litFloorFrame();
    LidrOptions o;
    o.timingMethod = TimingMethod::GpuQueries;
    // The passes a frame has, from a renderer that waits for its own frame's results.
    LidrRenderer waiting(testGl(), scene, o, scene.width, scene.height);
    waiting.setTiming(true, true);
    // The depth read-back ("volume-tiles") runs only in frames that cull by tiles, which a frame gives up where the
    // last tile frame saved too little (doc/architecture.md, "Tiles only where they pay"): left out of the lists.
    auto passNames = [](const FrameStats& stats) {
        std::vector<std::string> names;
        for (const PassTime& p : stats.passes)
            if (p.pass != "volume-tiles") names.push_back(p.pass);
        return names;
    };
    const std::vector<std::string> names = passNames(waiting.render(scene.camera, lights, shading));
    CHECK(waiting.lastFrame().timingLag == 0);
    REQUIRE(names.size() >= 3);

    LidrRenderer renderer(testGl(), scene, o, scene.width, scene.height);
    renderer.setTiming(true);
    int objects = 0, firstWithTimes = -1;
    for (int frame = 0; frame < 8; ++frame) {
        const FrameStats& stats = renderer.render(scene.camera, lights, shading);
        if (frame == 0) objects = gl::liveGlObjects();  // the renderer's own, and the first frame's queries
        glFinish();  // the GPU is done with this frame: its queries answer by the next collect
        if (stats.passes.empty()) continue;
        if (firstWithTimes < 0) firstWithTimes = frame;
        CHECK(stats.timingLag >= 1);
        for (const PassTime& p : stats.passes) CHECK(p.milliseconds >= 0.0);
        CHECK(passNames(stats) == names);
    }
    CHECK(firstWithTimes >= 1);  // never the frame itself: no stall on its queries
    CHECK(firstWithTimes <= 2);
    // One set of queries per ring slot at most: the other slots' sets.
    CHECK(gl::liveGlObjects() - objects <= (FrameTimer::kRingFrames - 1) * static_cast<int>(names.size() + 1));  // + volume-tiles
}

TEST_CASE("a timed pass that throws is ended by its scope: the timer goes on with the next pass", "[embed][timing][every-gl]") {
    testContext();
    FrameTimer timer(testGl(), TimingMethod::CpuFinish);
    auto failingPass = [&] {
        TimedPass time(timer, "failing");
        throw Error("the pass failed");
    };
    REQUIRE_THROWS_AS(failingPass(), Error);
    CHECK_FALSE(timer.passOpen());
    {
        TimedPass time(timer, "ended-early");
        time.end();  // ended once: the scope's end does nothing more
        CHECK_FALSE(timer.passOpen());
    }
    { TimedPass time(timer, "next"); }
    std::vector<std::string> names;
    for (const PassTime& p : timer.collect()) names.push_back(p.pass);
    CHECK(names == std::vector<std::string>{"failing", "ended-early", "next"});
}

TEST_CASE("a measuring frame counts each pass's draws, state calls and fragments", "[embed][timing][every-gl]") {
    testContext();
    const auto [scene, lights, shading] = litFloorFrame();
    LidrRenderer renderer(testGl(), scene, LidrOptions{}, scene.width, scene.height);

    // An application's frames (timing without waiting) never count fragments.
    renderer.setTiming(true, false);
    for (int frame = 0; frame < 3; ++frame)
        for (const PassTime& p : renderer.render(scene.camera, lights, shading).passes) CHECK(p.fragments == -1);

    renderer.setTiming(true, true);
    const FrameStats& stats = renderer.render(scene.camera, lights, shading);
    REQUIRE_FALSE(stats.passes.empty());
    long draws = 0, stateCalls = 0;
    const PassTime *prepass = nullptr, *volumes = nullptr, *forward = nullptr;
    for (const PassTime& p : stats.passes) {
        INFO("pass " << p.pass);
        CHECK(p.drawCalls >= 0);
        CHECK(p.stateCalls >= 0);
        CHECK((p.fragments >= 0) == testGl().pipelineStatistics);
        draws += p.drawCalls;
        stateCalls += p.stateCalls;
        if (p.pass == "depth-prepass") prepass = &p;
        if (p.pass == "light-volumes") volumes = &p;
        if (p.pass == "forward") forward = &p;
    }
    CHECK(draws <= stats.glCalls.drawCalls);
    CHECK(stateCalls <= stats.glCalls.stateCalls);
    REQUIRE(prepass);
    REQUIRE(volumes);
    REQUIRE(forward);
    CHECK(prepass->drawCalls >= 1);
    CHECK(volumes->drawCalls >= stats.volumeDrawCalls);  // the volumes, and the overlap probe's triangles
    CHECK(stats.volumeDrawCalls >= 1);
    if (!testGl().pipelineStatistics) {
        WARN("no ARB_pipeline_statistics_query: fragments not counted");
        return;
    }
    // The pre-pass and the forward pass draw the same opaque meshes (the forward pass with depth EQUAL): at least
    // every covered pixel each, never more in the forward pass; the light table is an upload, no fragment.
    const ImageFloat depth = renderer.targets().readDepth();
    long covered = 0;
    for (float d : depth.pixels) covered += d < 1.0f ? 1 : 0;
    REQUIRE(covered > 0);
    CHECK(prepass->fragments >= covered);
    CHECK(forward->fragments >= covered);
    CHECK(forward->fragments <= prepass->fragments);
    CHECK(volumes->fragments > 0);
    for (const PassTime& p : stats.passes)
        if (p.pass == "light-table") CHECK(p.fragments == 0);
}

// Implementations may shade more than the covered pixels along triangle edges (llvmpipe counts 2,304 for a 64x32
// viewport-filling triangle), never fewer; a pass without draws shades nothing.
TEST_CASE("a pass's fragment count is its fragment shader invocations, within bounds for known draws", "[embed][timing][every-gl]") {
    testContext();
    if (!testGl().pipelineStatistics) {
        WARN("no ARB_pipeline_statistics_query: fragments not counted");
        return;
    }
    const int width = 64, height = 32;
    gl::Texture color = gl::Texture::create2D(GL_RGBA8, width, height, GL_RGBA, GL_UNSIGNED_BYTE);
    gl::Framebuffer fbo = gl::Framebuffer::create();
    fbo.bind();
    fbo.attachTexture(GL_COLOR_ATTACHMENT0, color);
    const float triangle[6] = {-1.0f, -1.0f, 3.0f, -1.0f, -1.0f, 3.0f};  // covers the viewport
    gl::Buffer vertices = gl::Buffer::create(GL_ARRAY_BUFFER, triangle, sizeof triangle);
    gl::Program program =
        gl::Program::create("fill", "#version 120\nattribute vec2 p;\nvoid main() { gl_Position = vec4(p, 0.0, 1.0); }\n",
                            "#version 120\nvoid main() { gl_FragColor = vec4(1.0); }\n", {{"p", 0}});
    StateCache& cache = StateCache::current();
    cache.invalidate();
    cache.apply(RenderState{});
    program.use();
    glBindBuffer(GL_ARRAY_BUFFER, vertices.id());
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);

    FrameTimer timer(testGl(), TimingMethod::CpuFinish);
    timer.setWaitForResults(true);
    {
        TimedPass pass(timer, "full");
        cache.setViewport({0, 0, width, height});
        cache.drawArrays(GL_TRIANGLES, 0, 3);
    }
    { TimedPass pass(timer, "nothing"); }
    {
        TimedPass pass(timer, "two-quarters");
        cache.setViewport({0, 0, width / 2, height / 2});
        cache.drawArrays(GL_TRIANGLES, 0, 3);
        cache.setViewport({width / 2, height / 2, width / 2, height / 2});
        cache.drawArrays(GL_TRIANGLES, 0, 3);
    }
    const std::vector<PassTime> passes = timer.collect();
    glDisableVertexAttribArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    cache.invalidate();
    REQUIRE(passes.size() == 3);
    CHECK(passes[0].drawCalls == 1);
    CHECK(passes[0].fragments >= width * height);
    CHECK(passes[0].fragments <= width * height * 5 / 4);
    CHECK(passes[1].drawCalls == 0);
    CHECK(passes[1].stateCalls == 0);
    CHECK(passes[1].fragments == 0);
    CHECK(passes[2].drawCalls == 2);
    CHECK(passes[2].fragments >= width * height / 2);
    CHECK(passes[2].fragments <= width * height * 3 / 4);
    checkGl("fragment count test");
}
