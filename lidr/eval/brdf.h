#pragma once
// The CPU model of lidr's shading (shaders/common/shading.glsl) in double precision: the glTF 2.0
// metallic-roughness BRDF, lidr's point-light terms (both falloffs, the spot cone), directional-light and ambient
// terms. Tests check GPU pixels against it and bound its energy (white furnace).
#include <glm/glm.hpp>

#include "lidr/scene/environment.h"
#include "lidr/scene/scene.h"

namespace lidr {

struct BrdfSurface {
    glm::dvec3 position{0.0}, normal{0.0, 1.0, 0.0}, toEye{0.0, 1.0, 0.0};  // unit normal and toEye
    glm::dvec3 baseColor{1.0};
    double metallic = 0.0, roughness = 1.0;
    // The dielectric's F0 and F90 (DielectricSpecular: KHR_materials_ior / _specular); glTF's core 0.04 and 1.
    glm::dvec3 dielectricF0{0.04};
    double dielectricF90 = 1.0;
};

// The surface of `material` (metallicRoughnessOf) at a point seen from `eye`; no texture.
BrdfSurface brdfSurface(const Material& material, const glm::dvec3& position, const glm::dvec3& normal,
                        const glm::dvec3& eye);
// f(l, v): diffuse + specular, per colour channel (1/sr), for a unit direction towards the light.
glm::dvec3 evaluateBrdf(const BrdfSurface& s, const glm::dvec3& toLight);
// lidrShadeLight: f x pi x colour x distanceAttenuation x n.l, times spotTerm for a spot light.
glm::dvec3 shadePointLight(const BrdfSurface& s, const PointLight& light);
// The light's falloff at `distance`: saturate(1 - d^2 / r^2) (LightFalloff::Smooth) or
// saturate(1 - (d / r)^4) / max(d^2, 1e-4) (InverseSquare, KHR_lights_punctual's range window); 0 from r on.
double distanceAttenuation(const PointLight& light, double distance);
// KHR_lights_punctual's cone term for unit `toLight` (from the surface): saturate((cd - cos outer) /
// max(1e-3, cos inner - cos outer))^2 with cd the cosine to the axis; 1 for a point light.
double spotTerm(const PointLight& light, const glm::dvec3& toLight);
// lidrDirectionalLights' term of one light: f x pi x colour x n.l, from -direction (no attenuation).
glm::dvec3 shadeDirectionalLight(const BrdfSurface& s, const DirectionalLight& light);
// lidrAmbient without the emission: ambient x (albedo + F0 A + F90 B), Karis' environment-BRDF fit.
glm::dvec3 shadeAmbient(const BrdfSurface& s, const glm::dvec3& ambient);
// lidrEnvironment (shading.glsl) without the occlusion: albedo x E(n) / pi from the spherical harmonics, plus, unless
// diffuseOnly, the radiance in the reflected direction read from `stored` as the GPU filters it (trilinear at
// roughness x (levels - 1), faces clamped at their edges, decoded after filtering) times the split sum F0 A + B
// (the stored table, bilinear); all times `intensity`. roughness = sqrt(alpha) as the shader takes it.
glm::dvec3 shadeEnvironment(const BrdfSurface& s, const Environment& environment, const StoredEnvironment& stored,
                            double intensity, bool diffuseOnly = false);
// The integral of f x n.l over the hemisphere (the reflected fraction of light from every direction), by
// numerical quadrature with `steps` x 4 steps: the white-furnace figure (<= 1 conserves energy).
glm::dvec3 directionalAlbedo(const BrdfSurface& s, int steps = 256);

}  // namespace lidr
