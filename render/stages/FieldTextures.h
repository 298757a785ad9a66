// The field grid on the GPU: the GridBlock uniform and, per optical field
// the scene has (bridge/grid/OpticalFields.h), a 3D texture (δn always; κ,
// σs, g, ε only when present) or a storage buffer with its texels (the
// sharp mesh and water surfaces' trees and triangles). Re-uploads a field only when its version
// changed, and from host memory only the cells the new version changed when
// the texture holds the version before (FieldChange; a water surface
// repaints a thin band of the grid). Values come either from host memory
// (the driver copies them: host bytes) or from a GL buffer the simulation
// wrote in place (render/stages/FieldRing.h; the copy runs on the GPU: no
// host bytes).
#pragma once

#include "bridge/grid/FieldSet.h"
#include "gl/GlObjects.h"

#include <cstdint>

namespace eikon::render {

// Where one field's values are: host memory, or a GL buffer (offset 0); a
// persistently mapped buffer is both, read on the host and copied on the GPU.
struct FieldSource {
    const float* host = nullptr;
    GLuint buffer = 0;
    std::size_t floats = 0;  // 0: the scene has no such field
};

// One frame's fields as the textures take them (ε from host memory only:
// an imported volume's).
struct FieldUpload {
    GridSpec grid;
    double referenceIndex = 1.0;
#define EIKON_FIELD_SOURCE(member, ...) FieldSource member;
    EIKON_OPTICAL_FIELDS(EIKON_FIELD_SOURCE)
#undef EIKON_FIELD_SOURCE
#define EIKON_FIELD_VERSION(group) std::uint64_t group##Version = 0;
    EIKON_OPTICAL_FIELD_VERSIONS(EIKON_FIELD_VERSION)
#undef EIKON_FIELD_VERSION
    // Where each version differs from the one before (host sources only):
    // a texture one version behind takes just those cells.
    FieldChange indexChange, extinctionChange, scatteringChange;
};

FieldUpload hostUpload(const FieldSet& fields);

struct UploadBytes {
    std::size_t host = 0;  // read by the driver from host memory
    std::size_t gpu = 0;   // copied from GL buffers to textures on the GPU
};

class FieldTextures {
public:
    // Uploads what changed.
    UploadBytes upload(const FieldUpload& fields);

    const gl::Buffer& gridBlock() const { return gridBlock_; }
    const gl::Texture3D& index() const { return deltaIndex_.texture; }
    const gl::Texture3D& extinction() const { return extinction_.texture; }
    const gl::Texture3D& emission() const { return emission_.texture; }
    gl::Texture3D& gradient() { return gradient_; }
    const gl::Texture3D& gradient() const { return gradient_; }
    bool hasExtinction() const { return static_cast<bool>(extinction_.texture.id()); }
    bool hasScattering() const { return static_cast<bool>(scattering_.texture.id()); }
    bool hasAnisotropy() const { return static_cast<bool>(anisotropy_.texture.id()); }
    bool hasEmission() const { return static_cast<bool>(emission_.texture.id()); }
    std::uint64_t surfaceVersion() const { return surfaceVersion_; }
    // The sharp meshes' triangles (FieldSet.h's layout); no name when the scene has none.
    const gl::Buffer& surfaceTriangles() const { return surfaceTriangles_.buffer; }
    // The same as a buffer texture, for the surface layers' vertex shader.
    const gl::BufferTexture& surfaceTriangleTexels() const { return surfaceTriangles_.texels; }
    const gl::Buffer& surfaceNodes() const { return surfaceNodes_.buffer; }
    const GridSpec& grid() const { return grid_; }
    std::uint64_t indexVersion() const { return indexVersion_; }

    // Binds the grid block, the textures tracers sample and the surface
    // buffers (the nodes also as a buffer texture, for image space).
    void bindForTracing() const;

private:
    // One optical field on the GPU: a 3D texture, or a storage buffer and
    // its texels (the field's format, OpticalFields.h); empty where absent.
    struct FieldOnGpu {
        gl::Texture3D texture;
        gl::Buffer buffer;
        gl::BufferTexture texels;
    };

    GridSpec grid_;
    gl::Buffer gridBlock_;
    gl::Texture3D gradient_;
#define EIKON_FIELD_ON_GPU(member, ...) FieldOnGpu member##_;
    EIKON_OPTICAL_FIELDS(EIKON_FIELD_ON_GPU)
#undef EIKON_FIELD_ON_GPU
    // The version each group's fields hold; ~0 before their first upload.
#define EIKON_FIELD_VERSION_HELD(group) std::uint64_t group##Version_ = ~0ull;
    EIKON_OPTICAL_FIELD_VERSIONS(EIKON_FIELD_VERSION_HELD)
#undef EIKON_FIELD_VERSION_HELD
};

}  // namespace eikon::render
