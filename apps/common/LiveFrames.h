// The producer half of the live loop: a simulated scene's frames go through
// the GPU field ring (render/stages/FieldRing.h). With pipelining, frame k+1
// is simulated and written into its ring slot on a thread of its own while
// the renderer traces and views frame k; without, it runs after frame k has
// rendered. The images are the same either way. A solver on the GPU writes
// its frames into slots in GPU memory instead, on the GL thread.
#pragma once

#include "apps/common/ExportNeeds.h"
#include "render/stages/FieldRing.h"
#include "sim/SceneFields.h"

#include <chrono>
#include <cstdint>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace eikon::app {

// What produced the current frame: its simulated time and how long the
// simulation and the write into GPU memory took.
struct ProducedFrame {
    double time = 0.0;
    bool simulated = false;  // false for frame 0, the initial state
    double simulateMs = 0.0;
    double writeFieldsMs = 0.0;
    std::uint64_t surfaceVersion = 0;  // of the sharp surfaces written into the slot
    std::vector<sim::PhaseTiming> phases;
    std::optional<sim::FluidFrameReport> fluid;  // the fluid solver's substeps and budgets, when it ran
    std::string simulationDevice;     // where the fluid solver or the water ran: "cpu" or "gpu"
    // Bytes that crossed between host and GPU memory to make this frame: the
    // solver's own traffic and the optical fields written into the mapped ring slot.
    std::uint64_t busBytes = 0;
    std::vector<NamedArray> exportArrays;  // the solver's own fields, when captured for export
    std::vector<TriangleMesh> meshes;          // the deformed meshes, when captured for export
    // The optical fields the export reads, copied back from a slot in GPU
    // memory (null otherwise: the ring's mapped slot is read in place).
    std::shared_ptr<const FieldSet> exportedFields;
};

// Wall time since `start`, in milliseconds (the frame loop's stage figures).
double millisecondsSince(std::chrono::steady_clock::time_point start);

// Copies what export reads of the frame `fields` now hold (the simulation's
// own arrays that `needs` asks for, and the deformed meshes) into `frame`.
void captureForExport(const sim::SceneFields& fields, const ExportNeeds& needs, ProducedFrame& frame);

class LiveFrames {
public:
    // Writes frame 0 into the ring and publishes it. GL thread. Each frame
    // `exports` exports also keeps what it asks of the solver's own fields
    // (velocity, temperature, …) as they were when it was produced, and,
    // where the slots live in GPU memory, a host copy of the optical fields
    // it asks for; other frames read nothing back for export.
    LiveFrames(sim::SceneFields& fields, bool pipelined, ExportNeeds exports = {});
    ~LiveFrames();

    render::FieldRing& ring() { return ring_; }
    // The current frame's fields for its outputs: the ring's mapped slot, or
    // the host copy of an exported frame whose slot is in GPU memory.
    ConstFieldViews currentViews() const;
    // Takes effect at the next beginNext().
    void setPipelined(bool pipelined) { pipelined_ = pipelined; }
    const ProducedFrame& current() const { return current_; }

    // Acquires the next slot and, when pipelined, starts producing the next
    // frame into it. GL thread; call before rendering the current frame.
    void beginNext();
    // Whether waitNext() would return at once: the next frame, begun
    // pipelined, is produced (true when none is being produced on a thread).
    bool nextReady() const {
        return !pending_.valid() || pending_.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
    }
    // Produces the next frame (when not begun pipelined) or waits for it.
    const ProducedFrame& waitNext();
    // Publishes the next frame as current. GL thread; call once the current
    // frame's outputs were written from its slot.
    void publishNext();

private:
    ProducedFrame produce(const FieldViews& slot);

    // Writes the slot's fields: on the host, or on the GPU (writeFrameOnGpu).
    void writeFields(const FieldViews& slot);
    // What frame `frame` (its fields just written into the acquired slot)
    // keeps for export, and the bytes read back for it.
    std::uint64_t captureExport(int frame, ProducedFrame& produced);

    sim::SceneFields& fields_;
    bool pipelined_;
    ExportNeeds exports_;
    // The solver and its optical mapping run on the GPU and write the ring's
    // device-memory slots; exports keep the mapped slots the host reads.
    bool fieldsOnGpu_;
    render::FieldRing ring_;
    FieldViews next_;
    std::future<ProducedFrame> pending_;
    ProducedFrame current_, produced_;
    std::uint64_t version_ = 1;
    int producedFrame_ = 0;  // the frame the acquired slot holds or will hold
};

}  // namespace eikon::app
