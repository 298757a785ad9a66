#include "apps/eikon/PowerWarning.h"

#include <iostream>

namespace eikon::app {

void PowerWarning::check(int frame, const render::FrameResult& result) {
    if (warned_) return;
    const render::PhotonStats& p = result.photons;
    const double emitted = p.emitted.r + p.emitted.g + p.emitted.b;
    if (emitted <= 0.0) return;
    const Rgb lost = p.cutOff - p.rouletteGain;
    const double lostShare = (lost.r + lost.g + lost.b) / emitted;
    if (p.emissionError() > 1e-3) {
        std::cerr << "eikon: warning: frame " << frame << ": the lights emitted " << emitted << " W where they state "
                  << p.stated.r + p.stated.g + p.stated.b << " W toward the traced region (off by "
                  << p.emissionError() << "; report.jsonl, photons.emission_error); later frames are not reported here\n";
        warned_ = true;
    } else if (p.balanceError() > 1e-3) {
        std::cerr << "eikon: warning: frame " << frame << ": the photons' energy balance is off by "
                  << p.balanceError() << " (report.jsonl, photons); later frames are not reported here\n";
        warned_ = true;
    } else if (lostShare > 1e-3) {
        std::cerr << "eikon: warning: frame " << frame << ": " << 100.0 * lostShare
                  << "% of the emitted power was cut off with photons still in flight (tracer.max_steps, or "
                     "one step longer than the loop cap of OpenGL on the CPU); later frames are not reported "
                     "here\n";
        warned_ = true;
    }
}

}  // namespace eikon::app
