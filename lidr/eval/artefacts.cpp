#include "lidr/eval/artefacts.h"

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "lidr/base/error.h"

namespace lidr {

namespace {
nlohmann::json matrixJson(const glm::mat4& m) {
    nlohmann::json rows = nlohmann::json::array();  // row-major: rows[r][c]
    for (int r = 0; r < 4; ++r) rows.push_back({m[0][r], m[1][r], m[2][r], m[3][r]});
    return rows;
}
void writeJson(const std::filesystem::path& path, const nlohmann::json& j) {
    std::ofstream f(path);
    f << j.dump(2) << "\n";
    if (!f) throw Error("could not write '" + path.string() + "'");
}
}  // namespace

void writeFrameArtefacts(const std::string& dir, const FrameArtefacts& a, const PackingScheme& scheme) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw Error("cannot create dump folder '" + dir + "': " + ec.message());
    const fs::path root(dir);
    for (size_t i = 0; i < a.indexTargets.size(); ++i)
        writePng((root / ("index_target" + std::to_string(i) + ".png")).string(), a.indexTargets[i]);
    writePfm((root / "depth.pfm").string(), a.depth);
    if (!a.lightCounts.empty()) {
        ImageRGBA8 counts(a.depth.width, a.depth.height);
        for (size_t p = 0; p < a.lightCounts.size(); ++p) {
            counts.pixels[p * 4 + 0] = counts.pixels[p * 4 + 1] = counts.pixels[p * 4 + 2] = a.lightCounts[p];
            counts.pixels[p * 4 + 3] = 255;
        }
        writePng((root / "light_counts.png").string(), counts);
    }
    nlohmann::json lights = nlohmann::json::array();
    for (size_t i = 0; i < a.lights.size(); ++i) {
        const PointLight& l = a.lights[i];
        lights.push_back({{"index", i + 1},
                          {"position", {l.position.x, l.position.y, l.position.z}},
                          {"radius", l.radius},
                          {"color", {l.color.r, l.color.g, l.color.b}},
                          {"priority", l.priority}});
    }
    writeJson(root / "lights.json", {{"null_index", 0}, {"draw_order", a.drawOrder}, {"lights", lights}});
    writeJson(root / "camera.json",
              {{"width", a.camera.width},
               {"height", a.camera.height},
               {"eye", {a.camera.eye.x, a.camera.eye.y, a.camera.eye.z}},
               {"near", a.camera.nearPlane},
               {"far", a.camera.farPlane},
               {"view", matrixJson(a.camera.view)},
               {"projection", matrixJson(a.camera.projection)},
               {"view_projection", matrixJson(a.camera.viewProjection)},
               {"depth_convention", "window depth in [0,1], GL default depth range; PFM rows bottom to top"}});
    writeJson(root / "packing.json",
              {{"scheme", packingSchemeName(scheme.config().scheme)},
               {"budget", scheme.config().budget},
               {"index_bits", scheme.config().indexBits},
               {"targets", scheme.targetCount()},
               {"description", scheme.describe()},
               {"stencil_use", scheme.stencilUse()},
               {"volume_passes", scheme.geometryPasses()},
               {"null_ends_list", scheme.nullEndsList()},
               {"png_rows", "top to bottom (PNG order); GL row 0 is the last PNG row"}});
}

}  // namespace lidr
