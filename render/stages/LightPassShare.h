// A light pass shared among processes (`eikon run --distribute photons`):
// each traces its share of the frame's photons or wavefront seeds, and the
// raw tallies of all shares are combined before the receiver filter and the
// fluence smoothing. The tallies are integers (fixed-point power, counts),
// so their sum does not depend on how the pass was shared: K shares give
// the bits of one. The render layer knows nothing of how the shares talk;
// the exchange is given to it (apps/eikon/Ranks.h does it over MPI).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace eikon::render {

// Share `index` of `count`. Photons: the contiguous range shareRange gives
// (each photon's path depends only on its index and the seed). Wavefront:
// seed chunks index, index + count, … of the pass's sequence of chunks, so
// each chunk's tree of patches is the one a single process grows.
struct PassShare {
    unsigned index = 0;
    unsigned count = 1;
    bool whole() const { return count <= 1; }
    bool ownsChunk(std::size_t chunk) const { return count <= 1 || chunk % count == index; }
};

struct PhotonRange {
    std::size_t first = 0, count = 0;
};
// Share i of K takes ⌊N/K⌋ photons of N, one more for i < N mod K, in order.
PhotonRange shareRange(std::size_t photons, const PassShare& share);

// One share's raw tallies, flattened: what sums, what takes the maximum.
struct LightPassTallies {
    std::vector<std::uint64_t> sums;    // statistics, wavefront counters, receiver tallies, wavefront fluence (fixed point)
    std::vector<std::uint32_t> maxima;  // the largest invariant error, as float bits (non-negative floats order as their bits)
    // The photons' raw fluence and direction, recorded photon paths and their
    // power: float, so the photons' fluence of a scattering medium sums to
    // within rounding, not bit for bit (recorded paths are exact: each is
    // written by one share; the wavefront's fixed-point fluence goes with
    // `sums`).
    std::vector<float> floatSums;
};

class LightPassExchange {
public:
    virtual ~LightPassExchange() = default;
    // Replaces `tallies` by the sum (maximum) over all shares on the share
    // that writes the frame; the others' may be left as they were. Every
    // share calls it once per pass, in the same order.
    virtual void combine(LightPassTallies& tallies) = 0;
    // Whether combine leaves this share the whole pass's tallies (the share
    // that writes the frame); the others need not hand them back to the GPU.
    virtual bool receivesTotals() const = 0;
};

}  // namespace eikon::render
