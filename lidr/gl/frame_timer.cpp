#include "lidr/gl/frame_timer.h"
#include "lidr/base/gl.h"

#include <chrono>

#include "lidr/base/error.h"

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
    gpu_ = method == TimingMethod::GpuQueries || (method == TimingMethod::Auto && info.timerQuery && !software);
}

void FrameTimer::begin(const std::string& pass) {
    if (!enabled_) return;
    if (open_) throw Error("FrameTimer: pass '" + pass + "' begun inside another");
    open_ = true;
    if (gpu_) {
        Frame& f = ring_[current_];
        if (f.pending || f.number != frameNumber_) {  // first pass of this frame: the slot's old results go
            f.names.clear();
            f.pending = false;
            f.number = frameNumber_;
        }
        f.names.push_back(pass);
        if (f.queries.size() < f.names.size()) f.queries.emplace_back(gl::Kind::Query);
        glBeginQuery(GL_TIME_ELAPSED_EXT, f.queries[f.names.size() - 1].id());
    } else {
        names_.push_back(pass);
        glFinish();
        cpuStart_ = nowMilliseconds();
    }
}

void FrameTimer::end() {
    if (!enabled_) return;
    if (!open_) throw Error("FrameTimer::end without begin");
    open_ = false;
    if (gpu_) {
        glEndQuery(GL_TIME_ELAPSED_EXT);
    } else {
        glFinish();
        cpuMs_.push_back(nowMilliseconds() - cpuStart_);
    }
}

std::vector<PassTime> FrameTimer::read(Frame& f, bool wait) {
    std::vector<PassTime> out;
    for (size_t i = 0; i < f.names.size(); ++i) {
        GLuint id = f.queries[i].id();
        if (!wait) {
            GLuint available = 0;
            glGetQueryObjectuiv(id, GL_QUERY_RESULT_AVAILABLE, &available);
            if (!available) return {};
        }
        GLuint64EXT ns = 0;
        if (glGetQueryObjectui64v)
            glGetQueryObjectui64v(id, GL_QUERY_RESULT, &ns);
        else
            glGetQueryObjectui64vEXT(id, GL_QUERY_RESULT, &ns);
        out.push_back({f.names[i], double(ns) * 1e-6});
    }
    return out;
}

std::vector<PassTime> FrameTimer::collect() {
    std::vector<PassTime> out;
    lag_ = 0;
    if (gpu_) {
        Frame& now = ring_[current_];
        if (now.number == frameNumber_ && !now.names.empty()) now.pending = true;
        if (wait_) {
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
    } else {
        for (size_t i = 0; i < names_.size() && i < cpuMs_.size(); ++i) out.push_back({names_[i], cpuMs_[i]});
    }
    ++frameNumber_;
    names_.clear();
    cpuMs_.clear();
    checkGl("FrameTimer::collect");
    return out;
}

int FrameTimer::queryObjects() const {
    int n = 0;
    for (const Frame& f : ring_) n += static_cast<int>(f.queries.size());
    return n;
}

}  // namespace lidr
