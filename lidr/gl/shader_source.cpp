#include "lidr/gl/shader_source.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "lidr/base/error.h"

namespace lidr {

std::string shaderFile(const std::string& name) {
    for (const detail::EmbeddedShader* s = detail::kEmbeddedShaders; s->name; ++s)
        if (name == s->name) return s->source;
    throw Error("no shader file named '" + name + "' in shaders/");
}

static const char kSourceStrings[] = "// lidr source strings:";

// The source-string number of `file` in one expanded source: 0 for the file asked for, then one per file
// in the order its first #include is met.
static int sourceNumber(std::vector<std::string>& files, const std::string& file) {
    const auto it = std::find(files.begin(), files.end(), file);
    if (it != files.end()) return static_cast<int>(it - files.begin());
    files.push_back(file);
    return static_cast<int>(files.size()) - 1;
}

// A `#line` after which the compiler counts `nextLine` of source string `number`. Before GLSL 3.30 (lidr's
// shaders are 1.20, the per-sample path 1.50) the line after `#line L` is line L + 1; Mesa follows that.
static std::string lineDirective(int nextLine, int number) {
    return "#line " + std::to_string(nextLine - 1) + " " + std::to_string(number) + "\n";
}

static std::string expandIncludes(const std::string& name, const ShaderIncludes& subs, int depth,
                                  std::vector<std::string>& files, const std::string* text = nullptr) {
    if (depth > 8) throw Error("shader include nesting too deep at '" + name + "'");
    const int self = sourceNumber(files, name);
    std::istringstream in(text ? *text : shaderFile(name));
    std::string out, line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        const size_t p = line.find("#include");
        if (p != std::string::npos && line.find_first_not_of(" \t") == p) {
            const size_t a = line.find('"', p), b = line.find('"', a + 1);
            if (a == std::string::npos || b == std::string::npos)
                throw Error("bad #include in shader '" + name + "' line " + std::to_string(lineNo));
            std::string file = line.substr(a + 1, b - a - 1);
            for (const auto& [from, to] : subs)
                if (file == from) file = to;
            out += lineDirective(1, sourceNumber(files, file));
            out += expandIncludes(file, subs, depth + 1, files);
            out += lineDirective(lineNo + 1, self);
            continue;
        }
        out += line;
        out += '\n';
    }
    return out;
}

static std::string buildSource(const std::string& name, const std::string* text, const ShaderDefines& defines,
                               const ShaderIncludes& subs) {
    std::vector<std::string> files;
    std::string src = expandIncludes(name, subs, 0, files, text);
    std::string defs;
    for (const auto& [k, v] : defines) defs += "#define " + k + " " + v + "\n";
    defs += kSourceStrings;
    for (size_t i = 0; i < files.size(); ++i) defs += (i ? ", " : " ") + std::to_string(i) + " " + files[i];
    defs += '\n';
    const size_t v = src.find("#version");
    if (v == std::string::npos) return "#version 120\n" + defs + lineDirective(1, 0) + src;
    const size_t eol = src.find('\n', v);
    const int versionLine = 1 + static_cast<int>(std::count(src.begin(), src.begin() + static_cast<long>(v), '\n'));
    return src.substr(0, eol + 1) + defs + lineDirective(versionLine + 1, 0) + src.substr(eol + 1);
}

std::string buildShaderSource(const std::string& name, const ShaderDefines& defines, const ShaderIncludes& subs) {
    return buildSource(name, nullptr, defines, subs);
}

std::string buildShaderSourceFromText(const std::string& name, const std::string& text, const ShaderDefines& defines,
                                      const ShaderIncludes& subs) {
    return buildSource(name, &text, defines, subs);
}

// True if the source writes gl_FragData[i] with an index that is not the literal 0 (a loop index counts).
static bool writesSecondDrawBuffer(const std::string& src) {
    static const std::string kFragData = "gl_FragData[";
    for (size_t p = src.find(kFragData); p != std::string::npos; p = src.find(kFragData, p + 1)) {
        const size_t a = p + kFragData.size(), b = src.find(']', a);
        std::string index = src.substr(a, b == std::string::npos ? std::string::npos : b - a);
        index.erase(std::remove_if(index.begin(), index.end(), [](char c) { return c == ' ' || c == '\t'; }),
                    index.end());
        if (index != "0") return true;
    }
    return false;
}

