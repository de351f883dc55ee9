#include "lidr/scene/io/environment_file.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include <stb_image.h>
#include <stb_image_write.h>

#include "lidr/base/colour.h"
#include "lidr/base/error.h"
#include "lidr/scene/io/file_checks.h"

namespace lidr {

namespace {
namespace fs = std::filesystem;

constexpr float kMaxRadiance = 1e12f;  // beyond it the filters' float sums lose the rest of the panorama

using StbFloats = std::unique_ptr<float, void (*)(void*)>;

// The file's pixels as linear floats (3 channels), after the checks every environment file gets.
StbFloats loadPixels(const std::string& path, bool hdr, int maxSide, int& width, int& height) {
    const std::string problem = fileProblem(path);
    if (!problem.empty()) throw Error(path + ": " + problem);
    if (hdr && !stbi_is_hdr(path.c_str()))
        throw Error(path + ": not a Radiance HDR file (an environment panorama is linear light: .hdr, RGBE)");
    int channels = 0;
    if (!stbi_info(path.c_str(), &width, &height, &channels))
        throw Error(path + ": cannot read the image: " + stbi_failure_reason());
    if (width > maxSide || height > maxSide)
        throw Error(path + ": " + std::to_string(width) + " x " + std::to_string(height) + " pixels; at most " +
                    std::to_string(maxSide) + " a side");
    int w = 0, h = 0;
    StbFloats pixels(nullptr, stbi_image_free);
    if (hdr) {
        pixels.reset(stbi_loadf(path.c_str(), &w, &h, &channels, 3));
        if (!pixels) throw Error(path + ": cannot read the image: " + stbi_failure_reason());
    } else {  // PNG / JPEG: sRGB-encoded bytes, decoded here (stbi_loadf's own conversion is a plain 2.2 gamma)
        std::unique_ptr<stbi_uc, void (*)(void*)> bytes(stbi_load(path.c_str(), &w, &h, &channels, 3), stbi_image_free);
        if (!bytes) throw Error(path + ": cannot read the image: " + stbi_failure_reason());
        pixels = StbFloats(static_cast<float*>(std::malloc(size_t(w) * size_t(h) * 3 * sizeof(float))), std::free);
        if (!pixels) throw Error(path + ": out of memory for " + std::to_string(w) + " x " + std::to_string(h) + " pixels");
        for (size_t i = 0; i < size_t(w) * size_t(h) * 3; ++i) pixels.get()[i] = float(srgbToLinear(bytes.get()[i] / 255.0));
    }
    const size_t count = size_t(w) * size_t(h) * 3;
    float* p = pixels.get();
    for (size_t i = 0; i < count; ++i) {
        if (!std::isfinite(p[i]) || p[i] < 0.0f || p[i] > kMaxRadiance) {
            const size_t pixel = i / 3;
            throw Error(path + ": pixel (" + std::to_string(pixel % size_t(w)) + ", " + std::to_string(pixel / size_t(w)) +
                        ") is " + (std::isfinite(p[i]) ? str(double(p[i])) : std::string("not finite")) +
                        "; radiance must be finite, >= 0 and at most 1e12");
        }
    }
    width = w;
    height = h;
    return pixels;
}

// `pixels` (w x h x 3) box-filtered by 2^halvings into an image.
ImageRGBFloat boxFiltered(const float* pixels, int w, int h, int halvings) {
    const int f = 1 << halvings;
    ImageRGBFloat image(w / f, h / f);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            glm::dvec3 sum(0.0);
            for (int j = 0; j < f; ++j)
                for (int i = 0; i < f; ++i) {
                    const float* p = pixels + (size_t(y * f + j) * size_t(w) + size_t(x * f + i)) * 3;
                    sum += glm::dvec3(p[0], p[1], p[2]);
                }
            image.at(x, y) = glm::vec3(sum / double(f * f));
        }
    return image;
}

std::shared_ptr<const Environment> fromPanorama(const std::string& path, const EnvironmentProgress& progress) {
    int w = 0, h = 0;
    const StbFloats pixels = loadPixels(path, true, maxEnvironmentPanoramaWidth, w, h);
    if (w != 2 * h)
        throw Error(path + ": " + std::to_string(w) + " x " + std::to_string(h) +
                    " pixels; an equirectangular panorama is twice as wide as high");
    // Box-filtered down to at most 2048 wide first: the cube's 4 x 4 samples a texel then see every pixel's light
    // (a small sun is not missed or doubled).
    int halvings = 0;
    while ((w >> halvings) > 2048) ++halvings;
    const ImageRGBFloat panorama = boxFiltered(pixels.get(), w, h, halvings);
    if (progress) progress("read " + path + " (" + std::to_string(w) + " x " + std::to_string(h) + ")");
    const CubeImage cube = cubeFromEquirect(panorama, kEnvironmentSize);
    if (progress) progress("converted to a cube of " + std::to_string(kEnvironmentSize) + " texels a face");
    return std::make_shared<const Environment>(
        prefilterEnvironment(cube, path, kEnvironmentLevels, kEnvironmentSamples, progress));
}

std::shared_ptr<const Environment> fromFaces(const std::string& folder, const EnvironmentProgress& progress) {
    const char* names[6] = {"px", "nx", "py", "ny", "pz", "nz"};
    std::vector<ImageRGBFloat> faces;
    for (const char* name : names) {
        std::string found;
        for (const char* ext : {".hdr", ".png", ".jpg", ".jpeg"})
            if (found.empty() && fs::exists(fs::path(folder) / (std::string(name) + ext)))
                found = (fs::path(folder) / (std::string(name) + ext)).string();
        if (found.empty())
            throw Error(folder + ": no face '" + name + "' (.hdr, .png or .jpg): a folder environment holds six faces px, "
                        "nx, py, ny, pz, nz");
        const bool hdr = lowerCaseExtension(found) == ".hdr";
        int w = 0, h = 0;
        const StbFloats pixels = loadPixels(found, hdr, maxEnvironmentFaceSize, w, h);
        if (w != h) throw Error(found + ": " + std::to_string(w) + " x " + std::to_string(h) + " pixels; a cube face is square");
        if (!faces.empty() && w != faces.front().width)
            throw Error(found + ": " + std::to_string(w) + " x " + std::to_string(h) + " pixels; the other faces are " +
                        std::to_string(faces.front().width) + " x " + std::to_string(faces.front().width));
        faces.push_back(boxFiltered(pixels.get(), w, h, 0));
    }
    CubeImage cube(faces.front().width);
    for (int f = 0; f < 6; ++f)
        for (int y = 0; y < cube.size; ++y)
            for (int x = 0; x < cube.size; ++x) cube.at(f, x, y) = faces[size_t(f)].at(x, y);
    if (progress) progress("read six faces of " + std::to_string(cube.size) + " texels from " + folder);
    return std::make_shared<const Environment>(prefilterEnvironment(resampleCube(cube, kEnvironmentSize), folder,
                                                                    kEnvironmentLevels, kEnvironmentSamples, progress));
}
}  // namespace

