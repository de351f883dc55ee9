#include "lidr/technique/frame_plan.h"

#include <algorithm>
#include <numeric>

#include "lidr/render/light_table.h"
#include "lidr/technique/tile_decision.h"

namespace lidr {

std::vector<uint32_t> drawOrder(const std::vector<PointLight>& lights) {
    std::vector<uint32_t> order(lights.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return lights[a].priority > lights[b].priority; });
    for (uint32_t& i : order) ++i;  // 1-based light indices
    return order;
}

bool FramePlan::tilesNarrowed() const {
    return regions.on() ||
           (compactNumbering && AutoConfiguration::indexBitsFor(meshLights) > AutoConfiguration::indexBitsFor(drawnLights));
}

FramePlan planFrame(const CameraMatrices& camera, const std::vector<PointLight>& lights, const FramePlanSettings& s,
                    const FramePlanQueries& q) {
    FramePlan plan;
    plan.compactNumbering = s.autoWidth != nullptr;
    plan.volumes.reserve(lights.size());  // at most every light: no reallocation as they are kept
    if (plan.compactNumbering) {
        plan.tableLights.reserve(lights.size());
        plan.frameLights.reserve(lights.size());
    }
    for (uint32_t index : drawOrder(lights)) {
        const PointLight& l = lights[index - 1];
        const glm::vec4 posRadius(l.position, l.radius);
        if (s.cullLights && (!sphereMayBeVisible(camera, l.position, l.radius) || !q.touchesScene(posRadius))) continue;
        if (s.tiles) {
            ++plan.meshLights;
            plan.meshRectArea += sphereRectPixels(camera, l);
        }
        if (s.cullLights && s.tiles && !q.reachesTiles(posRadius) && !(s.transparentLists && q.reachesTransparent(posRadius)))
            continue;
        const int shadowTile = s.shadowTiles ? (*s.shadowTiles)[index - 1] : -1;
        if (plan.compactNumbering) {
            plan.tableLights.push_back(l);
            plan.frameLights.push_back(index);
            index = static_cast<uint32_t>(plan.frameLights.size());
        }
        plan.volumes.push_back({index, posRadius, -1, spotCone(l), shadowTile});
    }
    plan.drawnLights = static_cast<int>(plan.volumes.size());
    if (plan.compactNumbering && s.regionalIndices && s.tiles && plan.volumes.size() > 255) numberByRegion(plan, s, q);
    plan.widestList = plan.drawnLights;
    if (plan.regions.on()) {
        plan.widestList = 0;
        for (const VolumeLight& v : plan.volumes) plan.widestList = std::max(plan.widestList, int(v.index));
    }
    plan.indexBits = s.autoWidth ? s.autoWidth->chooseIndexBits(plan.widestList) : s.fixedIndexBits;
    return plan;
}

void numberByRegion(FramePlan& plan, const FramePlanSettings& s, const FramePlanQueries& q) {
    // A k-d split of the tiles: the region reached by the most lights is halved across its longer side until
    // every region is reached by at most 255 lights (8-bit indices), or that cannot be had within
    // s.maxRegions regions, or a single tile is reached by more (then global numbering stays).
    std::vector<VolumeLight>& volumes = plan.volumes;
    const int tilesX = s.tilesX, tilesY = s.tilesY;
    const size_t mapRows = (size_t(tilesX) * size_t(tilesY) + LightTable::kWidth - 1) / LightTable::kWidth;
    struct Rect {
        int x0, y0, x1, y1;  // tiles, ends exclusive
    };
    std::vector<Rect> rects{{0, 0, tilesX, tilesY}};
    IndexRegions regions;
    regions.tilesX = tilesX;
    regions.tileSize = s.tileSize;
    regions.regionOfTiles.assign(size_t(tilesX) * size_t(tilesY), 0);
    std::vector<uint32_t> reached(volumes.size());
    std::vector<int> perRegion(size_t(s.maxRegions), 0);
    auto count = [&](uint32_t bits, int add) {
        for (; bits; bits &= bits - 1) perRegion[size_t(__builtin_ctz(bits))] += add;
    };
    int split = -1;  // the region halved last: only the lights that reached it can reach other regions now
    for (;;) {
        regions.count = int(rects.size());
        if ((size_t(regions.count) + mapRows) * LightTable::kWidth - 1 > size_t(s.tableCapacity)) return;
        perRegion.resize(rects.size());
        for (size_t i = 0; i < volumes.size(); ++i) {
            if (split >= 0 && !(reached[i] & (1u << split))) continue;
            if (split >= 0) count(reached[i], -1);
            reached[i] = q.regionsReached(volumes[i].posRadius, regions);
            count(reached[i], +1);
        }
        const size_t worst = size_t(std::max_element(perRegion.begin(), perRegion.end()) - perRegion.begin());
        if (perRegion[worst] <= 255) break;
        Rect& r = rects[worst];
        if (rects.size() >= size_t(s.maxRegions) || (r.x1 - r.x0 == 1 && r.y1 - r.y0 == 1)) return;
        Rect half = r;
        if (r.x1 - r.x0 >= r.y1 - r.y0)
            r.x1 = half.x0 = (r.x0 + r.x1) / 2;
        else
            r.y1 = half.y0 = (r.y0 + r.y1) / 2;
        rects.push_back(half);
        split = int(worst);
        for (int y = half.y0; y < half.y1; ++y)
            for (int x = half.x0; x < half.x1; ++x) regions.regionOfTiles[size_t(y) * size_t(tilesX) + size_t(x)] = uint8_t(rects.size() - 1);
    }
    // Entries in the lights' draw order, each light once per region it reaches: a pixel lies in one region, so
    // its list keeps the lights' order. Entry (region r, index k) is the table's texel (k, r).
    const std::vector<PointLight> lights = std::move(plan.tableLights);
    const std::vector<uint32_t> sceneIndex = std::move(plan.frameLights);
    const size_t last = size_t(regions.count - 1);
    plan.tableLights.assign(last * 256 + size_t(perRegion[last]),
                            PointLight{lights.front().position, lights.front().radius, glm::vec3(0.0f), 0.0f});  // unused: black
    plan.frameLights.assign(plan.tableLights.size(), 0u);
    std::vector<VolumeLight> entries;
    std::fill(perRegion.begin(), perRegion.end(), 0);
    for (size_t i = 0; i < volumes.size(); ++i)
        for (uint32_t bits = reached[i]; bits; bits &= bits - 1) {
            const int r = __builtin_ctz(bits);
            const uint32_t k = uint32_t(++perRegion[size_t(r)]);
            const size_t entry = size_t(r) * 256 + k - 1;
            plan.tableLights[entry] = lights[volumes[i].index - 1];
            plan.frameLights[entry] = sceneIndex[volumes[i].index - 1];
            entries.push_back({k, volumes[i].posRadius, r, volumes[i].cone, volumes[i].shadowTile});
        }
    volumes = std::move(entries);
    plan.regions = std::move(regions);
}

}  // namespace lidr
