#include "lidr/scene/io/json_fields.h"

#include <cmath>
#include <limits>

#include "lidr/scene/io/file_checks.h"

namespace lidr {

namespace {

// JSON nesting allowed in a scene file (the format itself needs 6 levels); deeper input is refused while
// parsing, so an error's path stays short.
constexpr int maxJsonDepth = 64;


// Builds the document like nlohmann::json::parse, but a syntax error or an out-of-range number (1e999) is
// reported with the path of the value being read (lights[3].radius), and duplicate keys are errors.
class PathTrackingParser : public nlohmann::json_sax<Json> {
public:
    explicit PathTrackingParser(const std::string& file) : file_(file) {}

    Json document;

    bool null() override { return add(nullptr); }
    bool boolean(bool value) override { return add(value); }
    bool number_integer(number_integer_t value) override { return add(value); }
    bool number_unsigned(number_unsigned_t value) override { return add(value); }
    bool number_float(number_float_t value, const string_t&) override { return add(value); }
    bool string(string_t& value) override { return add(value); }
    bool binary(binary_t& value) override { return add(Json::binary(value)); }
    bool start_object(std::size_t) override { return open(Json::object()); }
    bool start_array(std::size_t) override { return open(Json::array()); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }

    bool key(string_t& name) override {
        Frame& top = open_.back();
        top.key = name;
        if (top.node->contains(name)) fail("duplicate key");
        return true;
    }

    bool parse_error(std::size_t, const std::string&, const Json::exception& error) override {
        // Drop nlohmann's "[json.exception.parse_error.101] " prefix.
        const std::string what = error.what();
        const size_t prefixEnd = what.find("] ");
        fail("malformed JSON: " + (prefixEnd == std::string::npos ? what : what.substr(prefixEnd + 2)));
    }

private:
    struct Frame {
        Json* node;
        std::string key;  // objects: the member being read
    };

    [[noreturn]] void fail(const std::string& problem) const {
        const std::string path = currentPath();
        throw Error(file_ + ": " + (path.empty() ? "" : path + ": ") + problem);
    }

    std::string currentPath() const {
        std::string path;
        for (size_t k = 0; k < open_.size(); ++k) {
            const Frame& frame = open_[k];
            if (frame.node->is_array()) {
                // An element still open is already in the array; the value being read is not yet.
                const size_t index = frame.node->size() - (k + 1 < open_.size() ? 1 : 0);
                path += "[" + std::to_string(index) + "]";
            } else if (!frame.key.empty()) {
                path += (path.empty() ? "" : ".") + clipped(frame.key);
            }
        }
        return path;
    }

    Json* insert(Json value) {
        if (open_.empty()) {
            document = std::move(value);
            return &document;
        }
        Frame& top = open_.back();
        if (top.node->is_array()) {
            top.node->push_back(std::move(value));
            return &top.node->back();
        }
        return &((*top.node)[top.key] = std::move(value));
    }

    bool add(Json value) {
        insert(std::move(value));
        return true;
    }

    bool open(Json container) {
        if (open_.size() >= size_t(maxJsonDepth))
            fail("nested deeper than " + std::to_string(maxJsonDepth) + " arrays and objects (scene files need at most 6)");
        Json* node = insert(std::move(container));
        open_.push_back({node, {}});
        return true;
    }

    bool close() {
        open_.pop_back();
        return true;
    }

    const std::string& file_;
    std::vector<Frame> open_;
};

}  // namespace

Json parseJsonWithPaths(const std::string& text, const std::string& file) {
    PathTrackingParser parser(file);
    Json::sax_parse(text, &parser);
    return std::move(parser.document);
}

float positive(const Field& field) {
    const float value = field.number();
    if (!(value > 0.0f)) field.fail("must be > 0, got " + str(value));
    return value;
}

float nonNegative(const Field& field) {
    const float value = field.number();
    if (!(value >= 0.0f)) field.fail("must be >= 0, got " + str(value));
    return value;
}

glm::vec3 color(const Field& field) {
    const glm::vec3 value = field.vec3OrScalar();
    if (value.x < 0.0f || value.y < 0.0f || value.z < 0.0f)
        field.fail("colour components must be >= 0, got " + str(value));
    return value;
}

glm::vec3 positiveVec3(const Field& field) {
    const glm::vec3 value = field.vec3OrScalar();
    if (!(value.x > 0.0f && value.y > 0.0f && value.z > 0.0f))
        field.fail("components must be > 0, got " + str(value));
    return value;
}

}  // namespace lidr
