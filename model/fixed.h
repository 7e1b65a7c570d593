// fixed.h — the fixed-point arithmetic of csgrt's exact path.
//
// Every operation here is an integer operation whose rounding is written out,
// so that the RTL can compute the very same bits. docs/numerics.md is the
// specification; this file is its executable form. Values are plain signed
// integers (i128 where a product is wider than 64 bits) holding a fixed-point
// number with a stated count of fraction bits; the format lives in the name
// and the comments of the caller, the helpers below are format-free.
#pragma once

#include <cstdint>

namespace csgrt {

using i64 = int64_t;
using u64 = uint64_t;
using i128 = __int128;
using u128 = unsigned __int128;

// Formats derived from the coordinate width B (docs/numerics.md, section 1).
struct Formats {
    int bits;          // B: width of a coordinate, a direction and a coefficient
    int frac;          // F = B - 3: fraction bits of coordinates, directions, t
    int coef_frac;     // FC = B - 1: fraction bits of quadric coefficients
    int cam_frac;      // F + 12: fraction bits of the camera's pixel-step vectors
    explicit Formats(int b = 24) : bits(b), frac(b - 3), coef_frac(b - 1), cam_frac(b - 3 + 12) {}
    // t saturates at |t| >= 2 (T_INT = 1 integer bit): see numerics.md.
    i64 t_limit() const { return i64(2) << frac; }
    i64 one() const { return i64(1) << frac; }
};

constexpr int kMinBits = 12;
constexpr int kMaxBits = 32;

// Round-half-up right shift: (x + 2^(k-1)) >> k with an arithmetic shift,
// i.e. round to nearest, ties toward +infinity. k = 0 is the identity.
inline i128 rshift_round(i128 x, int k) {
    if (k <= 0) return x;
    return (x + (i128(1) << (k - 1))) >> k;
}

// Integer square root, floor(sqrt(n)) for n >= 0, computed the way the RTL's
// pipeline does it: one result bit per stage, most significant first
// (restoring "digit-by-digit" method). `result_bits` is the number of stages;
// n must be < 4^result_bits.
inline u128 isqrt_bitwise(u128 n, int result_bits) {
    u128 root = 0;     // the result bits found so far
    u128 rem = 0;      // the partial remainder
    for (int i = result_bits - 1; i >= 0; --i) {
        // bring down the next two bits of n
        rem = (rem << 2) | ((n >> (2 * i)) & 3);
        u128 trial = (root << 2) | 1;   // (2*root + 1) at this scale
        root <<= 1;
        if (rem >= trial) {
            rem -= trial;
            root |= 1;
        }
    }
    return root;
}

// Unsigned restoring division, one quotient bit per stage, most significant
// first: floor(n / d) for d > 0, provided n / d < 2^quot_bits (the caller
// checks overflow first with div_overflows()).
inline u128 udiv_bitwise(u128 n, u128 d, int quot_bits) {
    u128 q = 0;
    u128 rem = n >> quot_bits;   // the bits above the quotient window; < d by precondition
    for (int i = quot_bits - 1; i >= 0; --i) {
        rem = (rem << 1) | ((n >> i) & 1);
        q <<= 1;
        if (rem >= d) {
            rem -= d;
            q |= 1;
        }
    }
    return q;
}

// floor(sqrt(n)) computed quickly (floating-point estimate, then corrected
// with exact integer comparisons). Returns exactly what isqrt_bitwise
// returns; the render path uses it for speed and fixed_test.cpp checks the
// two against each other.
inline u128 isqrt_fast(u128 n) {
    if (n == 0) return 0;
    if (n >> 64 == 0) {
        // 64-bit values: a double estimate (within a few units of the root,
        // which is below 2^32), corrected exactly; no long double conversion
        u64 r = u64(__builtin_sqrt(double(u64(n))));
        while (u128(r) * r > n) --r;
        while (u128(r + 1) * (r + 1) <= n) ++r;
        return r;
    }
    u128 r = u128(__builtin_sqrtl((long double)n));
    while (r * r > n) --r;
    while ((r + 1) * (r + 1) <= n) ++r;
    return r;
}

// True when floor(n / d) does not fit in quot_bits bits: n >= d * 2^quot_bits.
inline bool div_overflows(u128 n, u128 d, int quot_bits) {
    return (n >> quot_bits) >= d;
}

inline u128 uabs(i128 x) { return x < 0 ? u128(-x) : u128(x); }

// Signed division rounded toward zero, with the quotient's magnitude limited
// to quot_bits bits: returns false (and leaves q alone) when |n / d| would not
// fit, so that the caller saturates. d != 0.
inline bool sdiv_trunc(i128 n, i128 d, int quot_bits, i128& q) {
    u128 un = uabs(n), ud = uabs(d);
    if (div_overflows(un, ud, quot_bits)) return false;
    // floor(un / ud): the same value udiv_bitwise computes one bit per stage
    // (fixed_test.cpp checks them against each other); native division is
    // used here for speed.
    u128 uq = (un >> 64 == 0 && ud >> 64 == 0) ? u128(u64(un) / u64(ud)) : un / ud;
    q = ((n < 0) != (d < 0)) ? -i128(uq) : i128(uq);
    return true;
}

// Number of bits needed to hold |x| (0 for 0).
inline int bit_length(u128 x) {
    int n = 0;
    while (x) { ++n; x >>= 1; }
    return n;
}

}  // namespace csgrt
