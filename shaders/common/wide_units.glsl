// 64-bit fixed-point tallies as (low, high) pairs of 32-bit words, added by
// atomics with the carry: integer sums that do not depend on the order the
// additions arrive in. Shared by the wavefront's receiver and energy tallies
// (common/wavefront_deposits.glsl) and its fluence (common/fluence_deposits.glsl).
// GLSL only.

// A non-negative number of units as (low, high) words.
uvec2 wide_units(float units) {
    float high = floor(units / 4294967296.0f);
    float low = min(units - high * 4294967296.0f + 0.5f, 4294967040.0f);
    return uvec2(uint(max(low, 0.0f)), uint(high));
}

// A signed number of units as the (low, high) words of its 64-bit two's
// complement: added modulo 2^64, positive and negative parts cancel exactly.
uvec2 signed_wide_units(float units) {
    uvec2 magnitude = wide_units(abs(units));
    if (units >= 0.0f) return magnitude;
    uint low = ~magnitude.x + 1u;
    return uvec2(low, ~magnitude.y + (low == 0u ? 1u : 0u));
}

// words[index] (low) and words[index + 1] (high) += value, with the carry.
// A macro: GLSL cannot pass a buffer's array to a function.
#define ADD_WIDE_UNITS(words, index, value)                                 \
    {                                                                       \
        uvec2 value_ = (value);                                             \
        uint index_ = (index);                                              \
        if (value_.x != 0u) {                                               \
            uint before_ = atomicAdd(words[index_], value_.x);              \
            if (before_ + value_.x < before_) atomicAdd(words[index_ + 1u], 1u); \
        }                                                                   \
        if (value_.y != 0u) atomicAdd(words[index_ + 1u], value_.y);       \
    }
