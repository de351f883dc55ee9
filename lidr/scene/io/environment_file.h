#pragma once
// Environment lights from files (issue 39): what `--environment`, scene files' "environment" and lidr.h users name.
#include <memory>
#include <string>

#include "lidr/scene/environment.h"
#include "lidr/scene/scene.h"

namespace lidr {

constexpr int maxEnvironmentPanoramaWidth = 8192;  // 8192 x 4096 x 3 floats: 400 MB while it is converted
constexpr int maxEnvironmentFaceSize = 4096;

// `source`: "default" (the built-in studio room, lidr::defaultEnvironment()), "none" (null: no environment), or
// a file: an equirectangular Radiance HDR panorama (.hdr: twice as wide as high, three.js's mapping,
// lidr::equirectCoordinates), or a folder holding six faces px, nx, py, ny, pz, nz (+X, -X, +Y, -Y, +Z, -Z, each
// .hdr, .png or .jpg: PNG and JPEG are sRGB and decoded to linear), square, all of one size, each laid out as an
// OpenGL cube-map face (its first row is the face's t = 0 row, as most skybox sets are). Converted to a
// kEnvironmentSize cube, its spherical harmonics and prefiltered levels (prefilterEnvironment); `progress` hears
// each step. Everything is checked before the conversion: throws lidr::Error naming the file and the cause (not
// found, not readable, not a Radiance HDR file, the wrong proportions or face sizes, too large, a pixel not
// finite, negative or above 1e12).
std::shared_ptr<const Environment> loadEnvironment(const std::string& source, const EnvironmentProgress& progress = {});

// What lidr's tools (lidr-demo and lidr-viewer with --environment auto, the web page) give a glTF or OBJ model,
// which carries no environment of its own: the default environment, in place of the uniform ambient (set to 0),
// as the viewers people compare with light a model. Nothing where the scene has an environment already. Returns
// whether it gave one.
bool giveModelDefaultEnvironment(Scene& scene);

// A Radiance HDR file as linear RGB floats, rows top to bottom (stb_image); throws lidr::Error as above.
ImageRGBFloat readHdr(const std::string& path);
// Writes one (stb_image_write's RLE Radiance format); throws lidr::Error if the file cannot be written.
void writeHdr(const std::string& path, const ImageRGBFloat& image);

}  // namespace lidr
