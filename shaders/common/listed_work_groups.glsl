// A list a pass fills on the GPU, each invocation (or work group) taking a
// range [first, first + count) of it by an atomic on its length, for the
// next pass to cover by an indirect dispatch of group_size invocations a
// work group: the work groups the range starts, one at each multiple of
// group_size it holds. Added up over all ranges, by another atomic, they
// make the dispatch's ⌈length / group_size⌉, in whatever order the ranges
// arrive. GLSL only.
uint work_groups_started(uint first, uint count, uint group_size) {
    return (first + count + group_size - 1u) / group_size - (first + group_size - 1u) / group_size;
}
