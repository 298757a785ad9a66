// The sheets of the image-space caustic maps (render/stages/CausticPolygons.h,
// common/caustic_vertices.glsl): per light texel, the photon refracted
// through the surface (sheet 0) and the one reflected by it (sheet 1).
// Shared by GLSL and C++ (shaders/common/cpp_shim.h).

const int kCausticSheets = 2;
