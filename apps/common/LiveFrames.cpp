#include "apps/common/LiveFrames.h"

#include "bridge/core/Error.h"

#include <array>

namespace eikon::app {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void captureForExport(const sim::SceneFields& fields, ProducedFrame& frame) {
    frame.exportArrays = fields.exportArrays();
    frame.meshes.clear();
    for (const TriangleMesh* mesh : fields.deformedMeshes()) frame.meshes.push_back(*mesh);
}

LiveFrames::LiveFrames(sim::SceneFields& fields, bool pipelined, bool captureExportArrays)
    : fields_(fields),
      pipelined_(pipelined),
      captureExportArrays_(captureExportArrays),
      fieldsOnGpu_(fields.mapsOnGpu() && !captureExportArrays),
      ring_(fields.fields(), 2, fieldsOnGpu_ ? render::FieldRingMemory::Device : render::FieldRingMemory::Mapped) {
    const auto start = std::chrono::steady_clock::now();
    writeFields(ring_.acquire());
    current_.time = fields_.time();
    current_.surfaceVersion = fields_.fields().surfaceVersion;
    if (captureExportArrays_) captureForExport(fields_, current_);
    current_.writeFieldsMs = millisecondsSince(start);
    ring_.publish(version_, version_, version_, current_.surfaceVersion);
}

LiveFrames::~LiveFrames() {
    if (pending_.valid()) pending_.wait();  // the thread writes into the ring: let it finish first
}

void LiveFrames::writeFields(const FieldViews& slot) {
    if (!fieldsOnGpu_) {
        fields_.writeFrameInto(slot);
        return;
    }
    const std::array<GLuint, 3> buffers = ring_.acquiredDeviceBuffers();
    fields_.writeFrameOnGpu({buffers[0], buffers[1], buffers[2]});
}

ProducedFrame LiveFrames::produce(const FieldViews& slot) {
    ProducedFrame frame;
    frame.simulated = true;
    auto start = std::chrono::steady_clock::now();
    fields_.simulateFrame();
    frame.simulateMs = millisecondsSince(start);
    start = std::chrono::steady_clock::now();
    writeFields(slot);
    frame.writeFieldsMs = millisecondsSince(start);
    frame.time = fields_.time();
    frame.surfaceVersion = fields_.fields().surfaceVersion;
    frame.phases = fields_.lastTimings();
    if (captureExportArrays_) captureForExport(fields_, frame);
    frame.simulationDevice = fields_.fluidDevice();
    const std::size_t ringFloats = slot.deltaIndex.size() + slot.extinction.size() + slot.scattering.size() +
                                   slot.anisotropy.size() + slot.surfaceNodes.size() + slot.surfaceTriangles.size();
    frame.busBytes = fields_.takeFluidBusBytes() + ringFloats * sizeof(float);  // after the export's reads, which count too
    return frame;
}

void LiveFrames::beginNext() {
    EIKON_CHECK_MSG(!(pipelined_ && fieldsOnGpu_), "a solver on the GPU runs on the GL thread, not pipelined");
    next_ = ring_.acquire();
    if (pipelined_) pending_ = std::async(std::launch::async, [this, slot = next_] { return produce(slot); });
}

const ProducedFrame& LiveFrames::waitNext() {
    produced_ = pipelined_ ? pending_.get() : produce(next_);
    return produced_;
}

void LiveFrames::publishNext() {
    current_ = produced_;
    ++version_;
    const std::uint64_t constant = 1;  // κ and σs of a solver without dye never change
    ring_.publish(version_, fields_.extinctionChangesOverTime() ? version_ : constant,
                  fields_.scatteringChangesOverTime() ? version_ : constant, current_.surfaceVersion);
}

}  // namespace eikon::app
