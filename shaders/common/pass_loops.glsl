// What one pass of a tracer's loop spends of the loop budget
// (common/loop_budget.glsl) besides the loops that count themselves: the
// short loops over receivers and over sharp surfaces it may run. Included
// after common/receiver_blocks.glsl and common/sharp_surface_blocks.glsl.
uint loops_per_pass() {
    uint loops = 4u + 2u * receiver_count;
#if EIKON_SHARP_SURFACES
    loops += 3u * sharp_surface_count;
#endif
    return loops;
}
