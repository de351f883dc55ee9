#include "page_query.h"

#include <cctype>
#include <set>

#include "lidr/base/error.h"

namespace lidr::web {

namespace {

// The settings lidr_web_set applies (lidr_web.cpp), passed on as given.
const char* const kSettings[] = {"mode",    "scheme",        "budget",                "index-bits", "view",
                                 "shadows", "shadow-filter", "environment-intensity", "paused"};
// The page's own keys, read here.
const char* const kPageKeys[] = {"scene",       "lights", "width",       "height",      "bench",     "bench-modes",
                                 "environment", "check",  "check-model", "check-large", "check-huge"};

std::string knownKeys() {
    std::string list;
    for (const char* k : kSettings) list += (list.empty() ? "" : ", ") + std::string(k);
    for (const char* k : kPageKeys) list += ", " + std::string(k);
    return list;
}

int wholeNumber(const std::string& key, const std::string& value, int min, int max) {
    const bool digits = !value.empty() && value.size() <= 9 &&
                        value.find_first_not_of("0123456789") == std::string::npos;
    const int number = digits ? std::stoi(value) : -1;
    if (!digits || number < min || number > max)
        throw Error("URL query: " + key + " takes a whole number from " + std::to_string(min) + " to " +
                    std::to_string(max) + ", got '" + value + "'");
    return number;
}

void readPageKey(PageQuery& q, const std::string& key, const std::string& value) {
    if (key == "scene") q.scene = value;
    else if (key == "environment") q.environment = value;
    else if (key == "lights") q.lights = wholeNumber(key, value, 1, 65535);
    else if (key == "width") q.width = wholeNumber(key, value, kMinPageSide, kMaxPageSide);
    else if (key == "height") q.height = wholeNumber(key, value, kMinPageSide, kMaxPageSide);
    else if (key == "bench") q.bench = wholeNumber(key, value, 1, kMaxBenchFrames);
    else if (key == "bench-modes") {
        q.benchModes = commaList(value);
        if (q.benchModes.empty()) throw Error("URL query: bench-modes takes a list of modes (lidr,tiled), got none");
    } else if (key == "check") q.check = true;
    else if (key == "check-model") q.checkModel = value;
    else if (key == "check-large") q.checkLarge = value;
    else if (key == "check-huge") q.checkHuge = value;
}

}  // namespace

std::vector<std::string> commaList(const std::string& value) {
    std::vector<std::string> items;
    size_t from = 0;
    while (from <= value.size()) {
        const size_t comma = value.find(',', from);
        const std::string item = value.substr(from, comma == std::string::npos ? std::string::npos : comma - from);
        if (!item.empty()) items.push_back(item);
        if (comma == std::string::npos) break;
        from = comma + 1;
    }
    return items;
}

std::string urlDecode(const std::string& text) {
    std::string out;
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '+') {
            out += ' ';
        } else if (text[i] == '%' && i + 2 < text.size() &&
                   std::isxdigit(static_cast<unsigned char>(text[i + 1])) &&
                   std::isxdigit(static_cast<unsigned char>(text[i + 2]))) {
            out += char(std::stoi(text.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            out += text[i];
        }
    }
    return out;
}

PageQuery parsePageQuery(const std::string& query) {
    PageQuery q;
    std::set<std::string> seen;
    const std::string text = !query.empty() && query[0] == '?' ? query.substr(1) : query;
    size_t from = 0;
    while (from < text.size()) {
        size_t end = text.find('&', from);
        if (end == std::string::npos) end = text.size();
        const std::string pair = text.substr(from, end - from);
        from = end + 1;
        if (pair.empty()) continue;
        const size_t equals = pair.find('=');
        const std::string key = urlDecode(pair.substr(0, equals));
        const std::string value = equals == std::string::npos ? "" : urlDecode(pair.substr(equals + 1));
        if (!seen.insert(key).second) throw Error("URL query: " + key + " given twice");
        bool known = false;
        for (const char* k : kSettings)
            if (key == k) {
                q.settings.emplace_back(key, value);
                known = true;
            }
        for (const char* k : kPageKeys)
            if (key == k) {
                readPageKey(q, key, value);
                known = true;
            }
        if (!known) throw Error("URL query: unknown option '" + key + "' (known: " + knownKeys() + ")");
    }
    return q;
}

}  // namespace lidr::web
