#pragma once
// Many-light scenes for lidr-bench: the default room's geometry with 1,024 or 4,096 small lights (16-bit
// indices for LIDR), seen from above or at eye height. (The controlled-overlap scenes are in controlled_scenes.h.)
#include <string>

#include "lidr/scene/scene.h"

namespace lidr {

enum class ManyLightView { TopDown, FirstPerson };
// The default room's geometry (3 large movers kept) with `lightCount` - 3 particle lights whose radii shrink
// with sqrt(255 / lightCount), so the mean overlap stays near the default room's as the count grows.
// lightCount in [4, 65535].
Scene makeManyLightScene(int lightCount, ManyLightView view, int width = 1024, int height = 768, uint32_t seed = 1);
const char* manyLightViewName(ManyLightView view);  // "top", "fp"
// By name, as lidr-bench and lidr-demo take it: "many-N-top" or "many-N-fp" (1024x768). False for other names; a
// name with the prefix and a bad N or view throws lidr::Error naming the valid form.
bool makeManyLightSceneByName(const std::string& name, Scene& scene, uint32_t seed = 1);

// The default room (255 lights, its camera) with extra finely tessellated geometry, for frame time against
// scene triangles: a fixed lattice of `heavyMeshCount` spheres (3 layers between the floor and 4 m, over the
// whole floor) whose tessellation grows with `totalTriangles`, so the draw-call count stays the same and
// forward-multipass can still cull per mesh. The result has about `totalTriangles` triangles (at least the
// room's own plus one 8-segment sphere each); Scene::meshes gives the exact count. totalTriangles in
// [1, 20,000,000].
constexpr int heavyMeshCount = 192;
Scene makeHeavyScene(long totalTriangles, int width = 1024, int height = 768, uint32_t seed = 1);
// Triangles of every mesh in the scene.
long sceneTriangleCount(const Scene& scene);

// Deep, occluded scenes (issue 25): the cost of a light-volume pass that rasterises every light's screen area,
// hidden lights included, shows here and not in the room. Both are one mesh per material (a handful of draws,
// like an architectural model), 1024x768 by default, seeded static lights of radius 1 to 4 m.
//   Hall: a nave 70 m long between two rows of 16 pillars (stacked shafts on plinths) with arches along the
//         rows and across the nave, side aisles split into chapels, clerestory walls, about 60 k triangles; the
//         camera at eye height at one end looking down the nave (most aisle lights hidden by pillars and walls).
//   City: 8 x 8 blocks of buildings (6-30 m high) over 6 m streets, about 60 k triangles; the camera at street
//         level looking down a street (most lights hidden by buildings).
enum class OccludedSceneKind { Hall, City };
const char* occludedSceneName(OccludedSceneKind kind);  // "hall", "city"
// lightCount in [1, 65535].
Scene makeOccludedScene(OccludedSceneKind kind, int lightCount, int width = 1024, int height = 768,
                        uint32_t seed = 1);
// By name, as lidr-bench and lidr-demo take it: "hall-N" or "city-N" (N lights). False for other names; a name
// with the prefix and a bad N throws lidr::Error naming the valid form.
bool makeOccludedSceneByName(const std::string& name, Scene& scene, uint32_t seed = 1);

// Spot lights from above (issue 29): "spots-N" is many-N-top with every particle light a spot aimed straight
// down (outer cone 50 degrees, inner 35; the 3 large movers stay point lights); "spots-N-points" the very same
// lights as points, so one lidr-bench run gives the cone's saving as a ratio. False for other names; a name
// with the prefix and a bad N throws lidr::Error naming the valid form.
constexpr float kBenchSpotOuterDegrees = 50.0f, kBenchSpotInnerDegrees = 35.0f;
bool makeSpotSceneByName(const std::string& name, Scene& scene, uint32_t seed = 1);

}  // namespace lidr
