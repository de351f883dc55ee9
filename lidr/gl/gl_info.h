#pragma once
// What a GL context offers lidr: version, renderer and the optional features the passes choose between.
// platform/context.h makes the context and fills this; every layer above reads it without a context type.
#include <string>

namespace lidr {

// What the context turned out to be, and what the renderer may use. Filled after GLEW is initialised.
struct GlInfo {
    std::string backend;
    std::string version, renderer, vendor, glslVersion;
    int major = 0, minor = 0;
    int glsl = 0;  // GLSL version as a number: 120, 150, 450...; GLSL ES 1.00: 100
    // OpenGL ES (GL_VERSION "OpenGL ES 2.0 ..."): major/minor are the ES version; shaders are emitted as GLSL ES
    // 1.00 (lidr/gl/shader_source.h) and every capability below comes from ES 2.0 extensions (doc/contexts.md).
    bool gles = false;
    bool framebufferObject = false;   // ARB_framebuffer_object or EXT_framebuffer_object + packed depth-stencil;
                                      // ES 2.0: core FBOs + OES_packed_depth_stencil
    bool textureFloat = false;        // ARB_texture_float (light table in float textures); ES: OES_texture_float
    // Rendering to RGBA16F with additive blending, unclamped (multi-pass forward sums its lights there): GL 3.0,
    // or GL 2.1 with ARB_texture_float (the format) + ARB_color_buffer_float (float colour buffers blend in float,
    // fragment colours unclamped for them); ES 2.0 / WebGL 1: OES_texture_half_float + EXT_color_buffer_half_float.
    // What the extensions promise; the framebuffer's completeness is checked where the target is made.
    bool halfFloatColorBuffer = false;
    bool timerQuery = false;          // ARB_timer_query or EXT_timer_query; ES: none used (timing is CPU)
    bool occlusionQuery = true;       // sample-count queries (GL 1.5); ES 2.0: none (EXT_occlusion_query_boolean
                                      // only says "any", the overlap probe needs counts)
    bool depthClamp = false;          // ARB_depth_clamp or NV_depth_clamp; ES: not used (far-plane fallback)
    bool depthTexture = true;         // depth textures, copied to with glCopyTexSubImage2D (GL 1.4); ES:
                                      // OES_depth_texture (+ the copy, checked when the context is made)
    bool blendMinMax = true;          // GL_MAX blend equation (GL 1.4); ES: EXT_blend_minmax
    bool readDepthStencil = true;     // glReadPixels of depth and stencil (tests, artefacts, CPU truth); ES:
                                      // NV_read_depth_stencil (DEPTH_STENCIL, UNSIGNED_INT_24_8)
    bool fragmentHighp = true;        // fp32-class fragment floats; ES: GL_FRAGMENT_PRECISION_HIGH (highp float)
    bool drawBuffers = false;         // GL 2.0 glDrawBuffers; ES: EXT_draw_buffers
    bool multisampleFbo = false;      // EXT_framebuffer_multisample (or GL 3.0); ES 2.0: none
    int maxSamples = 0;
    // The optional per-sample MSAA index path (Trebilco's MSAA technique 1): multisample textures
    // (GL 3.2 / ARB_texture_multisample) read per sample (GL 4.0 / ARB_sample_shading).
    bool multisampleTexture = false;
    bool sampleShading = false;
    // Fragment shader invocations per pass (ARB_pipeline_statistics_query), counted by FrameTimer in measuring
    // runs; ES 2.0 and WebGL: none.
    bool pipelineStatistics = false;
    int maxColorTextureSamples = 0;
    int maxDrawBuffers = 1;
    int maxColorAttachments = 1;      // FBO colour attachments (index targets of one frame)
    int maxTextureUnits = 2;          // fragment-shader texture image units
    int maxVertexUniformVectors = 128;  // GL_MAX_VERTEX_UNIFORM_COMPONENTS / 4 (GL 2.1 guarantees 128)
    int maxTextureSize = 0;
    int stencilBits = 8;
    std::string summary() const;
};

// The GlInfo of the GL context current on this thread, for a program that made its own context (GLFW, SDL,
// EGL, Qt, an engine): loads lidr's GL entry points (GLEW; glewInit's "no GLX display" under EGL is accepted
// when GL answers) and reads what the context offers. Call it with the context current, before creating a
// renderer; lidr::GlContext calls it for the contexts lidr makes. Throws UnsupportedError when no context is
// current, entry points cannot be loaded or the context is below GL 2.1 (or OpenGL ES 2.0, or an ES context lacks an
// entry point lidr calls). backendName goes to GlInfo::backend.
GlInfo currentContextGlInfo(const std::string& backendName = "current");

}  // namespace lidr
