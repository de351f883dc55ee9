#include "lidr/gl/shader_source.h"

#include <cstring>
#include <sstream>

#include "lidr/base/error.h"

namespace lidr {

std::string shaderFile(const std::string& name) {
    for (const detail::EmbeddedShader* s = detail::kEmbeddedShaders; s->name; ++s)
        if (name == s->name) return s->source;
    throw Error("no shader file named '" + name + "' in shaders/");
}

static std::string expandIncludes(const std::string& name, const ShaderIncludes& subs, int depth) {
    if (depth > 8) throw Error("shader include nesting too deep at '" + name + "'");
    std::istringstream in(shaderFile(name));
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
            out += expandIncludes(file, subs, depth + 1);
            continue;
        }
        out += line;
        out += '\n';
    }
    return out;
}

std::string buildShaderSource(const std::string& name, const ShaderDefines& defines, const ShaderIncludes& subs) {
    std::string src = expandIncludes(name, subs, 0);
    std::string defs;
    for (const auto& [k, v] : defines) defs += "#define " + k + " " + v + "\n";
    const size_t v = src.find("#version");
    if (v == std::string::npos) return "#version 120\n" + defs + src;
    const size_t eol = src.find('\n', v);
    return src.substr(0, eol + 1) + defs + src.substr(eol + 1);
}

}  // namespace lidr
