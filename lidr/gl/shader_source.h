#pragma once
// GLSL sources come from the files in shaders/, embedded at build time (cmake/EmbedShaders.cmake).
// A source may say `#include "file.glsl"`; defines are inserted right after its `#version` line. Files are named
// by file name alone (shaders/common/, technique/, modes/ are for people; names are unique across them).
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

// The file with includes expanded and `#define NAME VALUE` lines added after `#version`. Each file is a GLSL
// source string (0: `name`, then each included file in first-include order) and `#line` directives keep the
// compiler's line numbers those of the files, so a log line "2:7(15): error" is line 7 of source string 2;
// a comment line "// lidr source strings: 0 a.frag, 1 b.glsl" after the defines names the numbers.
std::string buildShaderSource(const std::string& name, const ShaderDefines& defines = {},
                              const ShaderIncludes& substitutions = {});

// The same for a source the program gives (a user material shader): `text` is source string 0, named `name`
// in messages; its #include lines name lidr's shader files.
std::string buildShaderSourceFromText(const std::string& name, const std::string& text,
                                      const ShaderDefines& defines = {}, const ShaderIncludes& substitutions = {});

// "source strings: 0 a.frag, 1 b.glsl" from a source buildShaderSource made; empty for any other source.
std::string shaderSourceStrings(const std::string& source);

}  // namespace lidr
