// As-rigid-as-possible surface deformation ([Sorkine07]): handle vertices
// follow keyed rigid poses and the rest minimise
//   E = Σ_i Σ_{j∈N(i)} w_ij ‖(p'_i − p'_j) − R_i (p_i − p_j)‖²  ([Sorkine07] eq. 3)
// with cotangent weights w_ij = ½(cot α_ij + cot β_ij) (eq. 5, clamped at a
// small positive floor so the system stays positive definite on meshes with
// obtuse triangles). Local step (parallel over vertices): R_i = V·Uᵀ from the SVD of
// S_i = Σ_j w_ij e_ij e'_ijᵀ (eq. 6, the sign fixed so det R_i = +1). Global
// step: L p' = b with b_i = Σ_j ½ w_ij (R_i + R_j)(p_i − p_j) (eqs. 8–9);
// L restricted to the free vertices does not change with time, so its
// sparse Cholesky factor (Eigen SimplicialLDLT) is computed once.
#pragma once

#include "sim/deform/Deformer.h"

#include <memory>
#include <string>

namespace eikon::sim {

class ArapDeformer : public Deformer {
public:
    // Throws InputError (at `where`, the deformer's JSON path) for a handle
    // region that holds no vertex or a part of the mesh with no handle.
    ArapDeformer(const DeformerDesc& desc, const TriangleMesh& rest, const std::string& where);
    ~ArapDeformer() override;
    // `iterations` local/global rounds, warm-started from the last frame.
    void deform(double time, std::vector<glm::dvec3>& deformed) override;

    std::size_t handleVertexCount() const;

private:
    struct Solver;
    std::unique_ptr<Solver> solver_;
};

}  // namespace eikon::sim
