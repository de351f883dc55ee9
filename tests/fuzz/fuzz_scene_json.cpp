// libFuzzer harness: the JSON scene loader (lidr/scene/io/scene_loader.h, parseSceneJson).
// Every input must either give a valid Scene or throw lidr::Error; any other exception, a crash, a sanitizer
// report or a hang is a finding. Model and texture paths resolve against tests/fuzz/files (a small OBJ, MTL and
// PNG), so the fuzzer can reach the OBJ importer and the texture checks through a scene file.
// Build and run: doc/stability.md, "Sanitizers and fuzzing".
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_common.h"
#include "lidr/base/error.h"
#include "lidr/scene/io/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    if (lidr::fuzz::asksForHugeWork(text)) return -1;  // limits themselves are tested in test_scene.cpp
    try {
        const lidr::Scene scene = lidr::parseSceneJson(text, LIDR_FUZZ_FILES_DIR, "fuzz.json");
        lidr::fuzz::checkScene(scene);
    } catch (const lidr::Error&) {
        // a clear error: the expected outcome for bad input
    }
    return 0;
}
