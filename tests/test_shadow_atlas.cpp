// The shadow atlas (lidr/render/shadow_atlas.h): each spot light's map holds the depth of the nearest opaque
// surface along its texels' rays, checked against a CPU ray cast; maps are drawn again only when their light
// moved or a scene change touched its range; refused casters and sizes name the rule.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include <glm/gtc/matrix_transform.hpp>

#include "gl_test_context.h"
#include "lidr/render/gpu_scene.h"
#include "lidr/modes/reference_renderer.h"
#include "lidr/render/shadow_atlas.h"
#include "lidr/render/shadow_lookup.h"
#include "lidr/scene/primitives.h"

using namespace lidr;
using namespace lidr::test;

namespace {
// A 20 m floor at y = 0 and a 1 m box floating over its centre (1 <= y <= 2).
Scene floorAndBox() {
    Scene scene;
    scene.materials.push_back(Material{});
    addPlane(scene, glm::vec3(0.0f), glm::vec2(20.0f), 0);
    addBox(scene, glm::vec3(-0.5f, 1.0f, -0.5f), glm::vec3(0.5f, 2.0f, 0.5f), 0);
    return scene;
}

PointLight spotDown(const glm::vec3& position, float outerDegrees) {
    PointLight l;
    l.position = position;
    l.radius = 10.0f;
    l.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    l.outerConeAngle = glm::radians(outerDegrees);
    l.innerConeAngle = 0.5f * l.outerConeAngle;
    return l;
}

// Distance along the ray to the nearest of the floor and the box; 0: no hit.
enum class Hit { None, Floor, Box };
Hit castRay(const glm::dvec3& origin, const glm::dvec3& direction, double& t) {
    Hit hit = Hit::None;
    t = 1e30;
    if (direction.y < 0.0) {
        const double tf = -origin.y / direction.y;
        const glm::dvec3 p = origin + tf * direction;
        if (std::abs(p.x) <= 10.0 && std::abs(p.z) <= 10.0) t = tf, hit = Hit::Floor;
    }
    const glm::dvec3 lo(-0.5, 1.0, -0.5), hi(0.5, 2.0, 0.5);
    double t0 = 0.0, t1 = 1e30;
    for (int a = 0; a < 3; ++a) {
        if (std::abs(direction[a]) < 1e-12) {
            if (origin[a] < lo[a] || origin[a] > hi[a]) return hit;
            continue;
        }
        double ta = (lo[a] - origin[a]) / direction[a], tb = (hi[a] - origin[a]) / direction[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta), t1 = std::min(t1, tb);
    }
    if (t0 <= t1 && t0 < t) t = t0, hit = Hit::Box;
    return hit;
}
}  // namespace

