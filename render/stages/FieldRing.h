// The zero-copy bridge between the simulation and the GPU.
//
// Sun et al. ([Sun08] §5.2) lost about a tenth of every frame copying volumes
// between OpenGL and CUDA. Here each field the scene has (δn, κ, σs, g) lives
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
    struct Slot {
        std::array<gl::MappedBuffer, 6> buffers;  // δn, κ, σs, g, surface nodes and triangles (empty when absent)
        std::array<gl::Buffer, 4> device;         // δn, κ, σs, g in device memory, in place of the first four
        gl::Fence readByGpu;
        std::uint64_t indexVersion = 0, extinctionVersion = 0, scatteringVersion = 0, surfaceVersion = 0;
    };
    FieldViews views(const Slot& slot) const;

    GridSpec grid_;
    double referenceIndex_ = 1.0;
    FieldRingMemory memory_;
    std::array<std::size_t, 6> floats_{};  // per field; 0 when the scene lacks it
    std::vector<Slot> slots_;
    int current_ = -1;
    int acquired_ = -1;
    FieldRingStats stats_;
};

}  // namespace eikon::render
