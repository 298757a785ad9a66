// Restores the total of an advected scalar in a closed domain.
//
// MacCormack advection with its extrema clamp ([Selle08] §3.1) is
// not conservative: the clamp trims over- and undershoots asymmetrically, and
// a stirred blob loses or gains a few percent over hundreds of steps. With no
// open face nothing may enter or leave, so the drift is put back where the
// advection error arises, at the fronts: in proportion to
// w_c = (φ_c − low)(high − φ_c), which is zero in pure ambient and on
// plateaus, and never moves a value outside [low, high] (a global
// mass-fixing step, cf. [Rasch90] on semi-Lagrangian transport; [Kim05] §4
// for graphics).
#pragma once

#include "sim/field/GridField.h"

namespace eikon::sim {

// Moves Σφ toward `target` by at most what the front weights allow; values stay in [low, high].
void restoreTotal(GridField& field, double target, double low, double high);

}  // namespace eikon::sim
