#include "sim/gpu/GpuOpticalMapping.h"

#include "bridge/core/Error.h"
#include "bridge/layout/GpuLayouts.h"
#include "gl/ShaderLibrary.h"

namespace eikon::sim::gpu {

namespace {

bool positive(const Rgb& rgb) { return rgb.r > 0.0 || rgb.g > 0.0 || rgb.b > 0.0; }

gl::Program mappingProgram(const SimDesc& desc) {
    const bool liquid = desc.fluid == SimDesc::Fluid::Liquid;
    return gl::compileComputeProgram(
        "sim/optical_mapping.comp",
        {{"EIKON_LIQUID", liquid ? "1" : "0"},
         {"EIKON_LORENTZ_LORENZ", liquid && desc.mixing == SimDesc::Mixing::LorentzLorenz ? "1" : "0"},
         {"EIKON_HAS_EXTINCTION", positive(desc.dyeExtinction) ? "1" : "0"},
         {"EIKON_HAS_SCATTERING", positive(desc.dyeScattering) ? "1" : "0"}});
}

void setVector(const gl::Program& program, const char* name, glm::dvec3 v) {
    glProgramUniform3d(program.id(), program.uniform(name), v.x, v.y, v.z);
}

void setCells(const gl::Program& program, const char* name, glm::ivec3 v) {
    glProgramUniform3i(program.id(), program.uniform(name), v.x, v.y, v.z);
}

}  // namespace

GpuOpticalMapping::GpuOpticalMapping(const SimDesc& desc, const GridSpec& solverGrid, const GridSpec& renderGrid,
                                     double referenceIndex)
    : solver_(solverGrid),
      render_(renderGrid),
      absorbs_(positive(desc.dyeExtinction)),
      scatters_(positive(desc.dyeScattering)),
      program_(mappingProgram(desc)) {
    const GLuint id = program_.id();
    setCells(program_, "render_cells", render_.resolution);
    setVector(program_, "render_min", render_.boundsMin);
    setVector(program_, "render_voxel", render_.voxelSize());
    setCells(program_, "solver_cells", solver_.resolution);
    setVector(program_, "solver_min", solver_.boundsMin);
    setVector(program_, "solver_max", solver_.boundsMax);
    setVector(program_, "solver_voxel", solver_.voxelSize());
    glProgramUniform1d(id, program_.uniform("reference_index"), referenceIndex);
    if (desc.fluid == SimDesc::Fluid::Liquid) {
        glProgramUniform1d(id, program_.uniform("index_a"), desc.indexA);
        glProgramUniform1d(id, program_.uniform("index_b"), desc.indexB);
    } else {  // GladstoneDale::refractivityAt with the ambient pressure, over T
        glProgramUniform1d(id, program_.uniform("ambient_temperature"), desc.ambientTemperature);
        glProgramUniform1d(id, program_.uniform("air_scale"),
                           desc.refractivity * (desc.ambientPressure / desc.referencePressure) *
                               desc.referenceTemperature);
    }
    if (absorbs_) setVector(program_, "dye_extinction", {desc.dyeExtinction.r, desc.dyeExtinction.g, desc.dyeExtinction.b});
    if (scatters_) setVector(program_, "dye_scattering", {desc.dyeScattering.r, desc.dyeScattering.g, desc.dyeScattering.b});
}

void GpuOpticalMapping::map(const GpuField& temperature, const GpuField& concentration, const GpuField& dye,
                            const OpticalTargets& targets) const {
    EIKON_CHECK(temperature.size() == solver_.resolution && targets.deltaIndex != 0);
    EIKON_CHECK((targets.extinction != 0) == absorbs_ && (targets.scattering != 0) == scatters_);
    temperature.bind(layout::kOpticsTemperature);
    concentration.bind(layout::kOpticsConcentration);
    dye.bind(layout::kOpticsDye);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, layout::kOpticsDeltaIndex, targets.deltaIndex);
    if (absorbs_) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, layout::kOpticsExtinction, targets.extinction);
    if (scatters_) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, layout::kOpticsScattering, targets.scattering);
    program_.use();
    program_.dispatchOverCells(render_.resolution);
    // The renderer copies these buffers into its textures next.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

}  // namespace eikon::sim::gpu
