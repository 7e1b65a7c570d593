// tb_mul.cpp — csgrt_mul against the exact signed product, at every width
// of tb_mul.v's table. The same bench is built behavioural (build/tb/mul)
// and as the FPGA build maps it (build/tb/mul_ecp5: CSGRT_ECP5_DSP, tiles of
// MULT18X18D modelled by tb/ecp5/MULT18X18D.v, and fabric tiles): both must
// give the exact product two enabled clocks after the operands, with a
// random clock enable holding every register (the pipelines' stall).
// build/tb/mul_ecp5_treg: the tiled build with TILE_REG = 1 (a register
// behind each tile), three enabled clocks (MUL_TILE_REG).
#ifndef MUL_TILE_REG
#define MUL_TILE_REG 0
#endif
// Operands: the corners of each width (0, +-1, the extremes, single bits and
// their neighbours, every chunk boundary of the tiling at 18k bits) crossed
// with each other, then random values of random length.
#include "Vtb_mul.h"
#include "bits.h"
#include "stream.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <deque>
#include <optional>
#include <random>
#include <vector>

namespace {

using Top = Vtb_mul;
using i128 = __int128;

constexpr int kMaxW = 40;   // tb_mul.v MAXW
constexpr int kLatency = 2 + MUL_TILE_REG;   // enabled clocks from operands to product
struct Widths { int a, b; };
// tb_mul.v width_a / width_b, instance by instance
constexpr Widths kWidths[] = {{18, 18}, {24, 24}, {21, 21}, {17, 25}, {32, 32}, {19, 40}, {26, 24},
                              {36, 36}, {37, 5},  {2, 2},   {29, 29}, {16, 19}, {12, 12}, {34, 34},
                              // BITS 24's corners that LUT_TILE_MAX 81 moves to the fabric:
                              // 6 x 8, 9 x 9, 4 x 18 (and 6 x 6), 6 x 12
                              {24, 26}, {27, 27}, {22, 24}, {24, 30}};
constexpr int kN = sizeof(kWidths) / sizeof(kWidths[0]);

using tb::get_signed;
using tb::put_bits;

int64_t wrap(int64_t v, int w) {   // v as a w-bit two's complement number
    const uint64_t m = (w >= 64) ? ~0ull : ((1ull << w) - 1);
    uint64_t u = uint64_t(v) & m;
    if ((u >> (w - 1)) & 1) return int64_t(u | ~m);
    return int64_t(u);
}

// corner operands of a w-bit signed number
std::vector<int64_t> corners(int w) {
    std::vector<int64_t> c = {0, 1, -1, 2, -2};
    const int64_t mx = (int64_t(1) << (w - 1)) - 1, mn = -(int64_t(1) << (w - 1));
    c.insert(c.end(), {mx, mn, mx - 1, mn + 1});
    for (int k = 1; k < w - 1; ++k) {
        const int64_t p = int64_t(1) << k;
        c.insert(c.end(), {p, p - 1, -p, -p + 1});
    }
    for (int k = 18; k < w; k += 18) {   // chunk boundaries
        const int64_t p = int64_t(1) << k;
        c.insert(c.end(), {wrap(p - 1, w), wrap(p, w), wrap(p + 1, w), wrap(-p, w), wrap(-p - 1, w)});
    }
    for (int64_t& v : c) v = wrap(v, w);
    return c;
}

struct Result {
    uint64_t checked = 0, mismatches = 0;
    std::vector<std::string> messages;
};

// Feeds `count` operand pairs per instance, operand i of instance k given by
// `pick(k, i)`, with the clock enable high with probability ce_prob.
template <class Pick>
Result run(Top* t, size_t count, double ce_prob, uint64_t seed, Pick pick) {
    std::mt19937_64 rng(seed);
    std::bernoulli_distribution ce_dist(ce_prob);
    struct Op { int64_t a[kN], b[kN]; };
    // the DUT's pipeline in software: kLatency stages, shifted on each enabled clock
    std::deque<std::optional<Op>> pipe(kLatency);
    Result r;
    auto tick = [&] { t->clk_i = 0; t->eval(); t->clk_i = 1; t->eval(); };
    t->rst_ni = 0;
    t->ce_i = 1;
    t->valid_i = 0;
    tick();
    tick();
    t->rst_ni = 1;
    size_t sent = 0;
    for (uint64_t cycle = 0; r.checked < count && cycle < 20 * count + 100; ++cycle) {
        const bool ce = ce_dist(rng);
        Op op{};
        const bool send = ce && sent < count;
        for (int k = 0; k < kN; ++k) {
            // operands the DUT must not take (enable low) are random junk
            op.a[k] = send ? pick(k, sent, true) : int64_t(rng());
            op.b[k] = send ? pick(k, sent, false) : int64_t(rng());
            put_bits(t->a_i, k * kMaxW, kWidths[k].a, uint64_t(op.a[k]));
            put_bits(t->b_i, k * kMaxW, kWidths[k].b, uint64_t(op.b[k]));
        }
        if (send) ++sent;
        t->ce_i = ce;
        t->valid_i = send;
        tick();
        if (ce) {
            pipe.pop_back();
            pipe.push_front(send ? std::optional<Op>(op) : std::nullopt);
        }
        const std::optional<Op>& due = pipe.back();   // the operands whose product is due at p_o
        for (int k = 0; k < kN; ++k)
            if (((t->valid_o >> k) & 1) != uint32_t(due.has_value())) {
                ++r.mismatches;
                if (r.messages.size() < 8) r.messages.push_back("valid_o not kLatency enabled clocks after valid_i");
            }
        if (!ce || !due) continue;
        const Op& want = *due;
        for (int k = 0; k < kN; ++k) {
            const i128 exact = i128(want.a[k]) * i128(want.b[k]);
            const i128 got = get_signed(t->p_o, k * 2 * kMaxW, kWidths[k].a + kWidths[k].b);
            if (got != exact) {
                if (r.messages.size() < 8) {
                    char buf[200];
                    std::snprintf(buf, sizeof buf, "%d x %d: a=%lld b=%lld product %lld, DUT %lld", kWidths[k].a,
                                  kWidths[k].b, (long long)want.a[k], (long long)want.b[k], (long long)exact,
                                  (long long)got);
                    r.messages.push_back(buf);
                }
                ++r.mismatches;
            }
        }
        ++r.checked;
    }
    return r;
}

std::string summary(const Result& r) {
    std::string s = "checked " + std::to_string(r.checked) + " x " + std::to_string(kN) + " products, " +
                    std::to_string(r.mismatches) + " mismatches";
    for (const std::string& m : r.messages) s += "\n  " + m;
    return s;
}

TEST(Mul, CornersCrossed) {
    tb::Harness<Top> h;
    std::vector<std::vector<int64_t>> ca(kN), cb(kN);
    size_t n = 0;
    for (int k = 0; k < kN; ++k) {
        ca[k] = corners(kWidths[k].a);
        cb[k] = corners(kWidths[k].b);
        n = std::max(n, ca[k].size() * cb[k].size());
    }
    const Result r = run(h.top.get(), n, 0.7, tb::seed(11), [&](int k, size_t i, bool is_a) {
        const size_t na = ca[k].size(), nb = cb[k].size();
        const size_t j = i % (na * nb);
        return is_a ? ca[k][j / nb] : cb[k][j % nb];
    });
    EXPECT_EQ(r.checked, n);
    EXPECT_EQ(r.mismatches, 0u) << summary(r);
    std::printf("mul corners: %s\n", summary(r).c_str());
}

TEST(Mul, RandomWithStalls) {
    tb::Harness<Top> h;
    std::mt19937_64 rng(tb::seed(12));
    const size_t n = 200000;
    const Result r = run(h.top.get(), n, 0.6, tb::seed(13), [&](int k, size_t, bool is_a) {
        const int w = is_a ? kWidths[k].a : kWidths[k].b;
        const int len = 1 + int(rng() % uint64_t(w));   // random magnitude
        return wrap(int64_t(rng() >> (64 - len)) * ((rng() & 1) ? -1 : 1), w);
    });
    EXPECT_EQ(r.checked, n);
    EXPECT_EQ(r.mismatches, 0u) << summary(r);
    std::printf("mul random: %s\n", summary(r).c_str());
}

TEST(Mul, BackToBackLatency) {
    tb::Harness<Top> h;
    // the enable always high: each product exactly kLatency clocks after
    // its operands (run() checks valid_o and p_o against a kLatency-stage shadow)
    const Result r = run(h.top.get(), 1000, 1.0, tb::seed(14), [&](int k, size_t i, bool is_a) {
        return wrap(int64_t(i * 2654435761u) * (is_a ? 1 : -3), is_a ? kWidths[k].a : kWidths[k].b);
    });
    EXPECT_EQ(r.checked, 1000u);
    EXPECT_EQ(r.mismatches, 0u) << summary(r);
}

}  // namespace
