// Loads one file as lidr-demo --scene does (lidr::loadScene, no GL context) and prints the outcome for
// run_corpus.py: "ok", one "warning <line>" per Scene::warnings line, or "error <message>" (exit 1, as the tools
// exit on lidr::Error); any other exception is "unexpected <what>" (exit 2). The last line is the peak resident
// memory, "peak-rss-kib N".
#include <sys/resource.h>

#include <cstdio>
#include <exception>

#include "lidr/base/error.h"
#include "lidr/scene/io/scene_loader.h"

namespace {

void printPeakMemory() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::printf("peak-rss-kib %ld\n", usage.ru_maxrss);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: lidr-load-check FILE\n");
        return 2;
    }
    int status = 0;
    try {
        const lidr::Scene scene = lidr::loadScene(argv[1]);
        std::printf("ok\n");
        for (const std::string& warning : scene.warnings) std::printf("warning %s\n", warning.c_str());
    } catch (const lidr::Error& error) {
        std::printf("error %s\n", error.what());
        status = 1;
    } catch (const std::exception& error) {
        std::printf("unexpected %s\n", error.what());
        status = 2;
    }
    printPeakMemory();
    return status;
}
