// A SevenPointOperator's cell (sim/fluid/StencilOperator.h) as the one uint
// of flags the GPU solver reads per cell (sim/gpu/GpuStencilOperator writes
// it, shaders/sim/seven_point.glsl reads it): bits 0–5 the neighbours
// coupled to the cell (bit 2·axis + side, side 0 the lower one), bits 8–14
// its diagonal class (the faces whose weight adds to the diagonal), or
// kNotUnknown where the cell is no unknown. Shared by GLSL and C++
// (shaders/common/cpp_shim.h): the CPU operator takes kNotUnknown from here.

const uint kNotUnknown = 64u;          // the diagonal class of a cell that is no unknown
const uint kCoupledBits = 63u;         // the six faces' bits
const uint kDiagonalClassShift = 8u;   // where the diagonal class starts
const uint kDiagonalClassBits = 127u;  // the six faces' bits and kNotUnknown

uint stencilFlags(uint coupled, uint diagonal_class) { return coupled | (diagonal_class << kDiagonalClassShift); }
uint coupledBits(uint flags) { return flags & kCoupledBits; }
uint diagonalClass(uint flags) { return (flags >> kDiagonalClassShift) & kDiagonalClassBits; }
bool isUnknown(uint flags) { return diagonalClass(flags) != kNotUnknown; }
