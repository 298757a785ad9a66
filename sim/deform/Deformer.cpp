#include "sim/deform/Deformer.h"

#include "sim/deform/ArapDeformer.h"
#include "sim/deform/SpatialDeformers.h"

namespace eikon::sim {

std::unique_ptr<Deformer> makeDeformer(const DeformerDesc& desc, const TriangleMesh& rest, const std::string& where) {
    switch (desc.kind) {
        case DeformerDesc::Kind::None: return nullptr;
        case DeformerDesc::Kind::Rigid: return std::make_unique<RigidDeformer>(desc, rest);
        case DeformerDesc::Kind::Twist: return std::make_unique<TwistDeformer>(desc, rest);
        case DeformerDesc::Kind::Bend: return std::make_unique<BendDeformer>(desc, rest);
        case DeformerDesc::Kind::Arap: return std::make_unique<ArapDeformer>(desc, rest, where);
    }
    return nullptr;
}

}  // namespace eikon::sim
