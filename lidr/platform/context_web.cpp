// WebGL 1 backend of the web build (emscripten): a context on the page's <canvas>, the WebGL extensions lidr
// can use enabled, then GlInfo filled from it like any GLES 2.0 context (doc/web.md).
#include "lidr/base/gl.h"

#include <emscripten/html5.h>

#include <string>

#include "lidr/base/error.h"
#include "lidr/platform/context.h"

namespace lidr::detail {
namespace {

// The WebGL 1 extensions lidr's GLES 2.0 path looks for (doc/web.md). WebGL hides an extension until it is
// asked for; emscripten_webgl_enable_extension also installs the entry points of the ones that add functions
// (glDrawBuffers, vertex arrays, instancing). GL_EXTENSIONS lists every extension the browser offers, enabled
// or not, so each one lidr reads there is enabled here (EXT_depth_clamp: SavedGlState asks for DEPTH_CLAMP).
constexpr const char* kWantedExtensions[] = {
    "WEBGL_draw_buffers",      "EXT_blend_minmax",        "OES_texture_float",     "WEBGL_depth_texture",
    "OES_element_index_uint",  "OES_vertex_array_object", "ANGLE_instanced_arrays", "EXT_disjoint_timer_query",
    "OES_standard_derivatives", "EXT_frag_depth",           "EXT_depth_clamp",       "OES_texture_half_float",
    "EXT_color_buffer_half_float",  // with the one before: multi-pass forward sums its passes in half float
};

class WebGlContext final : public GlContext {
public:
    explicit WebGlContext(const ContextOptions& o) : canvas_(o.canvasSelector) {
        EmscriptenWebGLContextAttributes attributes;
        emscripten_webgl_init_context_attributes(&attributes);
        attributes.majorVersion = 1;  // WebGL 1 = OpenGL ES 2.0, the GL 2-class platform this build is for
        attributes.minorVersion = 0;
        attributes.alpha = EM_FALSE;
        attributes.depth = EM_TRUE;
        attributes.stencil = EM_TRUE;
        attributes.antialias = EM_FALSE;
        // Kept after presenting, so a screenshot or a read-back of the canvas sees the last frame.
        attributes.preserveDrawingBuffer = EM_TRUE;
        attributes.enableExtensionsByDefault = EM_FALSE;  // only the ones below, so GlInfo shows what is used
        emscripten_set_canvas_element_size(canvas_.c_str(), o.windowWidth, o.windowHeight);
        context_ = emscripten_webgl_create_context(canvas_.c_str(), &attributes);
        if (context_ <= 0)
            throw UnsupportedError("emscripten_webgl_create_context(\"" + canvas_ + "\") failed (" +
                                   std::to_string(context_) + "): no <canvas> by that selector, or no WebGL 1");
        makeCurrent();
        for (const char* name : kWantedExtensions) emscripten_webgl_enable_extension(context_, name);
        initialiseGl("webgl");
    }
    ~WebGlContext() override {
        if (context_ > 0) emscripten_webgl_destroy_context(context_);
    }
    void makeCurrent() override {
        if (emscripten_webgl_make_context_current(context_) != EMSCRIPTEN_RESULT_SUCCESS)
            throw Error("emscripten_webgl_make_context_current failed for canvas " + canvas_);
    }

private:
    std::string canvas_;
    EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context_ = 0;
};

}  // namespace

std::unique_ptr<GlContext> createWebGl(const ContextOptions& o) { return std::make_unique<WebGlContext>(o); }

}  // namespace lidr::detail
