// The atlas the caustic triangles are drawn into (render/stages/CausticPolygons.h):
// the receivers' maps stacked, a texel per pixel. GLSL only; needs
// receiver_blocks.glsl.

// The first row of receiver r's map in the atlas.
int atlas_row(int r) {
    int row = 0;
    for (int q = 0; q < r; ++q) row += int(receivers[q].map.y);
    return row;
}
