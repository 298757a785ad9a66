// The zero-copy field ring: the host writes a slot while the GPU reads
// another, fences keep a slot from being rewritten while the GPU still reads
// it, and a long run holds its memory flat.
#include "bridge/core/Error.h"
#include "render/stages/FieldRing.h"
#include "bridge/layout/GpuLayouts.h"
#include "render/stages/FieldTextures.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>
#include <string>

namespace eikon {
namespace {

FieldSet ringLayout(int n, bool withExtinction) {
    FieldSet layout;
    layout.grid = GridSpec{{n, n, n}, {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}};
    layout.referenceIndex = 1.0;
    layout.deltaIndex.assign(layout.grid.cellCount(), 0.0f);
    if (withExtinction) layout.extinction.assign(3 * layout.grid.cellCount(), 0.0f);
    return layout;
}

// Counts, on the GPU, the texels of the δn and κ textures that differ from
// `expected`: a frame the GPU reads must be exactly the frame written.
class TextureProbe {
public:
    TextureProbe() {
        const char* source = R"(#version 450 core
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(binding = 0) uniform sampler3D delta_index;
layout(binding = 1) uniform sampler3D extinction;
layout(std430, binding = 0) buffer Mismatches { uint mismatches; };
uniform float expected;
void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(cell, textureSize(delta_index, 0)))) return;
    bool wrong = texelFetch(delta_index, cell, 0).r != expected ||
                 texelFetch(extinction, cell, 0).rgb != vec3(expected, 2.0 * expected, 3.0 * expected);
    if (wrong) atomicAdd(mismatches, 1u);
})";
        program_ = gl::Program(glCreateShaderProgramv(GL_COMPUTE_SHADER, 1, &source));
        GLint linked = GL_FALSE;
        glGetProgramiv(program_.id(), GL_LINK_STATUS, &linked);
        if (!linked) throw std::runtime_error("probe shader failed to link");
        program_.readWorkGroupSize();
        counter_ = gl::Buffer(sizeof(GLuint));
        counter_.clearToZero();
    }

    void check(const render::FieldTextures& textures, int n, float expected) {
        program_.use();
        glBindTextureUnit(0, textures.index().id());
        textures.bindForTracing();  // κ at its tracing unit
        glUniform1i(program_.uniform("extinction"), static_cast<GLint>(eikon::layout::kExtinctionTexture));
        glUniform1f(program_.uniform("expected"), expected);
        counter_.bindStorage(0);
        program_.dispatchOverCells({n, n, n});
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }

    GLuint mismatches() const { return counter_.downloadAs<GLuint>(); }

private:
    gl::Program program_;
    gl::Buffer counter_;
};

std::size_t residentBytes() {
    std::ifstream statm("/proc/self/statm");
    std::size_t size = 0, resident = 0;
    statm >> size >> resident;
    return resident * 4096;
}

class FieldRingTest : public ::testing::Test {
protected:
    void SetUp() override { test::glContext(); }
};

TEST_F(FieldRingTest, SlotsHaveTheLayoutsFieldsAndNoHostCopy) {
    const FieldSet layout = ringLayout(6, false);
    render::FieldRing ring(layout);
    const FieldViews slot = ring.acquire();
    EXPECT_EQ(slot.deltaIndex.size(), layout.grid.cellCount());
    EXPECT_FALSE(slot.hasExtinction());
    std::fill(slot.deltaIndex.begin(), slot.deltaIndex.end(), 0.25f);
    ring.publish(1, 1, 1, 1);
    render::FieldTextures textures;
    const render::UploadBytes bytes = textures.upload(ring.current());
    EXPECT_EQ(bytes.gpu, layout.grid.cellCount() * sizeof(float));
    EXPECT_LE(bytes.host, 64u);  // the grid's uniform block, nothing of the fields
}

// 1000 frames with the host far faster than the GPU: every frame the GPU
// reads holds exactly the values written for it, the host never gets a slot
// the GPU has yet to finish copying, and resident memory stays flat.
TEST_F(FieldRingTest, ThousandFramesNeverWriteASlotTheGpuReads) {
    constexpr int kCells = 24, kFrames = 1000;
    const FieldSet layout = ringLayout(kCells, true);
    render::FieldRing ring(layout, 2);
    render::FieldTextures textures;
    TextureProbe probe;
    std::size_t residentAtStart = 0;
    for (int frame = 0; frame < kFrames; ++frame) {
        const FieldViews slot = ring.acquire();
        if (frame > 0) {
            ASSERT_NE(slot.deltaIndex.data(), ring.currentViews().deltaIndex.data());
        }
        const auto value = static_cast<float>(frame);
        std::fill(slot.deltaIndex.begin(), slot.deltaIndex.end(), value);
        for (std::size_t v = 0; v < slot.extinction.size(); v += 3) {
            slot.extinction[v] = value;
            slot.extinction[v + 1] = 2.0f * value;
            slot.extinction[v + 2] = 3.0f * value;
        }
        const auto version = static_cast<std::uint64_t>(frame + 1);
        ring.publish(version, version, version, 1);
        textures.upload(ring.current());
        ring.fenceCurrent();
        for (int pass = 0; pass < 3; ++pass) probe.check(textures, kCells, value);  // a slow GPU
        if (frame == 100) residentAtStart = residentBytes();
    }
    EXPECT_EQ(probe.mismatches(), 0u);
    EXPECT_EQ(ring.stats().acquisitions, static_cast<std::uint64_t>(kFrames));
    const double growth = static_cast<double>(residentBytes()) / static_cast<double>(residentAtStart) - 1.0;
    test::reportFigure("resident_growth_frames_100_to_1000", growth);
    test::reportFigure("busy_acquisitions", static_cast<double>(ring.stats().busyAcquisitions));
    EXPECT_LT(std::abs(growth), 0.05);
}

TEST_F(FieldRingTest, OneSlotIsRefused) { EXPECT_THROW(render::FieldRing(ringLayout(4, false), 1), InternalError); }

}  // namespace
}  // namespace eikon
