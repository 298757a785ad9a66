// The field grid on the GPU: the GridBlock uniform and one 3D texture per
// field the scene has (δn always; κ, σs, g, ε only when present), and the storage
// buffers of the sharp mesh and water surfaces' trees and triangles (when
// the scene has such surfaces). Re-uploads a field only when its version
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

// One frame's fields as the textures take them.
struct FieldUpload {
    GridSpec grid;
    double referenceIndex = 1.0;
    FieldSource deltaIndex, extinction, scattering, anisotropy;
    FieldSource surfaceNodes, surfaceTriangles;
    std::uint64_t indexVersion = 0, extinctionVersion = 0, scatteringVersion = 0, surfaceVersion = 0;
    FieldSource emission;  // host memory only (an imported volume's); versioned with κ
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
    const gl::Texture3D& index() const { return index_; }
    const gl::Texture3D& extinction() const { return extinction_; }
    const gl::Texture3D& emission() const { return emission_; }
    gl::Texture3D& gradient() { return gradient_; }
    const gl::Texture3D& gradient() const { return gradient_; }
    bool hasExtinction() const { return static_cast<bool>(extinction_.id()); }
    bool hasScattering() const { return static_cast<bool>(scattering_.id()); }
    bool hasAnisotropy() const { return static_cast<bool>(anisotropy_.id()); }
    bool hasEmission() const { return static_cast<bool>(emission_.id()); }
    std::uint64_t surfaceVersion() const { return surfaceVersion_; }
    // The sharp meshes' triangles (FieldSet.h's layout); no name when the scene has none.
    const gl::Buffer& surfaceTriangles() const { return surfaceTriangles_; }
    // The same as a buffer texture, for the surface layers' vertex shader.
    const gl::BufferTexture& surfaceTriangleTexels() const { return surfaceTriangleTexels_; }
    const gl::Buffer& surfaceNodes() const { return surfaceNodes_; }
    const GridSpec& grid() const { return grid_; }
    std::uint64_t indexVersion() const { return indexVersion_; }

    // Binds the grid block, the textures tracers sample and the surface
    // buffers (the nodes also as a buffer texture, for image space).
    void bindForTracing() const;

private:
    GridSpec grid_;
    gl::Buffer gridBlock_;
    gl::Texture3D index_;
    gl::Texture3D gradient_;
    gl::Texture3D extinction_;
    gl::Texture3D scattering_;
    gl::Texture3D anisotropy_;
    gl::Texture3D emission_;
    gl::Buffer surfaceNodes_;
    gl::Buffer surfaceTriangles_;
    gl::BufferTexture surfaceTriangleTexels_;
    gl::BufferTexture surfaceNodeTexels_;
    std::uint64_t indexVersion_ = ~0ull;
    std::uint64_t extinctionVersion_ = ~0ull;  // also covers emission
    std::uint64_t scatteringVersion_ = ~0ull;  // also covers anisotropy, which scattering owns
    std::uint64_t surfaceVersion_ = ~0ull;
};

}  // namespace eikon::render
