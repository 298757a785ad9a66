#include "render/stages/PrepareStage.h"

#include "bridge/layout/GpuLayouts.h"
#include "gl/GlDebug.h"
#include "gl/ShaderLibrary.h"
#include "render/stages/GaussianKernel.h"
#include "render/stages/NativePrepare.h"

namespace eikon::render {

PrepareStage::PrepareStage(const GridDesc& grid, const FieldTextures& fields, StageDevice device)
    : device_(device), kernel_(gaussianHalfKernel(grid.smoothingSigmaVoxels, grid.smoothingWindowVoxels)) {
    if (device_ == StageDevice::Gpu) gradientProgram_ = gl::compileComputeProgram("prepare_gradient.comp");
    if (kernel_.size() > 1) {
        if (device_ == StageDevice::Gpu) smoothProgram_ = gl::compileComputeProgram("smooth_index.comp");
        const glm::ivec3 r = fields.grid().resolution;
        // The native loops keep their scratch in host memory: they need only the result's texture.
        for (int i = device_ == StageDevice::Cpu ? 1 : 0; i < 2; ++i)
            scratch_[i] = gl::Texture3D(GL_R32F, r.x, r.y, r.z, gl::gridResource("the index smoothing's scratch", r.x, r.y, r.z));
    }
}

const gl::Texture3D& PrepareStage::smoothedIndex(const FieldTextures& fields) const {
    return kernel_.size() > 1 ? scratch_[1] : fields.index();
}

void PrepareStage::run(FieldTextures& fields) {
    if (device_ == StageDevice::Cpu)
        runNative(fields);
    else
        runCompute(fields);
}

void PrepareStage::runNative(FieldTextures& fields) {
    const glm::ivec3 r = fields.grid().resolution;
    hostIndex_.resize(static_cast<std::size_t>(fields.grid().cellCount()));
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);  // after any shader's writes to δn
    downloadTexels(fields.index(), GL_RED, hostIndex_.data(), hostIndex_.size() * sizeof(float));
    if (kernel_.size() > 1) {
        smoothIndexNative(hostIndex_, r, kernel_, hostScratch_);
        scratch_[1].upload(GL_RED, GL_FLOAT, hostIndex_.data());  // where smoothedIndex() looks
    }
    indexGradientNative(hostIndex_, r, glm::vec3(fields.grid().voxelSize()), hostGradient_);
    fields.gradient().upload(GL_RGBA, GL_FLOAT, hostGradient_.data());
    gl::checkpoint("prepare stage (native)");
}

void PrepareStage::runCompute(FieldTextures& fields) {
    const glm::ivec3 r = fields.grid().resolution;
    if (kernel_.size() > 1) {
        // x: raw → scratch 0, y: scratch 0 → scratch 1, z: scratch 1 → scratch 0; the swap below
        // then leaves the result in scratch_[1], where smoothedIndex() looks.
        smoothProgram_.use();
        glUniform1i(smoothProgram_.uniform("radius"), static_cast<GLint>(kernel_.size()) - 1);
        glUniform1fv(smoothProgram_.uniform("weights"), static_cast<GLsizei>(kernel_.size()), kernel_.data());
        const gl::Texture3D* sources[3] = {&fields.index(), &scratch_[0], &scratch_[1]};
        gl::Texture3D* targets[3] = {&scratch_[0], &scratch_[1], &scratch_[0]};
        const glm::ivec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        for (int pass = 0; pass < 3; ++pass) {
            glUniform3i(smoothProgram_.uniform("axis"), axes[pass].x, axes[pass].y, axes[pass].z);
            sources[pass]->bindSampler(layout::kIndexTexture);
            targets[pass]->bindImage(layout::kSmoothedIndexImage, GL_WRITE_ONLY);
            smoothProgram_.dispatchOverCells(r);
            glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        }
        std::swap(scratch_[0], scratch_[1]);  // the result now lives in scratch_[1]
    }
    fields.gridBlock().bindUniform(layout::kGridBlock);
    smoothedIndex(fields).bindSampler(layout::kIndexTexture);
    fields.gradient().bindImage(layout::kGradientImage, GL_WRITE_ONLY);
    gradientProgram_.dispatchOverCells(r);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    gl::checkpoint("prepare stage");
}

void PrepareStage::fillUniform(FieldTextures& fields, float deltaIndex) {
    const float texel[4] = {0.0f, 0.0f, 0.0f, deltaIndex};
    glClearTexImage(fields.gradient().id(), 0, GL_RGBA, GL_FLOAT, texel);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    gl::checkpoint("prepare stage, uniform index");
}

}  // namespace eikon::render
