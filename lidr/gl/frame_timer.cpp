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
    names_.push_back(pass);
    if (gpu_) {
        if (queries_.size() < names_.size()) queries_.emplace_back(gl::Kind::Query);
        glBeginQuery(GL_TIME_ELAPSED_EXT, queries_[names_.size() - 1].id());
    } else {
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

std::vector<PassTime> FrameTimer::collect() {
    std::vector<PassTime> out;
    for (size_t i = 0; i < names_.size(); ++i) {
        double ms = 0.0;
        if (gpu_) {
            GLuint64EXT ns = 0;
            if (glGetQueryObjectui64v)
                glGetQueryObjectui64v(queries_[i].id(), GL_QUERY_RESULT, &ns);
            else
                glGetQueryObjectui64vEXT(queries_[i].id(), GL_QUERY_RESULT, &ns);
            ms = double(ns) * 1e-6;
        } else {
            ms = cpuMs_[i];
        }
        out.push_back({names_[i], ms});
    }
    names_.clear();
    cpuMs_.clear();
    checkGl("FrameTimer::collect");
    return out;
}

}  // namespace lidr
