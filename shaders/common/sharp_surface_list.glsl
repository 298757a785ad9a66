// The scene's sharp surfaces in scene order (C++ mirror:
// layout::GpuSharpSurface, filled by render/stages/SharpSurfaceBuffer).
// GLSL only.
struct SharpSurface {
    vec4 shape_a;  // xyz sphere centre, or box min; w kind (kSharpSphere, kSharpBox, kSharpTriangles)
    vec4 shape_b;  // x sphere radius, or xyz box max; w a mesh's root node
    vec4 optics;   // x n_object − n_ref; y 1 if Fresnel reflects
};
layout(std140, binding = kSharpSurfaces) uniform SharpSurfaces { SharpSurface sharp_surfaces[kMaxSharpObjects]; };
