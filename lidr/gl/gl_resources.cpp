#include "lidr/gl/gl_resources.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <atomic>
#include <cctype>

#include <glm/gtc/type_ptr.hpp>

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/shader_source.h"

namespace lidr::gl {

static std::atomic<int> gLive{0};
int liveGlObjects() { return gLive.load(); }

Object::Object(Kind kind) : kind_(kind) {
    switch (kind) {
    case Kind::Texture: glGenTextures(1, &id_); break;
    case Kind::Renderbuffer: glGenRenderbuffers(1, &id_); break;
    case Kind::Framebuffer: glGenFramebuffers(1, &id_); break;
    case Kind::Buffer: glGenBuffers(1, &id_); break;
    case Kind::Program: id_ = glCreateProgram(); break;
    case Kind::Query: glGenQueries(1, &id_); break;
    }
    if (id_ == 0) throw GlError("could not create a GL object");
    ++gLive;
}

void Object::reset() {
    if (id_ == 0) return;
    switch (kind_) {
    case Kind::Texture: glDeleteTextures(1, &id_); break;
    case Kind::Renderbuffer: glDeleteRenderbuffers(1, &id_); break;
    case Kind::Framebuffer:
        glDeleteFramebuffers(1, &id_);
        StateCache::current().invalidate();  // GL binds framebuffer 0 if it was bound; its draw buffers go
        break;
    case Kind::Buffer: glDeleteBuffers(1, &id_); break;
    case Kind::Program: glDeleteProgram(id_); break;
    case Kind::Query: glDeleteQueries(1, &id_); break;
    }
    id_ = 0;
    --gLive;
}

Texture Texture::create2D(GLint internalFormat, int width, int height, GLenum format, GLenum type,
                          const void* data, GLint filter) {
    Texture t;
    static_cast<Object&>(t) = Object(Kind::Texture);
    t.width_ = width;
    t.height_ = height;
    // OpenGL ES 2.0 has no sized internal formats: the internal format is the format (RGBA + UNSIGNED_BYTE is
    // RGBA8, RGBA + FLOAT is OES_texture_float's, DEPTH_COMPONENT + UNSIGNED_INT is OES_depth_texture's).
    if (currentContextIsGles()) internalFormat = GLint(format);
    StateCache::current().bindTexture(GL_TEXTURE_2D, t.id_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter == GL_LINEAR_MIPMAP_LINEAR ? GL_LINEAR : filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, internalFormat, width, height, 0, format, type, data);
    if (filter == GL_LINEAR_MIPMAP_LINEAR) {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
        glGenerateMipmap(GL_TEXTURE_2D);
    }
    StateCache::current().bindTexture(GL_TEXTURE_2D, 0);
    checkGl("Texture::create2D");
    return t;
}

Texture Texture::create2DMultisample(GLint internalFormat, int width, int height, int samples) {
    Texture t;
    static_cast<Object&>(t) = Object(Kind::Texture);
    t.width_ = width;
    t.height_ = height;
    t.samples_ = samples;
    StateCache::current().bindTexture(GL_TEXTURE_2D_MULTISAMPLE, t.id_);
    glTexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, samples, internalFormat, width, height, GL_TRUE);
    StateCache::current().bindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
    checkGl("Texture::create2DMultisample");
    return t;
}

Texture Texture::createCube(GLint internalFormat, int size, int levels, GLenum format, GLenum type,
                            const std::function<const void*(int level, int face)>& data, float maxLod) {
    Texture t;
    static_cast<Object&>(t) = Object(Kind::Texture);
    t.width_ = t.height_ = size;
    t.target_ = GL_TEXTURE_CUBE_MAP;
    if (currentContextIsGles()) internalFormat = GLint(format);  // no sized formats (create2D)
    StateCache::current().bindTexture(GL_TEXTURE_CUBE_MAP, t.id_);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    if (!currentContextIsGles()) glTexParameterf(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LOD, maxLod);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int level = 0; level < levels; ++level)
        for (int face = 0; face < 6; ++face)
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + GLenum(face), level, internalFormat, std::max(1, size >> level),
                         std::max(1, size >> level), 0, format, type, data(level, face));
    StateCache::current().bindTexture(GL_TEXTURE_CUBE_MAP, 0);
    checkGl("Texture::createCube");
    return t;
}

