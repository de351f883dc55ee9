#pragma once
// Thin RAII owners of GL objects. Each one deletes its object in the destructor, so a renderer that is
// destroyed leaves nothing behind; liveGlObjects() counts what is alive (tests check it returns to zero).
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "lidr/base/gl_types.h"
#include "lidr/gl/bindings.h"

namespace lidr::gl {

int liveGlObjects();  // objects created through these wrappers and not yet deleted, all kinds together

enum class Kind { Texture, Renderbuffer, Framebuffer, Buffer, Program, Query };

// One GL name of one kind; moves, never copies.
class Object {
public:
    Object() = default;
    explicit Object(Kind kind);
    ~Object() { reset(); }
    Object(Object&& o) noexcept : kind_(o.kind_), id_(std::exchange(o.id_, 0u)) {}
    Object& operator=(Object&& o) noexcept {
        if (this != &o) {
            reset();
            kind_ = o.kind_;
            id_ = std::exchange(o.id_, 0u);
        }
        return *this;
    }
    Object(const Object&) = delete;
    Object& operator=(const Object&) = delete;
    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset();

protected:
    Kind kind_ = Kind::Texture;
    GLuint id_ = 0;
};

class Texture : public Object {
public:
    Texture() = default;
    // A 2D texture with NEAREST filtering and clamped edges (index and light-table textures are looked up at
    // texel centres; no filtering may mix neighbouring texels).
    static Texture create2D(GLint internalFormat, int width, int height, GLenum format, GLenum type,
                            const void* data = nullptr, GLint filter = GLint(glc::kNearest));
    // A multisample 2D texture (GL 3.2 / ARB_texture_multisample), read with texelFetch per sample.
    static Texture create2DMultisample(GLint internalFormat, int width, int height, int samples);
    // A cube map of `levels` mip levels (level i: size >> i texels a side, down to 1 x 1 for OpenGL ES 2.0's
    // completeness), face f of level i from data(i, f) (GL's face order +X, -X, +Y, -Y, +Z, -Z), trilinear
    // filtering, faces clamped at their edges; GL_TEXTURE_MAX_LOD set to maxLod where the context has it (desktop).
    static Texture createCube(GLint internalFormat, int size, int levels, GLenum format, GLenum type,
                              const std::function<const void*(int level, int face)>& data, float maxLod);
    int width() const { return width_; }
    int height() const { return height_; }
    int samples() const { return samples_; }
    void bind(int unit) const;
    // Level 0's texels from (0, 0) to (width, height) replaced (glTexSubImage2D; GL_UNPACK_ALIGNMENT must suit the
    // rows of `pixels`), the texture bound on the active unit (counted) and left there: the caller unbinds once
    // after its uploads (StateCache::bindTexture(GL_TEXTURE_2D, 0)). 2D textures.
    void upload(int width, int height, GLenum format, GLenum type, const void* pixels) const;

private:
    int width_ = 0, height_ = 0, samples_ = 0;
    GLenum target_ = 0x0DE1;  // GL_TEXTURE_2D
};

class Renderbuffer : public Object {
public:
    Renderbuffer() = default;
    static Renderbuffer create(GLenum internalFormat, int width, int height, int samples = 0);
};

class Framebuffer : public Object {
public:
    Framebuffer() = default;
    static Framebuffer create();
    void bind() const;
    void attachTexture(GLenum attachment, const Texture& t);
    void attachRenderbuffer(GLenum attachment, const Renderbuffer& rb);
    // `depth` as depth and stencil (a packed depth-stencil), or, with `separateStencil`, `depth` as depth and
    // it as stencil.
    void attachDepthStencil(const Renderbuffer& depth, const Renderbuffer* separateStencil = nullptr);
    void checkComplete(const char* name) const;  // throws GlError naming the status
    // For optional formats: UnsupportedError "WHAT is incomplete on RENDERER (status 0x...)" unless complete, so the
    // caller can fall back or refuse by name; leaves framebuffer 0 bound.
    void requireComplete(const std::string& what, const std::string& renderer) const;
    // The samples the driver gave its attachments (GL_SAMPLES; it may round a request up: llvmpipe makes 4 of 2);
    // leaves framebuffer 0 bound.
    int samples() const { return samplesOf(id_); }
    static int samplesOf(GLuint framebuffer);
};

class Buffer : public Object {
public:
    Buffer() = default;
    static Buffer create(GLenum target, const void* data, size_t bytes, GLenum usage = glc::kStaticDraw);
    size_t bytes() const { return bytes_; }

private:
    size_t bytes_ = 0;
};

// A uniform's location, looked up once (Program::uniform<T>), with a setter of its GLSL type. Looking up a
// name that no shader of the program declares throws Error (a typo); a declared name the compiler optimised
// away is location -1, and setting it does nothing, as in GL.
template <typename T>
class Uniform {
public:
    Uniform() = default;
    void set(const T& v) const;
    void setArray(const T* v, int count) const;  // uniform arrays: count elements from v
    GLint location() const { return location_; }

private:
    friend class Program;
    explicit Uniform(GLint location) : location_(location) {}
    GLint location_ = -1;
};

template <> void Uniform<int>::set(const int& v) const;
template <> void Uniform<float>::set(const float& v) const;
template <> void Uniform<glm::vec2>::set(const glm::vec2& v) const;
template <> void Uniform<glm::vec3>::set(const glm::vec3& v) const;
template <> void Uniform<glm::vec4>::set(const glm::vec4& v) const;
template <> void Uniform<glm::mat4>::set(const glm::mat4& v) const;
template <> void Uniform<float>::setArray(const float* v, int count) const;
template <> void Uniform<glm::vec3>::setArray(const glm::vec3* v, int count) const;
template <> void Uniform<glm::vec4>::setArray(const glm::vec4* v, int count) const;

class Program : public Object {
public:
    Program() = default;
    // Compiles and links; throws GlError with the info log and the name on failure.
    static Program create(const std::string& name, const std::string& vertexSource,
                          const std::string& fragmentSource,
                          const std::vector<std::pair<std::string, GLuint>>& attributes);
    void use() const;
    // The location of `name` (-1 when the compiler removed it); throws Error when no shader declares it.
    GLint location(const char* name) const;
    template <typename T>
    Uniform<T> uniform(const char* name) const {
        return Uniform<T>(location(name));
    }
    bool declares(const std::string& uniformName) const;  // a `uniform` declaration in the program's sources
    // Sets `name` only where the program declares it: lidr's shared shading and material uniforms, which a
    // program's own material shader (LidrOptions::materialShader) may leave out.
    template <typename T>
    void setIfDeclared(const char* name, const T& v) const {
        if (declares(name)) set(name, v);
    }
    // By name, for one-off values (the same check; typed handles are for what is set per draw).
    void set(const char* name, int v) const;
    void set(const char* name, float v) const;
    void set(const char* name, const glm::vec2& v) const;
    void set(const char* name, const glm::vec3& v) const;
    void set(const char* name, const glm::vec4& v) const;
    void set(const char* name, const glm::mat3& v) const;
    void set(const char* name, const glm::mat4& v) const;
    const std::string& name() const { return name_; }

