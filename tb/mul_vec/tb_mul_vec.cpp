// tb_mul_vec.cpp — csgrt_mul_vec's contract (rtl/csgrt_mul_vec.v): the
// operands given during beat k (steady for the whole beat) come out as the
// exact signed products on p_o for every clock of beat k+2 (k+3 for the
// time-shared instances with both OP_REG and TILE_REG: MUL_VEC_BEATS 3,
// written out by the build rule, not read from the RTL), stalls
// included, whether the products share one multiplier over a three-clock
// beat (II = 3; N = 1, 2, 3) or have one each (II = 1). Random operands,
// new ones at every advance of an instance's beat, and a random clock
// enable (the pipelines' stall) that also holds the beat's phase.
#include "Vtb_mul_vec.h"
#include "bits.h"
#include "stream.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <deque>
#include <random>
#include <string>
#include <vector>

namespace {

using Top = Vtb_mul_vec;
using i128 = __int128;

constexpr int kMaxW = 32;   // tb_mul_vec.v MAXW
struct Inst { int a, b, n, ii; };
// tb_mul_vec.v wa / wb / nprod / II, instance by instance
constexpr Inst kInst[] = {{24, 21, 3, 3}, {17, 18, 2, 3}, {18, 18, 1, 3}, {24, 21, 3, 1}};
constexpr int kN = 4;
#ifndef MUL_VEC_BEATS
#define MUL_VEC_BEATS 2
#endif
// the time-shared instances' latency in beats; the unshared one (II = 1) always has 2
constexpr int kBeats3 = MUL_VEC_BEATS;
int beats_of(int k) { return kInst[k].ii == 3 ? kBeats3 : 2; }

using tb::get_signed;
using tb::put_bits;

int64_t random_signed(std::mt19937_64& rng, int w) {
    const int len = 1 + int(rng() % uint64_t(w));   // random length: small and large values
    int64_t v = int64_t(rng() & ((uint64_t(1) << len) - 1));
    if (len == w && ((v >> (w - 1)) & 1)) v -= int64_t(1) << w;
    if (len < w && (rng() & 1)) v = -v;
    return v;
}

struct Pairs { int64_t a[3], b[3]; };

struct Result {
    uint64_t checked = 0, mismatches = 0;
    uint64_t adv_checked = 0, adv_mismatches = 0;   // adv_q_o against adv_o (csgrt_beat)
    std::string first;
};

Result run(double ce_prob, uint64_t clocks, uint64_t seed) {
    tb::Harness<Top> h;
    Top* t = h.top.get();
    std::mt19937_64 rng(seed);
    std::bernoulli_distribution ce_dist(ce_prob);
    auto fresh = [&](int k) {
        Pairs p{};
        for (int j = 0; j < kInst[k].n; ++j) {
            p.a[j] = random_signed(rng, kInst[k].a);
            p.b[j] = random_signed(rng, kInst[k].b);
        }
        return p;
    };
    auto drive = [&](int k, const Pairs& p) {
        for (int j = 0; j < kInst[k].n; ++j) {
            put_bits(t->a_i, (3 * k + j) * kMaxW, kInst[k].a, uint64_t(p.a[j]));
            put_bits(t->b_i, (3 * k + j) * kMaxW, kInst[k].b, uint64_t(p.b[j]));
        }
    };
    // each instance's operands, one entry per beat (newest at the back)
    std::deque<Pairs> beats[kN];
    for (int k = 0; k < kN; ++k) { beats[k].push_back(fresh(k)); drive(k, beats[k].back()); }

    // the enable is drawn a clock ahead: the beats' registered advance is
    // loaded with its next value (ce_next_i)
    bool ce_now = ce_dist(rng);
    t->clk_i = 0; t->rst_ni = 0; t->ce_i = 0; t->ce_next_i = ce_now;
    t->eval();
    for (int i = 0; i < 2; ++i) { t->clk_i = 1; t->eval(); t->clk_i = 0; t->eval(); }
    t->rst_ni = 1;
    Result r;
    for (uint64_t c = 0; c < clocks; ++c) {
        const bool ce_next = ce_dist(rng);
        t->ce_i = ce_now;
        t->ce_next_i = ce_next;
        ce_now = ce_next;
        t->eval();
        ++r.adv_checked;
        if (t->adv3_q_o != t->adv3_o || t->adv1_q_o != t->adv1_o) ++r.adv_mismatches;
        // p_o during beat k+B shows beat k's products (B = beats_of: the deque's front once it holds B+1 beats)
        for (int k = 0; k < kN; ++k) {
            if (beats[k].size() < size_t(beats_of(k) + 1)) continue;
            const Pairs& p = beats[k].front();
            for (int j = 0; j < kInst[k].n; ++j) {
                const int64_t want = p.a[j] * p.b[j];
                const int64_t got = int64_t(get_signed(t->p_o, (3 * k + j) * 2 * kMaxW, 2 * kMaxW));
                ++r.checked;
                if (got != want) {
                    if (!r.mismatches)
                        r.first = "clock " + std::to_string(c) + " instance " + std::to_string(k) + " product " +
                                  std::to_string(j) + ": got " + std::to_string(got) + ", want " +
                                  std::to_string(want);
                    ++r.mismatches;
                }
            }
        }
        const bool adv[kN] = {bool(t->adv3_o), bool(t->adv3_o), bool(t->adv3_o), bool(t->adv1_o)};
        t->clk_i = 1; t->eval();
        t->clk_i = 0; t->eval();
        for (int k = 0; k < kN; ++k) {
            if (!adv[k]) continue;   // operands change only after a beat's advance
            beats[k].push_back(fresh(k));
            drive(k, beats[k].back());
            if (beats[k].size() > size_t(beats_of(k) + 1)) beats[k].pop_front();
        }
    }
    return r;
}

TEST(MulVec, NoStalls) {
    const Result r = run(1.0, 3000, tb::seed(1));
    EXPECT_EQ(r.mismatches, 0u) << r.first;
    EXPECT_EQ(r.adv_mismatches, 0u);
    EXPECT_GT(r.checked, 20000u);
}

TEST(MulVec, RandomStalls) {
    const Result r = run(0.6, 20000, tb::seed(2));
    std::printf("mul_vec: %llu products checked, %llu mismatches\n", (unsigned long long)r.checked,
                (unsigned long long)r.mismatches);
    EXPECT_EQ(r.mismatches, 0u) << r.first;
    EXPECT_GT(r.checked, 100000u);
    EXPECT_EQ(r.adv_mismatches, 0u);
    EXPECT_EQ(r.adv_checked, 20000u);
}

}  // namespace
