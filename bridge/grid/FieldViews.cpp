#include "bridge/grid/FieldViews.h"

namespace eikon {

namespace {

template <typename Views, typename Fields>
Views viewsOfFields(Fields& fields) {
    Views views;
    views.grid = fields.grid;
    views.referenceIndex = fields.referenceIndex;
#define EIKON_FIELD_VIEW(member, ...) views.member = fields.member;
    EIKON_OPTICAL_FIELDS(EIKON_FIELD_VIEW)
#undef EIKON_FIELD_VIEW
    return views;
}

}  // namespace

FieldViews viewsOf(FieldSet& fields) { return viewsOfFields<FieldViews>(fields); }

ConstFieldViews viewsOf(const FieldSet& fields) { return viewsOfFields<ConstFieldViews>(fields); }

}  // namespace eikon
