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

struct PassTime {
    std::string pass;
    double milliseconds = 0.0;
};

enum class TimingMethod { Auto, GpuQueries, CpuFinish };
TimingMethod parseTimingMethod(const std::string& name);  // "auto", "gpu", "cpu"

class FrameTimer {
public:
    FrameTimer() = default;
    explicit FrameTimer(const GlInfo& info, TimingMethod method = TimingMethod::Auto);
    void begin(const std::string& pass);
    void end();
    // Waits for the frame's results, returns them in pass order and starts a new frame.
    std::vector<PassTime> collect();
    const char* method() const { return gpu_ ? "gpu-timer-query" : "cpu-glfinish"; }
    bool enabled() const { return enabled_; }
    void setEnabled(bool on) { enabled_ = on; }

private:
    bool gpu_ = false, enabled_ = true, open_ = false;
    std::vector<gl::Object> queries_;
    std::vector<std::string> names_;
    std::vector<double> cpuMs_;
    double cpuStart_ = 0.0;
};

double nowMilliseconds();  // steady clock

}  // namespace lidr
