#include "render/stages/LightPassShare.h"

#include <algorithm>

namespace eikon::render {

PhotonRange shareRange(std::size_t photons, const PassShare& share) {
    if (share.whole()) return {0, photons};
    // The first N mod K shares take one photon more; no product can overflow.
    const std::size_t base = photons / share.count, extra = photons % share.count;
    return {base * share.index + std::min<std::size_t>(share.index, extra), base + (share.index < extra ? 1 : 0)};
}

}  // namespace eikon::render
