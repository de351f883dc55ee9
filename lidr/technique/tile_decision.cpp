#include "lidr/technique/tile_decision.h"

#include <algorithm>

#include "lidr/scene/sphere_bounds.h"
#include "lidr/technique/light_volume_geometry.h"

namespace lidr {

TileDecision::Choice TileDecision::decide(double rectArea, double screenPixels) const {
    Choice c;
    c.rectArea = rectArea;
    c.tiles = rectArea >= kMinArea * screenPixels;
    if (c.tiles && measured_ && !narrower_ && framesSince_ < kRecheckFrames &&
        savingScreens_ * rectArea / std::max(rectArea_, 1.0) < kMinSaving) {
        c.tiles = false;
        c.skippedForSaving = true;
    }
    return c;
}

double TileDecision::savingScreens(const TileFrame& f, double screenPixels) {
    // A frame whose tiles culled every light drew nothing: the meshes would have drawn each light once.
    const double drawsPerLight = f.volumes == 0 ? 1.0 : double(f.stepLights) / double(f.volumes);
    return (f.meshRectArea * drawsPerLight - double(f.quadPixels)) / screenPixels;
}

void TileDecision::recordTileFrame(const TileFrame& frame, double screenPixels) {
    measured_ = true;
    savingScreens_ = savingScreens(frame, screenPixels);
    rectArea_ = frame.rectArea;
    narrower_ = frame.narrower;
    framesSince_ = 0;
}

void TileDecision::recordMeshFrame() {
    if (measured_) ++framesSince_;
}

double sphereRectPixels(const CameraMatrices& camera, const PointLight& l) {
    glm::ivec4 r;
    if (!spherePixelRect(camera, l.position, l.radius * LightVolumeGeometry::kSphereRadiusScale, r)) return 0.0;
    return double(r.z - r.x + 1) * double(r.w - r.y + 1);
}

double lightRectArea(const CameraMatrices& camera, const std::vector<PointLight>& lights) {
    double area = 0.0;
    for (const PointLight& l : lights) area += sphereRectPixels(camera, l);
    return area;
}

}  // namespace lidr
