// The optical fields of one frame, listed once. The list expands into
// FieldSet's vectors and FieldViews' spans (bridge/grid), the renderer's
// uploads (render/stages/FieldTextures) and its ring of live slots
// (render/stages/FieldRing), and the arrays an export writes
// (io/export/ExportArrays). A new field is a new row.
//
// X(member, channels, version, format, ring, exportName, unit, role, what):
//   member      the name of the field's vector, span and upload source
//   channels    floats per cell: 1, or 3 (RGB); 0 for the sharp surfaces'
//               arrays, which are not per cell (FieldSet.h gives their layout)
//   version     its version group: FieldSet::<version>Version changes
//               whenever the values of any field of the group do
//   format      what the GPU holds it in: R32F or RGBA32F, a 3D texture with
//               trilinear filtering; Buffer, a storage buffer and its texels
//   ring        its place in the live field ring: Volume (mapped, or in
//               device memory when the solver runs on the GPU), Surface
//               (always mapped), None (never in the ring: host memory only)
//   exportName  the array an export writes it as ("": not written), in the
//   unit, role  unit and ArrayRole (bridge/grid/NamedArrays.h) it carries
//   what        how errors about its GPU memory name it
// The order is FieldSet's, and the order of the exported arrays.
#pragma once

#define EIKON_OPTICAL_FIELDS(X)                                                                              \
    X(deltaIndex, 1, index, R32F, Volume, "delta_index", "1", Scalar, "the refractive index")               \
    X(extinction, 3, extinction, RGBA32F, Volume, "extinction", "1/m", Density, "the extinction")           \
    X(scattering, 3, scattering, RGBA32F, Volume, "scattering", "1/m", Density, "the scattering")           \
    X(anisotropy, 1, scattering, R32F, Volume, "anisotropy", "1", Scalar, "the anisotropy")                 \
    X(emission, 3, extinction, RGBA32F, None, "emission", "W/(m^3 sr)", Density, "the emission")            \
    X(surfaceNodes, 0, surface, Buffer, Surface, "", "", Scalar, "the sharp surfaces' trees")               \
    X(surfaceTriangles, 0, surface, Buffer, Surface, "", "", Scalar, "the sharp surfaces' triangles")

// The version groups: the fields of one change together (δn; κ and ε; σs
// and g, which scattering owns; the surfaces' nodes and triangles).
#define EIKON_OPTICAL_FIELD_VERSIONS(X) X(index) X(extinction) X(scattering) X(surface)

// Expands `code` for the fields of the ring only (EIKON_IN_RING_##ring(code)).
#define EIKON_IN_RING_Volume(...) __VA_ARGS__
#define EIKON_IN_RING_Surface(...) __VA_ARGS__
#define EIKON_IN_RING_None(...)
