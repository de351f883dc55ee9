#pragma once
// lidr-viewer --script FILE: a scripted sequence of inputs, one action a line, run frame by frame. It drives
// the viewer through the same paths as the keyboard, mouse and UI (keys go to the key handler, `set` to the
// setting the UI's widget changes), and its `expect` lines check what came out; the first failed check ends
// the viewer with a message naming the line and exit code 1. doc/viewer.md lists every action.
#include <string>
#include <vector>

namespace lidr::viewer {

struct ScriptAction {
    int line = 0;
    std::string verb;
    std::vector<std::string> args;
    std::string text;  // the line as written, for messages
};

// Reads and checks a script (verbs, argument counts, numbers); throws lidr::Error naming the file and line.
std::vector<ScriptAction> parseScript(const std::string& path);
std::vector<ScriptAction> parseScriptText(const std::string& text, const std::string& name);

// Parses a number argument of `a` or throws lidr::Error naming the line.
double scriptNumber(const ScriptAction& a, size_t arg);
int scriptInt(const ScriptAction& a, size_t arg);

}  // namespace lidr::viewer
