// The glTF validator's entry point, the order of its checks, its messages and its typed access to the JSON; the
// checks themselves are in gltf_validate_*.cpp, one file per glTF section (gltf_validator_internal.h lists them).
#include "lidr/scene/io/gltf_validator.h"

#include <filesystem>

#include "lidr/base/error.h"
#include "lidr/scene/io/file_checks.h"
#include "lidr/scene/io/gltf_validator_internal.h"

namespace lidr {

namespace gltf_validation {

namespace {

namespace fs = std::filesystem;

// The shape of JSON text, scanned without recursion (strings skipped) before any parser runs: a 100,000-deep
// document is refused before a parser recurses into it, a huge number of values before two parsers (this one's
// and tinygltf's) build trees of them.
struct JsonShape {
    size_t offsetPastDepth = std::string::npos;  // where the nesting first passes the limit
    uint64_t values = 0;                          // about: arrays and objects, plus one per ',' (an upper bound)
};

JsonShape jsonShape(const std::string& text, int depthLimit) {
    JsonShape shape;
    int depth = 0;
    bool inString = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\') ++i;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            ++shape.values;
            if (++depth > depthLimit && shape.offsetPastDepth == std::string::npos) shape.offsetPastDepth = i;
        } else if (c == ']' || c == '}') {
            --depth;
        } else if (c == ',') {
            ++shape.values;
        }
    }
    return shape;
}

const char* kindName(Kind kind) {
    switch (kind) {
    case Kind::Object: return "an object";
    case Kind::Array: return "an array";
    case Kind::String: return "a string";
    case Kind::Number: return "a number";
    case Kind::Integer: return "an integer";
    case Kind::Boolean: return "true or false";
    }
    return "";
}

bool isKind(const Json& value, Kind kind) {
    switch (kind) {
    case Kind::Object: return value.is_object();
    case Kind::Array: return value.is_array();
    case Kind::String: return value.is_string();
    case Kind::Number: return value.is_number();
    case Kind::Integer: return value.is_number_integer();  // 1.0 too is refused: tinygltf would not read it
    case Kind::Boolean: return value.is_boolean();
    }
    return false;
}

}  // namespace

std::string pointerSegment(const std::string& key) {
    std::string out;
    for (char c : clipped(key)) {
        if (c == '~') out += "~0";
        else if (c == '/') out += "~1";
        else out += c;
    }
    return out;
}

void Validator::run() {
    const std::string problem = fileProblem(path_);
    if (problem.empty() == false) throw Error(path_ + ": glTF file " + problem);
    std::error_code error;
    fileSize_ = fs::file_size(path_, error);
    if (error) throw Error(path_ + ": glTF file: " + error.message());
    const bool binary = lowerCaseExtension(path_) == ".glb";
    const std::string text = binary ? readGlb() : readGltfText();
    const JsonShape shape = jsonShape(text, maxGltfJsonDepth);
    if (shape.offsetPastDepth != std::string::npos)
        fail("", "JSON nested deeper than " + std::to_string(maxGltfJsonDepth) + " arrays and objects (at byte " +
                     std::to_string(shape.offsetPastDepth) + " of the JSON)");
    if (shape.values > maxGltfJsonValues)
        fail("", "JSON of about " + std::to_string(shape.values) + " values; lidr reads at most " +
                     std::to_string(maxGltfJsonValues));
    try {
        root_ = Json::parse(text);
    } catch (const Json::exception& error) {
        const std::string what = error.what();
        const size_t prefixEnd = what.find("] ");
        fail("", "malformed JSON: " + (prefixEnd == std::string::npos ? what : what.substr(prefixEnd + 2)));
    }
    if (!root_.is_object()) fail("", "the document must be a JSON object, got " + std::string(root_.type_name()));
    checkAsset();
    checkTopLevelArrays();
    checkExtensionLists();
    checkBuffers();
    checkBufferViews();
    checkAccessors();
    checkImages();
    checkSamplersAndTextures();
    checkMaterials();
    checkCameras();
    checkLights();
    checkMeshes();
    checkSkins();
    checkNodes();
    checkScenes();
    checkAnimations();
}

void Validator::fail(const std::string& pointer, const std::string& rule) const {
    throw Error(path_ + ": " + (pointer.empty() ? "/" : pointer) + ": " + rule);
}

void Validator::warn(const std::string& text) { warnings_.push_back(path_ + ": " + text); }

void Validator::expect(const Json& value, const std::string& at, Kind kind) const {
    if (!isKind(value, kind)) fail(at, "must be " + std::string(kindName(kind)) + ", got " + value.type_name() +
                                           (value.is_number() ? " " + str(value.get<double>()) : ""));
}

const Json* Validator::member(const Json& object, const std::string& at, const char* key, Kind kind, bool required) const {
    const auto it = object.find(key);
    if (it == object.end()) {
        if (required) fail(at + "/" + key, "required property missing");
        return nullptr;
    }
    expect(*it, at + "/" + key, kind);
    return &*it;
}

double Validator::number(const Json& object, const std::string& at, const char* key, double fallback) const {
    const Json* value = member(object, at, key, Kind::Number);
    return value ? value->get<double>() : fallback;
}

int64_t Validator::integer(const Json& object, const std::string& at, const char* key, int64_t fallback, bool required) const {
    const Json* value = member(object, at, key, Kind::Integer, required);
    if (!value) return fallback;
    if (value->is_number_unsigned() && value->get<uint64_t>() > uint64_t(INT64_MAX))
        fail(at + "/" + key, "integer " + std::to_string(value->get<uint64_t>()) + " is out of range");
    return value->get<int64_t>();
}

size_t Validator::count(const char* array) const {
    const auto it = root_.find(array);
    return it != root_.end() && it->is_array() ? it->size() : 0;
}

int64_t Validator::indexAt(const Json& value, const std::string& at, size_t size, const char* what) const {
    expect(value, at, Kind::Integer);
    const double d = value.get<double>();
    if (d < 0) fail(at, "index " + str(d) + " is negative");
    if (d >= double(size))
        fail(at, "index " + str(d) + " is out of range (" + std::to_string(size) + " " + what + ")");
    return int64_t(d);
}

int64_t Validator::index(const Json& object, const std::string& at, const char* key, const char* target, bool required) const {
    const auto it = object.find(key);
    if (it == object.end()) {
        if (required) fail(at + "/" + key, "required property missing");
        return -1;
    }
    return indexAt(*it, at + "/" + key, count(target), target);
}

std::vector<double> Validator::numbers(const Json& object, const std::string& at, const char* key, size_t size) const {
    const Json* array = member(object, at, key, Kind::Array);
    if (!array) return {};
    if (array->size() != size)
        fail(at + "/" + key, "must have " + std::to_string(size) + " numbers, got " + std::to_string(array->size()));
    std::vector<double> out;
    for (size_t i = 0; i < size; ++i) {
        expect((*array)[i], at + "/" + key + "/" + std::to_string(i), Kind::Number);
        out.push_back((*array)[i].get<double>());
    }
    return out;
}

void Validator::inRange(const std::vector<double>& values, const std::string& at, double low, double high) const {
    for (size_t i = 0; i < values.size(); ++i)
        if (!(values[i] >= low && values[i] <= high))
            fail(at + "/" + std::to_string(i), "must be in [" + str(low) + ", " + str(high) + "], got " + str(values[i]));
}

}  // namespace gltf_validation

void validateGltfFile(const std::string& path, std::vector<std::string>& warnings) {
    gltf_validation::Validator(path, warnings).run();
}

}  // namespace lidr
