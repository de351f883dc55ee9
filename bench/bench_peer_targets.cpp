// summary.md's "best peer" targets (issue 37): LIDR's default configuration against tiled forward, clustered
// forward and, where measured, the deferred modes (issue 45) in the same rounds, per scene and size, with each
// ratio and the best peer (the fastest of them), and --mode auto against the fastest of LIDR, tiled and clustered.
#include <string>
#include <vector>

#include <algorithm>

#include "bench_report_text.h"
#include "bench_targets.h"

namespace lidr::bench {

namespace {

struct PeerRows {
    const Row* lidr = nullptr;
    const Row* tiled = nullptr;
    const Row* clustered = nullptr;
    const Row* autoMode = nullptr;
    const Row* deferred = nullptr;
    const Row* deferredStencil = nullptr;
    const Row* tiledDeferred = nullptr;
    std::vector<const Row*> peers() const {
        std::vector<const Row*> out;
        for (const Row* r : {tiled, clustered, deferred, deferredStencil, tiledDeferred})
            if (r) out.push_back(r);
        return out;
    }
    // The fastest peer (median frame), null where none was measured.
    const Row* bestPeer() const {
        const std::vector<const Row*> p = peers();
        if (p.empty()) return nullptr;
        return *std::min_element(p.begin(), p.end(), [](const Row* a, const Row* b) {
            return a->frameMs.median < b->frameMs.median;
        });
    }
    // The fastest of LIDR, tiled and clustered: --mode auto's candidates among them.
    const Row* fastestAutoCandidate() const {
        const Row* f = lidr;
        for (const Row* r : {tiled, clustered})
            if (r && r->frameMs.median < f->frameMs.median) f = r;
        return f;
    }
};

// The goal for LIDR over the best peer on this scene and size; 0 where none applies.
double peerGoal(const Row& r) {
    if (r.run.width != 1024 || r.run.height != 768) return 0.0;
    const std::string& s = r.run.scene;
    if (s == "hall-255" || s == "city-255") return 0.8;
    if (s == "hall-1024" || s.rfind("many-4096", 0) == 0) return 0.65;
    return 0.0;
}

}  // namespace

void writePeerTargets(std::ostream& o, const std::vector<Row>& rows) {
    std::vector<PeerRows> sets;
    for (const Row& r : rows) {
        if (r.run.config.key() != "lidr auto sphere opaque") continue;
        const auto find = [&](const std::string& key) {
            return findRow(rows, r.run.scene, r.run.width, r.run.height, key);
        };
        PeerRows p{&r, find("tiled min/max opaque"), find("clustered opaque"), find("auto opaque"),
                   find("deferred opaque"), find("deferred-stencil opaque"), find("tiled-deferred opaque")};
        if (p.tiled || p.clustered) sets.push_back(p);
    }
    if (sets.empty()) return;
    o << "## Targets (issue 37): LIDR against the best peer\n\n"
         "Opaque, per scene and size: LIDR's default (`lidr auto sphere`) frame over tiled forward's (min/max) and "
         "clustered forward's (its default grid), each in the same rounds (median ratio, min-max over the rounds); "
         "deferred (stencil off, on) and tiled deferred where the run measured them; the best peer is the fastest "
         "peer in this run. `auto / fastest` is `--mode auto` over the fastest of "
         "LIDR, tiled and clustered. Targets at 1024x768: LIDR <= 0.8x the best peer on hall-255 and city-255, "
         "<= 0.65x on hall-1024 and many-4096; everywhere 0 dropped light-pixels in LIDR, tiled and clustered "
         "(where the run checked their lists) and auto <= 1.05x the fastest.\n\n"
         "| scene | LIDR ms | tiled ms | clustered ms | LIDR / tiled | LIDR / clustered | LIDR / deferred, "
         "deferred-stencil, tiled-deferred | best peer | LIDR / best peer | auto / fastest | targets |\n"
         "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const PeerRows& p : sets) {
        const Row& l = *p.lidr;
        double toTiled = -1, toClustered = -1, toBest = -1, autoRatio = -1;
        const std::string tiledCell = ratioCell(l, p.tiled, toTiled);
        const std::string clusteredCell = ratioCell(l, p.clustered, toClustered);
        const Row* best = p.bestPeer();
        const std::string bestCell = ratioCell(l, best, toBest);
        const Row* fastest = p.fastestAutoCandidate();
        std::string deferredCell;
        for (const Row* d : {p.deferred, p.deferredStencil, p.tiledDeferred}) {
            double unused = -1;
            deferredCell += (deferredCell.empty() ? "" : ", ") + (d ? ratioCell(l, d, unused) : std::string("-"));
        }
        const std::string autoCell = p.autoMode ? ratioCell(*p.autoMode, fastest, autoRatio) : "-";
        std::vector<std::string> verdicts;
        const auto judge = [&](const std::string& what, double value, double goal) {
            if (value >= 0) verdicts.push_back(what + (value <= goal ? " met" : " **missed**"));
        };
        const double goal = peerGoal(l);
        if (goal > 0) judge("best peer <= " + num(goal, 2), toBest, goal);
        long drops = l.hasLists ? l.droppedLightPixels : 0;
        bool checked = l.hasLists;
        for (const Row* peer : p.peers())
            if (peer->hasPixelLists) {
                drops += peer->droppedLightPixels;
                checked = true;
            }
        if (checked) judge("0 drops", double(drops), 0.0);
        judge("auto <= 1.05", autoRatio, 1.05);
        std::string targets;
        for (const std::string& v : verdicts) targets += (targets.empty() ? "" : "; ") + v;
        o << "| " << sceneKey(l) << " | " << ms(l.frameMs.median) << " | "
          << (p.tiled ? ms(p.tiled->frameMs.median) : "-") << " | "
          << (p.clustered ? ms(p.clustered->frameMs.median) : "-") << " | " << tiledCell << " | " << clusteredCell
          << " | " << deferredCell << " | " << (best ? best->run.config.label() : "-") << " | " << bestCell << " | " << autoCell
          << (p.autoMode ? " of " + fastest->run.config.label() : "") << " | " << (targets.empty() ? "-" : targets)
          << " |\n";
    }
    o << "\n";
}

}  // namespace lidr::bench
