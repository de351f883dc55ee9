#pragma once
// GLSL sources come from the files in shaders/, embedded at build time (cmake/EmbedShaders.cmake).
// A source may say `#include "file.glsl"`; defines are inserted right after its `#version` line.
#include <string>
#include <utility>
#include <vector>

namespace lidr {

namespace detail {
struct EmbeddedShader {
    const char* name;
    const char* source;
};
extern const EmbeddedShader kEmbeddedShaders[];
}  // namespace detail

using ShaderDefines = std::vector<std::pair<std::string, std::string>>;
// Include substitutions: {"lidr_unpack.glsl", "unpack_bitshift.glsl"} makes that #include read the other file.
using ShaderIncludes = std::vector<std::pair<std::string, std::string>>;

// The raw text of shaders/<name>; throws lidr::Error if there is no such file.
std::string shaderFile(const std::string& name);

// The file with includes expanded and `#define NAME VALUE` lines added after `#version`.
std::string buildShaderSource(const std::string& name, const ShaderDefines& defines = {},
                              const ShaderIncludes& substitutions = {});

}  // namespace lidr
