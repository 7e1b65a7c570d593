// fixed_test.cpp — the fixed-point operations of fixed.h against exact
// integer arithmetic: exhaustively at small widths, randomly at 24 and 32
// bits. The reference for each operation is written differently from the
// bit-serial algorithm under test (plain integer division, squaring).
#include "fixed.h"

#include <gtest/gtest.h>

#include <random>

using namespace csgrt;

namespace {

// floor(n / d) for d > 0, from C++'s truncating division.
i128 floor_div(i128 n, i128 d) {
    i128 q = n / d;
    if ((n % d != 0) && (n < 0)) --q;
    return q;
}

u128 random_bits(std::mt19937_64& rng, int bits) {
    u128 v = (u128(rng()) << 64) | rng();
    return bits >= 128 ? v : v & ((u128(1) << bits) - 1);
}

}  // namespace

TEST(Fixed, RshiftRoundExhaustive) {
    // round half up: floor(x / 2^k + 1/2) = floor((2x + 2^k) / 2^(k+1))
    for (int k = 0; k <= 10; ++k)
        for (i64 x = -(1 << 14); x <= (1 << 14); ++x) {
            const i128 expect = k == 0 ? x : floor_div(2 * i128(x) + (i128(1) << k), i128(1) << (k + 1));
            ASSERT_EQ(i64(rshift_round(x, k)), i64(expect)) << "x=" << x << " k=" << k;
        }
}

TEST(Fixed, RshiftRoundTiesGoUp) {
    EXPECT_EQ(i64(rshift_round(1, 1)), 1);    // 0.5 -> 1
    EXPECT_EQ(i64(rshift_round(-1, 1)), 0);   // -0.5 -> 0
    EXPECT_EQ(i64(rshift_round(3, 1)), 2);    // 1.5 -> 2
    EXPECT_EQ(i64(rshift_round(-3, 1)), -1);  // -1.5 -> -1
}

TEST(Fixed, IsqrtExhaustive16Bit) {
    for (u64 n = 0; n < (1u << 16); ++n) {
        const u64 r = u64(isqrt_bitwise(n, 8));
        ASSERT_LE(r * r, n) << n;
        ASSERT_GT((r + 1) * (r + 1), n) << n;
    }
}

TEST(Fixed, IsqrtRandomWide) {
    std::mt19937_64 rng(1);
    for (int bits : {24, 32}) {
        const int F = bits - 3;
        const int stages = F + 6;   // the intersection unit's square root
        for (int i = 0; i < 200000; ++i) {
            const int nb = 1 + int(rng() % (2 * stages));
            const u128 n = random_bits(rng, nb);
            const u128 r = isqrt_bitwise(n, stages);
            ASSERT_TRUE(r * r <= n && (r + 1) * (r + 1) > n);
        }
        // corners: perfect squares and their neighbours, the largest input
        for (u128 r : {u128(0), u128(1), (u128(1) << stages) - 1, u128(123456789)}) {
            EXPECT_EQ(isqrt_bitwise(r * r, stages), r);
            if (r > 0) { EXPECT_EQ(isqrt_bitwise(r * r - 1, stages), r - 1); }
        }
    }
}

TEST(Fixed, DivExhaustiveSmall) {
    const int qb = 6;
    for (i64 n = -(1 << 11); n <= (1 << 11); ++n)
        for (i64 d = -(1 << 6); d <= (1 << 6); ++d) {
            if (d == 0) continue;
            i128 q = 7777;
            const bool ok = sdiv_trunc(n, d, qb, q);
            const i64 exact = n / d;   // C++ truncates toward zero
            const bool fits = (n < 0 ? -n : n) / (d < 0 ? -d : d) < (1 << qb);
            ASSERT_EQ(ok, fits) << n << "/" << d;
            if (ok) { ASSERT_EQ(i64(q), exact) << n << "/" << d; }
        }
}

TEST(Fixed, DivRandomWide) {
    std::mt19937_64 rng(2);
    for (int bits : {24, 32}) {
        const int F = bits - 3;
        const int qb = F + 1;
        for (int i = 0; i < 200000; ++i) {
            i128 n = i128(random_bits(rng, 1 + int(rng() % (2 * F + 9))));
            i128 d = i128(random_bits(rng, 1 + int(rng() % (F + 9))));
            if (d == 0) d = 1;
            if (rng() & 1) n = -n;
            if (rng() & 1) d = -d;
            i128 q = 0;
            const bool ok = sdiv_trunc(n, d, qb, q);
            const i128 exact = n / d;
            const bool fits = (exact < 0 ? -exact : exact) < (i128(1) << qb);
            ASSERT_EQ(ok, fits);
            if (ok) { ASSERT_TRUE(q == exact); }
        }
    }
}

TEST(Fixed, FastPathsEqualTheBitSerialAlgorithms) {
    // The render path uses isqrt_fast and native division; they must return
    // exactly what the one-bit-per-stage algorithms (the RTL's) return.
    std::mt19937_64 rng(3);
    for (int i = 0; i < 300000; ++i) {
        const int stages = 1 + int(rng() % 40);
        const u128 n = random_bits(rng, 1 + int(rng() % (2 * stages)));
        ASSERT_TRUE(isqrt_fast(n) == isqrt_bitwise(n, stages));
        const int qb = 1 + int(rng() % 36);
        const u128 d = random_bits(rng, 1 + int(rng() % 40)) | 1;
        const u128 num = random_bits(rng, 1 + int(rng() % 70));
        if (!div_overflows(num, d, qb)) {
            i128 q;
            ASSERT_TRUE(sdiv_trunc(i128(num), i128(d), qb, q));
            ASSERT_TRUE(u128(q) == udiv_bitwise(num, d, qb));
        }
    }
}
