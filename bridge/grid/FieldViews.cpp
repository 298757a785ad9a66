#include "bridge/grid/FieldViews.h"

namespace eikon {

FieldViews viewsOf(FieldSet& fields) {
    return {fields.grid, fields.referenceIndex, fields.deltaIndex, fields.extinction, fields.scattering,
            fields.anisotropy, fields.surfaceNodes, fields.surfaceTriangles, fields.emission};
}

ConstFieldViews viewsOf(const FieldSet& fields) {
    return {fields.grid, fields.referenceIndex, fields.deltaIndex, fields.extinction, fields.scattering,
            fields.anisotropy, fields.surfaceNodes, fields.surfaceTriangles, fields.emission};
}

}  // namespace eikon
