#include "render/stages/FieldTextures.h"

#include "bridge/core/Error.h"
#include "bridge/layout/GpuLayouts.h"

#include <string>

namespace eikon::render {

namespace {

bool sameGrid(const GridSpec& a, const GridSpec& b) {
    return a.resolution == b.resolution && a.boundsMin == b.boundsMin && a.boundsMax == b.boundsMax;
}

FieldSource hostSource(const std::vector<float>& values) { return {values.data(), 0, values.size()}; }

// Copies `source` into `texture` (created on demand with `internalFormat`):
// from a buffer bound as the pixel unpack buffer the copy stays on the GPU.
// `layers` grids stack along z.
void uploadField(gl::Texture3D& texture, GLenum internalFormat, GLenum format, const GridSpec& grid,
                 const FieldSource& source, UploadBytes& bytes, int layers = 1) {
    if (!texture.id())
        texture = gl::Texture3D(internalFormat, grid.resolution.x, grid.resolution.y, grid.resolution.z * layers);
    const std::size_t size = source.floats * sizeof(float);
    if (source.buffer) {
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, source.buffer);
        texture.upload(format, GL_FLOAT, nullptr);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        bytes.gpu += size;
    } else {
        texture.upload(format, GL_FLOAT, source.host);
        bytes.host += size;
    }
}

}  // namespace

FieldUpload hostUpload(const FieldSet& fields) {
    return {fields.grid,
            fields.referenceIndex,
            hostSource(fields.deltaIndex),
            hostSource(fields.extinction),
            hostSource(fields.scattering),
            hostSource(fields.anisotropy),
            hostSource(fields.surfaceDistance),
            hostSource(fields.surfaceBounds),
            fields.indexVersion,
            fields.extinctionVersion,
            fields.scatteringVersion,
            fields.surfaceVersion};
}

UploadBytes FieldTextures::upload(const FieldUpload& fields) {
    UploadBytes bytes;
    if (!gridBlock_.id() || !sameGrid(grid_, fields.grid)) {
        grid_ = fields.grid;
        const glm::ivec3 r = grid_.resolution;
        layout::GpuGrid block{};
        block.boundsMin = glm::vec4(glm::vec3(grid_.boundsMin), static_cast<float>(fields.referenceIndex));
        block.boundsMax = glm::vec4(glm::vec3(grid_.boundsMax), 0.0f);
        block.voxelSize = glm::vec4(glm::vec3(grid_.voxelSize()), static_cast<float>(grid_.voxelVolume()));
        block.resolution = glm::ivec4(r, 0);
        gridBlock_ = gl::Buffer(sizeof block, &block);
        index_ = {};
        gradient_ = gl::Texture3D(GL_RGBA32F, r.x, r.y, r.z);
        extinction_ = {};
        scattering_ = {};
        anisotropy_ = {};
        surfaceDistance_ = {};
        indexVersion_ = extinctionVersion_ = scatteringVersion_ = surfaceVersion_ = ~0ull;
        bytes.host += sizeof block;
    }
    if (fields.indexVersion != indexVersion_) uploadField(index_, GL_R32F, GL_RED, grid_, fields.deltaIndex, bytes);
    indexVersion_ = fields.indexVersion;
    if (!fields.extinction.floats) extinction_ = {};
    else if (fields.extinctionVersion != extinctionVersion_)
        uploadField(extinction_, GL_RGBA32F, GL_RGB, grid_, fields.extinction, bytes);
    extinctionVersion_ = fields.extinctionVersion;
    const bool scatteringChanged = fields.scatteringVersion != scatteringVersion_;
    if (!fields.scattering.floats) scattering_ = {};
    else if (scatteringChanged) uploadField(scattering_, GL_RGBA32F, GL_RGB, grid_, fields.scattering, bytes);
    if (!fields.anisotropy.floats) anisotropy_ = {};
    else if (scatteringChanged) uploadField(anisotropy_, GL_R32F, GL_RED, grid_, fields.anisotropy, bytes);
    scatteringVersion_ = fields.scatteringVersion;
    if (!fields.surfaceDistance.floats) {
        surfaceDistance_ = {};
        surfaceBounds_.clear();
    } else if (fields.surfaceVersion != surfaceVersion_) {
        EIKON_CHECK_MSG(fields.surfaceBounds.host, "sharp surface bounds are read from host memory");
        const int layers = static_cast<int>(fields.surfaceBounds.floats / kSurfaceBoundsFloats);
        GLint largest = 0;
        glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &largest);
        if (grid_.resolution.z * layers > largest)
            throw InputError("sharp mesh and water surfaces", "at most " + std::to_string(largest / grid_.resolution.z) +
                             " on a grid " + std::to_string(grid_.resolution.z) + " cells deep (GL_MAX_3D_TEXTURE_SIZE " +
                             std::to_string(largest) + "; set \"surface\": \"smooth\" on the others)",
                             std::to_string(layers));
        uploadField(surfaceDistance_, GL_R32F, GL_RED, grid_, fields.surfaceDistance, bytes, layers);
        surfaceBounds_.assign(fields.surfaceBounds.host, fields.surfaceBounds.host + fields.surfaceBounds.floats);
        bytes.host += fields.surfaceBounds.floats * sizeof(float);
    }
    surfaceVersion_ = fields.surfaceVersion;
    return bytes;
}

void FieldTextures::bindForTracing() const {
    gridBlock_.bindUniform(layout::kGridBlock);
    gradient_.bindSampler(layout::kGradientTexture);
    if (hasExtinction()) extinction_.bindSampler(layout::kExtinctionTexture);
    if (hasScattering()) scattering_.bindSampler(layout::kScatteringTexture);
    if (hasAnisotropy()) anisotropy_.bindSampler(layout::kAnisotropyTexture);
    if (surfaceDistance_.id()) surfaceDistance_.bindSampler(layout::kSurfaceDistanceTexture);
}

}  // namespace eikon::render