void Texture::bind(int unit) const {
    glActiveTexture(GL_TEXTURE0 + unit);
    StateCache::current().bindTexture(samples_ > 0 ? GL_TEXTURE_2D_MULTISAMPLE : target_, id_);
}

void Texture::upload(int width, int height, GLenum format, GLenum type, const void* pixels) const {
    StateCache::current().bindTexture(GL_TEXTURE_2D, id_);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, format, type, pixels);
}

Renderbuffer Renderbuffer::create(GLenum internalFormat, int width, int height, int samples) {
    Renderbuffer r;
    static_cast<Object&>(r) = Object(Kind::Renderbuffer);
    glBindRenderbuffer(GL_RENDERBUFFER, r.id_);
    if (samples > 0)
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, internalFormat, width, height);
    else
        glRenderbufferStorage(GL_RENDERBUFFER, internalFormat, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    checkGl("Renderbuffer::create");
    return r;
}

Framebuffer Framebuffer::create() {
    Framebuffer f;
    static_cast<Object&>(f) = Object(Kind::Framebuffer);
    return f;
}

void Framebuffer::bind() const { StateCache::current().bindFramebuffer(id_); }

void Framebuffer::attachTexture(GLenum attachment, const Texture& t) {
    StateCache::current().bindFramebuffer(id_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, t.samples() > 0 ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D,
                           t.id(), 0);
}

void Framebuffer::attachRenderbuffer(GLenum attachment, const Renderbuffer& rb) {
    StateCache::current().bindFramebuffer(id_);
    if (attachment == GL_DEPTH_STENCIL_ATTACHMENT && currentContextIsGles()) {
        // OpenGL ES 2.0 has no DEPTH_STENCIL_ATTACHMENT: a packed depth-stencil renderbuffer
        // (OES_packed_depth_stencil) is attached as depth and as stencil.
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb.id());
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb.id());
        return;
    }
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, attachment, GL_RENDERBUFFER, rb.id());
}

void Framebuffer::attachDepthStencil(const Renderbuffer& depth, const Renderbuffer* separateStencil) {
    if (!separateStencil) {
        attachRenderbuffer(GL_DEPTH_STENCIL_ATTACHMENT, depth);
        return;
    }
    attachRenderbuffer(GL_DEPTH_ATTACHMENT, depth);
    attachRenderbuffer(GL_STENCIL_ATTACHMENT, *separateStencil);
}

void Framebuffer::checkComplete(const char* name) const {
    StateCache::current().bindFramebuffer(id_);
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "framebuffer '%s' is incomplete (status 0x%04x)", name, status);
        throw GlError(buf);
    }
}

void Framebuffer::requireComplete(const std::string& what, const std::string& renderer) const {
    StateCache::current().bindFramebuffer(id_);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    StateCache::current().bindFramebuffer(0);
    checkGl(what.c_str());
    if (status == GL_FRAMEBUFFER_COMPLETE) return;
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", status);
    throw UnsupportedError(what + " is incomplete on " + renderer + " (status " + code +
                           (status == GL_FRAMEBUFFER_UNSUPPORTED ? ", GL_FRAMEBUFFER_UNSUPPORTED" : "") + ")");
}

int Framebuffer::samplesOf(GLuint framebuffer) {
    StateCache::current().bindFramebuffer(framebuffer);
    GLint samples = 0;
    glGetIntegerv(GL_SAMPLES, &samples);
    StateCache::current().bindFramebuffer(0);
    checkGl("framebuffer sample count");
    return int(samples);
}

Buffer Buffer::create(GLenum target, const void* data, size_t bytes, GLenum usage) {
    Buffer b;
    static_cast<Object&>(b) = Object(Kind::Buffer);
    b.bytes_ = bytes;
    glBindBuffer(target, b.id_);
    glBufferData(target, static_cast<GLsizeiptr>(bytes), data, usage);
    glBindBuffer(target, 0);
    checkGl("Buffer::create");
    return b;
}

