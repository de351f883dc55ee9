#pragma once
// The automatic configuration of LIDR (doc/auto.md): what each frame needs, decided from what it holds.
// - Index width: the narrowest (4, 8 or 16 bits) that holds the frame's visible lights, which are numbered
//   compactly in draw order (the light table holds only them).
// - Budget: the smallest of 1, 2, 4, 8, 16, 32 (at most maxBudget) that drops nothing, measured on the GPU after the volume pass
//   (OverlapProbe). A frame that needs more than it was packed with is packed again at once, the same frame.
// Both widen at once and narrow only after `holdFrames` frames in a row that would all fit the narrower
// choice, so a camera moving through the scene does not flip them every frame. The first measurement is
// taken as it is (no history to hold against). Whether the budget could narrow is asked only every
// `narrowingInterval` frames (asksNarrowing()); each answer stands for the frames since the last one. Every frame
// still asks whether it overflows, so a frame is never left over its budget: a narrowing that a frame between two
// answers would have contradicted costs one re-pack, never a dropped light.
#include <string>

namespace lidr {

class AutoConfiguration {
public:
    static constexpr int kDefaultHoldFrames = 8;
    static constexpr int kInitialBudget = 4;
    static constexpr int kDefaultNarrowingInterval = 4;
    explicit AutoConfiguration(int maxBudget = 16, int holdFrames = kDefaultHoldFrames, int narrowingInterval = 1);

    // The narrowest width that holds `visibleLights` lights: 4 up to 15, 8 up to 255, 16 up to 65,535; throws
    // lidr::Error above.
    static int indexBitsFor(int visibleLights);

    // The width for this frame's visible lights (widens at once, narrows after the hold).
    int chooseIndexBits(int visibleLights);
    // The budget to pack this frame with: the last decision (kInitialBudget before any measurement).
    int budget() const { return budget_; }
    // Whether this frame's measurement should also ask below the budget: the first frame, then every
    // narrowingInterval-th.
    bool asksNarrowing() const { return !measured_ || framesSinceNarrowing_ + 1 >= narrowingInterval_; }
    // After the volume pass: `need` is the smallest budget that drops nothing (0: more than the largest).
    // `narrowingAsked` false: only "over the budget" was measured, and a need equal to the budget means "fits,
    // less unknown" (it neither counts towards narrowing nor restarts the count).
    // Returns the budget to re-pack this frame with when the frame overflowed and a larger budget exists;
    // 0 when the frame stands as packed.
    int observeNeed(int need, bool narrowingAsked = true);
    int maxBudget() const { return maxBudget_; }
    // The largest budget this frame may take (its index width decides how many targets a budget needs: 32 fits
    // 4- and 8-bit indices, 16 the 16-bit ones); a budget above it is lowered to it now. Throws lidr::Error for a
    // value other than 1, 2, 4, 8, 16 or 32.
    void setMaxBudget(int maxBudget);
    static void checkMaxBudget(int maxBudget);
    bool measured() const { return measured_; }  // a first measurement was taken
    int holdFrames() const { return holdFrames_; }
    int narrowingInterval() const { return narrowingInterval_; }

private:
    int maxBudget_, holdFrames_, narrowingInterval_;
    int framesSinceNarrowing_ = 0;  // frames since the last one that asked below the budget
    int framesUncounted_ = 0;       // frames since the last answer or restart of the narrowing count
    int budget_ = kInitialBudget, bits_ = 0;
    bool measured_ = false;
    int budgetLowFrames_ = 0, budgetLowMax_ = 0;  // frames in a row that needed less, and the most they needed
    int bitsLowFrames_ = 0, bitsLowMax_ = 0;
};

}  // namespace lidr
