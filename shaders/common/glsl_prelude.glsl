// GLSL side of the shim that lets the shared files of shaders/common (those
// cpp_shim.h includes, and integrators.glsl) compile both as GLSL and as C++
// over GLM (the C++ side is shaders/common/cpp_shim.h), in the way NanoVDB's
// PNanoVDB.h serves C and GLSL with PNANOVDB_INOUT(T).
// Rules for shared files: float literals carry an `f`, parameters that are
// written use INOUT(T) (read and written) or OUT(T) (written only), no GLSL-only built-ins beyond what GLM provides;
// `precise` (no reassociation) is honoured by GLSL and is a no-op in C++,
// which does not reassociate without -ffast-math. GLM has no member
// swizzles: shared files write xyz_of(v) for v.xyz, xy_of(v) and zw_of(v)
// for v.xy and v.zw.
#define INOUT(T) inout T
#define OUT(T) out T
vec3 xyz_of(vec4 v) { return v.xyz; }
vec2 xy_of(vec4 v) { return v.xy; }
vec2 zw_of(vec4 v) { return v.zw; }
