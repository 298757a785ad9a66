// A caustic triangle's power per receiver texel (caustic_polygons.vert),
// added by blending into the receivers' atlas.
flat in vec3 texel_watts;

layout(location = 0) out vec4 deposit;

void main() { deposit = vec4(texel_watts, 0.0f); }