static GLuint compileShader(GLenum type, const std::string& glsl120, const std::string& name) {
    // An OpenGL ES context compiles the same source as GLSL ES 1.00 (lidr/gl/shader_source.h).
    const std::string source =
        currentContextIsGles()
            ? glslEs100FromGlsl120(glsl120, type == GL_VERTEX_SHADER ? ShaderStage::Vertex : ShaderStage::Fragment, name)
            : glsl120WithExtensions(glsl120, type == GL_VERTEX_SHADER ? ShaderStage::Vertex : ShaderStage::Fragment);
    GLuint s = glCreateShader(type);
    const char* src = source.c_str();
    glShaderSource(s, 1, &src, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
        std::string log(static_cast<size_t>(len > 1 ? len : 1), '\0');
        glGetShaderInfoLog(s, len, nullptr, log.data());
        glDeleteShader(s);
        const std::string strings = shaderSourceStrings(source);
        throw GlError("shader '" + name + "' (" + (type == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                      ") failed to compile" + (strings.empty() ? "" : " (" + strings + ")") + ":\n" + log);
    }
    return s;
}

namespace {
// The names a GLSL source declares `uniform` (after include expansion; comments stripped first):
// "uniform vec4 a, b[4];" gives a and b.
void declaredUniforms(const std::string& source, std::vector<std::string>& out) {
    std::string code;
    code.reserve(source.size());
    for (size_t i = 0; i < source.size(); ++i) {
        if (source.compare(i, 2, "//") == 0) {
            while (i < source.size() && source[i] != '\n') ++i;
            code += '\n';
        } else if (source.compare(i, 2, "/*") == 0) {
            const size_t end = source.find("*/", i + 2);
            i = end == std::string::npos ? source.size() : end + 1;
            code += ' ';
        } else {
            code += source[i];
        }
    }
    auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    for (size_t at = code.find("uniform"); at != std::string::npos; at = code.find("uniform", at + 7)) {
        if ((at > 0 && word(code[at - 1])) || (at + 7 < code.size() && word(code[at + 7]))) continue;
        const size_t end = code.find(';', at);
        if (end == std::string::npos) break;
        // Drop array sizes, split the declarators; each one's last word is a name (the first also holds the type).
        std::string decl;
        int depth = 0;
        for (size_t i = at + 7; i < end; ++i) {
            if (code[i] == '[') ++depth;
            if (depth == 0) decl += code[i];
            if (code[i] == ']') --depth;
        }
        size_t start = 0;
        for (;;) {
            const size_t comma = decl.find(',', start);
            std::string part = decl.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
            size_t e = part.size();
            while (e > 0 && !word(part[e - 1])) --e;
            size_t b = e;
            while (b > 0 && word(part[b - 1])) --b;
            if (e > b) out.push_back(part.substr(b, e - b));
            if (comma == std::string::npos) break;
            start = comma + 1;
        }
    }
}
}  // namespace

Program Program::create(const std::string& name, const std::string& vs, const std::string& fs,
                        const std::vector<std::pair<std::string, GLuint>>& attributes) {
    Program p;
    declaredUniforms(vs, p.declared_);
    declaredUniforms(fs, p.declared_);
    static_cast<Object&>(p) = Object(Kind::Program);
    p.name_ = name;
    GLuint v = compileShader(GL_VERTEX_SHADER, vs, name);
    GLuint f = 0;
    try {
        f = compileShader(GL_FRAGMENT_SHADER, fs, name);
    } catch (...) {
        glDeleteShader(v);
        throw;
    }
    glAttachShader(p.id_, v);
    glAttachShader(p.id_, f);
    for (const auto& [attr, slot] : attributes) glBindAttribLocation(p.id_, slot, attr.c_str());
    glLinkProgram(p.id_);
    glDetachShader(p.id_, v);
    glDetachShader(p.id_, f);
    glDeleteShader(v);
    glDeleteShader(f);
    GLint ok = 0;
    glGetProgramiv(p.id_, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetProgramiv(p.id_, GL_INFO_LOG_LENGTH, &len);
        std::string log(static_cast<size_t>(len > 1 ? len : 1), '\0');
        glGetProgramInfoLog(p.id_, len, nullptr, log.data());
        throw GlError("program '" + name + "' failed to link:\n" + log);
    }
    checkGl(("Program::create " + name).c_str());
    p.sources_ = std::make_unique<Sources>();
    p.sources_->vertex = vs;
    p.sources_->fragment = fs;
    p.sources_->attributes = attributes;
    return p;
}

namespace {
// `defines` as lines after the first line (the #version, and with it anything the source needs first).
std::string withDefines(const std::string& source, const std::vector<std::pair<std::string, std::string>>& defines) {
    std::string lines;
    for (const auto& [name, value] : defines) lines += "#define " + name + " " + value + "\n";
    const size_t eol = source.find('\n');
    if (source.compare(0, 8, "#version") != 0 || eol == std::string::npos) return lines + source;
    return source.substr(0, eol + 1) + lines + source.substr(eol + 1);
}
}  // namespace

const Program& Program::variant(uint32_t key,
                                const std::function<std::vector<std::pair<std::string, std::string>>()>& makeDefines) const {
    if (key == 0 || !sources_) return *this;
    auto it = sources_->variants.find(key);
    if (it == sources_->variants.end()) {
        const std::vector<std::pair<std::string, std::string>> defines = makeDefines();
        Program v = create(name_ + "-variant-" + std::to_string(key), withDefines(sources_->vertex, defines),
                           withDefines(sources_->fragment, defines), sources_->attributes);
        v.sources_.reset();
        it = sources_->variants.emplace(key, std::make_unique<Program>(std::move(v))).first;
    }
    return *it->second;
}

namespace {
bool floatUniform(GLenum type) {
    return type == GL_FLOAT || type == GL_FLOAT_VEC2 || type == GL_FLOAT_VEC3 || type == GL_FLOAT_VEC4 ||
           type == GL_FLOAT_MAT2 || type == GL_FLOAT_MAT3 || type == GL_FLOAT_MAT4;
}
}  // namespace

void Program::copyUniformsFrom(const Program& source) const {
    if (copiesFrom_ != source.id_) {  // the plan: matching locations, element by element for arrays
        copies_.clear();
        GLint count = 0, longest = 0;
        glGetProgramiv(source.id_, GL_ACTIVE_UNIFORMS, &count);
        glGetProgramiv(source.id_, GL_ACTIVE_UNIFORM_MAX_LENGTH, &longest);
        std::vector<char> buffer(size_t(std::max(longest, 1)) + 16);
        for (GLint i = 0; i < count; ++i) {
            GLint size = 0;
            GLenum type = 0;
            glGetActiveUniform(source.id_, GLuint(i), GLsizei(buffer.size()), nullptr, &size, &type, buffer.data());
            std::string name = buffer.data();
            if (name.compare(0, 3, "gl_") == 0) continue;
            if (name.size() > 3 && name.compare(name.size() - 3, 3, "[0]") == 0) name.resize(name.size() - 3);
            for (GLint e = 0; e < size; ++e) {
                const std::string element = size > 1 ? name + "[" + std::to_string(e) + "]" : name;
                const GLint from = glGetUniformLocation(source.id_, element.c_str());
                const GLint to = glGetUniformLocation(id_, element.c_str());
                if (from >= 0 && to >= 0) copies_.push_back({from, to, type});
            }
        }
        copiesFrom_ = source.id_;
    }
    // Every value is read with `source` in use and written with this program in use (as the caller left it):
    // WebGL through Emscripten resolves a uniform location through the program in use, glGetUniform of another
    // program's included.
    struct Value {
        GLfloat f[16];
        GLint i[4];
    };
    std::vector<Value> values(copies_.size());
    glUseProgram(source.id_);
    for (size_t k = 0; k < copies_.size(); ++k) {
        if (floatUniform(copies_[k].type)) glGetUniformfv(source.id_, copies_[k].from, values[k].f);
        else glGetUniformiv(source.id_, copies_[k].from, values[k].i);
    }
    glUseProgram(id_);
    for (size_t k = 0; k < copies_.size(); ++k) {
        const UniformCopy& c = copies_[k];
        const GLfloat* v = values[k].f;
        const GLint* n = values[k].i;
        switch (c.type) {
        case GL_FLOAT: glUniform1fv(c.to, 1, v); break;
        case GL_FLOAT_VEC2: glUniform2fv(c.to, 1, v); break;
        case GL_FLOAT_VEC3: glUniform3fv(c.to, 1, v); break;
        case GL_FLOAT_VEC4: glUniform4fv(c.to, 1, v); break;
        case GL_FLOAT_MAT2: glUniformMatrix2fv(c.to, 1, GL_FALSE, v); break;
        case GL_FLOAT_MAT3: glUniformMatrix3fv(c.to, 1, GL_FALSE, v); break;
        case GL_FLOAT_MAT4: glUniformMatrix4fv(c.to, 1, GL_FALSE, v); break;
        case GL_INT_VEC2: case GL_BOOL_VEC2: glUniform2iv(c.to, 1, n); break;
        case GL_INT_VEC3: case GL_BOOL_VEC3: glUniform3iv(c.to, 1, n); break;
        case GL_INT_VEC4: case GL_BOOL_VEC4: glUniform4iv(c.to, 1, n); break;
        default: glUniform1iv(c.to, 1, n); break;  // int, bool and sampler types
        }
    }
}

void Program::use() const {
    StateCache::current().countProgramBind();
    glUseProgram(id_);
}

bool Program::declares(const std::string& n) const {
    return std::find(declared_.begin(), declared_.end(), n) != declared_.end();
}

GLint Program::location(const char* n) const {
    auto it = uniforms_.find(n);
    if (it != uniforms_.end()) return it->second;
    if (!declares(n))
        throw Error("program '" + name_ + "' has no uniform '" + n + "': none of its shaders declares it");
    GLint loc = glGetUniformLocation(id_, n);
    uniforms_.emplace(n, loc);
    return loc;
}

template <> void Uniform<int>::set(const int& v) const { glUniform1i(location_, v); }
template <> void Uniform<float>::set(const float& v) const { glUniform1f(location_, v); }
template <> void Uniform<glm::vec2>::set(const glm::vec2& v) const { glUniform2fv(location_, 1, glm::value_ptr(v)); }
template <> void Uniform<glm::vec3>::set(const glm::vec3& v) const { glUniform3fv(location_, 1, glm::value_ptr(v)); }
template <> void Uniform<glm::vec4>::set(const glm::vec4& v) const { glUniform4fv(location_, 1, glm::value_ptr(v)); }
template <> void Uniform<glm::mat4>::set(const glm::mat4& v) const {
    glUniformMatrix4fv(location_, 1, GL_FALSE, glm::value_ptr(v));
}
template <> void Uniform<float>::setArray(const float* v, int count) const { glUniform1fv(location_, count, v); }
template <> void Uniform<glm::vec3>::setArray(const glm::vec3* v, int count) const {
    glUniform3fv(location_, count, glm::value_ptr(v[0]));
}
template <> void Uniform<glm::vec4>::setArray(const glm::vec4* v, int count) const {
    glUniform4fv(location_, count, glm::value_ptr(v[0]));
}

void Program::set(const char* n, int v) const { glUniform1i(location(n), v); }
void Program::set(const char* n, float v) const { glUniform1f(location(n), v); }
void Program::set(const char* n, const glm::vec2& v) const { glUniform2fv(location(n), 1, glm::value_ptr(v)); }
void Program::set(const char* n, const glm::vec3& v) const { glUniform3fv(location(n), 1, glm::value_ptr(v)); }
void Program::set(const char* n, const glm::vec4& v) const { glUniform4fv(location(n), 1, glm::value_ptr(v)); }
void Program::set(const char* n, const glm::mat3& v) const {
    glUniformMatrix3fv(location(n), 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::mat4& v) const {
    glUniformMatrix4fv(location(n), 1, GL_FALSE, glm::value_ptr(v));
}

}  // namespace lidr::gl