std::string glslEs100FromGlsl120(const std::string& source, ShaderStage stage, const std::string& name) {
    const size_t v = source.find("#version");
    if (v == std::string::npos)
        throw Error("shader '" + name + "' has no #version line; lidr's sources say #version 120");
    const size_t eol = source.find('\n', v);
    const std::string versionLine = source.substr(v, eol == std::string::npos ? std::string::npos : eol - v);
    int version = 0;
    std::sscanf(versionLine.c_str(), "#version %d", &version);
    if (version != 120 && version != 100)
        throw Error("shader '" + name + "' is GLSL " + std::to_string(version) +
                    "; OpenGL ES 2.0 compiles GLSL ES 1.00, which lidr makes from GLSL 1.20 sources only");
    const bool writesFragDepth = stage == ShaderStage::Fragment && source.find("gl_FragDepth") != std::string::npos;
    const bool usesTextureLod = stage == ShaderStage::Fragment && source.find("textureCubeLod") != std::string::npos;
    std::string header = "#version 100\n";
    if (stage == ShaderStage::Fragment) {
        // Conditional: a single-target variant of a shader that names gl_FragData[1] under #if still compiles
        // where the extension is missing (multi-target schemes are refused before any shader is built there).
        if (writesSecondDrawBuffer(source))
            header += "#ifdef GL_EXT_draw_buffers\n#extension GL_EXT_draw_buffers : require\n#endif\n";
        // gl_FragDepth is EXT_frag_depth's gl_FragDepthEXT (the pixel-list test hook and the emulated 16-bit depth
        // write it; ES 2.0's shadow maps do not); a context without the extension fails the compile naming it.
        if (writesFragDepth) header += "#extension GL_EXT_frag_depth : require\n";
        // dFdx / dFdy are OES_standard_derivatives' in ES 2.0: enabled where offered (a shader that needs them
        // tests GL_OES_standard_derivatives; the shadow maps' depth: shadow_depth.frag).
        if (source.find("dFdx") != std::string::npos)
            header += "#ifdef GL_OES_standard_derivatives\n#extension GL_OES_standard_derivatives : enable\n#endif\n";
        // textureCubeLod is EXT_shader_texture_lod's textureCubeLodEXT in ES 2.0 fragment shaders (the environment's
        // LOD lookup; the variant that calls it is compiled only where GlInfo::textureLod says the context has it).
        if (usesTextureLod) header += "#ifdef GL_EXT_shader_texture_lod\n#extension GL_EXT_shader_texture_lod : enable\n#endif\n";
        header +=
            "#ifdef GL_FRAGMENT_PRECISION_HIGH\n"
            "precision highp float;\n"
            "precision highp sampler2D;\n"
            "precision highp samplerCube;\n"
            "#else\n"
            "precision mediump float;\n"
            "precision mediump sampler2D;\n"
            "precision mediump samplerCube;\n"
            "#define LIDR_FRAGMENT_FP16 1\n"
            "#endif\n";
    }
    // `#line L N`: in GLSL 1.20 the next line is L + 1, in GLSL ES 1.00 (as in GLSL 3.30) it is L.
    std::istringstream in(eol == std::string::npos ? std::string() : source.substr(eol + 1));
    std::string body, line;
    while (std::getline(in, line)) {
        int number = 0, string = 0, used = 0;
        if (std::sscanf(line.c_str(), " #line %d %d%n", &number, &string, &used) == 2 &&
            line.find_first_not_of(" \t", size_t(used)) == std::string::npos)
            line = "#line " + std::to_string(number + 1) + " " + std::to_string(string);
        for (size_t p = 0; writesFragDepth && (p = line.find("gl_FragDepth", p)) != std::string::npos; p += 15)
            line.replace(p, 12, "gl_FragDepthEXT");
        for (size_t p = 0; usesTextureLod && (p = line.find("textureCubeLod(", p)) != std::string::npos; p += 18)
            line.replace(p, 15, "textureCubeLodEXT(");
        body += line;
        body += '\n';
    }
    return source.substr(0, v) + header + body;
}

std::string glsl120WithExtensions(const std::string& source, ShaderStage stage) {
    if (stage != ShaderStage::Fragment || source.find("textureCubeLod") == std::string::npos) return source;
    const size_t v = source.find("#version");
    const size_t eol = v == std::string::npos ? std::string::npos : source.find('\n', v);
    if (eol == std::string::npos) return source;
    return source.substr(0, eol + 1) +
           "#ifdef GL_ARB_shader_texture_lod\n#extension GL_ARB_shader_texture_lod : enable\n#endif\n" +
           source.substr(eol + 1);
}

std::string perSampleGlsl150(std::string source, bool sampleShading) {
    const std::string v120 = "#version 120";
    const size_t at = source.find(v120);
    if (at == std::string::npos) throw Error("shader without #version 120");
    return source.replace(at, v120.size(), sampleShading ? "#version 150 compatibility\n#extension GL_ARB_sample_shading : require"
                                                         : "#version 150 compatibility");
}

std::string shaderSourceStrings(const std::string& source) {
    const size_t a = source.find(kSourceStrings);
    if (a == std::string::npos) return {};
    const size_t from = a + std::strlen(kSourceStrings);
    const size_t b = source.find('\n', from);
    return "source strings:" + source.substr(from, b == std::string::npos ? b : b - from);
}

}  // namespace lidr
