#include "lidr/scene/io/bart_scene.h"

#include <filesystem>

#include "lidr/base/error.h"
#include "lidr/scene/bart_lights.h"
#include "lidr/scene/io/file_checks.h"
#include "lidr/scene/io/scene_loader.h"

namespace lidr {

std::string bartSceneFile(const std::string& bart) {
    namespace fs = std::filesystem;
    if (lowerCaseExtension(bart) == ".aff") {
        const std::string problem = fileProblem(bart);
        if (!problem.empty()) throw Error("--bart: the AFF file '" + bart + "' " + problem);
        return bart;
    }
    for (const fs::path& candidate : {fs::path(bart) / "aff" / "Robot.aff", fs::path(bart) / "Robot.aff"})
        if (fileProblem(candidate.string()).empty()) return candidate.lexically_normal().string();
    throw Error("--bart: no BART Robots scene in '" + bart + "' (looked for aff/Robot.aff and Robot.aff; the scene is "
                "../shared/bart-robots beside lidr's source tree, or give an .aff file)");
}

bool makeBartSceneByName(const std::string& name, Scene& scene, uint32_t seed, const std::string& bart,
                         std::string* description) {
    const std::string prefix = "bart-robots";
    if (name.compare(0, prefix.size(), prefix) != 0) return false;
    if (name != "bart-robots-many" && name != "bart-robots-few")
        throw Error("bad scene name '" + name + "': use bart-robots-many (the paper's 924 static lights) or "
                    "bart-robots-few (one light on each robot)");
    const bool many = name == "bart-robots-many";
    scene = loadScene(bartSceneFile(bart));
    BartLightOptions options;
    options.setup = many ? BartLightSetup::ManyStatic : BartLightSetup::FewDynamic;
    options.seed = seed;
    const std::string said = addBartLights(scene, options);
    if (description) *description = said;
    scene.name = name;
    scene.transparency = false;
    scene.validate();
    return true;
}

}  // namespace lidr
