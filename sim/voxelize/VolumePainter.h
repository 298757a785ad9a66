// Volume painting ([Sun08] §6.2.1): brushes, each a fixed pattern
// of material, dragged through the volume; the pattern, scaled to the brush
// radius and turned to follow the stroke, is added to δn, κ and σs.
//
// A stroke of one point stamps the brush once, its centre value being the
// stroke's amounts. Along a polyline the brush is stamped every σ (σ =
// radius/2) with weight Δs/(√(2π)·σ), so the stamps sum to a tube whose
// centre line carries the stroke's amounts and whose cross-section is the
// Gaussian exp(−d²/2σ²) of the distance d to the path (the sum of Gaussians
// spaced σ apart differs from the integral by under 1e-8). Stamps are cut
// off at 4σ (weight e^−8 ≈ 3e-4).
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/grid/FieldViews.h"
#include "bridge/scene/Scene.h"
#include "bridge/grid/CellBox.h"

namespace eikon::sim {

// Adds the scene's strokes, in order, to the cells of `region` (the whole
// grid by default); creates κ or σs where a stroke needs them.
void paintStrokes(const Scene& scene, FieldSet& fields, const CellBox* region = nullptr);
// The same in place, over memory that already has every field a stroke needs.
void paintStrokes(const Scene& scene, const FieldViews& fields, const CellBox* region = nullptr);

// Whether `stroke` paints anything at the point `at` (within the cut-off of
// one of its stamps): a refused painted value names the strokes that reach it.
bool strokeReaches(const PaintStroke& stroke, const glm::dvec3& at);

// The smoke brush's pattern in [0, 1] at a point in brush coordinates
// (radii along the stroke tangent and two normals): three octaves of value
// noise, fixed to the brush so that it turns with the stroke.
double smokePattern(const glm::dvec3& local, unsigned seed);

}  // namespace eikon::sim
