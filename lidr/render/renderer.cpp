#include "lidr/render/renderer.h"

namespace lidr {

double FrameStats::frameMilliseconds() const {
    double sum = 0.0;
    for (const PassTime& p : passes) sum += p.milliseconds;
    return sum;
}

}  // namespace lidr
