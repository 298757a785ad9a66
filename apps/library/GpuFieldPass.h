// The library's GPU path (eikon::Field::buffer): the caller's fields in GL
// buffers of the renderer's context, taken without a byte crossing to the
// host. The index's fields (temperature, index, δn) are mapped to δn by a
// compute pass (shaders/caller_fields.comp) through the host path's own
// text (shaders/common/gas_index.glsl) into a buffer of the pass's; a
// density, and grey extinction and scattering, to RGB κ and σs through
// shaders/common/volume_coefficient.glsl into buffers of the pass's; RGB
// extinction and scattering alone are checked there and copied into their
// textures from where they lie. Every check of the host path is made on the
// GPU; the pass reads back a few words, the first cell failing each.
#pragma once

#include "apps/library/BufferField.h"
#include "bridge/scene/Scene.h"
#include "gl/GlObjects.h"

#include <map>
#include <optional>
#include <vector>

namespace eikon::library {

class GpuFieldPass {
public:
    // For `scene` (its grid and medium) with reference index n_ref.
    GpuFieldPass(const Scene& scene, double referenceIndex);

    // The outcome of one frame's buffers: δn's buffer (0: the index is the
    // host's), the caller's extinction and scattering buffers (0: none), and
    // the smallest nonzero temperature where every nonzero one is at least
    // kAbsoluteTemperatureLooking (for the renderer's refusal of an
    // undeclared absolute temperature; none otherwise).
    struct Taken {
        GLuint deltaIndex = 0, extinction = 0, scattering = 0;
        std::optional<float> absoluteLookingTemperature;
    };
    // Checks and maps `buffers` (the renderer's context current) with the
    // scene's `volume` keys `optics`. eikon::Error naming the field, what
    // was expected and what was found (the cell and its value): nothing of
    // the last frame taken is changed then.
    Taken take(const std::vector<BufferField>& buffers, const VolumeDesc& optics);
    // The frame taken is the renderer's: the next take writes δn, κ and σs elsewhere.
    void keep();

private:
    // The pass's text for the buffers handed (shaders/caller_fields.comp's variants).
    struct Variant {
        bool temperature = false;
        int base = 0;  // 0: the medium's index, 1: an index buffer, 2: a δn buffer
        int extinctionChannels = 0, scatteringChannels = 0;  // 0: none
        bool density = false;
        bool writesExtinction = false, writesScattering = false;  // κ, σs mapped into the pass's buffers
        auto operator<=>(const Variant&) const = default;
    };
    const gl::Program& program(const Variant& variant);
    void checkScene(const std::vector<BufferField>& buffers, const VolumeDesc& optics) const;

    Scene scene_;
    double referenceIndex_;
    std::map<Variant, gl::Program> programs_;
    // δn, κ and σs into one buffer each while the other holds the last
    // frame kept: a refused frame leaves it.
    gl::Buffer deltaIndex_[2], extinction_[2], scattering_[2];
    int next_ = 0;
    gl::Buffer checks_;
};

}  // namespace eikon::library
