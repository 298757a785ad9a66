#include "apps/eikon/FluidWarning.h"

#include <iostream>

namespace eikon::app {

void FluidWarning::check(int frame, const ProducedFrame& produced) {
    if (warned_ || !produced.simulated || !produced.fluid || produced.fluid->fastFlow.empty()) return;
    std::cerr << "eikon: warning: frame " << frame << ": " << produced.fluid->fastFlow
              << "; later frames are not reported here\n";
    warned_ = true;
}

}  // namespace eikon::app