std::shared_ptr<const Environment> loadEnvironment(const std::string& source, const EnvironmentProgress& progress) {
    if (source == "none") return nullptr;
    if (source == "default") return defaultEnvironment();
    std::error_code ec;
    if (fs::is_directory(source, ec)) return fromFaces(source, progress);
    if (lowerCaseExtension(source) != ".hdr") {
        const std::string problem = fileProblem(source);
        throw Error(source + ": " + (problem.empty() ? "not an environment: give an equirectangular .hdr panorama, a folder of "
                                                        "six faces, default or none"
                                                      : problem));
    }
    return fromPanorama(source, progress);
}

bool giveModelDefaultEnvironment(Scene& scene) {
    if (scene.environment) return false;
    scene.environment = defaultEnvironment();
    scene.ambient = glm::vec3(0.0f);
    return true;
}

ImageRGBFloat readHdr(const std::string& path) {
    int w = 0, h = 0;
    const StbFloats pixels = loadPixels(path, true, maxEnvironmentPanoramaWidth, w, h);
    return boxFiltered(pixels.get(), w, h, 0);
}

void writeHdr(const std::string& path, const ImageRGBFloat& image) {
    if (!stbi_write_hdr(path.c_str(), image.width, image.height, 3, &image.pixels[0].x))
        throw Error("could not write '" + path + "'");
}

}  // namespace lidr
