// Links lidr through find_package(lidr) and uses its public API as a user's program would: the umbrella
// header after GLFW's (no include-order trap), a packing scheme's CPU model (no context needed), then one
// frame rendered headless (EGL) and checked: lit pixels in the image, and the caller's viewport kept.
#include <cstdio>

#include <GLFW/glfw3.h>  // includes <GL/gl.h> first, as many programs do

#include <lidr/lidr.h>
#include <lidr/technique/light_volume_mesh.h>

int main() {
    const lidr::LightVolumeMesh mesh = lidr::makeLightVolumeMesh(2);
    lidr::GlInfo noContext;  // no context needed for the CPU model
    auto scheme = lidr::createPackingScheme({lidr::PackingSchemeKind::BitShift, 4, 8}, noContext);
    const auto texel = scheme->encodePixel({200, 17, 3});
    const auto slots = scheme->decodePixel(texel.data());
    const bool cpuOk = mesh.insideRadius >= 1.0f && slots.size() == 4 && slots[0] == 3 && slots[1] == 17 &&
                       slots[2] == 200 && slots[3] == 0;
    std::printf("consumer: CPU model %s (%s)\n", cpuOk ? "ok" : "FAILED", scheme->describe().c_str());
    try {
        auto context = lidr::GlContext::create();
        lidr::Scene scene = lidr::makeDefaultScene();
        scene.width = 160;
        scene.height = 120;
        lidr::LidrRenderer renderer(context->info(), scene, lidr::LidrOptions{}, scene.width, scene.height);
        glViewport(1, 2, 3, 4);
        renderer.render(scene.camera, scene.lightsAt(1.0f), {scene.ambient, scene.backgroundColor});
        GLint viewport[4] = {};
        glGetIntegerv(GL_VIEWPORT, viewport);
        const lidr::ImageRGBA8 image = renderer.targets().readColor();
        long lit = 0;
        for (size_t p = 0; p < image.pixels.size(); p += 4) lit += image.pixels[p] + image.pixels[p + 1] + image.pixels[p + 2] > 60;
        const bool frameOk = lit > long(image.pixels.size() / 4 / 10) && viewport[0] == 1 && viewport[1] == 2 &&
                             viewport[2] == 3 && viewport[3] == 4;
        std::printf("consumer: frame %s (%ld of %zu pixels lit, %s)\n", frameOk ? "ok" : "FAILED", lit,
                    image.pixels.size() / 4, context->info().renderer.c_str());
        return cpuOk && frameOk ? 0 : 1;
    } catch (const lidr::Error& e) {
        std::printf("consumer: %s\n", e.what());
        return 1;
    }
}
