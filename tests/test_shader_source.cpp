// Shader sources: includes expanded with #line directives, so a compiler's line numbers are those of the
// files (GLSL 1.20: the line after `#line L N` is line L + 1 of source string N), and a compile error names
// the files behind the source-string numbers.
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "gl_test_context.h"
#include "lidr/base/error.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/gl/shader_source.h"

using namespace lidr;
using namespace lidr::test;
using Catch::Matchers::Contains;

namespace {
std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
}
}  // namespace

TEST_CASE("buildShaderSource: after #version, every line is where #line says, in the file it names", "[shader][cpu]") {
    struct Case {
        std::string name;
        ShaderDefines defines;
        ShaderIncludes subs;
        std::vector<std::string> files;
    };
    const std::vector<Case> cases = {
        {"tiled_forward.frag", {{"LIDR_X", "1"}}, {}, {"tiled_forward.frag", "light_table.glsl", "shading.glsl", "output_transform.glsl", "material.glsl", "shadow_lookup.glsl", "tiled_grid.glsl"}},
        {"lidr_forward.frag", {}, {{"lidr_unpack.glsl", "unpack_max_stencil.glsl"}},
         {"lidr_forward.frag", "lidr_depth.glsl", "shading.glsl", "output_transform.glsl", "material.glsl", "lidr_lights.glsl", "light_table.glsl",
          "unpack_max_stencil.glsl", "lidr_channel_stream.glsl", "lidr_bytes.glsl", "lidr_index_samplers.glsl",
          "sample_distances.glsl", "shadow_lookup.glsl"}},
        // Emulated 16-bit depth (LidrOptions::emulatedDepthBits): a second substitution, the same line mapping.
        {"lidr_forward.frag", {{"LIDR_DEPTH_STEPS", "65535.0"}},
         {{"lidr_unpack.glsl", "unpack_max_stencil.glsl"}, {"lidr_depth.glsl", "lidr_depth_emulated.glsl"}},
         {"lidr_forward.frag", "lidr_depth_emulated.glsl", "shading.glsl", "output_transform.glsl", "material.glsl", "lidr_lights.glsl", "light_table.glsl",
          "unpack_max_stencil.glsl", "lidr_channel_stream.glsl", "lidr_bytes.glsl", "lidr_index_samplers.glsl",
          "sample_distances.glsl", "shadow_lookup.glsl"}},
        {"geometry.vert", {}, {}, {"geometry.vert"}},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        const std::string src = buildShaderSource(c.name, c.defines, c.subs);
        std::string strings = "source strings:";
        for (size_t i = 0; i < c.files.size(); ++i) strings += (i ? ", " : " ") + std::to_string(i) + " " + c.files[i];
        CHECK(shaderSourceStrings(src) == strings);
        std::vector<std::vector<std::string>> text;
        for (const std::string& f : c.files) text.push_back(lines(shaderFile(f)));
        const std::vector<std::string> out = lines(src);
        REQUIRE(out.size() > 1);
        CHECK(out[0] == "#version 120");
        int file = -1, line = 0, checked = 0, directives = 0;
        for (size_t i = 1; i < out.size(); ++i) {
            int l = 0, n = 0;
            if (std::sscanf(out[i].c_str(), "#line %d %d", &l, &n) == 2) {
                file = n;
                line = l + 1;
                ++directives;
                continue;
            }
            if (file < 0) continue;  // the defines and the source-string comment
            INFO("output line " << i + 1 << ": " << out[i] << " (string " << file << " line " << line << ")");
            REQUIRE(file < static_cast<int>(text.size()));
            REQUIRE(line >= 1);
            REQUIRE(line <= static_cast<int>(text[static_cast<size_t>(file)].size()));
            CHECK(text[static_cast<size_t>(file)][static_cast<size_t>(line - 1)] == out[i]);
            ++checked;
            ++line;
        }
        CHECK(directives == 1 + 2 * (static_cast<int>(c.files.size()) - 1));  // each file included once here
        CHECK(checked > 10);
    }
}

TEST_CASE("a compile error in an included file names that file's source string and line", "[shader][every-gl]") {
    testContext();
    // shading.glsl line 7 is `uniform vec3 uEyePosition;`: defined away it is a syntax error there.
    REQUIRE(lines(shaderFile("shading.glsl")).at(6) == "uniform vec3 uEyePosition;");
    const std::string fs = buildShaderSource("forward_ambient.frag", {{"uEyePosition", "+"}});
    try {
        gl::Program::create("broken", buildShaderSource("geometry.vert"), fs, {});
        FAIL("the broken shader compiled");
    } catch (const GlError& e) {
        INFO(e.what());
        CHECK_THAT(e.what(), Contains("source strings: 0 forward_ambient.frag, 1 shading.glsl"));
        CHECK_THAT(e.what(), Contains("1:7(") || Contains("1(7)"));  // Mesa "1:7(15)", NVIDIA "1(7)"
    }
}
