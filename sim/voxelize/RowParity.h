// Inside and outside of points on the axis-aligned lines of a grid, by ray
// parity of a closed triangle mesh: a point is inside when the line through
// it crosses the mesh an odd number of times before it (Jordan–Brouwer).
//
// Rows are the lines {(x, j, k) : x ∈ ℝ} for integers j, k. Each triangle is
// binned onto the rows its y–z bounding box covers; a row crosses a triangle
// where its point (j, k) lies inside the triangle's y–z projection. That
// test is made watertight as in rasterisers and [Woop13]: each edge's
// function is evaluated with its two vertices in one fixed order (by index),
// so the two triangles sharing an edge see exactly opposite values; a point
// exactly on an edge or vertex is decided by simulation of simplicity
// ([Edelsbrunner90]), as if it were moved to (j + ε, k + ε²). Each triangle
// then either holds the moved point or not, consistently with its
// neighbours, so a row through vertices or along edges crosses a closed mesh
// an even number of times and counts a shared edge once, whatever the mesh's
// winding.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace eikon::sim {

class RowParity {
public:
    // Rows j in [rowMin.x, rowMax.x], k in [rowMin.y, rowMax.y] (inclusive).
    // Triangles index `vertices`; the mesh must be closed for the parity to
    // mean inside. Both are copied.
    RowParity(const std::vector<glm::dvec3>& vertices, const std::vector<glm::ivec3>& triangles, glm::ivec2 rowMin,
              glm::ivec2 rowMax);

    // The x at which row (j, k) crosses the mesh, sorted ascending (empty for
    // a row outside the range given).
    void crossings(int j, int k, std::vector<double>& xs) const;

    // True when an odd number of `sortedCrossings` lie below x.
    static bool inside(const std::vector<double>& sortedCrossings, double x);

private:
    std::size_t rowIndex(int j, int k) const;
    // Sign (+1, −1, or 0 for an edge whose projection is a point) of the
    // y–z edge function of the directed edge from vertex p to vertex q at
    // (j, k), ties broken by simulation of simplicity; `value` receives it.
    int edgeSign(int p, int q, double j, double k, double& value) const;

    std::vector<glm::dvec3> vertices_;
    std::vector<glm::ivec3> triangles_;
    glm::ivec2 rowMin_;
    glm::ivec2 rowMax_;
    std::vector<std::size_t> binStart_;  // CSR: triangles of row r are binTriangles_[binStart_[r] .. binStart_[r + 1])
    std::vector<int> binTriangles_;
};

}  // namespace eikon::sim
