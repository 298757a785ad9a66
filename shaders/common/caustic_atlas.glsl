// The atlas the caustic triangles are drawn into (render/stages/CausticPolygons.h):
// the receivers' maps stacked, a texel per pixel. GLSL only; needs
// receiver_blocks.glsl.

// The first row of receiver r's map in the atlas.
int atlas_row(int r) {
    int row = 0;
    for (int q = 0; q < int(receiver_count); ++q) row += q < r ? int(receivers[q].map.y) : 0;
    return row;
}
