// libFuzzer harness: the OBJ/MTL importer (lidr/scene/io/scene_loader.h, appendObj).
// The input is an OBJ file, optionally followed by "\n%%MTL\n" and the text of the .mtl file it may name as
// `mtllib fuzz.mtl`. Both are written into a private temporary folder (appendObj reads files) and imported into a
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
        std::string pattern = (std::filesystem::temp_directory_path() / "lidr-fuzz-obj-XXXXXX").string();
        if (!::mkdtemp(pattern.data())) std::abort();
        return pattern;
    }();
    return dir;
}

void writeFile(const std::string& path, const char* data, size_t size) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(data, std::streamsize(size));
    if (!out) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const char* text = reinterpret_cast<const char*>(data);
    static const char separator[] = "\n%%MTL\n";
    const void* split = ::memmem(text, size, separator, sizeof separator - 1);
    const size_t objSize = split ? size_t(static_cast<const char*>(split) - text) : size;
    const std::string obj = workDir() + "/fuzz.obj", mtl = workDir() + "/fuzz.mtl";
    writeFile(obj, text, objSize);
    if (split) {
        const size_t mtlStart = objSize + sizeof separator - 1;
        writeFile(mtl, text + mtlStart, size - mtlStart);
    } else {
        std::filesystem::remove(mtl);
    }
    try {
        lidr::Scene scene;
        lidr::appendObj(scene, obj, glm::mat4(1.0f));
        lidr::fuzz::checkScene(scene);
    } catch (const lidr::Error&) {
    }
    return 0;
}
