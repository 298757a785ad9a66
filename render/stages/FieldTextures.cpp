#include "render/stages/FieldTextures.h"

#include "bridge/layout/GpuLayouts.h"

namespace eikon::render {

namespace {

bool sameGrid(const GridSpec& a, const GridSpec& b) {
    return a.resolution == b.resolution && a.boundsMin == b.boundsMin && a.boundsMax == b.boundsMax;
}

// Uploads a three-channel field into an RGBA32F texture (created on demand).
std::size_t uploadRgb(gl::Texture3D& texture, const GridSpec& grid, const std::vector<float>& values) {
    if (!texture.id()) texture = gl::Texture3D(GL_RGBA32F, grid.resolution.x, grid.resolution.y, grid.resolution.z);
    texture.upload(GL_RGB, GL_FLOAT, values.data());
    return values.size() * sizeof(float);
}

}  // namespace

std::size_t FieldTextures::upload(const FieldSet& fields) {
    std::size_t bytes = 0;
    if (!gridBlock_.id() || !sameGrid(grid_, fields.grid)) {
        grid_ = fields.grid;
        const glm::ivec3 r = grid_.resolution;
        layout::GpuGrid block{};
        block.boundsMin = glm::vec4(glm::vec3(grid_.boundsMin), static_cast<float>(fields.referenceIndex));
        block.boundsMax = glm::vec4(glm::vec3(grid_.boundsMax), 0.0f);
        block.voxelSize = glm::vec4(glm::vec3(grid_.voxelSize()), static_cast<float>(grid_.voxelVolume()));
        block.resolution = glm::ivec4(r, 0);
        gridBlock_ = gl::Buffer(sizeof block, &block);
        index_ = gl::Texture3D(GL_R32F, r.x, r.y, r.z);
        gradient_ = gl::Texture3D(GL_RGBA32F, r.x, r.y, r.z);
        extinction_ = {};
        scattering_ = {};
        anisotropy_ = {};
        indexVersion_ = extinctionVersion_ = scatteringVersion_ = ~0ull;
        bytes += sizeof block;
    }
    if (fields.indexVersion != indexVersion_) {
        index_.upload(GL_RED, GL_FLOAT, fields.deltaIndex.data());
        bytes += fields.deltaIndex.size() * sizeof(float);
        indexVersion_ = fields.indexVersion;
    }
    if (!fields.hasExtinction()) extinction_ = {};
    else if (fields.extinctionVersion != extinctionVersion_) bytes += uploadRgb(extinction_, grid_, fields.extinction);
    extinctionVersion_ = fields.extinctionVersion;
    if (!fields.hasScattering()) scattering_ = {};
    else if (fields.scatteringVersion != scatteringVersion_) bytes += uploadRgb(scattering_, grid_, fields.scattering);
    if (!fields.hasAnisotropy()) {
        anisotropy_ = {};
    } else if (fields.scatteringVersion != scatteringVersion_) {
        if (!anisotropy_.id()) anisotropy_ = gl::Texture3D(GL_R32F, grid_.resolution.x, grid_.resolution.y, grid_.resolution.z);
        anisotropy_.upload(GL_RED, GL_FLOAT, fields.anisotropy.data());
        bytes += fields.anisotropy.size() * sizeof(float);
    }
    scatteringVersion_ = fields.scatteringVersion;
    return bytes;
}

void FieldTextures::bindForTracing() const {
    gridBlock_.bindUniform(layout::kGridBlock);
    gradient_.bindSampler(layout::kGradientTexture);
    if (hasExtinction()) extinction_.bindSampler(layout::kExtinctionTexture);
    if (hasScattering()) scattering_.bindSampler(layout::kScatteringTexture);
    if (hasAnisotropy()) anisotropy_.bindSampler(layout::kAnisotropyTexture);
}

}  // namespace eikon::render
