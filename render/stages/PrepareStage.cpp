#include "render/stages/PrepareStage.h"

#include "bridge/layout/GpuLayouts.h"
#include "render/gl/GlDebug.h"
#include "render/gl/ShaderLibrary.h"

namespace eikon::render {

PrepareStage::PrepareStage() : program_(gl::compileComputeProgram("prepare_gradient.comp")) {}

void PrepareStage::run(FieldTextures& fields) {
    fields.gridBlock().bindUniform(layout::kGridBlock);
    fields.index().bindSampler(layout::kIndexTexture);
    fields.gradient().bindImage(0, GL_WRITE_ONLY);
    const glm::ivec3 r = fields.grid().resolution;
    program_.dispatchCovering(static_cast<std::size_t>(r.x), static_cast<std::size_t>(r.y),
                              static_cast<std::size_t>(r.z), 4, 4, 4);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    gl::checkpoint("prepare stage");
}

}  // namespace eikon::render
