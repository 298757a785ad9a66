// Image-space rows (render.method "image_space") in an eikonal accuracy
// case: the same measures of the same scene drawn by the raster
// approximation ([Hu07], [Wyman06]), so the report shows what it costs
// beside the tracer.
#pragma once

#include "verify/accuracy/AccuracyCase.h"

#include <memory>

namespace eikon::accuracy {

// `eikonal` with `imageSpace`'s runs after its own, under the eikonal case's
// name (so --case runs both); each setting is run by the case whose method it names.
std::unique_ptr<AccuracyCase> withImageSpaceRows(std::unique_ptr<AccuracyCase> eikonal,
                                                 std::unique_ptr<AccuracyCase> imageSpace);

}  // namespace eikon::accuracy
