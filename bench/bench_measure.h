#pragma once
// Measuring lidr-bench's plan: the scene sets (the runs of one scene and size), each measured in interleaved rounds
// by a SetMeasurer (build, references, warm-up, rounds, rows), a progress bar, and SIGINT/SIGTERM ending the sweep
// after the current row with what was measured so far kept.
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "bench_config.h"
#include "bench_options.h"
#include "bench_report.h"

namespace lidr::bench {

// SIGINT and SIGTERM set the stop flag (stopRequested): the sweep finishes its current row and writes its outputs.
void installSignalHandlers();
bool stopRequested();

// A one-line bar on stderr with the time left, estimated from the configurations done so far weighted by
// their expected cost (expectedCost). Shown only when enabled (a terminal), and only once the sweep has run a few
// seconds.
class Progress {
public:
    Progress(bool enabled, const std::vector<double>& weights);
    void show(size_t done, const std::string& what);
    void finish();

private:
    bool enabled_, shown_ = false;
    std::vector<double> weights_;
    double totalWeight_ = 0.0, start_ = 0.0;
};

// Pixels x lights for the forward modes, pixels for the rest: the weight of a run in the progress estimate.
double expectedCost(const Run& r, const Scene& scene);
// The plan's runs by scene and size, in plan order (which keeps each reference's runs together).
std::vector<std::vector<const Run*>> sceneSets(const Plan& plan);

struct Reference;
struct Slot;

// Measures scene sets one after another into `writer`'s rows.
class SetMeasurer {
public:
    SetMeasurer(const GlInfo& info, const Settings& settings, const std::map<std::string, Scene>& scenes,
                Progress& progress, ReportWriter& writer, RunInfo& runInfo);
    ~SetMeasurer();
    // One scene set: every configuration built, judged against its reference, warmed up and measured in rounds
    // (in parts of at most Settings::maxLive renderers, the baseline in each), a row written for each.
    void measure(const std::vector<const Run*>& wholeSet);

private:
    struct SetState;
    // One part of a set; false where it was interrupted before any round (nothing of the set to write).
    bool measurePart(SetState& set, const std::vector<const Run*>& part, const std::string& setKey);
    void renderReferences(SetState& set, std::vector<Slot>& slots, std::vector<double>& firstWall,
                          const std::string& setKey);
    // The rounds over the slots that take part; returns how many ran.
    int runRounds(SetState& set, std::vector<Slot>& slots, const std::vector<size_t>& active, size_t baseline, const std::string& setKey);
    Row rowFor(SetState& set, Slot& slot, const Slot& baseline, int rounds);
    void judge(SetState& set, Slot& slot, Row& row, const Renderer* baselineRenderer);
    int maxOverlapFor(const Run& run, const Scene& scene, const std::vector<PointLight>& lights,
                      const Renderer* depthSource);

    const GlInfo& info_;
    const Settings& settings_;
    const std::map<std::string, Scene>& scenes_;
    Progress& progress_;
    ReportWriter& writer_;
    RunInfo& runInfo_;
    std::map<std::string, int> maxOverlaps_;  // scene|size -> most lights touching one surface pixel
    int nextId_ = 1;
    size_t runsDone_ = 0;
    int roundsDone_ = 0;
};

}  // namespace lidr::bench
