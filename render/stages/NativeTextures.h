// What the native passes read of a field texture: its texels on the host,
// fetched by cell (texelFetch) or filtered as OpenGL's GL_LINEAR with
// GL_CLAMP_TO_EDGE filters a 3D texture (textureLod at level 0; OpenGL 4.5
// §8.14.2, eq. 8.9–8.10): between the eight texel centres around the point,
// each lerp a + w·(b − a) as llvmpipe's sampler computes it.
#pragma once

#include "render/stages/NativeCellLoop.h"

#include <glm/glm.hpp>

#include <algorithm>

namespace eikon::render {

template <class Texel>
struct HostTexture3D {
    const Texel* texels = nullptr;
    glm::ivec3 size{0};

    Texel fetch(const glm::ivec3& cell) const { return texels[cellOffset(cell, size)]; }

    // At normalised coordinates uvw (texel centres at (i + 1/2) / size).
    Texel linear(const glm::vec3& uvw) const {
        const glm::vec3 u = uvw * glm::vec3(size) - 0.5f;
        const glm::vec3 base = glm::floor(u);
        const glm::vec3 w = u - base;
        const glm::ivec3 i0 = glm::clamp(glm::ivec3(base), glm::ivec3(0), size - 1);
        const glm::ivec3 i1 = glm::clamp(glm::ivec3(base) + 1, glm::ivec3(0), size - 1);
        auto at = [&](int x, int y, int z) { return fetch({x, y, z}); };
        auto lerp = [](const Texel& a, const Texel& b, float t) { return a + t * (b - a); };
        const Texel x00 = lerp(at(i0.x, i0.y, i0.z), at(i1.x, i0.y, i0.z), w.x);
        const Texel x10 = lerp(at(i0.x, i1.y, i0.z), at(i1.x, i1.y, i0.z), w.x);
        const Texel x01 = lerp(at(i0.x, i0.y, i1.z), at(i1.x, i0.y, i1.z), w.x);
        const Texel x11 = lerp(at(i0.x, i1.y, i1.z), at(i1.x, i1.y, i1.z), w.x);
        return lerp(lerp(x00, x10, w.y), lerp(x01, x11, w.y), w.z);
    }
};

}  // namespace eikon::render
