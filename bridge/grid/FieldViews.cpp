#include "bridge/grid/FieldViews.h"

namespace eikon {

FieldViews viewsOf(FieldSet& fields) {
    return {fields.grid, fields.referenceIndex, fields.deltaIndex, fields.extinction, fields.scattering,
            fields.anisotropy, fields.surfaceDistance, fields.surfaceBounds};
}

ConstFieldViews viewsOf(const FieldSet& fields) {
    return {fields.grid, fields.referenceIndex, fields.deltaIndex, fields.extinction, fields.scattering,
            fields.anisotropy, fields.surfaceDistance, fields.surfaceBounds};
}

}  // namespace eikon
