#include "render/stages/FieldRing.h"

#include "bridge/core/Error.h"

#include <utility>

namespace eikon::render {

namespace {

enum Field { kIndex, kExtinction, kScattering, kAnisotropy, kSurfaceNodes, kSurfaceTriangles };

std::span<float> span(const gl::MappedBuffer& buffer, std::size_t floats) {
    return floats ? std::span<float>(buffer.floats(), floats) : std::span<float>();
}

FieldSource source(GLuint buffer, std::size_t floats) { return floats ? FieldSource{nullptr, buffer, floats} : FieldSource{}; }

constexpr std::size_t kVolumeFields = 4;  // δn, κ, σs, g: those that may live in device memory

}  // namespace

FieldRing::FieldRing(const FieldSet& layout, int slots, FieldRingMemory memory)
    : grid_(layout.grid),
      referenceIndex_(layout.referenceIndex),
      memory_(memory),
      floats_{layout.deltaIndex.size(),      layout.extinction.size(),    layout.scattering.size(),
              layout.anisotropy.size(),      layout.surfaceNodes.size(),    layout.surfaceTriangles.size()},
      slots_(static_cast<std::size_t>(slots)) {
    EIKON_CHECK_MSG(slots >= 2, "a field ring needs two slots or more");
    for (Slot& slot : slots_)
        for (std::size_t field = 0; field < floats_.size(); ++field) {
            if (!floats_[field]) continue;
            const gl::GpuResource resource{field < kVolumeFields ? "grid.resolution" : "objects",
                                           "a slot of the live field ring"};
            if (memory_ == FieldRingMemory::Device && field < kVolumeFields)
                slot.device[field] = gl::Buffer(floats_[field] * sizeof(float), nullptr, 0, resource);
            else
                slot.buffers[field] = gl::MappedBuffer(floats_[field] * sizeof(float), resource);
        }
    stats_.slots = slots;
}

FieldViews FieldRing::views(const Slot& slot) const {
    const bool mapped = memory_ == FieldRingMemory::Mapped;  // device memory has no host view
    return {grid_,
            referenceIndex_,
            span(slot.buffers[kIndex], mapped ? floats_[kIndex] : 0),
            span(slot.buffers[kExtinction], mapped ? floats_[kExtinction] : 0),
            span(slot.buffers[kScattering], mapped ? floats_[kScattering] : 0),
            span(slot.buffers[kAnisotropy], mapped ? floats_[kAnisotropy] : 0),
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
    // A mapped slot is also read on the host (the frame's closed forms,
    // render/graph/UniformMedium.h, and a diagnostic's varying voxels).
    auto volume = [&](std::size_t field) {
        if (!floats_[field]) return FieldSource{};
        if (memory_ == FieldRingMemory::Device) return FieldSource{nullptr, slot.device[field].id(), floats_[field]};
        return FieldSource{slot.buffers[field].floats(), slot.buffers[field].id(), floats_[field]};
    };
    return {grid_,
            referenceIndex_,
            volume(kIndex),
            volume(kExtinction),
            volume(kScattering),
            volume(kAnisotropy),
            source(slot.buffers[kSurfaceNodes].id(), floats_[kSurfaceNodes]),
            source(slot.buffers[kSurfaceTriangles].id(), floats_[kSurfaceTriangles]),
            slot.indexVersion,
            slot.extinctionVersion,
            slot.scatteringVersion,
            slot.surfaceVersion,
            FieldSource{},  // emission comes only from imported volumes, never through the ring
            FieldChange{},  // a slot's fields are copied whole, on the GPU
            FieldChange{},
            FieldChange{}};
}

std::array<GLuint, 3> FieldRing::acquiredDeviceBuffers() const {
    EIKON_CHECK_MSG(acquired_ >= 0 && memory_ == FieldRingMemory::Device, "no device-memory slot acquired");
    const Slot& slot = slots_[static_cast<std::size_t>(acquired_)];
    return {slot.device[kIndex].id(), slot.device[kExtinction].id(), slot.device[kScattering].id()};
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
