#include "lidr/eval/brdf.h"

#include <algorithm>
#include <cmath>

namespace lidr {

namespace {
constexpr double kPi = 3.14159265358979323846;

double alphaOf(const BrdfSurface& s) { return std::max(s.roughness * s.roughness, 0.01); }  // as shading.glsl
glm::dvec3 albedoOf(const BrdfSurface& s) { return s.baseColor * (1.0 - s.metallic); }
glm::dvec3 f0Of(const BrdfSurface& s) { return glm::mix(s.dielectricF0, s.baseColor, s.metallic); }
double f90Of(const BrdfSurface& s) { return s.dielectricF90 + (1.0 - s.dielectricF90) * s.metallic; }
}  // namespace

BrdfSurface brdfSurface(const Material& material, const glm::dvec3& position, const glm::dvec3& normal,
                        const glm::dvec3& eye) {
    const MetallicRoughness m = metallicRoughnessOf(material);
    BrdfSurface s;
    s.position = position;
    s.normal = glm::normalize(normal);
    s.toEye = glm::normalize(eye - position);
    s.baseColor = glm::dvec3(m.baseColor);
    s.metallic = m.metallic;
    s.roughness = m.roughness;
    if (!material.dielectric.isDefault()) {  // the shaders' uniforms are floats
        s.dielectricF0 = glm::dvec3(material.dielectric.f0());
        s.dielectricF90 = double(material.dielectric.f90());
    }
    return s;
}

glm::dvec3 evaluateBrdf(const BrdfSurface& s, const glm::dvec3& L) {
    const double nDotL = glm::dot(s.normal, L);
    if (nDotL <= 0.0) return glm::dvec3(0.0);
    const glm::dvec3 H = glm::normalize(L + s.toEye);
    const double nDotV = std::max(glm::dot(s.normal, s.toEye), 1e-4);
    const double nDotH = std::max(glm::dot(s.normal, H), 0.0);
    const double vDotH = std::clamp(glm::dot(s.toEye, H), 0.0, 1.0);
    const double alpha = alphaOf(s), a2 = alpha * alpha;
    const double denom = nDotH * nDotH * (a2 - 1.0) + 1.0;
    const double D = a2 / (kPi * denom * denom);
    const double visibility = 0.5 / (nDotL * std::sqrt(nDotV * nDotV * (1.0 - a2) + a2) +
                                     nDotV * std::sqrt(nDotL * nDotL * (1.0 - a2) + a2));
    const glm::dvec3 f0 = f0Of(s);
    const glm::dvec3 F = f0 + (f90Of(s) - f0) * std::pow(1.0 - vDotH, 5.0);
    return (1.0 - F) * albedoOf(s) / kPi + F * (D * visibility);
}

double distanceAttenuation(const PointLight& light, double distance) {
    const double d2 = distance * distance, r = double(light.radius), q = d2 / (r * r);
    if (light.falloff == LightFalloff::Smooth) return std::clamp(1.0 - q, 0.0, 1.0);
    return std::clamp(1.0 - q * q, 0.0, 1.0) / std::max(d2, 1e-4);
}

double spotTerm(const PointLight& light, const glm::dvec3& toLight) {
    if (!light.isSpot()) return 1.0;
    const double cosOuter = std::cos(double(light.outerConeAngle)), cosInner = std::cos(double(light.innerConeAngle));
    const double scale = 1.0 / std::max(1e-3, cosInner - cosOuter);
    const double cd = glm::dot(-toLight, glm::normalize(glm::dvec3(light.direction)));
    const double t = std::clamp(cd * scale - cosOuter * scale, 0.0, 1.0);
    return t * t;
}

glm::dvec3 shadePointLight(const BrdfSurface& s, const PointLight& light) {
    const glm::dvec3 toLight = glm::dvec3(light.position) - s.position;
    const double d2 = glm::dot(toLight, toLight);
    const double attenuation = distanceAttenuation(light, std::sqrt(d2));
    if (attenuation <= 0.0) return glm::dvec3(0.0);
    const glm::dvec3 L = toLight / std::sqrt(std::max(d2, 1e-24));
    const double nDotL = glm::dot(s.normal, L);
    if (nDotL <= 0.0) return glm::dvec3(0.0);
    return evaluateBrdf(s, L) * (kPi * nDotL * attenuation * spotTerm(light, L)) * glm::dvec3(light.color);
}

glm::dvec3 shadeDirectionalLight(const BrdfSurface& s, const DirectionalLight& light) {
    const glm::dvec3 L = -glm::normalize(glm::dvec3(light.direction));
    const double nDotL = glm::dot(s.normal, L);
    if (nDotL <= 0.0) return glm::dvec3(0.0);
    return evaluateBrdf(s, L) * (kPi * nDotL) * glm::dvec3(light.color);
}

glm::dvec3 shadeAmbient(const BrdfSurface& s, const glm::dvec3& ambient) {
    const double nDotV = std::clamp(glm::dot(s.normal, s.toEye), 0.0, 1.0);
    const double roughness = std::sqrt(alphaOf(s));
    const glm::dvec4 r = roughness * glm::dvec4(-1.0, -0.0275, -0.572, 0.022) + glm::dvec4(1.0, 0.0425, 1.04, -0.04);
    const double a004 = std::min(r.x * r.x, std::exp2(-9.28 * nDotV)) * r.x + r.y;
    const glm::dvec2 ab = glm::dvec2(-1.04, 1.04) * a004 + glm::dvec2(r.z, r.w);
    return ambient * (albedoOf(s) + f0Of(s) * ab.x + f90Of(s) * ab.y);
}

glm::dvec3 shadeEnvironment(const BrdfSurface& s, const Environment& environment, const StoredEnvironment& stored,
                            double intensity, bool diffuseOnly) {
    // The shader's SH uniforms are the coefficients times the intensity, rounded to float.
    std::array<glm::dvec3, 9> sh;
    for (size_t i = 0; i < 9; ++i) sh[i] = glm::dvec3(glm::vec3(environment.sh[i] * intensity));
    glm::dvec3 light = albedoOf(s) * irradianceOverPi(sh, s.normal);
    if (diffuseOnly) return light;
    const double nDotV = std::clamp(glm::dot(s.normal, s.toEye), 0.0, 1.0);
    const double roughness = std::sqrt(alphaOf(s));
    const glm::dvec3 r = 2.0 * glm::dot(s.normal, s.toEye) * s.normal - s.toEye;
    const glm::dvec3 radiance = sampleStoredSpecular(stored, r, roughness * (stored.roughnessLevels - 1));
    const glm::dvec2 ab = sampleStoredSplitSum(stored, nDotV, roughness);
    return light + radiance * (f0Of(s) * ab.x + f90Of(s) * ab.y) * intensity;
}

glm::dvec3 directionalAlbedo(const BrdfSurface& s, int steps) {
    // Midpoint rule in (theta, phi) about the normal, d(omega) = sin(theta) d(theta) d(phi): uniform in theta
    // so that a narrow lobe gets steps anywhere in the hemisphere.
    const glm::dvec3 n = s.normal;
    const glm::dvec3 t = glm::normalize(std::abs(n.x) < 0.9 ? glm::cross(n, glm::dvec3(1, 0, 0)) : glm::cross(n, glm::dvec3(0, 1, 0)));
    const glm::dvec3 b = glm::cross(n, t);
    const int phiSteps = 4 * steps;
    const double dTheta = 0.5 * kPi / steps, dPhi = 2.0 * kPi / phiSteps;
    glm::dvec3 sum(0.0);
    for (int i = 0; i < steps; ++i) {
        const double theta = (i + 0.5) * dTheta, cosTheta = std::cos(theta), sinTheta = std::sin(theta);
        for (int j = 0; j < phiSteps; ++j) {
            const double phi = (j + 0.5) * dPhi;
            const glm::dvec3 L = cosTheta * n + sinTheta * (std::cos(phi) * t + std::sin(phi) * b);
            sum += evaluateBrdf(s, L) * (cosTheta * sinTheta);
        }
    }
    return sum * (dTheta * dPhi);
}

}  // namespace lidr
