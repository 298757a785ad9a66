// The loop iterations an invocation may still run where the driver caps
// them (gl/GlContext.h, loopBudgetForRenderer, given as
// EIKON_LOOP_BUDGET; 0: no cap, and nothing is counted). Every loop that may
// run long spends from it, and a tracer whose budget is gone ends its ray —
// a photon as cut off, counted in the energy balance — before the driver
// would end its loops midway and leave its state undefined. GLSL only.
#ifndef EIKON_LOOP_BUDGET
#define EIKON_LOOP_BUDGET 0
#endif

#if EIKON_LOOP_BUDGET > 0
uint loop_budget = uint(EIKON_LOOP_BUDGET);
void spend_loops(uint iterations) { loop_budget -= min(iterations, loop_budget); }
bool loops_left() { return loop_budget > 0u; }
#else
void spend_loops(uint iterations) {}
bool loops_left() { return true; }
#endif
