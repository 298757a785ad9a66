// The field grid on the GPU: the GridBlock uniform and one 3D texture per
// field the scene has (δn always; κ and σs only when present). Re-uploads a
// field only when its version changed.
#pragma once

#include "bridge/grid/FieldSet.h"
#include "render/gl/GlObjects.h"

#include <cstdint>

namespace eikon::render {

class FieldTextures {
public:
    // Uploads what changed; returns the host bytes handed to the driver.
    std::size_t upload(const FieldSet& fields);

    const gl::Buffer& gridBlock() const { return gridBlock_; }
    const gl::Texture3D& index() const { return index_; }
    gl::Texture3D& gradient() { return gradient_; }
    bool hasExtinction() const { return static_cast<bool>(extinction_.id()); }
    bool hasScattering() const { return static_cast<bool>(scattering_.id()); }
    bool hasAnisotropy() const { return static_cast<bool>(anisotropy_.id()); }
    const GridSpec& grid() const { return grid_; }
    std::uint64_t indexVersion() const { return indexVersion_; }

    // Binds the grid block and the textures tracers sample.
    void bindForTracing() const;

private:
    GridSpec grid_;
    gl::Buffer gridBlock_;
    gl::Texture3D index_;
    gl::Texture3D gradient_;
    gl::Texture3D extinction_;
    gl::Texture3D scattering_;
    gl::Texture3D anisotropy_;
    std::uint64_t indexVersion_ = ~0ull;
    std::uint64_t extinctionVersion_ = ~0ull;
    std::uint64_t scatteringVersion_ = ~0ull;  // also covers anisotropy, which scattering owns
};

}  // namespace eikon::render
