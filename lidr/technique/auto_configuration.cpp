#include "lidr/technique/auto_configuration.h"

#include <algorithm>

#include "lidr/base/error.h"

namespace lidr {

AutoConfiguration::AutoConfiguration(int maxBudget, int holdFrames, int narrowingInterval)
    : maxBudget_(maxBudget), holdFrames_(holdFrames), narrowingInterval_(narrowingInterval) {
    checkMaxBudget(maxBudget);
    if (holdFrames < 0) throw Error("automatic configuration: hold frames must be >= 0");
    if (narrowingInterval < 1) throw Error("automatic configuration: the narrowing interval must be >= 1 frame");
    budget_ = std::min(kInitialBudget, maxBudget_);
}

void AutoConfiguration::checkMaxBudget(int maxBudget) {
    if (maxBudget < 1 || maxBudget > 32 || (maxBudget & (maxBudget - 1)) != 0)
        throw Error("automatic budget: the largest budget must be 1, 2, 4, 8, 16 or 32, got " + std::to_string(maxBudget));
}

void AutoConfiguration::setMaxBudget(int maxBudget) {
    checkMaxBudget(maxBudget);
    maxBudget_ = maxBudget;
    budget_ = std::min(budget_, maxBudget_);
}

int AutoConfiguration::indexBitsFor(int visibleLights) {
    if (visibleLights < 0) throw Error("automatic index width: negative light count");
    if (visibleLights <= 15) return 4;
    if (visibleLights <= 255) return 8;
    if (visibleLights <= 65535) return 16;
    throw Error(std::to_string(visibleLights) + " visible lights exceed the 65,535 that 16-bit indices hold");
}

int AutoConfiguration::chooseIndexBits(int visibleLights) {
    const int need = indexBitsFor(visibleLights);
    if (bits_ == 0 || need >= bits_) {
        bits_ = need;
        bitsLowFrames_ = 0;
        return bits_;
    }
    bitsLowMax_ = bitsLowFrames_ == 0 ? need : std::max(bitsLowMax_, need);
    if (++bitsLowFrames_ >= holdFrames_) {
        bits_ = bitsLowMax_;
        bitsLowFrames_ = 0;
    }
    return bits_;
}

int AutoConfiguration::observeNeed(int need, bool narrowingAsked) {
    const int framesAnswered = ++framesUncounted_;  // the frames this frame's narrowing answer stands for
    framesSinceNarrowing_ = narrowingAsked ? 0 : framesSinceNarrowing_ + 1;
    const bool overflow = need == 0 || need > budget_;
    const int target = need == 0 ? maxBudget_ : std::min(need, maxBudget_);
    if (!measured_) {
        measured_ = true;
        framesUncounted_ = 0;
        const int repack = overflow && target > budget_ ? target : 0;
        budget_ = target;
        return repack;
    }
    if (target >= budget_) {
        if (!narrowingAsked && !overflow) return 0;  // fits; whether less would have is unknown
        budgetLowFrames_ = 0;
        framesUncounted_ = 0;
        const int repack = overflow && target > budget_ ? target : 0;
        budget_ = target;
        return repack;
    }
    budgetLowMax_ = budgetLowFrames_ == 0 ? target : std::max(budgetLowMax_, target);
    budgetLowFrames_ += framesAnswered;
    framesUncounted_ = 0;
    if (budgetLowFrames_ >= holdFrames_) {
        budget_ = budgetLowMax_;
        budgetLowFrames_ = 0;
    }
    return 0;
}

}  // namespace lidr
