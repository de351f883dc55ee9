// OBJ as users have it (issue 14): groups and objects as meshes, large meshes split for culling, smooth normals on
// request, MTL Ke / illum / Tf / d / Tr, and every fallback a warning on the Scene; the emissive term in every mode.
#include <catch2/catch.hpp>

#include "lidr/eval/brdf.h"
#include "lidr/render/output_transform.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "temp_dir.h"
#include "gl_test_context.h"
#include "lidr/base/error.h"
#include "lidr/eval/image_compare.h"
#include "lidr/modes/render_mode.h"
#include "lidr/scene/io/mesh_split.h"
#include "lidr/scene/io/scene_loader.h"

namespace fs = std::filesystem;
using Catch::Contains;

using lidr::test::TempDir;

namespace {


// Two unit quads side by side in the xz plane (4 triangles), as text for the `v` and `f` lines.
const char* const twoQuads = "v 0 0 0\nv 1 0 0\nv 1 0 -1\nv 0 0 -1\nv 2 0 0\nv 2 0 -1\n";

const lidr::Material& materialOf(const lidr::Scene& scene, const std::string& name) {
    for (const lidr::Material& m : scene.materials)
        if (m.name == name) return m;
    FAIL("no material " << name);
    return scene.materials[0];
}

bool anyWarning(const lidr::Scene& scene, const std::string& text) {
    return std::any_of(scene.warnings.begin(), scene.warnings.end(),
                       [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

}  // namespace

TEST_CASE("OBJ: g groups and o objects become separate meshes, also without usemtl", "[obj][cpu]") {
    TempDir dir;
    const lidr::Scene scene = lidr::loadScene(dir.write("atrium.obj", std::string(twoQuads) +
        "g left\nf 1 2 3\nf 1 3 4\ng right\nf 2 5 6\nf 2 6 3\no pillar\nf 1 5 6\n"));
    REQUIRE(scene.meshes.size() == 3);
    CHECK(scene.meshes[0].name == "atrium/left/default");
    CHECK(scene.meshes[1].name == "atrium/right/default");
    CHECK(scene.meshes[2].name == "atrium/pillar/default");
    CHECK(scene.meshes[0].triangleCount() == 2);
    CHECK(scene.meshes[1].triangleCount() == 2);
    CHECK(scene.meshes[2].triangleCount() == 1);
    // no g/o: one mesh per material, named as before
    const lidr::Scene plain = lidr::loadScene(dir.write("plain.obj", std::string(twoQuads) + "f 1 2 3 4\nf 2 5 6 3\n"));
    REQUIRE(plain.meshes.size() == 1);
    CHECK(plain.meshes[0].name == "plain/default");
}

TEST_CASE("OBJ: meshes above 16384 triangles are split spatially, every triangle kept once", "[obj][cpu]") {
    // A 100 x 100 grid of quads: 20,000 triangles in one group.
    std::string obj;
    const int n = 100;
    for (int z = 0; z <= n; ++z)
        for (int x = 0; x <= n; ++x) obj += "v " + std::to_string(x) + " 0 " + std::to_string(-z) + "\n";
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x) {
            const int a = z * (n + 1) + x + 1;
            obj += "f " + std::to_string(a) + " " + std::to_string(a + 1) + " " + std::to_string(a + n + 2) + " " +
                   std::to_string(a + n + 1) + "\n";
        }
    TempDir dir;
    const lidr::Scene scene = lidr::loadScene(dir.write("grid.obj", obj));
    REQUIRE(scene.meshes.size() == 2);  // 20,000 > 16,384: halves of 10,000
    std::multiset<std::tuple<float, float, float>> corners;
    size_t triangles = 0;
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const lidr::Mesh& mesh = scene.meshes[m];
        CHECK(mesh.name == "grid/default#" + std::to_string(m));
        CHECK(mesh.triangleCount() <= lidr::maxTrianglesPerImportedMesh);
        triangles += mesh.triangleCount();
        for (uint32_t i : mesh.indices) corners.insert({mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z});
    }
    CHECK(triangles == 20000);
    CHECK(corners.size() == 60000);
    // split along x (the longer axis ties with z; x first): the halves do not overlap beyond one column
    const float maxLeft = std::max_element(scene.meshes[0].positions.begin(), scene.meshes[0].positions.end(),
                                           [](auto& a, auto& b) { return a.x < b.x; })->x;
    const float minRight = std::min_element(scene.meshes[1].positions.begin(), scene.meshes[1].positions.end(),
                                            [](auto& a, auto& b) { return a.x < b.x; })->x;
    CHECK(maxLeft <= 51.0f);
    CHECK(minRight >= 49.0f);
    // the splitter alone: parts of at most the limit, the same triangles
    lidr::Mesh whole = scene.meshes[0];
    const std::vector<lidr::Mesh> parts = lidr::splitMeshSpatially(whole, 1000);
    CHECK(parts.size() == 16);  // 10,000 halved until <= 1000: 16 parts of 625
    size_t sum = 0;
    for (const lidr::Mesh& part : parts) {
        sum += part.triangleCount();
        CHECK(part.triangleCount() <= 1000);
    }
    CHECK(sum == whole.triangleCount());
}

TEST_CASE("OBJ: smooth normals on request for faces without vn", "[obj][cpu]") {
    TempDir dir;
    // A roof: two faces meeting at a ridge, no normals, no smoothing group.
    const std::string roof = dir.write("roof.obj", "v 0 0 0\nv 0 1 1\nv 0 0 2\nv 1 0 0\nv 1 1 1\nv 1 0 2\nf 1 4 5 2\nf 2 5 6 3\n");
    const lidr::Scene flat = lidr::loadScene(roof);
    REQUIRE(flat.meshes.size() == 1);
    CHECK(flat.meshes[0].positions.size() == 8);  // flat: the ridge vertices are not shared
    lidr::ObjImportOptions smooth;
    smooth.smoothNormals = true;
    const lidr::Scene smoothed = lidr::loadScene(roof, smooth);
    REQUIRE(smoothed.meshes.size() == 1);
    const lidr::Mesh& mesh = smoothed.meshes[0];
    CHECK(mesh.positions.size() == 6);
    for (size_t i = 0; i < mesh.positions.size(); ++i)
        // the ridge: the average of the two faces (wound facing down here), straight down
        if (mesh.positions[i].y == 1.0f) CHECK(glm::length(mesh.normals[i] - glm::vec3(0, -1, 0)) < 1e-5f);
    // the scene-file field does the same per model
    dir.write("roof.json", R"({"models": [{"file": "roof.obj", "smooth_normals": true}], "lights": [{"position": [0, 2, 0], "radius": 3}]})");
    CHECK(lidr::loadScene((fs::path(roof).parent_path() / "roof.json").string()).meshes[0].positions.size() == 6);
}

TEST_CASE("OBJ: MTL Ke, illum, Tf, d and Tr, and every fallback a warning", "[obj][cpu]") {
    TempDir dir;
    dir.write("box.mtl",
              "newmtl lamp\nKd 0.5 0.5 0.5\nKe 4 3 2\nillum 2\n"
              "newmtl flat\nKd 0.2 0.4 0.6\nillum 0\n"
              "newmtl matte\nKd 0.5 0.5 0.5\nKs 1 1 1\nillum 1\n"
              "newmtl glass\nKd 0.1 0.1 0.1\nTf 0.7 0.7 0.7\nillum 7\n"
              "newmtl mirror\nKd 0.1 0.1 0.1\nillum 3\n"
              "newmtl odd\nillum 12\n"
              "newmtl plastic\nKs 0.5 0.5 0.5\n"
              "newmtl ghost\nd 0\n"
              "newmtl inverted\nTr 1\n");
    std::string obj = std::string("mtllib box.mtl\n") + twoQuads;
    for (const char* m : {"lamp", "flat", "matte", "glass", "mirror", "odd", "plastic", "ghost", "inverted", "nosuch"})
        obj += std::string("usemtl ") + m + "\nf 1 2 3\n";
    const lidr::Scene scene = lidr::loadScene(dir.write("box.obj", obj));
    CHECK(materialOf(scene, "lamp").emissive == lidr::displayColourToLinear(glm::vec3(4, 3, 2)));  // decoded: doc/colour.md
    CHECK(materialOf(scene, "flat").emissive == lidr::srgbToLinear(glm::vec3(0.2f, 0.4f, 0.6f)));  // illum 0: Kd as is, unlit
    CHECK(materialOf(scene, "flat").diffuse == glm::vec3(0.0f));
    CHECK(materialOf(scene, "matte").specular == glm::vec3(0.0f));              // illum 1: no highlights
    CHECK(materialOf(scene, "glass").opacity == Approx(0.3f));                  // illum 7: 1 - mean(Tf)
    CHECK(materialOf(scene, "plastic").specular == lidr::srgbToLinear(glm::vec3(0.5f)));            // no illum: as illum 2
    CHECK(materialOf(scene, "plastic").emissive == glm::vec3(0.0f));
    CHECK(materialOf(scene, "ghost").opacity == 1.0f);
    CHECK(materialOf(scene, "inverted").opacity == 1.0f);
    CHECK(anyWarning(scene, "box.obj: material 'glass': illum 7 (glass) drawn as a transparent surface with opacity 0.3"));
    CHECK(anyWarning(scene, "material 'mirror': illum 3 asks for reflection/refraction"));
    CHECK(anyWarning(scene, "material 'odd': unknown illum 12"));
    CHECK(anyWarning(scene, "material 'ghost': d 0 (or Tr 1) would make it invisible; drawn opaque"));
    CHECK(anyWarning(scene, "material 'inverted': d 0 (or Tr 1)"));
    CHECK(anyWarning(scene, "box.obj: material [ 'nosuch' ] not found in .mtl"));
    CHECK(!anyWarning(scene, "'lamp'"));
    CHECK(!anyWarning(scene, "'plastic'"));

    const lidr::Scene noMtl = lidr::loadScene(dir.write("lost.obj", std::string("mtllib lost.mtl\n") + twoQuads + "usemtl x\nf 1 2 3\n"));
    CHECK(anyWarning(noMtl, "lost.obj: Material file [ lost.mtl ] not found"));
    REQUIRE(noMtl.meshes.size() == 1);
    CHECK(noMtl.materials[size_t(noMtl.meshes[0].material)].name == "default");
}

TEST_CASE("OBJ: a negative Ke is an error naming the keyword; scene-file materials take \"emissive\"", "[obj][cpu][bad-input]") {
    TempDir dir;
    dir.write("neg.mtl", "newmtl n\nKe 0 -1 0\n");
    REQUIRE_THROWS_WITH(lidr::loadScene(dir.write("neg.obj", std::string("mtllib neg.mtl\n") + twoQuads + "usemtl n\nf 1 2 3\n")),
                        Contains("neg.obj: material 'n': Ke must be finite and >= 0"));
    const lidr::Scene scene = lidr::loadScene(dir.write("glow.json", R"({"materials": [{"name": "glow", "emissive": [1, 0.5, 0]}],
        "primitives": [{"shape": "box", "min": [0, 0, 0], "max": [1, 1, 1], "material": "glow"}], "lights": []})"));
    CHECK(materialOf(scene, "glow").emissive == lidr::srgbToLinear(glm::vec3(1, 0.5f, 0)));
    REQUIRE_THROWS_WITH(lidr::loadScene(dir.write("bad.json", R"({"materials": [{"name": "g", "emissive": -1}]})")),
                        Contains("materials[0].emissive: colour components must be >= 0"));
}

TEST_CASE("emissive materials look the same in every mode, with no light at all", "[obj][every-gl]") {
    TempDir dir;
    lidr::Scene scene = lidr::loadScene(dir.write("glow.json", R"({
        "camera": {"position": [0, 0, 4], "target": [0, 0, 0]},
        "ambient": 0.1,
        "materials": [{"name": "glow", "diffuse": [0.5, 0.5, 0.5], "emissive": [0.6, 0.2, 0.0]}],
        "primitives": [{"shape": "box", "min": [-1, -1, -1], "max": [1, 1, 1], "material": "glow"}]})"));
    scene.width = lidr::test::testWidth();
    scene.height = lidr::test::testHeight();
    std::vector<lidr::ImageRGBA8> images;
    bool eightBitMultipass = false;
    for (const char* mode : {"lidr", "tiled", "clustered", "forward-multipass", "forward-brute"}) {
        lidr::RenderModeOptions options;
        options.mode = mode;
        auto renderer = lidr::createRenderer(options, lidr::test::testGl(), scene, scene.width, scene.height);
        renderer->render(scene.camera, scene.lightsAt(scene.time), {scene.ambient});
        images.push_back(renderer->targets().readColor());
        // the box's centre: the ambient term + emissive (colours decoded from sRGB; lidr/eval/brdf.h), through the default
        // output transform (PBR Neutral, sRGB): the CPU model's pixel, +- rounding
        // (the box's front face, normal +z, seen head-on from the camera at z = 4)
        const lidr::BrdfSurface surface = lidr::brdfSurface(scene.materials[0], glm::dvec3(0, 0, 1), glm::dvec3(0, 0, 1),
                                                            glm::dvec3(0, 0, 4));
        const glm::dvec3 linear = lidr::shadeAmbient(surface, glm::dvec3(0.1)) +
                                  glm::dvec3(lidr::srgbToLinear(glm::vec3(0.6f, 0.2f, 0.0f)));
        // multi-pass forward without half-float colour buffers sums in its 8-bit linear target, then encodes
        // (doc/colour.md): rounded first
        const auto* multipass = dynamic_cast<const lidr::MultipassForwardRenderer*>(renderer.get());
        if (multipass) eightBitMultipass = std::string(multipass->accumulation()) == "8-bit";
        const glm::dvec3 summed = multipass && eightBitMultipass ? glm::round(linear * 255.0) / 255.0 : linear;
        const glm::dvec3 expected = 255.0 * lidr::applyOutputTransform(summed, lidr::OutputTransform{});
        const uint8_t* centre = images.back().at(scene.width / 2, scene.height / 2);
        INFO(mode << ": " << int(centre[0]) << " " << int(centre[1]) << " " << int(centre[2]) << ", expected "
                  << expected.r << " " << expected.g << " " << expected.b);
        for (int k = 0; k < 3; ++k) CHECK(std::abs(int(centre[k]) - expected[k]) <= 1.0);
    }
    // lidr, tiled, clustered and forward-brute transform the same float sum; multi-pass its half-float sum (1 step),
    // or its 8-bit linear sum
    for (size_t i = 1; i < images.size(); ++i)
        CHECK(lidr::compareImages(images[0], images[i]).maxAbsError <= (i == 3 ? (eightBitMultipass ? 2 : 1) : 0));
}
