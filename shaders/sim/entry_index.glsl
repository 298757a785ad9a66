// The entry of a one-dimensional pass (sim/gpu/GpuDispatch.h): entries are
// laid out over work groups in x, then in y once x would exceed
// GL_MAX_COMPUTE_WORK_GROUP_COUNT (65 535 groups: 16.8 million entries of
// 256, fewer than a 256³ grid has). Callers check it against their count.
uint entryIndex() { return gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x; }