TEST_CASE("shadow atlas: each map holds the nearest surface's depth along its texels' rays", "[shadows][every-gl]") {
    testContext();
    const Scene scene = floorAndBox();
    GpuScene gpu(scene);
    ShadowAtlasOptions options;
    options.size = 512;
    options.tileSize = 128;
    options.slopeBias = 0.0f;  // the surfaces' own depths, unbiased
    options.packedDepth = GENERATE(false, true);  // a depth texture; RGBA8 holding 24 bits (ES 2.0's fallback)
    if (testGl().gles && !options.packedDepth) return;  // ES 2.0 reads no depth texture back
    ShadowAtlas atlas(testGl(), options);
    CHECK(atlas.packed() == options.packedDepth);
    // A spot straight above the box, a point light beside it (six faces) and a spot at a slant.
    PointLight slanted = spotDown({3.0f, 4.0f, 1.0f}, 50.0f);
    slanted.direction = glm::normalize(glm::vec3(-0.6f, -1.0f, -0.2f));
    PointLight point;
    point.position = {2.0f, 3.0f, 1.5f};
    point.radius = 8.0f;
    const std::vector<PointLight> lights = {spotDown({0.0f, 5.0f, 0.0f}, 40.0f), point, slanted};
    REQUIRE(atlas.update(gpu, lights, {0, 1, 2}) == 8);
    REQUIRE(atlas.slots().size() == 8);
    const std::vector<float> depth = atlas.readDepth();
    std::map<int, long> floorTexels, boxTexels, emptyTexels;
    for (const ShadowAtlas::Slot& slot : atlas.slots()) {
        {  // every slot in one pass (sections would run apart and the counts below would see one)
            const CameraMatrices& cam = slot.camera;
            const int n = atlas.tileSize();
            const glm::dmat4 inverse(cam.inverseViewProjection);
            auto rayAt = [&](double x, double y) {  // through tile position (x, y) in texels
                const glm::dvec4 far = inverse * glm::dvec4(2.0 * x / n - 1.0, 2.0 * y / n - 1.0, 1.0, 1.0);
                return glm::normalize(glm::dvec3(far) / far.w - glm::dvec3(cam.eye));
            };
            long compared = 0;
            double worst = 0.0;
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    double t = 0.0;
                    const Hit hit = castRay(glm::dvec3(cam.eye), rayAt(x + 0.5, y + 0.5), t);
                    // Only texels whose corners see the same surface: at an edge the rasteriser's coverage rule
                    // decides, which the ray cast does not model.
                    bool interior = true;
                    for (int c = 0; c < 4 && interior; ++c) {
                        double tc = 0.0;
                        interior = castRay(glm::dvec3(cam.eye), rayAt(x + (c & 1), y + (c >> 1)), tc) == hit;
                    }
                    if (!interior) continue;
                    const float stored = depth[size_t(slot.rect.y + y) * size_t(atlas.size()) + size_t(slot.rect.x + x)];
                    // Along the ray t is not the view depth: beyond the far plane (the range) nothing is drawn.
                    const double viewDepth = t * glm::dot(rayAt(x + 0.5, y + 0.5), glm::dvec3(cam.forward));
                    if (hit == Hit::None || viewDepth > double(cam.farPlane) * 1.001) {
                        ++emptyTexels[slot.light];
                        CHECK(stored == 1.0f);
                        continue;
                    }
                    if (viewDepth > double(cam.farPlane) * 0.999) continue;  // at the far plane: clipping decides
                    (hit == Hit::Floor ? floorTexels : boxTexels)[slot.light] += 1;
                    const glm::dvec3 point = glm::dvec3(cam.eye) + t * rayAt(x + 0.5, y + 0.5);
                    const glm::dvec4 clip = glm::dmat4(cam.viewProjection) * glm::dvec4(point, 1.0);
                    const double expected = 0.5 * clip.z / clip.w + 0.5;
                    // fp32 vertex transform and the 24-bit buffer: a few steps of 2^-24 (measured: up to 2.6e-7).
                    worst = std::max(worst, std::abs(double(stored) - expected));
                    ++compared;
                }
            INFO("light " << slot.light << " face " << slot.face << ": compared " << compared << ", worst " << worst);
            CHECK(worst < 1e-6);
        }
    }
    for (int light : {0, 1, 2}) {
        INFO("light " << light << ": floor " << floorTexels[light] << ", box " << boxTexels[light] << ", empty "
                      << emptyTexels[light]);
        CHECK(floorTexels[light] > 1000);
        CHECK(boxTexels[light] > 100);
    }
    CHECK(emptyTexels[1] > 3 * 128 * 128 / 2);  // the point light's upper faces see nothing within its range
}

TEST_CASE("shadow atlas: the packed RGBA8 atlas holds the depth texture's values, slope bias included", "[shadows][every-gl]") {
    // Both maps' shaders compute the depth from the world position and add the slope bias from screen derivatives
    // (shadow_depth.frag); one writes gl_FragDepth into a depth texture, the other packs 24 bits into RGBA8. So the
    // two hold the same depth rounded twice, biased or not.
    testContext();
    if (testGl().gles) return;  // ES 2.0 reads no depth texture back
    const Scene scene = floorAndBox();
    GpuScene gpu(scene);
    PointLight slanted = spotDown({3.0f, 4.0f, 1.0f}, 50.0f);
    slanted.direction = glm::normalize(glm::vec3(-0.6f, -1.0f, -0.2f));
    const std::vector<PointLight> lights = {slanted, spotDown({0.0f, 5.0f, 0.0f}, 40.0f)};
    const float slopeBias = GENERATE(0.0f, 2.0f);
    ShadowAtlasOptions options;
    options.size = 256;
    options.tileSize = 128;
    options.slopeBias = slopeBias;
    ShadowAtlas depth(testGl(), options);
    options.packedDepth = true;
    ShadowAtlas packed(testGl(), options);
    REQUIRE(depth.update(gpu, lights, {0, 1}) == 2);
    REQUIRE(packed.update(gpu, lights, {0, 1}) == 2);
    const std::vector<float> a = depth.readDepth(), b = packed.readDepth();
    REQUIRE(a.size() == b.size());
    double worst = 0.0;
    long covered = 0, over = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        worst = std::max(worst, std::abs(double(a[i]) - double(b[i])));
        covered += a[i] < 1.0f;
        over += std::abs(double(a[i]) - double(b[i])) > 1e-6;
    }
    INFO("slope bias " << slopeBias << ": texels with a surface: " << covered << ", worst difference " << worst
                       << ", over 1e-6: " << over);
    CHECK(covered > 10000);
    // Within 1e-6 but for texels whose centre lies on a triangle's edge, where the two rasterisations may pick
    // different triangles or a derivative straddles the edge (at most 1 in 1,000). Measured on llvmpipe and
    // softpipe alike: unbiased 0 of 30,047 texels over 1e-6, slope bias 2: 2 of 29,910 (2.6e-4 at most). When
    // the depth-texture maps took their slope bias from glPolygonOffset, softpipe's differed at 1,472 texels.
    CHECK(over * 1000 <= covered);
    CHECK(worst < 1e-3);
}

