// The zero-copy bridge between the simulation and the GPU.
//
// Sun et al. ([Sun08] §5.2) lost about a tenth of every frame copying volumes
// between OpenGL and CUDA. Here each field of the ring the scene has (δn,
// κ, σs, g and the sharp surfaces' arrays: bridge/grid/OpticalFields.h) lives
// in a ring of persistently mapped GL buffers (gl/MappedBuffer.h): the
// simulation writes frame k+1 straight into one slot, from any thread, while
// the GPU copies frame k from another slot into the 3D textures the tracer
// samples (a GPU-side copy: the shaders need hardware trilinear filtering,
// which buffer textures lack). A fence placed after that copy guards each
// slot; acquire() waits on it before the slot is written again. No host
// memory is copied on this path.
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/grid/FieldViews.h"
#include "gl/MappedBuffer.h"
#include "render/stages/FieldTextures.h"

#include <array>
#include <cstdint>
#include <vector>

namespace eikon::render {

struct FieldRingStats {
    int slots = 0;
    std::uint64_t acquisitions = 0;
    std::uint64_t busyAcquisitions = 0;  // the slot's fence had not signalled yet: acquire() waited
    double waitMilliseconds = 0.0;       // spent in those waits
};

// Where a slot's δn, κ, σs and g live: in persistently mapped buffers the
// host writes (a simulation on the CPU), or in GPU memory only, written by
// GPU passes (the solver and its optical mapping on the GPU: nothing crosses
// the bus). The sharp surfaces' buffers are mapped either way.
enum class FieldRingMemory { Mapped, Device };

class FieldRing {
public:
    // Slots shaped like `layout`: its grid and the fields it has. At least two.
    explicit FieldRing(const FieldSet& layout, int slots = 2, FieldRingMemory memory = FieldRingMemory::Mapped);

    // GL thread. Hands out the next slot once the GPU no longer reads it. Its
    // views stay valid for the ring's life; write them from any thread, then
    // publish().
    FieldViews acquire();
    // GL thread. The acquired slot becomes current, with these versions.
    void publish(std::uint64_t indexVersion, std::uint64_t extinctionVersion, std::uint64_t scatteringVersion,
                 std::uint64_t surfaceVersion);

    // The current slot for FieldTextures::upload; after issuing the commands
    // that read it, call fenceCurrent().
    FieldUpload current() const;
    ConstFieldViews currentViews() const;
    void fenceCurrent();

    const FieldRingStats& stats() const { return stats_; }
    FieldRingMemory memory() const { return memory_; }
    // The GL buffers of the acquired slot's δn, κ, σs (0 where the scene
    // lacks the field), for GPU passes to write. Device memory only.
    std::array<GLuint, 3> acquiredDeviceBuffers() const;

private:
    // One field of a slot: mapped, or (a volume field, in device memory) a
    // plain GL buffer; neither when the scene lacks the field.
    struct SlotField {
        gl::MappedBuffer mapped;
        gl::Buffer device;
    };
    struct Slot {
#define EIKON_SLOT_FIELD(member, channels, version, format, ring, ...) EIKON_IN_RING_##ring(SlotField member;)
        EIKON_OPTICAL_FIELDS(EIKON_SLOT_FIELD)
#undef EIKON_SLOT_FIELD
        gl::Fence readByGpu;
#define EIKON_SLOT_VERSION(group) std::uint64_t group##Version = 0;
        EIKON_OPTICAL_FIELD_VERSIONS(EIKON_SLOT_VERSION)
#undef EIKON_SLOT_VERSION
    };
    // The floats of each field of the ring; 0 when the scene lacks it.
    struct FieldFloats {
#define EIKON_RING_FLOATS(member, channels, version, format, ring, ...) EIKON_IN_RING_##ring(std::size_t member = 0;)
        EIKON_OPTICAL_FIELDS(EIKON_RING_FLOATS)
#undef EIKON_RING_FLOATS
    };
    FieldViews views(const Slot& slot) const;

    GridSpec grid_;
    double referenceIndex_ = 1.0;
    FieldRingMemory memory_;
    FieldFloats floats_;
    std::vector<Slot> slots_;
    int current_ = -1;
    int acquired_ = -1;
    FieldRingStats stats_;
};

}  // namespace eikon::render
