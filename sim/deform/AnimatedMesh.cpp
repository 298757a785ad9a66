#include "sim/deform/AnimatedMesh.h"

#include "bridge/core/Error.h"
#include "io/mesh/MeshReader.h"
#include "sim/deform/Keyframes.h"

#include <cmath>

namespace eikon::sim {

AnimatedMesh::AnimatedMesh(const ObjectDesc& object, const std::string& where) {
    if (object.kind == ObjectDesc::Kind::Water) {
        water_ = std::make_unique<WaterSurface>(object.water);
        current_ = water_->mesh();
        return;
    }
    try {
        rest_ = io::readMesh(object.mesh.path, io::MeshClosure::Closed);
    } catch (const InputError& error) {  // the mesh's own message, told where the scene names it
        throw InputError(where + ".mesh.path: " + error.what());
    }
    const glm::dmat4 placement = placementMatrix(object.mesh.placement);
    for (glm::dvec3& v : rest_.vertices) v = glm::dvec3(placement * glm::dvec4(v, 1.0));
    current_ = rest_;
    deformer_ = makeDeformer(object.mesh.deformer, rest_, where + ".deformer");
    advanceTo(0.0);
}

AnimatedMesh::~AnimatedMesh() = default;

void AnimatedMesh::advanceTo(double time) {
    if (water_) {
        water_->advanceTo(time);
        current_ = water_->mesh();
        return;
    }
    if (!deformer_) return;
    deformer_->deform(time, scratch_);
    for (std::size_t v = 0; v < scratch_.size(); ++v) {
        const glm::dvec3& p = scratch_[v];
        if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) current_.vertices[v] = p;
    }
}

}  // namespace eikon::sim
