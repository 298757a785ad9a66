#include "render/stages/FieldRing.h"

#include "bridge/core/Error.h"

#include <utility>

namespace eikon::render {

namespace {

std::span<float> span(const gl::MappedBuffer& buffer, std::size_t floats) {
    return floats ? std::span<float>(buffer.floats(), floats) : std::span<float>();
}

// Whether a field of the ring is a volume field: those may live in device
// memory (GPU passes write them) and, mapped, are read on the host too; the
// surfaces' arrays are always mapped and read by the GPU only.
constexpr bool kVolumeField_Volume = true;
constexpr bool kVolumeField_Surface = false;

}  // namespace

FieldRing::FieldRing(const FieldSet& layout, int slots, FieldRingMemory memory)
    : grid_(layout.grid), referenceIndex_(layout.referenceIndex), memory_(memory), slots_(static_cast<std::size_t>(slots)) {
    EIKON_CHECK_MSG(slots >= 2, "a field ring needs two slots or more");
#define EIKON_RING_FLOATS(member, channels, version, format, ring, ...) \
    EIKON_IN_RING_##ring(floats_.member = layout.member.size();)
    EIKON_OPTICAL_FIELDS(EIKON_RING_FLOATS)
#undef EIKON_RING_FLOATS
    const auto make = [&](SlotField& field, std::size_t floats, bool volumeField) {
        if (!floats) return;
        const gl::GpuResource resource{volumeField ? "grid.resolution" : "objects", "a slot of the live field ring"};
        if (memory_ == FieldRingMemory::Device && volumeField)
            field.device = gl::Buffer(floats * sizeof(float), nullptr, 0, resource);
        else
            field.mapped = gl::MappedBuffer(floats * sizeof(float), resource);
    };
    for (Slot& slot : slots_) {
#define EIKON_MAKE_SLOT_FIELD(member, channels, version, format, ring, ...) \
    EIKON_IN_RING_##ring(make(slot.member, floats_.member, kVolumeField_##ring);)
        EIKON_OPTICAL_FIELDS(EIKON_MAKE_SLOT_FIELD)
#undef EIKON_MAKE_SLOT_FIELD
    }
    stats_.slots = slots;
}

FieldViews FieldRing::views(const Slot& slot) const {
    const bool mapped = memory_ == FieldRingMemory::Mapped;  // device memory has no host view
    FieldViews views;
    views.grid = grid_;
    views.referenceIndex = referenceIndex_;
#define EIKON_SLOT_VIEW(member, channels, version, format, ring, ...)                                       \
    EIKON_IN_RING_##ring(views.member = span(slot.member.mapped,                                            \
                                             mapped || !kVolumeField_##ring ? floats_.member : 0);)
    EIKON_OPTICAL_FIELDS(EIKON_SLOT_VIEW)
#undef EIKON_SLOT_VIEW
    return views;
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
    // render/graph/UniformMedium.h, and a diagnostic's varying voxels); a
    // slot's fields are copied whole, on the GPU (no FieldChange). Emission
    // comes only from imported volumes, never through the ring.
    const auto source = [&](const SlotField& field, std::size_t floats, bool volumeField) {
        if (!floats) return FieldSource{};
        if (field.device.id()) return FieldSource{nullptr, field.device.id(), floats};
        return FieldSource{volumeField ? field.mapped.floats() : nullptr, field.mapped.id(), floats};
    };
    FieldUpload upload;
    upload.grid = grid_;
    upload.referenceIndex = referenceIndex_;
#define EIKON_SLOT_SOURCE(member, channels, version, format, ring, ...) \
    EIKON_IN_RING_##ring(upload.member = source(slot.member, floats_.member, kVolumeField_##ring);)
    EIKON_OPTICAL_FIELDS(EIKON_SLOT_SOURCE)
#undef EIKON_SLOT_SOURCE
#define EIKON_SLOT_VERSION(group) upload.group##Version = slot.group##Version;
    EIKON_OPTICAL_FIELD_VERSIONS(EIKON_SLOT_VERSION)
#undef EIKON_SLOT_VERSION
    return upload;
}

std::array<GLuint, 3> FieldRing::acquiredDeviceBuffers() const {
    EIKON_CHECK_MSG(acquired_ >= 0 && memory_ == FieldRingMemory::Device, "no device-memory slot acquired");
    const Slot& slot = slots_[static_cast<std::size_t>(acquired_)];
    return {slot.deltaIndex.device.id(), slot.extinction.device.id(), slot.scattering.device.id()};
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
