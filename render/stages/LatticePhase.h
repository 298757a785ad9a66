// How the multiple-scattering lattice shares anisotropically scattered
// light among its links (shaders/common/lattice_phase.glsl): the links'
// cells on the sphere, and the phase matrix of every scattering after the
// first, tabulated over the Henyey–Greenstein asymmetry g for one grid's
// voxel shape.
#pragma once

#include <glm/vec3.hpp>

#include <vector>

namespace eikon::render {

// Each link slot's share of the sphere's directions when every direction
// goes to its nearest link, on voxels of `voxelSize` (sums to 1): the
// isotropic distribution the Henyey–Greenstein shares are taken relative to.
std::vector<float> latticeLinkSolidAngles(int directions, const glm::dvec3& voxelSize);

// The phase matrix of later scatterings at LATTICE_PHASE_NODES values of g
// (layout and interpolation: lattice_phase.glsl): at node g, column j is
// (S(ĉ_j) − f e_j)/(1 − f), S(ĉ_j) = lattice_hg_shares about link j (its
// rings: LATTICE_PHASE_RINGS) and f = lattice_delta_fraction(g). Where a
// link's own share s is below f (18 links, g above about 1/3) its diagonal
// entry is held at 0 and the column renormalised: its mean cosine is then
// (g − s)/(1 − s), above (g − f)/(1 − f) (docs/accuracy.md).
std::vector<float> latticePhaseTable(int directions, const glm::dvec3& voxelSize);

}  // namespace eikon::render
