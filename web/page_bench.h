#pragma once
// The web page's timing run (bench=N in the URL query, doc/web.md): the table it shows and prints, made from each
// mode's frame times. Plain C++ (no emscripten), so the native tests check it (tests/test_web_query.cpp); the
// frames themselves are drawn and timed by lidr_web.cpp (runBench).
#include <string>
#include <vector>

namespace lidr::web {

struct BenchRow {
    std::string mode;
    std::vector<double> frameMs;  // each frame, finished by a 1-pixel read of its target
    std::string refused;          // why the mode did not run (the library's reason); empty: it ran
};

// The table: a title line (`what`: size, scene, lights, context), a header, a row per mode (frames, mean, median,
// min and max ms, frames per second from the mean), or the mode and why it was refused.
std::string benchTable(const std::string& what, const std::vector<BenchRow>& rows);

}  // namespace lidr::web
