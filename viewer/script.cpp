#include "script.h"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "lidr/base/error.h"

namespace lidr::viewer {
namespace {

struct VerbSpec {
    size_t minArgs, maxArgs;
    const char* usage;
};

const std::map<std::string, VerbSpec>& verbs() {
    static const std::map<std::string, VerbSpec> v = {
        {"wait", {1, 1, "wait FRAMES"}},
        {"key", {2, 2, "key KEY FRAMES (hold KEY down for FRAMES frames)"}},
        {"press", {1, 1, "press KEY"}},
        {"mouse", {2, 2, "mouse DX DY (a look drag, in pixels)"}},
        {"set", {2, 2, "set NAME VALUE"}},
        {"compute", {0, 0, "compute (the debug views and error figures, as the C key)"}},
        {"screenshot", {1, 1, "screenshot FILE.png (the window, UI included)"}},
        {"capture", {1, 1, "capture FILE.png (the rendered frame alone)"}},
        {"save", {1, 1, "save DIR (screenshot, frame, debug views, raw artefacts)"}},
        {"mark", {0, 0, "mark (remember the camera for expect-moved)"}},
        {"expect-moved", {2, 2, "expect-moved forward|back|left|right|up|down MIN_DISTANCE"}},
        {"expect-match", {3, 3, "expect-match FILE.png MAX_ERROR MIN_PSNR ({drawn} in FILE: the mode that drew the frame)"}},
        {"expect-view-match", {2, 2, "expect-view-match FILE.png MAX_ERROR"}},
        {"expect-ui", {1, 1, "expect-ui SCREENSHOT.png"}},
        {"expect-stat", {3, 3, "expect-stat NAME ==|!=|<|<=|>|>= VALUE"}},
        {"expect-setting", {2, 2, "expect-setting NAME VALUE"}},
        {"expect-refused", {0, 0, "expect-refused (the last setting change was refused, the viewer kept going)"}},
        {"expect-applied", {0, 0, "expect-applied (the last setting change was applied)"}},
        {"expect-file", {1, 1, "expect-file PATH"}},
        {"resize", {2, 2, "resize WIDTH HEIGHT (the window; the frame follows unless --fixed-size)"}},
        {"expect-size", {2, 2, "expect-size WIDTH HEIGHT (the rendered frame's size)"}},
        {"expect-mode-views", {0, 0, "expect-mode-views (the debug views of the mode that drew the last frame are offered and computed)"}},
        {"drop", {1, 16, "drop FILE... (files dropped on the window, as GLFW's drop callback hands them over)"}},
        {"quit", {0, 0, "quit"}},
    };
    return v;
}

}  // namespace

double scriptNumber(const ScriptAction& a, size_t arg) {
    const std::string& s = a.args.at(arg);
    size_t used = 0;
    double v = 0.0;
    try {
        v = std::stod(s, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != s.size() || !std::isfinite(v))
        throw Error("script line " + std::to_string(a.line) + ": '" + s + "' is not a number (" + a.text + ")");
    return v;
}

int scriptInt(const ScriptAction& a, size_t arg) {
    const double v = scriptNumber(a, arg);
    if (v != std::floor(v) || v < 0 || v > 1e6)
        throw Error("script line " + std::to_string(a.line) + ": '" + a.args.at(arg) +
                    "' must be a whole number from 0 to 1000000 (" + a.text + ")");
    return int(v);
}

std::vector<ScriptAction> parseScriptText(const std::string& text, const std::string& name) {
    std::vector<ScriptAction> out;
    std::istringstream in(text);
    std::string line;
    int n = 0;
    while (std::getline(in, line)) {
        ++n;
        const size_t hash = line.find('#');
        std::string body = hash == std::string::npos ? line : line.substr(0, hash);
        std::istringstream words(body);
        ScriptAction a;
        a.line = n;
        a.text = body;
        while (a.text.size() && std::isspace(static_cast<unsigned char>(a.text.back()))) a.text.pop_back();
        if (!(words >> a.verb)) continue;
        for (std::string w; words >> w;) a.args.push_back(w);
        const auto it = verbs().find(a.verb);
        if (it == verbs().end()) {
            std::string known;
            for (const auto& [k, spec] : verbs()) known += (known.empty() ? "" : ", ") + k;
            throw Error(name + ":" + std::to_string(n) + ": unknown action '" + a.verb + "' (actions: " + known + ")");
        }
        if (a.args.size() < it->second.minArgs || a.args.size() > it->second.maxArgs)
            throw Error(name + ":" + std::to_string(n) + ": '" + a.text + "': expected " + it->second.usage);
        try {
            if (a.verb == "wait" || a.verb == "key") scriptInt(a, a.verb == "wait" ? 0 : 1);
            if (a.verb == "mouse") scriptNumber(a, 0), scriptNumber(a, 1);
            if (a.verb == "expect-moved") scriptNumber(a, 1);
            if (a.verb == "expect-match") scriptInt(a, 1), scriptNumber(a, 2);
            if (a.verb == "expect-view-match") scriptInt(a, 1);
            if (a.verb == "expect-stat") {
                static const char* ops[] = {"==", "!=", "<", "<=", ">", ">="};
                bool ok = false;
                for (const char* op : ops) ok |= a.args[1] == op;
                if (!ok) throw Error("script line " + std::to_string(n) + ": unknown comparison '" + a.args[1] + "'");
                scriptNumber(a, 2);
            }
        } catch (const Error& e) {
            throw Error(name + ": " + e.what());
        }
        out.push_back(a);
    }
    return out;
}

std::vector<ScriptAction> parseScript(const std::string& path) {
    std::ifstream f(path);
    if (!f) throw Error("cannot read script '" + path + "'");
    std::stringstream ss;
    ss << f.rdbuf();
    return parseScriptText(ss.str(), path);
}

}  // namespace lidr::viewer
