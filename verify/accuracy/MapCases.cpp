// The receiver-map cases (verify/accuracy/ReceiverMapCase): the path cases'
// media on receivers, where both light estimators are measured, and for the
// glass sphere image space's caustic maps too.
#include "verify/accuracy/Cases.h"

#include "verify/accuracy/CatenaryMap.h"
#include "verify/accuracy/FishEyeMap.h"
#include "verify/accuracy/GlassSphereMap.h"
#include "verify/accuracy/ImageSpaceRows.h"
#include "verify/accuracy/LuneburgMap.h"
#include "verify/accuracy/MirageMap.h"
#include "verify/accuracy/ReceiverCaseScene.h"
#include "verify/accuracy/ReceiverMapCase.h"

namespace eikon::accuracy {

std::unique_ptr<AccuracyCase> makeCatenaryMapCase() {
    return makeReceiverMapCase({"catenary_map", "relative L1 over the receiver against the closed-form catenaries' rows",
                                catenaryMapScene, catenaryMapField, 1.0, catenaryReferenceRows, catenaryMapError});
}

std::unique_ptr<AccuracyCase> makeMirageMapCase() {
    return makeReceiverMapCase({"mirage_map", "relative L1 over the receiver against the reference tracer's rows",
                                mirageMapScene, mirageMapField, 1.05, mirageReferenceRows, mirageMapError});
}

std::unique_ptr<AccuracyCase> makeLuneburgMapCase() {
    return makeReceiverMapCase({"luneburg_map", "relative L1 over the receiver against the closed form R²D²/(ρ² + D²)²",
                                luneburgMapScene, luneburgMapField, 1.0, luneburgMapTexelMeans, texelMapError});
}

std::unique_ptr<AccuracyCase> makeFishEyeMapCase() {
    return makeReceiverMapCase({"fisheye_map", "relative L1 over the receiver against the reference tracer's rings",
                                fishEyeMapScene, fishEyeMapField, 1.0, fishEyeReferenceMap, texelMapError});
}

std::unique_ptr<AccuracyCase> makeGlassSphereMapCase() {
    return withImageSpaceRows(
        makeReceiverMapCase({"glass_sphere_map", "relative L1 over the receiver against the reference tracer's rings",
                             glassSphereMapScene, glassSphereMapField, 1.0, glassSphereReferenceMap, texelMapError}),
        makeGlassSphereCausticRows());
}

}  // namespace eikon::accuracy
