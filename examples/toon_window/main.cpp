// Example: lidr inside a program that owns its GL context and window (GLFW), with a material shader of its
// own: a toon ramp lit by LIDR's per-pixel light lists (shaders: #include "lidr_lights.glsl").
//   toon_window [--frames N] [--hidden] [--out frame.png]   a GLFW window (needs a display; CTest: xvfb-run)
//   toon_window --headless [--out frame.png]               its own EGL surfaceless context and FBO instead
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLFW/glfw3.h>  // includes <GL/gl.h>: lidr's headers do not mind

#include <lidr/lidr.h>

// The material: lidr's surface inputs (shading.glsl) and light list (lidr_lights.glsl), the shading ours.
static const char* kToonShader = R"(#version 120
#include "shading.glsl"
#include "lidr_lights.glsl"
void main() {
    LidrSurface s = lidrSurface();
    vec3 color = lidrAmbient(s);
    LidrLight light;
    lidrBeginLights();
    for (int i = 0; i < LIDR_MAX_LIGHTS; ++i) {
        if (!lidrNextLight(light)) break;
        vec3 toLight = light.position - s.position;
        float falloff = clamp(1.0 - dot(toLight, toLight) / (light.radius * light.radius), 0.0, 1.0);
        float diffuse = max(dot(s.normal, normalize(toLight)), 0.0) * falloff;
        float band = diffuse > 0.6 ? 1.0 : (diffuse > 0.25 ? 0.6 : (diffuse > 0.02 ? 0.25 : 0.0));
        color += s.albedo * light.color * band;
    }
    gl_FragColor = vec4(color, uMaterialOpacity);
}
)";

// A surfaceless EGL context of the program's own (Mesa), for machines without a display.
static bool makeEglContext() {
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    EGLDisplay display = getPlatformDisplay ? getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr)
                                            : EGL_NO_DISPLAY;
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr) || !eglBindAPI(EGL_OPENGL_API)) return false;
    EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, nullptr);
    return context != EGL_NO_CONTEXT && eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context);
}

int main(int argc, char** argv) {
    bool headless = false, hidden = false;
    int frames = 0;  // 0: until the window is closed
    std::string out;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--headless") headless = true;
        else if (a == "--hidden") hidden = true;
        else if (a == "--frames" && i + 1 < argc) frames = std::atoi(argv[++i]);
        else if (a == "--out" && i + 1 < argc) out = argv[++i];
        else {
            std::fprintf(stderr, "toon_window: unknown argument '%s'\n", a.c_str());
            return 2;
        }
    }
    const int width = 640, height = 400;
    GLFWwindow* window = nullptr;
    if (headless) {
        if (!makeEglContext()) return std::fprintf(stderr, "toon_window: no EGL surfaceless context\n"), 1;
        frames = 1;
    } else {
        if (!glfwInit()) return std::fprintf(stderr, "toon_window: glfwInit failed (no display?)\n"), 1;
        glfwWindowHint(GLFW_VISIBLE, hidden ? GLFW_FALSE : GLFW_TRUE);
        glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
        window = glfwCreateWindow(width, height, "lidr: toon material", nullptr, nullptr);
        if (!window) return std::fprintf(stderr, "toon_window: no GLFW window\n"), 1;
        glfwMakeContextCurrent(window);
        glfwSwapInterval(1);
    }
    int status = 0;
    try {
        const lidr::GlInfo info = lidr::currentContextGlInfo("own context");  // our context, lidr's view of it
        lidr::Scene scene = lidr::makeDefaultScene();
        lidr::LidrOptions options;
        options.materialShader = kToonShader;
        lidr::LidrRenderer renderer(info, scene, options, width, height);
        lidr::FramePresenter presenter;

        // Headless: the frame goes into an FBO of ours; windowed: into the window (framebuffer 0).
        GLuint fbo = 0, color = 0;
        if (headless) {
            glGenTextures(1, &color);
            glBindTexture(GL_TEXTURE_2D, color);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
            auto genFramebuffers = reinterpret_cast<PFNGLGENFRAMEBUFFERSPROC>(eglGetProcAddress("glGenFramebuffers"));
            auto bindFramebuffer = reinterpret_cast<PFNGLBINDFRAMEBUFFERPROC>(eglGetProcAddress("glBindFramebuffer"));
            auto framebufferTexture =
                reinterpret_cast<PFNGLFRAMEBUFFERTEXTURE2DPROC>(eglGetProcAddress("glFramebufferTexture2D"));
            genFramebuffers(1, &fbo);
            bindFramebuffer(GL_FRAMEBUFFER, fbo);
            framebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
        }
        for (int frame = 0; frames == 0 || frame < frames; ++frame) {
            if (window && glfwWindowShouldClose(window)) break;
            const float t = 0.05f * float(frame);
            renderer.render(scene.camera, scene.lightsAt(t), {scene.ambient, scene.backgroundColor});
            presenter.present(renderer.targets(), fbo, 0, 0, width, height);
            // Our own drawing after lidr's: the state we set before is still ours (lidr put it back).
            glEnable(GL_SCISSOR_TEST);
            glScissor(8, 8, 24, 24);
            glClearColor(1.0f, 0.8f, 0.0f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT);
            glDisable(GL_SCISSOR_TEST);
            if (frame + 1 == frames && !out.empty()) {
                lidr::writePng(out, lidr::readPixelsRGBA8(width, height));
                std::printf("toon_window: wrote %s\n", out.c_str());
            }
            if (window) {
                glfwSwapBuffers(window);
                glfwPollEvents();
            }
        }
        lidr::checkGl("toon_window");
    } catch (const lidr::Error& e) {
        std::fprintf(stderr, "toon_window: %s\n", e.what());
        status = 1;
    }
    if (window) {
        glfwDestroyWindow(window);
        glfwTerminate();
    }
    return status;
}
