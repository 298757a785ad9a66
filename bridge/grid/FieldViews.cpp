#include "bridge/grid/FieldViews.h"

namespace eikon {

FieldViews viewsOf(FieldSet& fields) {
    return {fields.grid, fields.referenceIndex, fields.deltaIndex, fields.extinction, fields.scattering,
            fields.anisotropy};
}

ConstFieldViews viewsOf(const FieldSet& fields) {
    return {fields.grid, fields.referenceIndex, fields.deltaIndex, fields.extinction, fields.scattering,
            fields.anisotropy};
}

FieldSet copyToFieldSet(const ConstFieldViews& views) {
    FieldSet fields;
    fields.grid = views.grid;
    fields.referenceIndex = views.referenceIndex;
    fields.deltaIndex.assign(views.deltaIndex.begin(), views.deltaIndex.end());
    fields.extinction.assign(views.extinction.begin(), views.extinction.end());
    fields.scattering.assign(views.scattering.begin(), views.scattering.end());
    fields.anisotropy.assign(views.anisotropy.begin(), views.anisotropy.end());
    return fields;
}

}  // namespace eikon
