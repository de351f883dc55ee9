// Links lidr through find_package(lidr) and uses its public API: a light volume mesh and a packing
// scheme's CPU model need no GL context, so this runs anywhere.
#include <cstdio>

#include <lidr/technique/light_volume_mesh.h>
#include <lidr/technique/packing_scheme.h>

int main() {
    const lidr::LightVolumeMesh mesh = lidr::makeLightVolumeMesh(2);
    lidr::GlInfo info;  // no context needed for the CPU model
    auto scheme = lidr::createPackingScheme({"bitshift", 4, 8}, info);
    const auto texel = scheme->encodePixel({200, 17, 3});
    const auto slots = scheme->decodePixel(texel.data());
    const bool ok = mesh.insideRadius >= 1.0f && slots.size() == 4 && slots[0] == 3 && slots[1] == 17 &&
                    slots[2] == 200 && slots[3] == 0;
    std::printf("consumer: %s (%s)\n", ok ? "ok" : "FAILED", scheme->describe().c_str());
    return ok ? 0 : 1;
}
