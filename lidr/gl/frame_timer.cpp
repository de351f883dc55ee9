#include "lidr/gl/frame_timer.h"
#include "lidr/base/gl.h"

#include <chrono>

// Valgrind's callgrind client requests (where the headers are installed): with the CPU method, each pass's
// instructions are dumped apart (scripts/callgrind_passes.sh); outside valgrind each is a few no-op instructions.
#if defined(__has_include)
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define LIDR_CALLGRIND_PASSES 1
#endif
#endif

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"

#ifndef GL_FRAGMENT_SHADER_INVOCATIONS_ARB
#define GL_FRAGMENT_SHADER_INVOCATIONS_ARB 0x82F4  // ARB_pipeline_statistics_query (never used without it)
#endif

namespace lidr {

double nowMilliseconds() {
    using namespace std::chrono;
    return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

TimingMethod parseTimingMethod(const std::string& name) {
    if (name == "auto") return TimingMethod::Auto;
    if (name == "gpu") return TimingMethod::GpuQueries;
    if (name == "cpu") return TimingMethod::CpuFinish;
    throw Error("unknown timing method '" + name + "' (valid: auto, gpu, cpu)");
}

FrameTimer::FrameTimer(const GlInfo& info, TimingMethod method) {
    const bool software = info.renderer.find("llvmpipe") != std::string::npos ||
                          info.renderer.find("softpipe") != std::string::npos ||
                          info.renderer.find("swrast") != std::string::npos;
    if (method == TimingMethod::GpuQueries && !info.timerQuery)
        throw UnsupportedError("GPU timer queries asked for, but the context has no ARB/EXT_timer_query");
    fragmentQueries_ = info.pipelineStatistics;
    gpu_ = method == TimingMethod::GpuQueries || (method == TimingMethod::Auto && info.timerQuery && !software);
}

FrameTimer::Frame& FrameTimer::beginFrameSlot() {
    Frame& f = ring_[current_];
    if (f.pending || f.number != frameNumber_) {  // first pass of this frame: the slot's old results go
        f.passes.clear();
        f.pending = false;
        f.number = frameNumber_;
    }
    return f;
}

void FrameTimer::begin(const std::string& pass) {
    if (!enabled_) return;
    if (open_) throw Error("FrameTimer: pass '" + pass + "' begun inside another");
    open_ = true;
    Frame& f = beginFrameSlot();
    PassTime p;
    p.pass = pass;
    const bool count = countsFragments();
    p.fragments = count ? 0 : -1;  // >= 0 marks a pass whose fragment query was issued; read() fills it
    f.passes.push_back(p);
    const size_t i = f.passes.size() - 1;
    if (count) {
        if (f.fragmentQueries.size() <= i) f.fragmentQueries.emplace_back(gl::Kind::Query);
        glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, f.fragmentQueries[i].id());
    }
    if (gpu_) {
        if (f.queries.size() <= i) f.queries.emplace_back(gl::Kind::Query);
        glBeginQuery(GL_TIME_ELAPSED_EXT, f.queries[i].id());
    } else {
        glFinish();
        cpuStart_ = nowMilliseconds();
#ifdef LIDR_CALLGRIND_PASSES
        CALLGRIND_ZERO_STATS;  // what ran before the pass (and the GL work glFinish waited for) is not its own
#endif
    }
    const GlCallCounters& c = StateCache::current().counters();
    passStart_ = {c.drawCalls, c.stateCalls};
}

void FrameTimer::end() {
    if (!enabled_) return;
    if (!open_) throw Error("FrameTimer::end without begin");
    open_ = false;
    Frame& f = ring_[current_];
    PassTime& p = f.passes.back();
    const GlCallCounters& c = StateCache::current().counters();
    p.drawCalls = c.drawCalls - passStart_.draws;
    p.stateCalls = c.stateCalls - passStart_.states;
    if (gpu_) {
        glEndQuery(GL_TIME_ELAPSED_EXT);
    } else {
        glFinish();
        cpuMs_.push_back(nowMilliseconds() - cpuStart_);
#ifdef LIDR_CALLGRIND_PASSES
        if (RUNNING_ON_VALGRIND) {
            const std::string description = "lidr-pass " + p.pass;  // alive while valgrind reads it
            CALLGRIND_DUMP_STATS_AT(description.c_str());
        }
#endif
    }
    if (p.fragments >= 0) glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
}

namespace {
bool queryAvailable(GLuint id) {
    GLuint available = 0;
    glGetQueryObjectuiv(id, GL_QUERY_RESULT_AVAILABLE, &available);
    return available != 0;
}

// Timer queries exist only with ARB_timer_query (core glGetQueryObjectui64v) or EXT_timer_query (its EXT entry point).
GLuint64 timeResult(GLuint id) {
    GLuint64EXT ns = 0;
    if (glGetQueryObjectui64v)
        glGetQueryObjectui64v(id, GL_QUERY_RESULT, &ns);
    else
        glGetQueryObjectui64vEXT(id, GL_QUERY_RESULT, &ns);
    return ns;
}

// Fragment counts: 64-bit where the entry point exists, else 32-bit (GL 1.5).
long countResult(GLuint id) {
    if (glGetQueryObjectui64v) {
        GLuint64 n = 0;
        glGetQueryObjectui64v(id, GL_QUERY_RESULT, &n);
        return static_cast<long>(n);
    }
    GLuint n = 0;
    glGetQueryObjectuiv(id, GL_QUERY_RESULT, &n);
    return static_cast<long>(n);
}
}  // namespace

std::vector<PassTime> FrameTimer::read(Frame& f, bool wait) {
    if (!wait) {
        for (size_t i = 0; i < f.passes.size(); ++i)
            if ((gpu_ && !queryAvailable(f.queries[i].id())) ||
                (f.passes[i].fragments >= 0 && !queryAvailable(f.fragmentQueries[i].id())))
                return {};
    }
    std::vector<PassTime> out = f.passes;
    for (size_t i = 0; i < out.size(); ++i) {
        if (gpu_)
            out[i].milliseconds = double(timeResult(f.queries[i].id())) * 1e-6;
        else if (i < cpuMs_.size())
            out[i].milliseconds = cpuMs_[i];
        if (out[i].fragments >= 0) out[i].fragments = countResult(f.fragmentQueries[i].id());
    }
    return out;
}

std::vector<PassTime> FrameTimer::collect() {
    std::vector<PassTime> out;
    lag_ = 0;
    Frame& now = ring_[current_];
    if (now.number == frameNumber_ && !now.passes.empty()) now.pending = true;
    if (!gpu_ || wait_) {
        // The CPU method is synchronous; waiting reads this frame's own results.
        if (now.pending) out = read(now, true);
        now.pending = false;
    } else {
        // The newest earlier frame whose queries have all answered; older pending frames are dropped.
        for (int back = 1; back < kRingFrames; ++back) {
            Frame& f = ring_[(current_ + kRingFrames - back) % kRingFrames];
            if (!f.pending || f.number != frameNumber_ - back) continue;
            out = read(f, false);
            if (out.empty()) continue;
            lag_ = back;
            for (Frame& older : ring_)
                if (older.pending && older.number <= f.number) older.pending = false;
            break;
        }
    }
    current_ = (current_ + 1) % kRingFrames;
    ++frameNumber_;
    cpuMs_.clear();
    checkGl("FrameTimer::collect");
    return out;
}

int FrameTimer::queryObjects() const {
    int n = 0;
    for (const Frame& f : ring_) n += static_cast<int>(f.queries.size() + f.fragmentQueries.size());
    return n;
}

}  // namespace lidr
