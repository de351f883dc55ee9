// OSMesa backend, compiled only into lidr::lidr_osmesa (where libOSMesa exists; it is gone from Mesa 25.1 on).
//
// OSMesa has its own GL dispatch and exports every gl* symbol itself, while lidr's other backends reach GL
// through glvnd (libOpenGL/libGL), whose entry points know nothing of an OSMesa context. So:
//  - lidr_osmesa links libOSMesa and not libOpenGL/libGL, which then come only as GLEW's dependency, one level
//    further down the breadth-first symbol lookup: lidr's direct GL 1.1 calls bind to libOSMesa.
//  - Debian's GLEW is a GLX build that loads every other entry point with glXGetProcAddressARB. This file
//    defines that function, which precedes glvnd's in lookup order, and answers it with OSMesaGetProcAddress
//    while an OSMesa context is current (GLX names and everything else go on to glvnd's definition).
// Both bindings are checked when a context is created, so a program that links glvnd ahead of lidr_osmesa
// gets a clear error instead of GL calls that go nowhere.
#include <dlfcn.h>

#include <cstdlib>
#include <cstring>
#include <string>

#include "lidr/platform/context.h"
#include "lidr/base/error.h"
#include "lidr/base/gl.h"

#ifndef GLAPI
#define GLAPI extern  // GL/osmesa.h expects GL/gl.h's GLAPI, which GLEW's header undefines
#endif
#include <GL/osmesa.h>

namespace {
using ProcAddressFn = void (*(*)(const GLubyte*))();

ProcAddressFn glvndProcAddress() {
    static const auto next = reinterpret_cast<ProcAddressFn>(dlsym(RTLD_NEXT, "glXGetProcAddressARB"));
    return next;
}
}  // namespace

extern "C" __attribute__((visibility("default"))) void (*glXGetProcAddressARB(const GLubyte* name))() {
    const char* n = reinterpret_cast<const char*>(name);
    if (OSMesaGetCurrentContext() != nullptr && std::strncmp(n, "glX", 3) != 0)
        return reinterpret_cast<void (*)()>(OSMesaGetProcAddress(n));
    const ProcAddressFn next = glvndProcAddress();
    return next ? next(name) : nullptr;
}

namespace lidr::detail {
namespace {

std::string objectFile(const void* address) {
    Dl_info info{};
    if (!dladdr(address, &info) || !info.dli_fname) return "an unknown object";
    return info.dli_fname;
}

bool sameObject(const void* a, const void* b) {
    Dl_info ia{}, ib{};
    return dladdr(a, &ia) && dladdr(b, &ib) && ia.dli_fbase == ib.dli_fbase;
}

class OSMesaGlContext final : public GlContext {
public:
    OSMesaGlContext() {
        // lidr renders into FBOs; the default framebuffer only has to exist, so a tiny one will do.
        const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8,
                               OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, 0};
        context_ = OSMesaCreateContextAttribs(attribs, nullptr);
        if (!context_) context_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
        if (!context_) throw UnsupportedError("OSMesaCreateContextAttribs and OSMesaCreateContextExt failed");
        try {
            initialise();
        } catch (...) {
            release();
            throw;
        }
    }
    ~OSMesaGlContext() override { release(); }
    void makeCurrent() override {
        if (!OSMesaMakeCurrent(context_, buffer_, GL_UNSIGNED_BYTE, kSize, kSize))
            throw UnsupportedError("OSMesaMakeCurrent failed");
    }

private:
    void initialise() {
        makeCurrent();

        // Direct GL calls must reach libOSMesa, not a glvnd stub with no context behind it.
        if (!sameObject(reinterpret_cast<const void*>(&glGetString),
                        reinterpret_cast<const void*>(&OSMesaCreateContextExt)))
            throw UnsupportedError(
                "glGetString binds to " + objectFile(reinterpret_cast<const void*>(&glGetString)) +
                ", not to libOSMesa: the program links libOpenGL/libGL ahead of lidr_osmesa. Link it against "
                "lidr::lidr_osmesa only, not OpenGL::GL or OpenGL::OpenGL");
        initialiseGl("osmesa");
        // GLEW's pointers must come from OSMesaGetProcAddress, i.e. this file's glXGetProcAddressARB won.
        if (reinterpret_cast<void*>(glGenFramebuffers) != reinterpret_cast<void*>(OSMesaGetProcAddress("glGenFramebuffers")))
            throw UnsupportedError("GLEW did not load its entry points from OSMesa (glXGetProcAddressARB binds to " +
                                   objectFile(dlsym(RTLD_DEFAULT, "glXGetProcAddressARB")) +
                                   "): the program links libGL ahead of lidr_osmesa");
    }
    void release() {
        if (OSMesaGetCurrentContext() == context_) OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
        OSMesaDestroyContext(context_);
    }

    static constexpr int kSize = 16;
    OSMesaContext context_ = nullptr;
    unsigned char buffer_[kSize * kSize * 4] = {};
};

}  // namespace

std::unique_ptr<GlContext> createOSMesa() { return std::make_unique<OSMesaGlContext>(); }

}  // namespace lidr::detail
