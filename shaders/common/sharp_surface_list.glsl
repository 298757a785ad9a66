// The scene's sharp surfaces in scene order (members:
// layout::GpuSharpSurface, filled by render/stages/SharpSurfaceBuffer).
// GLSL only.
struct SharpSurface { EIKON_GPU_SHARP_SURFACE };
layout(std140, binding = kSharpSurfaces) uniform SharpSurfaces { SharpSurface sharp_surfaces[kMaxSharpObjects]; };
