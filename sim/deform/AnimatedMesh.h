// The shape of one mesh or water object of a scene at the current time: the
// placed rest mesh moved by its deformer, or the water body of a wave
// surface. `mesh()` is the frame's deformed mesh, for the voxelizer and for
// export.
#pragma once

#include "bridge/mesh/TriangleMesh.h"
#include "bridge/scene/Scene.h"
#include "sim/deform/Deformer.h"
#include "sim/deform/WaterSurface.h"

#include <memory>
#include <string>

namespace eikon::sim {

class AnimatedMesh {
public:
    // Reads the mesh file (which must be closed) and applies the placement,
    // or builds the water body; `where` is the object's JSON path for errors.
    AnimatedMesh(const ObjectDesc& object, const std::string& where);
    ~AnimatedMesh();

    // Moves the shape to `time`, s; positions that come out non-finite (a
    // deformer driven past sense) keep their last finite value.
    void advanceTo(double time);
    bool changesOverTime() const { return deformer_ != nullptr || water_ != nullptr; }
    const TriangleMesh& mesh() const { return current_; }
    // The wave surface of a water object (its height field), or null.
    const WaterSurface* water() const { return water_.get(); }

private:
    TriangleMesh rest_;
    TriangleMesh current_;
    std::unique_ptr<Deformer> deformer_;
    std::unique_ptr<WaterSurface> water_;
    std::vector<glm::dvec3> scratch_;
};

}  // namespace eikon::sim
