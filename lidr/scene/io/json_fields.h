#pragma once
// JSON documents read with the path of every value, so each problem reads "<file>: <path>: <problem>"
// (lights[3].radius: must be > 0, got -1). Used by the lidr scene-file reader (scene_file.h).
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "lidr/base/error.h"
#include "lidr/scene/io/file_checks.h"

namespace lidr {

using Json = nlohmann::json;

// Parses like nlohmann::json::parse, but a syntax error or an out-of-range number (1e999) is reported with the
// path of the value being read, duplicate keys are errors, and nesting deeper than 64 levels is refused.
// Throws lidr::Error "<file>: <path>: <problem>".
Json parseJsonWithPaths(const std::string& text, const std::string& file);

// A value of the document with its path, so every problem reads "<file>: <path>: <problem>".
class Field {
public:
    Field(const Json& value, std::string path, const std::string& file)
        : value_(value), path_(std::move(path)), file_(file) {}

    const std::string& path() const { return path_; }

    [[noreturn]] void fail(const std::string& problem) const {
        throw Error(file_ + ": " + (path_.empty() ? "" : path_ + ": ") + problem);
    }

    bool has(const char* key) const { return value_.is_object() && value_.contains(key); }
    bool isArray() const { return value_.is_array(); }

    // A member that must be there.
    Field operator[](const char* key) const {
        if (!value_.is_object()) fail("expected an object, got " + typeName());
        const std::string childPath = path_.empty() ? clipped(key) : path_ + "." + clipped(key);
        if (!has(key)) Field(value_, childPath, file_).fail("missing required field");
        return Field(value_.at(key), childPath, file_);
    }

    // An object whose keys are all in `known`: a typo is an error, not a silently ignored setting.
    void expectObject(std::initializer_list<const char*> known) const {
        if (!value_.is_object()) fail("expected an object, got " + typeName());
        for (const auto& member : value_.items()) {
            bool isKnown = false;
            for (const char* name : known) isKnown = isKnown || member.key() == name;
            if (!isKnown) (*this)[member.key().c_str()].fail("unknown key");
        }
    }

    std::vector<Field> items(size_t requiredSize = 0) const {
        if (!value_.is_array()) fail("expected an array, got " + typeName());
        if (requiredSize && value_.size() != requiredSize)
            fail("expected " + std::to_string(requiredSize) + " elements, got " + std::to_string(value_.size()));
        std::vector<Field> result;
        for (size_t i = 0; i < value_.size(); ++i)
            result.emplace_back(value_[i], path_ + "[" + std::to_string(i) + "]", file_);
        return result;
    }

    // A finite number that fits a float.
    float number() const {
        if (!value_.is_number()) fail("expected a number, got " + typeName());
        const double value = value_.get<double>();
        if (!std::isfinite(value) || std::abs(value) > double(std::numeric_limits<float>::max()))
            fail("number " + str(value) + " is out of range");
        return float(value);
    }

    int64_t integer(int64_t min, int64_t max) const {
        if (!value_.is_number()) fail("expected an integer, got " + typeName());
        const double value = value_.get<double>();
        if (value != std::floor(value)) fail("expected an integer, got " + str(value));
        if (value < double(min) || value > double(max))
            fail("must be in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " + str(value));
        return int64_t(value);
    }

    bool boolean() const {
        if (!value_.is_boolean()) fail("expected true or false, got " + typeName());
        return value_.get<bool>();
    }

    std::string text() const {
        if (!value_.is_string()) fail("expected a string, got " + typeName());
        return value_.get<std::string>();
    }

    glm::vec3 vec3() const {
        const std::vector<Field> elements = items(3);
        return {elements[0].number(), elements[1].number(), elements[2].number()};
    }

    // [x, y, z], or one number for all three.
    glm::vec3 vec3OrScalar() const { return value_.is_number() ? glm::vec3(number()) : vec3(); }

private:
    std::string typeName() const { return value_.type_name(); }

    const Json& value_;
    std::string path_;
    const std::string& file_;
};

float positive(const Field& field);
float nonNegative(const Field& field);
glm::vec3 color(const Field& field);          // [r, g, b] or one number, components >= 0
glm::vec3 positiveVec3(const Field& field);   // [x, y, z] or one number, components > 0

}  // namespace lidr
