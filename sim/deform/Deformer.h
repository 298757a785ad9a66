// A deformer maps a mesh's rest vertices to their positions at a time; the
// triangles never change. Rigid, twist and bend are closed-form functions of
// time (SpatialDeformers.h); ARAP solves for its shape (ArapDeformer.h).
#pragma once

#include "bridge/mesh/TriangleMesh.h"
#include "bridge/scene/MeshObjectDesc.h"

#include <memory>
#include <string>
#include <vector>

namespace eikon::sim {

class Deformer {
public:
    virtual ~Deformer() = default;
    // Positions of `rest`'s vertices at `time`, s, into `deformed` (same size).
    virtual void deform(double time, std::vector<glm::dvec3>& deformed) = 0;
};

// The deformer a scene asks for, over the placed rest mesh; nullptr for
// none. `where` (the deformer's JSON path) names it in errors.
std::unique_ptr<Deformer> makeDeformer(const DeformerDesc& desc, const TriangleMesh& rest, const std::string& where);

}  // namespace eikon::sim
