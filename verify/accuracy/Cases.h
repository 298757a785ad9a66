// Constructors of the individual accuracy cases (allCases() lists them).
#pragma once

#include "verify/accuracy/AccuracyCase.h"

namespace eikon::accuracy {

std::unique_ptr<AccuracyCase> makePointLightCase();    // IrradianceCases.cpp
std::unique_ptr<AccuracyCase> makeBeerLambertCase();   // IrradianceCases.cpp
std::unique_ptr<AccuracyCase> makeLinearSlabCase();    // LayeredCases.cpp
std::unique_ptr<AccuracyCase> makeMirageCase();        // LayeredCases.cpp
std::unique_ptr<AccuracyCase> makeMirageMapCase();     // MapCases.cpp
std::unique_ptr<AccuracyCase> makeCatenaryMapCase();   // MapCases.cpp
std::unique_ptr<AccuracyCase> makeLuneburgCase();      // LensCases.cpp
std::unique_ptr<AccuracyCase> makeLuneburgMapCase();   // MapCases.cpp
std::unique_ptr<AccuracyCase> makeFishEyeCase();       // LensCases.cpp
std::unique_ptr<AccuracyCase> makeFishEyeMapCase();    // MapCases.cpp
std::unique_ptr<AccuracyCase> makeGlassSphereCase();   // LensCases.cpp
std::unique_ptr<AccuracyCase> makeGlassSphereMapCase();  // MapCases.cpp
std::unique_ptr<AccuracyCase> makeHeatShimmerCase();   // ShimmerCase.cpp

// The glass-sphere cases' image-space rows, which makeGlassSphereMapCase and
// makeGlassSphereCase add (ImageSpaceRows.h); GlassSphereImageSpace.cpp.
std::unique_ptr<AccuracyCase> makeGlassSphereCausticRows();
std::unique_ptr<AccuracyCase> makeGlassSphereViewRows();

}  // namespace eikon::accuracy