TEST_CASE("shadow atlas: a map is drawn again only when its light moved or a change touched its range", "[shadows][every-gl]") {
    testContext();
    Scene scene = floorAndBox();
    addBox(scene, glm::vec3(40.0f, 0.0f, 40.0f), glm::vec3(41.0f, 1.0f, 41.0f), 0);  // far from both lights
    GpuScene gpu(scene);
    ShadowAtlasOptions options;
    options.size = 128;
    options.tileSize = 64;
    ShadowAtlas atlas(testGl(), options);
    std::vector<PointLight> lights = {spotDown({0.0f, 5.0f, 0.0f}, 40.0f), spotDown({-15.0f, 4.0f, 0.0f}, 30.0f)};
    CHECK(atlas.update(gpu, lights, {0, 1}) == 2);
    CHECK(atlas.update(gpu, lights, {0, 1}) == 0);  // static: nothing again
    gpu.setTransform(2, glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, 0.0f, 0.0f)));  // out of both ranges
    CHECK(atlas.update(gpu, lights, {0, 1}) == 0);
    gpu.setTransform(1, glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0.0f, 0.0f)));  // the box, in light 0's range
    CHECK(atlas.update(gpu, lights, {0, 1}) == 1);
    lights[1].position.y += 0.25f;
    CHECK(atlas.update(gpu, lights, {0, 1}) == 1);
    CHECK(atlas.update(gpu, lights, {1, 0}) == 2);  // slots swapped: both maps hold another light now
    // More changes than the scene keeps a record of (all far away): the maps cannot know, so they are drawn.
    for (size_t i = 0; i <= GpuScene::kKeptChanges; ++i)
        gpu.setTransform(2, glm::translate(glm::mat4(1.0f), glm::vec3(float(i % 7), 0.0f, 0.0f)));
    CHECK(atlas.update(gpu, lights, {1, 0}) == 2);
    CHECK(atlas.mapsDrawnTotal() == 8);
}

TEST_CASE("shadow atlas: refused sizes and casters name the rule", "[shadows][bad-input][every-gl]") {
    testContext();
    ShadowAtlasOptions options;
    options.size = 300;
    CHECK_THROWS_WITH(ShadowAtlas(testGl(), options), Catch::Contains("must be powers of two"));
    options.size = 128;
    options.tileSize = 256;
    CHECK_THROWS_WITH(ShadowAtlas(testGl(), options), Catch::Contains("tile size <= size"));
    options.tileSize = 64;
    ShadowAtlas atlas(testGl(), options);
    const Scene scene = floorAndBox();
    GpuScene gpu(scene);
    std::vector<PointLight> lights = {PointLight{}, spotDown({0.0f, 5.0f, 0.0f}, 85.0f), spotDown({0.0f, 5.0f, 0.0f}, 40.0f)};
    CHECK_THROWS_WITH(atlas.update(gpu, lights, {1}), Catch::Contains("wider than one map covers"));
    CHECK_THROWS_WITH(atlas.update(gpu, lights, {2, 2, 2, 2, 2}), Catch::Contains("need 5 maps (a spot light 1, a point light 6), the atlas holds 4"));
    CHECK_THROWS_WITH(atlas.update(gpu, lights, {0}), Catch::Contains("need 6 maps"));
    CHECK_THROWS_WITH(spotShadowCamera(lights[0], 64), Catch::Contains("is not a spot light"));
    CHECK_THROWS_WITH(pointShadowCamera(lights[2], 0, 64), Catch::Contains("one map, not a cube"));
    CHECK_THROWS_WITH(atlas.update(gpu, lights, {7}), Catch::Contains("is not one of the 3 lights"));
    CHECK(atlas.mapsDrawnTotal() == 0);
}