    // Shader variants, the Filament / bgfx way: this program's own sources compiled again with `defines` added
    // after each `#version` line, on first use, and kept under `key` (a bit set the caller defines; equal keys
    // must mean equal defines). Key 0 is this program itself. The variant lives as long as this program.
    // `defines` is called only on the first use of a key: draws look their variant up per mesh, every frame.
    const Program& variant(uint32_t key, const std::function<std::vector<std::pair<std::string, std::string>>()>& defines) const;
    const Program& variant(uint32_t key, const std::vector<std::pair<std::string, std::string>>& defines) const {
        return variant(key, [&] { return defines; });
    }
    // Sets every active uniform this program shares with `source` (same name and type) to source's value: a
    // variant takes the per-frame state its base program was given (samplers' units included).
    void copyUniformsFrom(const Program& source) const;

private:
    struct Sources {
        std::string vertex, fragment;
        std::vector<std::pair<std::string, GLuint>> attributes;
        std::map<uint32_t, std::unique_ptr<Program>> variants;
    };
    struct UniformCopy {
        GLint from = -1, to = -1;
        GLenum type = 0;
    };
    std::unique_ptr<Sources> sources_;  // the base program's (variants have none: they make no variants)
    mutable std::vector<UniformCopy> copies_;  // from the base program, found on the first copy
    mutable GLuint copiesFrom_ = 0;
    std::string name_;
    std::vector<std::string> declared_;  // uniform names the sources declare
    mutable std::unordered_map<std::string, GLint> uniforms_;
};

}  // namespace lidr::gl
