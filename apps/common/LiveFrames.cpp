#include "apps/common/LiveFrames.h"

#include "bridge/core/Error.h"

#include <algorithm>
#include <array>
#include <memory>
#include <utility>

namespace eikon::app {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void captureForExport(const sim::SceneFields& fields, const ExportNeeds& needs, ProducedFrame& frame) {
    frame.exportArrays = fields.exportArrays(needs.names());
    frame.meshes.clear();
    for (const TriangleMesh* mesh : fields.deformedMeshes()) frame.meshes.push_back(*mesh);
}

LiveFrames::LiveFrames(sim::SceneFields& fields, bool pipelined, ExportNeeds exports)
    : fields_(fields),
      pipelined_(pipelined),
      exports_(std::move(exports)),
      fieldsOnGpu_(fields.mapsOnGpu()),
      ring_(fields.fields(), 2, fieldsOnGpu_ ? render::FieldRingMemory::Device : render::FieldRingMemory::Mapped) {
    const auto start = std::chrono::steady_clock::now();
    writeFields(ring_.acquire());
    current_.time = fields_.time();
    current_.surfaceVersion = fields_.fields().surfaceVersion;
    current_.busBytes = captureExport(0, current_);
    current_.writeFieldsMs = millisecondsSince(start);
    ring_.publish(version_, version_, version_, current_.surfaceVersion);
}

std::uint64_t LiveFrames::captureExport(int frame, ProducedFrame& produced) {
    if (!exports_.exportsFrame(frame)) return 0;
    captureForExport(fields_, exports_, produced);
    if (!fieldsOnGpu_) return 0;  // the mapped slot is read in place
    // The optical fields the export reads, from the acquired slot in GPU memory.
    auto copy = std::make_shared<FieldSet>();
    const FieldSet& layout = fields_.fields();
    copy->grid = layout.grid;
    copy->referenceIndex = layout.referenceIndex;
    const std::array<GLuint, 3> buffers = ring_.acquiredDeviceBuffers();
    std::uint64_t bytes = 0;
    auto readBack = [&](GLuint buffer, std::size_t floats, bool wanted, std::vector<float>& into) {
        into.assign(floats, 0.0f);  // present (zero) where not exported: the views keep the layout
        if (!wanted || !buffer || floats == 0) return;
        glGetNamedBufferSubData(buffer, 0, static_cast<GLsizeiptr>(floats * sizeof(float)), into.data());
        bytes += floats * sizeof(float);
    };
    readBack(buffers[0], layout.deltaIndex.size(), exports_.wants("index") || exports_.wants("delta_index"),
             copy->deltaIndex);
    readBack(buffers[1], layout.extinction.size(), exports_.wants("extinction"), copy->extinction);
    readBack(buffers[2], layout.scattering.size(), exports_.wants("scattering"), copy->scattering);
    produced.exportedFields = std::move(copy);
    return bytes;
}

ConstFieldViews LiveFrames::currentViews() const {
    ConstFieldViews views = ring_.currentViews();
    if (current_.exportedFields) {  // an exported frame whose slot is in GPU memory
        const ConstFieldViews copy = viewsOf(*current_.exportedFields);
        views.deltaIndex = copy.deltaIndex;
        views.extinction = copy.extinction;
        views.scattering = copy.scattering;
    }
    return views;
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
    const int index = ++producedFrame_;
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
    frame.fluid = fields_.fluidReport();
    const std::uint64_t exportedBytes = captureExport(index, frame);
    frame.simulationDevice = fields_.fluidDevice();
    std::size_t ringFloats = 0;  // the slot's fields of the ring that the host wrote
#define EIKON_RING_FIELD_FLOATS(member, channels, version, format, ring, ...) \
    EIKON_IN_RING_##ring(ringFloats += slot.member.size();)
    EIKON_OPTICAL_FIELDS(EIKON_RING_FIELD_FLOATS)
#undef EIKON_RING_FIELD_FLOATS
    // After the export's reads, which count too.
    frame.busBytes = fields_.takeFluidBusBytes() + ringFloats * sizeof(float) + exportedBytes;
    return frame;
}

void LiveFrames::beginNext() {
    EIKON_CHECK_MSG(!(pipelined_ && fieldsOnGpu_), "a solver on the GPU runs on the GL thread, not pipelined");
    next_ = ring_.acquire();
    if (pipelined_) pending_ = std::async(std::launch::async, [this, slot = next_] { return produce(slot); });
}

const ProducedFrame& LiveFrames::waitNext() {
    produced_ = pending_.valid() ? pending_.get() : produce(next_);
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