TEST_CASE("shadow lookup: the map position the shader derives from the light is the atlas camera's", "[shadows][cpu]") {
    // shadow_lookup.glsl (and its CPU twin) rebuild each map's camera from the light alone: they must land on the
    // texel and window depth spotShadowCamera / pointShadowCamera drew, for every face and spot orientation.
    PointLight point;
    point.position = {1.0f, 2.0f, -3.0f};
    point.radius = 6.0f;
    std::vector<PointLight> lights = {point};
    for (const glm::vec3 direction : {glm::vec3(0, -1, 0), glm::vec3(0.3f, 0.95f, 0.1f), glm::vec3(-1, -0.2f, 0.4f),
                                      glm::vec3(0, 0, 1)}) {
        PointLight spot = spotDown({-2.0f, 3.0f, 1.0f}, 55.0f);
        spot.direction = direction;
        lights.push_back(spot);
    }
    uint32_t state = 12345;
    auto uniform = [&]() {
        state = state * 1664525u + 1013904223u;
        return float(state >> 8) / float(1 << 24) * 2.0f - 1.0f;
    };
    const int firstTile = 3;
    long seen = 0;
    double worstNdc = 0.0, worstDepth = 0.0;
    for (const PointLight& light : lights)
        for (int i = 0; i < 4000; ++i) {
            const glm::vec3 p = light.position + glm::vec3(uniform(), uniform(), uniform()) * light.radius;
            const ShadowMapCoord c = shadowMapCoord(light, firstTile, p);
            if (!c.seen) continue;
            const CameraMatrices cam = light.isSpot() ? spotShadowCamera(light, 256)
                                                      : pointShadowCamera(light, c.tile - firstTile, 256);
            const glm::dvec4 clip = glm::dmat4(cam.viewProjection) * glm::dvec4(glm::dvec3(p), 1.0);
            INFO("light at " << light.position.x << " tile " << c.tile);
            REQUIRE(clip.w > 0.0);
            const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
            // The face the twin chose sees the point (|ndc| <= 1 there), at the same place and depth.
            CHECK(std::abs(ndc.x) <= 1.0 + 1e-5);
            CHECK(std::abs(ndc.y) <= 1.0 + 1e-5);
            worstNdc = std::max({worstNdc, std::abs(ndc.x - c.ndc.x), std::abs(ndc.y - c.ndc.y)});
            worstDepth = std::max(worstDepth, std::abs(0.5 * ndc.z + 0.5 - double(c.windowDepth)));
            ++seen;
        }
    INFO("points " << seen << ", worst ndc " << worstNdc << ", worst depth " << worstDepth);
    CHECK(seen > 8000);
    CHECK(worstNdc < 1e-5);    // a 1/50th of a texel of a 4096-texel map
    CHECK(worstDepth < 1e-6);  // a few steps of the 24-bit map
    // Outside a spot's view and behind it: not seen (the lookup says lit; the cone term decides there).
    CHECK_FALSE(shadowMapCoord(lights[1], 0, lights[1].position + glm::vec3(0.0f, 1.0f, 0.0f)).seen);
    CHECK_FALSE(shadowMapCoord(lights[1], 0, lights[1].position + glm::vec3(3.0f, -0.1f, 0.0f)).seen);
}

