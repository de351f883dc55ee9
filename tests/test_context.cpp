// GL context backends: the backend asked for is the one used and named in GlInfo, a backend the linked
// library does not offer is refused with a clear error, and the context really renders into an FBO.
// Runs in lidr-tests (lidr::lidr, EGL) and lidr-tests-osmesa (lidr::lidr_osmesa).
#include <algorithm>
#include <cstdlib>
#include <vector>

#include <catch2/catch.hpp>

#include "gl_test_context.h"
#include "lidr/base/error.h"
#include "lidr/base/gl.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/render_targets.h"

using namespace lidr;
using namespace lidr::test;
using Catch::Matchers::Contains;

namespace {
bool offered(ContextBackend b) {
    const std::vector<ContextBackend> all = availableContextBackends();
    return std::find(all.begin(), all.end(), b) != all.end();
}
}  // namespace

TEST_CASE("the context is the backend LIDR_CONTEXT names, and GlInfo says which", "[context][every-gl]") {
    const GlInfo& info = testGl();
    INFO("GlInfo backend '" << info.backend << "'");
    const ContextBackend used = parseContextBackend(info.backend);  // throws on a name lidr does not know
    REQUIRE(used != ContextBackend::Auto);
    REQUIRE(offered(used));
    const char* env = std::getenv("LIDR_CONTEXT");
    if (env && *env && parseContextBackend(env) != ContextBackend::Auto) REQUIRE(used == parseContextBackend(env));
}

TEST_CASE("lidr offers EGL, lidr_osmesa offers only OSMesa", "[context][every-gl]") {
    if (testGl().backend == "osmesa") {
        REQUIRE(availableContextBackends() == std::vector<ContextBackend>{ContextBackend::OSMesa});
    } else {
        CHECK(offered(ContextBackend::EglSurfaceless));
        CHECK(offered(ContextBackend::EglDevice));
        CHECK(offered(ContextBackend::EglGles2));
        CHECK_FALSE(offered(ContextBackend::OSMesa));
    }
}

TEST_CASE("a backend the linked library does not offer is refused, naming it and why", "[context][every-gl]") {
    testContext();  // the refusal below must leave the test context alone
    for (ContextBackend b : {ContextBackend::EglSurfaceless, ContextBackend::EglDevice, ContextBackend::EglGles2,
                             ContextBackend::Glfw, ContextBackend::GlfwGles2, ContextBackend::OSMesa}) {
        if (offered(b)) continue;
        ContextOptions options;
        options.backend = b;
        INFO("backend " << contextBackendName(b));
        REQUIRE_THROWS_AS(GlContext::create(options), UnsupportedError);
        REQUIRE_THROWS_WITH(GlContext::create(options), Contains(std::string(contextBackendName(b)) + ": "));
        if (b == ContextBackend::OSMesa)
            REQUIRE_THROWS_WITH(GlContext::create(options), Contains("OSMesa"));
        else if (testGl().backend == "osmesa")
            REQUIRE_THROWS_WITH(GlContext::create(options), Contains("link lidr::lidr for"));
    }
    testContext();
    REQUIRE(glGetString(GL_VERSION) != nullptr);
}

TEST_CASE("the context renders: a cleared and a scissor-cleared FBO read back exactly", "[context][every-gl]") {
    testContext();
    const int w = 8, h = 6;
    gl::Texture color = gl::Texture::create2D(GL_RGBA8, w, h, GL_RGBA, GL_UNSIGNED_BYTE);
    gl::Framebuffer fbo = gl::Framebuffer::create();
    fbo.bind();
    fbo.attachTexture(GL_COLOR_ATTACHMENT0, color);
    fbo.checkComplete("context test FBO");
    glViewport(0, 0, w, h);

    RenderState state;
    applyRenderState(state);
    glClearColor(0.2f, 0.4f, 0.6f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    state.scissor = true;
    state.scissorBox = glm::ivec4(2, 1, 3, 4);  // x, y, width, height
    applyRenderState(state);
    glClearColor(1.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    applyRenderState(RenderState{});

    std::vector<unsigned char> pixels(static_cast<size_t>(w) * h * 4, 7);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    checkGl("context test read-back");
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const bool inside = x >= 2 && x < 5 && y >= 1 && y < 5;
            const unsigned char* p = &pixels[(static_cast<size_t>(y) * w + x) * 4];
            INFO("pixel " << x << "," << y);
            if (inside) {
                REQUIRE((p[0] == 255 && p[1] == 0 && p[2] == 0 && p[3] == 0));
            } else {
                REQUIRE((p[0] == 51 && p[1] == 102 && p[2] == 153 && p[3] == 255));
            }
        }
}

TEST_CASE("render-target memory and MSAA sample counts are checked without a context (issue 13)", "[context][cpu]") {
    using Catch::Contains;
    // 1024 x 768, no MSAA, 8 index bytes: colour 4 + depth 4 + index 8 bytes per pixel.
    CHECK(lidr::estimateRenderTargetBytes(1024, 768, 0, 8) == 1024ull * 768 * 16);
    CHECK(lidr::estimateRenderTargetBytes(1024, 768, 4, 8) == 1024ull * 768 * (16 + 32));
    CHECK(lidr::estimateRenderTargetBytes(1024, 768, 4, 8, true) == 1024ull * 768 * (16 + 32 + 32));
    CHECK(lidr::indexBytesPerPixel(8, 8) == 8);
    CHECK(lidr::indexBytesPerPixel(1, 4) == 4);
    CHECK(lidr::indexBytesPerPixel(16, 16) == 32);
    REQUIRE_NOTHROW(lidr::checkRenderTargetMemory(4096, 4096, 8, 16));  // 1.5 GiB
    REQUIRE_THROWS_WITH(lidr::checkRenderTargetMemory(16384, 16384, 8, 8),
                        Contains("16384x16384 with MSAA 8x") && Contains("need about 20480 MiB") &&
                            Contains("the limit is 2048 MiB"));
    for (int ok : {0, 2, 4, 8, 16, 32, 64}) REQUIRE_NOTHROW(lidr::checkSampleCount(ok, "--msaa"));
    for (int bad : {-1, 1, 3, 6, 12, 128})
        REQUIRE_THROWS_WITH(lidr::checkSampleCount(bad, "--msaa"),
                            Contains("--msaa must be 0 (off) or a power of two 2, 4, 8") &&
                                Contains("got " + std::to_string(bad)));
}
