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

enum class ShaderStage { Vertex, Fragment };

// A GLSL 1.20 source (what buildShaderSource makes) as GLSL ES 1.00 for an OpenGL ES 2.0 context; gl::Program
// calls it when the current context is ES, so every shader, a program's material shader included, comes from
// the same files. Only the header changes; the rest is the source as it was (lidr's shaders keep to the common
// subset: no integer bit operations, constant loop bounds, float literals where a float is meant, no texelFetch):
//   `#version 120` -> `#version 100`;
//   fragment shaders: `#extension GL_EXT_draw_buffers : require` (where the context defines GL_EXT_draw_buffers)
//     if gl_FragData[i], i > 0, is written, then
//     highp float and highp sampler2D where GL_FRAGMENT_PRECISION_HIGH is defined (samplers default to lowp, and
//     Mesa really returns lowp texels: the light table and the depth copy lose their precision), else mediump
//     with LIDR_FRAGMENT_FP16 defined (the bit-exact fp16 unpack of lidr_bytes.glsl; doc/contexts.md says which
//     paths that proves exact);
//   `#line L N` -> `#line L+1 N`: GLSL 1.20 counts the next line as L + 1, GLSL ES 1.00 as L (both number source
//   strings, so the "lidr source strings" names hold).
//   gl_FragDepth -> EXT_frag_depth's gl_FragDepthEXT, the extension required (the compile names it if missing);
//   textureCubeLod -> EXT_shader_texture_lod's textureCubeLodEXT, the extension enabled where defined; samplerCube
//   at the precision of sampler2D.
// Throws lidr::Error for a source that needs more than GLSL 1.20 (the per-sample MSAA path's 1.50), naming it.
std::string glslEs100FromGlsl120(const std::string& source, ShaderStage stage, const std::string& name);

// A GLSL 1.20 source as a desktop context compiles it: a fragment shader that names textureCubeLod (shading.glsl's
// environment lookup) enables ARB_shader_texture_lod where the context defines it (GLSL 1.20 has the *Lod lookups
// in vertex shaders only; the variant that calls it is compiled only where GlInfo::textureLod says so).
std::string glsl120WithExtensions(const std::string& source, ShaderStage stage);

// A GLSL 1.20 source (what buildShaderSource makes) as GLSL 1.50 compatibility with ARB_sample_shading, for
// the per-sample MSAA paths: texelFetch on sampler2DMS and gl_SampleID; the compatibility profile keeps every
// GLSL 1.20 construct the shaders use. sampleShading false: without the extension (texelFetch on sampler2DMS
// alone: the sample distances of LIDR's MSAA spans). Throws lidr::Error for a source without `#version 120`.
std::string perSampleGlsl150(std::string source, bool sampleShading = true);

// "source strings: 0 a.frag, 1 b.glsl" from a source buildShaderSource made; empty for any other source.
std::string shaderSourceStrings(const std::string& source);

}  // namespace lidr
