// libFuzzer harness: BART's AFF reader (lidr/scene/io/aff_importer.h) through loadScene, with its includes and PPM
// textures. The input is the scene file `fuzz.aff`, optionally followed by a line "%%INC" and the text of
// `inc.aff` (which the scene may include, `i 0 inc.aff`, and which may include it back), and a line "%%PPM" and
// the bytes of `fuzz.ppm` (a texture either may name). All are written into a private temporary folder; the result
// must be a valid Scene or an lidr::Error. Build and run: doc/stability.md.
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "fuzz_common.h"
#include "lidr/base/error.h"
#include "lidr/scene/animation.h"
#include "lidr/scene/io/scene_loader.h"

namespace {

const std::string& workDir() {
    static const std::string dir = [] {
        std::string pattern = (std::filesystem::temp_directory_path() / "lidr-fuzz-aff-XXXXXX").string();
        if (!::mkdtemp(pattern.data())) std::abort();
        return pattern;
    }();
    return dir;
}

void writeFile(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out) std::abort();
}

// Splits off the text after "\n<marker>\n" (the rest of the input, up to the next marker), or nothing.
std::string section(std::string& text, const std::string& marker) {
    const std::string separator = "\n" + marker + "\n";
    const size_t at = text.find(separator);
    if (at == std::string::npos) return {};
    std::string rest = text.substr(at + separator.size());
    text.resize(at);
    return rest;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string text(reinterpret_cast<const char*>(data), size);
    const std::string ppm = section(text, "%%PPM");
    const std::string include = section(text, "%%INC");
    const std::string scene = workDir() + "/fuzz.aff", inc = workDir() + "/inc.aff", texture = workDir() + "/fuzz.ppm";
    writeFile(scene, text);
    writeFile(inc, include);
    writeFile(texture, ppm);
    try {
        lidr::Scene loaded = lidr::loadScene(scene);
        lidr::fuzz::checkScene(loaded);
        // The animation must be playable: every frame's transforms, lights and camera finite.
        const lidr::SceneAnimation& a = loaded.animation;
        for (float t : {a.start, 0.5f * (a.start + a.end), a.end}) {
            for (const glm::mat4& m : lidr::meshTransformsAt(loaded, t))
                for (int c = 0; c < 4; ++c)
                    for (int r = 0; r < 4; ++r)
                        if (!std::isfinite(m[c][r])) std::abort();
            loaded.lightsAt(t);
            lidr::cameraAt(loaded, t);
        }
    } catch (const lidr::Error&) {
    }
    return 0;
}
