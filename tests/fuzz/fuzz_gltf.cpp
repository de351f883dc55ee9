// libFuzzer harness: the glTF importer (lidr/scene/io/gltf_importer.h, through loadScene). The input is a glTF
// file: binary (.glb) when it starts with the magic "glTF", else JSON (.gltf). It is written into a private
// temporary folder (tinygltf reads files, and external buffers or images relative to them) and loaded as a whole
// scene; the result must be a valid Scene or an lidr::Error. Build and run: doc/stability.md.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "fuzz_common.h"
#include "lidr/base/error.h"
#include "lidr/scene/io/scene_loader.h"

namespace {

const std::string& workDir() {
    static const std::string dir = [] {
        std::string pattern = (std::filesystem::temp_directory_path() / "lidr-fuzz-gltf-XXXXXX").string();
        if (!::mkdtemp(pattern.data())) std::abort();
        return pattern;
    }();
    return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    const std::string path = workDir() + (binary ? "/fuzz.glb" : "/fuzz.gltf");
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
        if (!out) std::abort();
    }
    try {
        const lidr::Scene scene = lidr::loadScene(path);
        lidr::fuzz::checkScene(scene);
    } catch (const lidr::Error&) {
    }
    std::filesystem::remove(path);
    return 0;
}
