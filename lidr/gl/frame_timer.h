#pragma once
// Per-pass timing: GPU timer queries (ARB_timer_query / EXT_timer_query) or CPU time around glFinish;
// method() says which, and every report carries it. Auto picks queries on hardware, glFinish on Mesa's
// software rasterisers: llvmpipe bins a pass's triangles and rasterises them at a later flush, so its
// queries charge one pass's work to another (measured: the light-table upload showed 19 ms by query,
// 0.04 ms by glFinish; lidr-demo --timer gpu|cpu).
#include <string>
#include <vector>

#include "lidr/gl/gl_info.h"
#include "lidr/gl/gl_resources.h"

namespace lidr {

// One pass of a frame: its time and what it asked of the GPU. The counts are the pass's share of the
// StateCache counters (gl_state.h); `fragments` is the number of fragment shader invocations, counted only in
// measuring runs (FrameTimer::setWaitForResults) where the context has ARB_pipeline_statistics_query.
struct PassTime {
    std::string pass;
    double milliseconds = 0.0;
    long drawCalls = 0;    // glDrawArrays / glDrawElements
    long stateCalls = 0;   // state-setting GL calls issued (those the cache skipped are not in it)
    long fragments = -1;   // fragment shader invocations; -1: not counted
};

enum class TimingMethod { Auto, GpuQueries, CpuFinish };
TimingMethod parseTimingMethod(const std::string& name);  // "auto", "gpu", "cpu"

// Timing is opt-in (LidrOptions::timing and the other modes' `timing`, off by default). GPU timer queries are
// read without stalling: each frame's queries go into a ring of kRingFrames sets, and collect() returns the
// newest earlier frame whose results have all arrived (lag() frames old), or nothing yet; the queries of a
// frame never answered are reused kRingFrames frames later. setWaitForResults(true) instead waits for this
// frame's results (lidr-demo and lidr-bench, which want each frame's own times). The CPU method (glFinish
// around each pass) is synchronous by nature and always reports this frame. Waiting also turns on counting each
// pass's fragment shader invocations where the context can (GlInfo::pipelineStatistics): a measuring run reads
// them anyway, and an application's frames never pay for the queries.
class FrameTimer {
public:
    static constexpr int kRingFrames = 4;
    FrameTimer() = default;
    explicit FrameTimer(const GlInfo& info, TimingMethod method = TimingMethod::Auto);
    // Passes are timed through TimedPass (below), which pairs these two.
    void begin(const std::string& pass);
    void end();
    bool passOpen() const { return open_; }
    // Pass times (see above) and the start of a new frame. Empty when timing is off, or when no earlier
    // frame's GPU queries have answered yet.
    std::vector<PassTime> collect();
    // Frames between the frame just collected and the one whose times it returned (0: its own).
    int lag() const { return lag_; }
    const char* method() const { return gpu_ ? "gpu-timer-query" : "cpu-glfinish"; }
    bool enabled() const { return enabled_; }
    void setEnabled(bool on) { enabled_ = on; }
    void setWaitForResults(bool wait) { wait_ = wait; }
    bool countsFragments() const { return enabled_ && wait_ && fragmentQueries_; }
    int queryObjects() const;  // GL query objects this timer holds (none until a GPU-timed or counted pass begins)

private:
    struct Frame {
        std::vector<gl::Object> queries, fragmentQueries;
        std::vector<PassTime> passes;  // names and counts; times and fragments filled when read (fragments 0:
                                       // its query was issued, -1: not counted)
        long number = -1;
        bool pending = false;  // ended, results not read yet
    };
    Frame& beginFrameSlot();
    std::vector<PassTime> read(Frame& frame, bool wait);
    bool gpu_ = false, enabled_ = true, open_ = false, wait_ = false, fragmentQueries_ = false;
    Frame ring_[kRingFrames];
    int current_ = 0, lag_ = 0;
    long frameNumber_ = 0;
    std::vector<double> cpuMs_;  // this frame's pass times (CPU method)
    double cpuStart_ = 0.0;
    struct Counts {
        long draws = 0, states = 0;
    } passStart_;
};

// One timed pass: begun at construction, ended by end() or when the scope closes, whichever comes first. A pass
// that throws therefore cannot leave the timer open (the next frame's begin() would refuse), and a pass's time
// cannot be left unended by an early return.
class TimedPass {
public:
    TimedPass(FrameTimer& timer, const std::string& pass) : timer_(&timer) { timer.begin(pass); }
    ~TimedPass() {
        if (timer_ && timer_->passOpen()) timer_->end();  // end() throws only when no pass is open
    }
    void end() {
        FrameTimer* t = timer_;
        timer_ = nullptr;
        if (t) t->end();
    }
    TimedPass(const TimedPass&) = delete;
    TimedPass& operator=(const TimedPass&) = delete;

private:
    FrameTimer* timer_;
};

double nowMilliseconds();  // steady clock

}  // namespace lidr
