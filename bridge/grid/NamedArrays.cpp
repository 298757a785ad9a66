#include "bridge/grid/NamedArrays.h"

namespace eikon {

const NamedArray* ExportFrame::find(const std::string& name) const {
    for (const NamedArray& array : arrays)
        if (array.name == name) return &array;
    return nullptr;
}

}  // namespace eikon
