// The glTF validator's checks of what surfaces look like: images (the PNG or JPEG header of every one, wherever it
// is stored), samplers, textures and materials (gltf_validator_internal.h).
#include <algorithm>
#include <initializer_list>

#include "lidr/scene/io/file_checks.h"
#include "lidr/scene/io/gltf_validator_internal.h"

namespace lidr::gltf_validation {

void Validator::checkImageBytes(const std::string& bytes, const std::string& at, const std::string& declaredType,
                                const std::string& name) const {
    const ImageHeader header = pngOrJpegHeader(bytes);
    if (header.kind.empty()) fail(at, name + " is neither PNG nor JPEG (the image formats of glTF 2.0)");
    if (!declaredType.empty() && declaredType != header.kind)
        fail(at, name + " is " + header.kind + " but declared " + clipped(declaredType));
    if (!header.sized) fail(at, name + ": the " + header.kind + " header gives no size (cut off?)");
    if (header.width == 0 || header.height == 0 || header.width > uint64_t(maxTextureSide) ||
        header.height > uint64_t(maxTextureSide))
        fail(at, name + " is " + std::to_string(header.width) + "x" + std::to_string(header.height) +
                     "; textures must be 1.." + std::to_string(maxTextureSide) + " pixels per side");
}

void Validator::checkImages() {
    forEach("images", [&](const Json& image, const std::string& at, size_t i) {
        const std::string name = "image " + std::to_string(i);
        const Json* mime = member(image, at, "mimeType", Kind::String);
        const std::string mimeType = mime ? mime->get<std::string>() : "";
        if (mime && mimeType != "image/png" && mimeType != "image/jpeg")
            fail(at + "/mimeType", "'" + clipped(mimeType) + "' is not image/png or image/jpeg");
        const Json* uri = member(image, at, "uri", Kind::String);
        const int64_t view = index(image, at, "bufferView", "bufferViews");
        if (uri && view >= 0) fail(at, "has both uri and bufferView; give one");
        if (!uri && view < 0) fail(at, "has neither uri nor bufferView");
        if (view >= 0) {
            if (!mime) fail(at + "/mimeType", "required with bufferView");
            const ViewInfo& v = views_[size_t(view)];
            checkImageBytes(bufferBytes(v.buffer, v.byteOffset, v.byteLength), at + "/bufferView", mimeType, name);
            return;
        }
        const std::string text = uri->get<std::string>();
        if (text.rfind("data:", 0) == 0) {
            std::string base64;
            const std::string type = dataUri(text, at + "/uri", base64);
            if (type != "image/png" && type != "image/jpeg")
                fail(at + "/uri", "data: URI type '" + clipped(type) + "' is not image/png or image/jpeg");
            checkImageBytes(base64Decode(base64, 0, imageHeaderBytes), at + "/uri", type, name + " (data: URI)");
        } else {
            const std::string file = externalFile(text, at + "/uri", "image");
            checkImageBytes(readFileBytes(file, 0, imageHeaderBytes), at + "/uri", mimeType, name + " '" + file + "'");
        }
    });
}

void Validator::checkSamplersAndTextures() {
    forEach("samplers", [&](const Json& sampler, const std::string& at, size_t) {
        const auto oneOf = [&](const char* key, std::initializer_list<int64_t> allowed) {
            if (!sampler.contains(key)) return;
            const int64_t value = integer(sampler, at, key, 0);
            if (std::find(allowed.begin(), allowed.end(), value) == allowed.end())
                fail(at + "/" + key, std::to_string(value) + " is not a GL filter or wrap mode glTF allows");
        };
        oneOf("magFilter", {9728, 9729});
        oneOf("minFilter", {9728, 9729, 9984, 9985, 9986, 9987});
        oneOf("wrapS", {33071, 33648, 10497});
        oneOf("wrapT", {33071, 33648, 10497});
    });
    forEach("textures", [&](const Json& texture, const std::string& at, size_t) {
        index(texture, at, "sampler", "samplers");
        index(texture, at, "source", "images");
    });
}

void Validator::textureInfo(const Json& object, const std::string& at, const char* key) const {
    const Json* info = member(object, at, key, Kind::Object);
    if (!info) return;
    const std::string where = at + "/" + key;
    index(*info, where, "index", "textures", true);
    if (integer(*info, where, "texCoord", 0) < 0) fail(where + "/texCoord", "must be >= 0");
}

void Validator::checkMaterials() {
    forEach("materials", [&](const Json& material, const std::string& at, size_t) {
        if (const Json* pbr = member(material, at, "pbrMetallicRoughness", Kind::Object)) {
            const std::string where = at + "/pbrMetallicRoughness";
            inRange(numbers(*pbr, where, "baseColorFactor", 4), where + "/baseColorFactor", 0, 1);
            for (const char* key : {"metallicFactor", "roughnessFactor"}) {
                const double value = number(*pbr, where, key, 1);
                if (!(value >= 0 && value <= 1)) fail(where + "/" + key, "must be in [0, 1], got " + str(value));
            }
            textureInfo(*pbr, where, "baseColorTexture");
            textureInfo(*pbr, where, "metallicRoughnessTexture");
        }
        textureInfo(material, at, "normalTexture");
        textureInfo(material, at, "occlusionTexture");
        textureInfo(material, at, "emissiveTexture");
        inRange(numbers(material, at, "emissiveFactor", 3), at + "/emissiveFactor", 0, 1);
        if (const Json* mode = member(material, at, "alphaMode", Kind::String)) {
            const std::string value = mode->get<std::string>();
            if (value != "OPAQUE" && value != "MASK" && value != "BLEND")
                fail(at + "/alphaMode", "'" + clipped(value) + "' is not OPAQUE, MASK or BLEND");
        }
        if (number(material, at, "alphaCutoff", 0.5) < 0) fail(at + "/alphaCutoff", "must be >= 0");
        member(material, at, "doubleSided", Kind::Boolean);
    });
}

}  // namespace lidr::gltf_validation
