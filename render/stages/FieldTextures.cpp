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

constexpr std::uint64_t kNothingHeld = ~0ull;  // a texture's version before its first upload

// Copies `source` into `texture` (created on demand with `internalFormat`):
// from a buffer bound as the pixel unpack buffer the copy stays on the GPU;
// from host memory into a texture that already holds the version before,
// only the cells `change` names.
void uploadField(gl::Texture3D& texture, const char* what, GLenum internalFormat, GLenum format, const GridSpec& grid,
                 const FieldSource& source, const FieldChange& change, std::uint64_t held, std::uint64_t version,
                 UploadBytes& bytes) {
    const glm::ivec3 r = grid.resolution;
    const bool whole = !texture.id() || held == kNothingHeld || !change.onlyCellsSince(held, version);
    if (!texture.id()) texture = gl::Texture3D(internalFormat, r.x, r.y, r.z, gl::gridResource(what, r.x, r.y, r.z));
    const std::size_t size = source.floats * sizeof(float);
    if (!source.buffer && !whole) {
        texture.uploadBox(format, GL_FLOAT, source.host, change.cells.min, change.cells.max);
        bytes.host += size / static_cast<std::size_t>(grid.cellCount()) * static_cast<std::size_t>(change.cells.cellCount());
    } else if (source.buffer) {
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, source.buffer);
        texture.upload(format, GL_FLOAT, nullptr);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        bytes.gpu += size;
    } else {
        texture.upload(format, GL_FLOAT, source.host);
        bytes.host += size;
    }
}

// Copies `source` into the storage buffer `buffer` (made anew when its size
// changes), from host memory or, on the GPU, from a GL buffer.
// Returns whether `buffer` was made anew (of another size).
bool uploadBuffer(gl::Buffer& buffer, const FieldSource& source, UploadBytes& bytes) {
    const std::size_t size = source.floats * sizeof(float);
    GLint64 largest = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &largest);
    if (size > static_cast<std::size_t>(largest))
        throw InputError("objects (the sharp mesh and water surfaces)",
                         "at most " + std::to_string(largest) + " bytes of triangles or tree nodes "
                         "(GL_MAX_SHADER_STORAGE_BLOCK_SIZE; set \"surface\": \"smooth\" on some)",
                         std::to_string(size) + " bytes");
    const bool anew = buffer.bytes() != size;
    if (anew) buffer = gl::Buffer(size, {"objects", "the sharp surfaces' triangles and tree"});
    if (source.buffer) {
        glCopyNamedBufferSubData(source.buffer, buffer.id(), 0, 0, static_cast<GLsizeiptr>(size));
        bytes.gpu += size;
    } else {
        buffer.upload(source.host, size);
        bytes.host += size;
    }
    return anew;
}

}  // namespace

FieldUpload hostUpload(const FieldSet& fields) {
    return {fields.grid,
            fields.referenceIndex,
            hostSource(fields.deltaIndex),
            hostSource(fields.extinction),
            hostSource(fields.scattering),
            hostSource(fields.anisotropy),
            hostSource(fields.surfaceNodes),
            hostSource(fields.surfaceTriangles),
            fields.indexVersion,
            fields.extinctionVersion,
            fields.scatteringVersion,
            fields.surfaceVersion,
            hostSource(fields.emission),
            fields.indexChange,
            fields.extinctionChange,
            fields.scatteringChange};
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
        gradient_ = gl::Texture3D(GL_RGBA32F, r.x, r.y, r.z, gl::gridResource("the index gradient", r.x, r.y, r.z));
        extinction_ = {};
        scattering_ = {};
        anisotropy_ = {};
        emission_ = {};
        indexVersion_ = extinctionVersion_ = scatteringVersion_ = surfaceVersion_ = kNothingHeld;
        bytes.host += sizeof block;
    }
    if (fields.indexVersion != indexVersion_)
        uploadField(index_, "the refractive index", GL_R32F, GL_RED, grid_, fields.deltaIndex, fields.indexChange,
                    indexVersion_, fields.indexVersion, bytes);
    indexVersion_ = fields.indexVersion;
    const bool extinctionChanged = fields.extinctionVersion != extinctionVersion_;
    if (!fields.extinction.floats) extinction_ = {};
    else if (extinctionChanged)
        uploadField(extinction_, "the extinction", GL_RGBA32F, GL_RGB, grid_, fields.extinction, fields.extinctionChange,
                    extinctionVersion_, fields.extinctionVersion, bytes);
    if (!fields.emission.floats) emission_ = {};
    else if (extinctionChanged)
        uploadField(emission_, "the emission", GL_RGBA32F, GL_RGB, grid_, fields.emission, fields.extinctionChange,
                    extinctionVersion_, fields.extinctionVersion, bytes);
    extinctionVersion_ = fields.extinctionVersion;
    const bool scatteringChanged = fields.scatteringVersion != scatteringVersion_;
    if (!fields.scattering.floats) scattering_ = {};
    else if (scatteringChanged)
        uploadField(scattering_, "the scattering", GL_RGBA32F, GL_RGB, grid_, fields.scattering, fields.scatteringChange,
                    scatteringVersion_, fields.scatteringVersion, bytes);
    if (!fields.anisotropy.floats) anisotropy_ = {};
    else if (scatteringChanged)
        uploadField(anisotropy_, "the anisotropy", GL_R32F, GL_RED, grid_, fields.anisotropy, fields.scatteringChange,
                    scatteringVersion_, fields.scatteringVersion, bytes);
    scatteringVersion_ = fields.scatteringVersion;
    if (!fields.surfaceTriangles.floats) {
        surfaceNodes_ = {};
        surfaceNodeTexels_ = {};
        surfaceTriangleTexels_ = {};
        surfaceTriangles_ = {};
    } else if (fields.surfaceVersion != surfaceVersion_) {
        if (uploadBuffer(surfaceNodes_, fields.surfaceNodes, bytes))
            surfaceNodeTexels_ = gl::BufferTexture(surfaceNodes_, GL_RGBA32F, {"objects", "the sharp surfaces' trees"});
        if (uploadBuffer(surfaceTriangles_, fields.surfaceTriangles, bytes))
            surfaceTriangleTexels_ =
                gl::BufferTexture(surfaceTriangles_, GL_RGBA32F, {"objects", "the sharp surfaces' triangles"});
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
    if (hasEmission()) emission_.bindSampler(layout::kEmissionTexture);
    if (surfaceTriangles_.id()) {
        surfaceNodes_.bindStorage(layout::kSurfaceNodes);
        surfaceNodeTexels_.bindSampler(layout::kSurfaceNodeTexture);
        surfaceTriangles_.bindStorage(layout::kSurfaceTriangles);
    }
}

}  // namespace eikon::render
