#include "page_query.h"

#include <algorithm>
#include <cctype>
#include <set>

#include "lidr/base/error.h"

namespace lidr::web {

namespace {

// The option table's renderer settings the page has controls for (lidr_web_set's names, the table's names).
const char* const kTableSettings[] = {"mode", "scheme", "budget", "index-bits", "shadows", "shadow-filter"};
// The page's own settings (lidr_web_set), passed on as given.
const char* const kPageSettings[] = {"view", "environment-intensity", "paused"};
// The page's own keys, read here.
const char* const kPageKeys[] = {"scene",       "lights", "width",       "height",      "bench",     "bench-modes",
                                 "environment", "check",  "check-model", "check-large", "check-huge"};

std::string pageKeys() {
    std::string list;
    for (const char* k : kTableSettings) list += (list.empty() ? "" : ", ") + std::string(k);
    for (const char* k : kPageSettings) list += ", " + std::string(k);
    for (const char* k : kPageKeys) list += ", " + std::string(k);
    return list;
}

template <size_t N>
bool among(const std::string& key, const char* const (&keys)[N]) {
    for (const char* k : keys)
        if (key == k) return true;
    return false;
}

// Each key once: the table would take the last of a repeated setting, the page refuses it.
void checkRepeats(const std::string& text) {
    std::set<std::string> seen;
    size_t from = 0;
    while (from < text.size()) {
        size_t end = text.find('&', from);
        if (end == std::string::npos) end = text.size();
        const std::string key = urlDecode(text.substr(from, std::min(text.find('=', from), end) - from));
        from = end + 1;
        if (!key.empty() && !seen.insert(key).second) throw Error("URL query: " + key + " given twice");
    }
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
    checkRepeats(!query.empty() && query[0] == '?' ? query.substr(1) : query);
    // The renderer's settings: set and checked by the library's table; the rest are the page's.
    const std::vector<std::pair<std::string, std::string>> others = setRenderOptionsFromQuery(q.options, query);
    for (const auto& [name, value] : q.options) {
        if (!among(name, kTableSettings))
            throw Error("URL query: " + name + " is a renderer option the page has no control for (it takes " +
                        pageKeys() + ")");
        q.settings.emplace_back(name, value);
    }
    for (const auto& [key, value] : others) {
        if (among(key, kPageSettings)) q.settings.emplace_back(key, value);
        else if (among(key, kPageKeys)) readPageKey(q, key, value);
        else throw Error("URL query: unknown option '" + key + "' (the page takes " + pageKeys() + ")");
    }
    return q;
}

}  // namespace lidr::web
