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
    FieldUpload upload;
    upload.grid = fields.grid;
    upload.referenceIndex = fields.referenceIndex;
#define EIKON_HOST_SOURCE(member, ...) upload.member = hostSource(fields.member);
    EIKON_OPTICAL_FIELDS(EIKON_HOST_SOURCE)
#undef EIKON_HOST_SOURCE
#define EIKON_HOST_VERSION(group) upload.group##Version = fields.group##Version;
    EIKON_OPTICAL_FIELD_VERSIONS(EIKON_HOST_VERSION)
#undef EIKON_HOST_VERSION
    upload.indexChange = fields.indexChange;
    upload.extinctionChange = fields.extinctionChange;
    upload.scatteringChange = fields.scatteringChange;
    return upload;
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
        gradient_ = gl::Texture3D(GL_RGBA32F, r.x, r.y, r.z, gl::gridResource("the index gradient", r.x, r.y, r.z));
        // Textures of the old grid's shape go; every field is uploaded anew.
#define EIKON_DROP_TEXTURE(member, ...) member##_.texture = {};
        EIKON_OPTICAL_FIELDS(EIKON_DROP_TEXTURE)
#undef EIKON_DROP_TEXTURE
#define EIKON_FORGET_VERSION(group) group##Version_ = kNothingHeld;
        EIKON_OPTICAL_FIELD_VERSIONS(EIKON_FORGET_VERSION)
#undef EIKON_FORGET_VERSION
        bytes.host += sizeof block;
    }
    // A group's fields are uploaded when its version moved on; a field the
    // frame lacks is dropped.
#define EIKON_GROUP_CHANGED(group) const bool group##Changed = fields.group##Version != group##Version_;
    EIKON_OPTICAL_FIELD_VERSIONS(EIKON_GROUP_CHANGED)
#undef EIKON_GROUP_CHANGED
#define EIKON_UPLOAD_R32F(member, version, what)                                                             \
    uploadField(member##_.texture, what, GL_R32F, GL_RED, grid_, fields.member, fields.version##Change,      \
                version##Version_, fields.version##Version, bytes)
#define EIKON_UPLOAD_RGBA32F(member, version, what)                                                          \
    uploadField(member##_.texture, what, GL_RGBA32F, GL_RGB, grid_, fields.member, fields.version##Change,   \
                version##Version_, fields.version##Version, bytes)
#define EIKON_UPLOAD_Buffer(member, version, what)                                                           \
    if (uploadBuffer(member##_.buffer, fields.member, bytes))                                                \
    member##_.texels = gl::BufferTexture(member##_.buffer, GL_RGBA32F, {"objects", what})
#define EIKON_UPLOAD_FIELD(member, channels, version, format, ring, exportName, unit, role, what) \
    if (!fields.member.floats) member##_ = {};                                                     \
    else if (version##Changed) EIKON_UPLOAD_##format(member, version, what);
    EIKON_OPTICAL_FIELDS(EIKON_UPLOAD_FIELD)
#undef EIKON_UPLOAD_FIELD
#undef EIKON_UPLOAD_Buffer
#undef EIKON_UPLOAD_RGBA32F
#undef EIKON_UPLOAD_R32F
#define EIKON_HOLD_VERSION(group) group##Version_ = fields.group##Version;
    EIKON_OPTICAL_FIELD_VERSIONS(EIKON_HOLD_VERSION)
#undef EIKON_HOLD_VERSION
    return bytes;
}

void FieldTextures::bindForTracing() const {
    gridBlock_.bindUniform(layout::kGridBlock);
    gradient_.bindSampler(layout::kGradientTexture);
    if (hasExtinction()) extinction_.texture.bindSampler(layout::kExtinctionTexture);
    if (hasScattering()) scattering_.texture.bindSampler(layout::kScatteringTexture);
    if (hasAnisotropy()) anisotropy_.texture.bindSampler(layout::kAnisotropyTexture);
    if (hasEmission()) emission_.texture.bindSampler(layout::kEmissionTexture);
    if (surfaceTriangles_.buffer.id()) {
        surfaceNodes_.buffer.bindStorage(layout::kSurfaceNodes);
        surfaceNodes_.texels.bindSampler(layout::kSurfaceNodeTexture);
        surfaceTriangles_.buffer.bindStorage(layout::kSurfaceTriangles);
    }
}

}  // namespace eikon::render
