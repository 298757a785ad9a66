#include "render/stages/FieldRing.h"

#include "bridge/core/Error.h"

#include <utility>

namespace eikon::render {

namespace {

enum Field { kIndex, kExtinction, kScattering, kAnisotropy, kSurfaceNodes, kSurfaceTriangles };

std::span<float> span(const gl::MappedBuffer& buffer, std::size_t floats) {
    return floats ? std::span<float>(buffer.floats(), floats) : std::span<float>();
}

FieldSource source(const gl::MappedBuffer& buffer, std::size_t floats) {
    return floats ? FieldSource{nullptr, buffer.id(), floats} : FieldSource{};
}

}  // namespace

FieldRing::FieldRing(const FieldSet& layout, int slots)
    : grid_(layout.grid),
      referenceIndex_(layout.referenceIndex),
      floats_{layout.deltaIndex.size(),      layout.extinction.size(),    layout.scattering.size(),
              layout.anisotropy.size(),      layout.surfaceNodes.size(),    layout.surfaceTriangles.size()},
      slots_(static_cast<std::size_t>(slots)) {
    EIKON_CHECK_MSG(slots >= 2, "a field ring needs two slots or more");
    for (Slot& slot : slots_)
        for (std::size_t field = 0; field < floats_.size(); ++field)
            if (floats_[field])
                slot.buffers[field] = gl::MappedBuffer(
                    floats_[field] * sizeof(float),
                    {field < 4 ? "grid.resolution" : "objects", "a slot of the live field ring"});
    stats_.slots = slots;
}

FieldViews FieldRing::views(const Slot& slot) const {
    return {grid_,
            referenceIndex_,
            span(slot.buffers[kIndex], floats_[kIndex]),
            span(slot.buffers[kExtinction], floats_[kExtinction]),
            span(slot.buffers[kScattering], floats_[kScattering]),
            span(slot.buffers[kAnisotropy], floats_[kAnisotropy]),
            span(slot.buffers[kSurfaceNodes], floats_[kSurfaceNodes]),
            span(slot.buffers[kSurfaceTriangles], floats_[kSurfaceTriangles])};
}

FieldViews FieldRing::acquire() {
    EIKON_CHECK_MSG(acquired_ < 0, "a field ring slot acquired twice without publish");
    const int next = (current_ + 1) % static_cast<int>(slots_.size());
    Slot& slot = slots_[static_cast<std::size_t>(next)];
    ++stats_.acquisitions;
    if (!slot.readByGpu.signaled()) ++stats_.busyAcquisitions;
    stats_.waitMilliseconds += slot.readByGpu.wait().count();
    acquired_ = next;
    return views(slot);
}

void FieldRing::publish(std::uint64_t indexVersion, std::uint64_t extinctionVersion, std::uint64_t scatteringVersion,
                        std::uint64_t surfaceVersion) {
    EIKON_CHECK_MSG(acquired_ >= 0, "publish without an acquired field ring slot");
    Slot& slot = slots_[static_cast<std::size_t>(acquired_)];
    slot.indexVersion = indexVersion;
    slot.extinctionVersion = extinctionVersion;
    slot.scatteringVersion = scatteringVersion;
    slot.surfaceVersion = surfaceVersion;
    current_ = std::exchange(acquired_, -1);
}

FieldUpload FieldRing::current() const {
    EIKON_CHECK_MSG(current_ >= 0, "no field ring slot published yet");
    const Slot& slot = slots_[static_cast<std::size_t>(current_)];
    return {grid_,
            referenceIndex_,
            source(slot.buffers[kIndex], floats_[kIndex]),
            source(slot.buffers[kExtinction], floats_[kExtinction]),
            source(slot.buffers[kScattering], floats_[kScattering]),
            source(slot.buffers[kAnisotropy], floats_[kAnisotropy]),
            source(slot.buffers[kSurfaceNodes], floats_[kSurfaceNodes]),
            source(slot.buffers[kSurfaceTriangles], floats_[kSurfaceTriangles]),
            slot.indexVersion,
            slot.extinctionVersion,
            slot.scatteringVersion,
            slot.surfaceVersion,
            FieldSource{}};  // emission comes only from imported volumes, never through the ring
}

ConstFieldViews FieldRing::currentViews() const {
    EIKON_CHECK_MSG(current_ >= 0, "no field ring slot published yet");
    return views(slots_[static_cast<std::size_t>(current_)]);
}

void FieldRing::fenceCurrent() {
    EIKON_CHECK_MSG(current_ >= 0, "no field ring slot published yet");
    slots_[static_cast<std::size_t>(current_)].readByGpu.insert();
}

}  // namespace eikon::render
