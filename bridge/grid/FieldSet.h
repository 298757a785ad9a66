// The optical fields of one frame on a dense grid, as the simulation hands
// them to the renderer: index offset δn = n − n_ref (docs/architecture.md,
// Conventions: a mirage lives on Δn ≈ 1e-5, which float32 n would round
// away), extinction κ and scattering σs in 1/m per RGB channel. Each field carries a version that
// changes whenever its values do, so stages can skip unchanged inputs.
#pragma once

#include "bridge/grid/CellBox.h"
#include "bridge/grid/GridSpec.h"
#include "bridge/grid/OpticalFields.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace eikon {

// The sharp mesh and water surfaces as triangles in bounding-volume
// hierarchies (bridge/mesh/TriangleBvh.h), all objects in two arrays whose
// layout the tracers read (shaders/common/sharp_triangle_surfaces.glsl):
// a node is min xyz, then `first`, max xyz, then `count` (integers held
// exactly as floats); a triangle is its three corners, each followed by a
// float (the first corner's: the mesh's ordinal, its root node; the others
// padding), then its three corner normals each followed by padding (the normal
// of the smooth surface the facets approximate, or the facet's own at a
// crease).
constexpr std::size_t kSurfaceNodeFloats = 8;
constexpr std::size_t kSurfaceTriangleFloats = 24;
// The triangles `bytes` of that layout hold.
constexpr std::size_t surfaceTrianglesIn(std::size_t bytes) { return bytes / (kSurfaceTriangleFloats * sizeof(float)); }

// The cells in which version `version` of a volume field differs from the
// version before it. A copy that holds the version before needs only these
// cells (render/stages/FieldTextures.h uploads just them); a producer that
// bumps a field's version without saying where leaves `version` behind,
// which means anywhere.
struct FieldChange {
    std::uint64_t version = 0;
    CellBox cells;

    // Whether going from version `held` to `current` touched only `cells`.
    bool onlyCellsSince(std::uint64_t held, std::uint64_t current) const {
        return version == current && held + 1 == current;
    }
};

// One vector per optical field (OpticalFields.h), `channels` floats per
// cell, empty where the scene lacks the field: δn always; extinction κ and
// scattering σs in 1/m (RGB) where nonzero somewhere; the Henyey–Greenstein
// g where nonzero somewhere; the emitted radiance per unit length ε in
// W/(m³·sr) (RGB) where something glows (an imported volume's blackbody
// emission or emission grid, sim/optics/VolumeOptics.h); and the sharp mesh
// and water surfaces (sim/SharpMeshSurfaces.h): the nodes of every object's
// tree, the roots first (node k is the root of the k-th such object in scene
// order), and the triangles the leaves index.
struct FieldSet {
    GridSpec grid;
    double referenceIndex = 1.0;  // n_ref
#define EIKON_FIELD_VECTOR(member, ...) std::vector<float> member;
    EIKON_OPTICAL_FIELDS(EIKON_FIELD_VECTOR)
#undef EIKON_FIELD_VECTOR
#define EIKON_FIELD_VERSION(group) std::uint64_t group##Version = 0;
    EIKON_OPTICAL_FIELD_VERSIONS(EIKON_FIELD_VERSION)
#undef EIKON_FIELD_VERSION
    FieldChange indexChange, extinctionChange, scatteringChange;

    bool hasExtinction() const { return !extinction.empty(); }
    bool hasScattering() const { return !scattering.empty(); }
    bool hasAnisotropy() const { return !anisotropy.empty(); }
    bool hasEmission() const { return !emission.empty(); }
};

// Replaces `current` with `next` and bumps `version` if their values differ.
void publishField(std::vector<float>& current, std::vector<float>&& next, std::uint64_t& version);

// Where a field's values came from, for a refusal of one: given the field
// ("index", "extinction", "scattering", "anisotropy", "emission" or
// "surfaces") and the world position of the refused value (its cell's
// centre; null for a refusal of the whole field), the file and the key paths
// a user edits to change it: "scene.json: paint[0].index, medium.index".
using FieldOrigin = std::function<std::string(std::string_view field, const glm::dvec3* at)>;

// Throws InputError naming, through `origin`, the keys behind the first value
// that is not finite or out of range (n ≤ 0, κ < 0, σs < 0, σs > κ, |g| ≥ 1,
// ε < 0, a surface vertex or normal not finite), with its world position, or
// behind a field of the wrong size: fields are checked where they enter the
// bridge, never traced silently.
void validateFields(const FieldSet& fields, const FieldOrigin& origin);

}  // namespace eikon