TEST_CASE("shadows in the reference: every floor pixel away from a shadow's edge is as a CPU ray cast says", "[shadows][every-gl]") {
    // The brute-force reference with shadows against an independent truth: for each light alone, a floor pixel
    // whose segment to the light the box blocks (by the ray cast in double precision) must look as if the light
    // were absent, an unblocked one as if it cast no shadow. Pixels within a band around the true edge (the maps'
    // own error: texels and bias) are counted apart; the band is three texels' footprints wide.
    testContext();
    Scene scene = floorAndBox();
    scene.width = 192;
    scene.height = 144;
    scene.camera.position = {4.0f, 9.0f, 7.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    PointLight spot = spotDown({0.4f, 3.2f, 0.2f}, 60.0f);
    spot.castsShadow = true;
    PointLight point;
    point.position = {2.0f, 3.0f, 1.5f};
    point.radius = 9.0f;
    point.castsShadow = true;
    // Measured (llvmpipe, 192 x 144): spot 277 blocked, 19,374 open, 225 in the band; point 442, 16,452, 352.
    const bool fixedTable = GENERATE(false, true);
    const bool filtered = GENERATE(false, true);
    const bool packed = GENERATE(false, true);
    ReferenceRenderer reference(testGl(), scene, scene.width, scene.height, 2, fixedTable);
    ShadingParameters on = sceneShading(scene), off = on;
    on.shadows.enabled = true;
    on.shadows.filtered = filtered;
    on.shadows.atlas.size = 1024;
    on.shadows.atlas.tileSize = 256;
    on.shadows.atlas.packedDepth = packed;
    const CameraMatrices cam = cameraMatrices(scene.camera, scene.width, scene.height);
    for (const PointLight& light : {spot, point}) {
        DYNAMIC_SECTION((light.isSpot() ? "spot" : "point") << " light, " << (fixedTable ? "fixed-point" : "float")
                                                            << " light table, " << (filtered ? "filtered" : "nearest")
                                                            << (packed ? ", packed atlas" : "")) {
            const ImageRGBA8 shadowed = (reference.render(scene.camera, {light}, on), reference.targets().readColor());
            CHECK(reference.lastFrame().shadowCasters == 1);
            CHECK(reference.lastFrame().shadowMapsDrawn == shadowTiles(light));
            const ImageRGBA8 unshadowed = (reference.render(scene.camera, {light}, off), reference.targets().readColor());
            const ImageRGBA8 dark = (reference.render(scene.camera, {}, off), reference.targets().readColor());
            reference.render(scene.camera, {light}, on);
            CHECK(reference.lastFrame().shadowMapsDrawn == 0);  // nothing moved: the maps are kept
            const float tanHalf = light.isSpot() ? std::tan(light.outerConeAngle) : 1.0f;
            long blocked = 0, open = 0, band = 0, wrong = 0;
            auto blockedFrom = [&](const glm::dvec3& p) {
                const glm::dvec3 toLight = glm::dvec3(light.position) - p;
                double t = 0.0;
                const Hit hit = castRay(p + toLight * 1e-6, glm::normalize(toLight), t);
                return hit == Hit::Box && t < glm::length(toLight);
            };
            for (int y = 0; y < scene.height; ++y)
                for (int x = 0; x < scene.width; ++x) {
                    const glm::dvec3 eye(cam.eye);
                    const glm::dvec3 ray = glm::normalize(glm::dvec3(unprojectPixel(cam, x, y, 1.0f)) - eye);
                    double t = 0.0;
                    if (castRay(eye, ray, t) != Hit::Floor) continue;
                    const glm::dvec3 p = eye + t * ray;
                    const double distance = glm::length(glm::dvec3(light.position) - p);
                    if (distance >= light.radius * 0.99) continue;  // beyond the range: no light either way
                    // A map texel's footprint on the floor at this distance, stretched by the slant.
                    const double incidence = std::max(0.2, (double(light.position.y) - p.y) / distance);
                    const double eps = 3.0 * 2.0 * distance * tanHalf / 256.0 / incidence;
                    const bool truth = blockedFrom(p);
                    bool uniform = true;
                    for (int k = 0; k < 8 && uniform; ++k) {
                        const double a = k * 0.7853981633974483;
                        uniform = blockedFrom(p + eps * glm::dvec3(std::cos(a), 0.0, std::sin(a))) == truth;
                    }
                    if (!uniform) {
                        ++band;
                        continue;
                    }
                    const ImageRGBA8& expected = truth ? dark : unshadowed;
                    bool same = true;
                    for (int c = 0; c < 3; ++c)
                        same = same && std::abs(int(shadowed.at(x, y)[c]) - int(expected.at(x, y)[c])) <= 1;
                    (truth ? blocked : open) += 1;
                    if (!same) ++wrong;
                }
            INFO("blocked " << blocked << ", open " << open << ", edge band " << band << ", wrong " << wrong);
            CHECK(blocked > 200);
            CHECK(open > 2000);
            CHECK(wrong == 0);
        }
    }
}
