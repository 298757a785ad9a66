// Where a triangle mesh's surface is smooth and where it has an edge: two
// facets that meet at less than kCreaseDegrees approximate one smooth
// surface, whose normal the corners carry (sim/SharpMeshSurfaces.h, the
// water's corner normals); at more they meet at an edge, and each keeps
// its own. 50° smooths any surface cut into eight or more facets per turn —
// a sphere's, a deformed blob's (whose coarse facets an as-rigid-as-possible
// bend folds by up to 47°), a water surface's — and keeps the edges of a
// hexagonal prism (60°) or a bar (90°) sharp. Image space's caustic cells
// (render/stages/CausticPolygons.h) take the same angle for where the map
// from the light to the receivers breaks.
#pragma once

#include <cmath>
#include <numbers>

namespace eikon {

constexpr double kCreaseDegrees = 50.0;

inline double creaseCosine() { return std::cos(kCreaseDegrees * std::numbers::pi / 180.0); }

}  // namespace eikon
