// tb_sqrt.cpp — csgrt_sqrt against isqrt_bitwise() (model/fixed.h).
// RESULT_BITS 6 and 10: every radicand. RESULT_BITS 27 (F+6 at B = 24):
// corners (0, 1, squares and their neighbours, all-ones) and 1,000,000
// random radicands with a random bit length. Every run crosses random input
// gaps and random output back-pressure; a back-to-back run checks the
// latency (RESULT_BITS + 1) and full throughput. The same with II = 3
// (csgrt_sqrt_core FOLD = 3: three result bits per stage): RESULT_BITS 8
// and 10 every radicand, 27 corners and 200,000 random radicands; latency
// 3 ceil(RESULT_BITS / 3) + 1 and one result per three clocks.
#include "Vtb_sqrt.h"
#include "fixed.h"
#include "stream.h"

#include <gtest/gtest.h>

#include <vector>

namespace {

using Top = Vtb_sqrt;

#define SQRT_PORTS(P, R)                                                                               \
    tb::StreamPorts ports_##P(Top* t) {                                                              \
        return {&t->P##_clk_i, &t->P##_rst_ni, &t->P##_valid_i,                              \
                &t->P##_ready_o, &t->P##_valid_o, &t->P##_ready_i};                          \
    }                                                                                                 \
    tb::StreamResult run_##P(Top* t, const std::vector<uint64_t>& in, double gap, double stall,      \
                              uint64_t seed) {                                                        \
        return tb::run_stream(                                                                        \
            t, ports_##P(t), in.size(),                                                              \
            [&](size_t i) {                                                                           \
                t->P##_n_i = in[i];                                                                \
                t->P##_user_i = uint16_t(i);                                                       \
            },                                                                                        \
            [&](size_t i) -> std::string {                                                            \
                const uint64_t want = uint64_t(csgrt::isqrt_bitwise(in[i], R));                       \
                const uint64_t got = t->P##_root_o;                                                \
                if (got == want && t->P##_user_o == uint16_t(i)) return "";                        \
                std::ostringstream s;                                                                 \
                s << "n=" << in[i] << " root DUT " << got << " model " << want << " tag "             \
                  << t->P##_user_o;                                                                \
                return s.str();                                                                       \
            },                                                                                        \
            gap, stall, seed);                                                                        \
    }

SQRT_PORTS(r6, 6)
SQRT_PORTS(r10, 10)
SQRT_PORTS(r27, 27)
SQRT_PORTS(f8, 8)
SQRT_PORTS(f10, 10)
SQRT_PORTS(f27, 27)

std::vector<uint64_t> all_inputs(int bits) {
    std::vector<uint64_t> v(size_t(1) << bits);
    for (size_t i = 0; i < v.size(); ++i) v[i] = i;
    return v;
}

TEST(Sqrt, Exhaustive6) {
    tb::Harness<Top> h;
    auto r = run_r6(h.top.get(), all_inputs(12), 0.3, 0.3, tb::seed(1));
    EXPECT_TRUE(r.ok()) << r.summary();
    std::printf("sqrt R=6: %s\n", r.summary().c_str());
}

TEST(Sqrt, Exhaustive10) {
    tb::Harness<Top> h;
    auto r = run_r10(h.top.get(), all_inputs(20), 0.2, 0.2, tb::seed(2));
    EXPECT_TRUE(r.ok()) << r.summary();
    std::printf("sqrt R=10: %s\n", r.summary().c_str());
}

TEST(Sqrt, LatencyAndThroughput) {
    tb::Harness<Top> h;
    std::vector<uint64_t> in(1000);
    for (size_t i = 0; i < in.size(); ++i) in[i] = i * 7919u;
    auto r = run_r27(h.top.get(), in, 0.0, 0.0, 3);
    EXPECT_TRUE(r.ok()) << r.summary();
    EXPECT_EQ(r.min_latency, 27 + 1);
    EXPECT_EQ(r.max_latency, 27 + 1);
    // full throughput: one result per clock after the pipeline fills
    EXPECT_LE(r.cycles, in.size() + 28 + 2 + 201);
    auto r6 = run_r6(h.top.get(), all_inputs(12), 0.0, 0.0, 4);
    EXPECT_TRUE(r6.ok()) << r6.summary();
    EXPECT_EQ(r6.min_latency, 6 + 1);
    EXPECT_EQ(r6.max_latency, 6 + 1);
}

std::vector<uint64_t> inputs27(size_t nrand, uint64_t seed) {
    const int R = 27;
    const uint64_t max = (uint64_t(1) << (2 * R)) - 1;
    std::vector<uint64_t> in;
    // corners: small values, squares and neighbours across the range, max
    for (uint64_t i = 0; i < 1024; ++i) in.push_back(i);
    for (int b = 0; b < R; ++b)
        for (uint64_t x : {uint64_t(1) << b, (uint64_t(1) << b) - 1, (uint64_t(1) << b) + 1, (uint64_t(3) << b) >> 1}) {
            const uint64_t sq = x * x;
            for (uint64_t v : {sq - 1, sq, sq + 1, sq + 2 * x, sq + 2 * x + 1})
                if (v <= max) in.push_back(v);
        }
    const uint64_t rmax = (uint64_t(1) << R) - 1;
    for (uint64_t v : {max, max - 1, rmax * rmax, rmax * rmax - 1, uint64_t(1) << (2 * R - 1)}) in.push_back(v);
    std::mt19937_64 rng(seed);
    for (size_t i = 0; i < nrand; ++i) {
        const int len = int(rng() % (2 * R + 1));
        in.push_back(len == 0 ? 0 : (rng() & tb::mask(len)));
    }
    return in;
}

TEST(Sqrt, Random27) {
    const auto in = inputs27(size_t(1000000 * tb::scale()), tb::seed(27));
    tb::Harness<Top> h;
    auto r = run_r27(h.top.get(), in, 0.25, 0.25, tb::seed(28));
    EXPECT_TRUE(r.ok()) << r.summary();
    std::printf("sqrt R=27: %s\n", r.summary().c_str());
}

TEST(Sqrt, FoldedExhaustive8And10) {
    tb::Harness<Top> h;
    auto r8 = run_f8(h.top.get(), all_inputs(16), 0.3, 0.3, tb::seed(5));
    EXPECT_TRUE(r8.ok()) << r8.summary();
    std::printf("sqrt R=8 II=3: %s\n", r8.summary().c_str());
    auto r10 = run_f10(h.top.get(), all_inputs(20), 0.2, 0.2, tb::seed(6));
    EXPECT_TRUE(r10.ok()) << r10.summary();
    std::printf("sqrt R=10 II=3: %s\n", r10.summary().c_str());
}

TEST(Sqrt, FoldedLatencyAndThroughput) {
    tb::Harness<Top> h;
    std::vector<uint64_t> in(1000);
    for (size_t i = 0; i < in.size(); ++i) in[i] = i * 7919u;
    auto r = run_f27(h.top.get(), in, 0.0, 0.0, 7);
    EXPECT_TRUE(r.ok()) << r.summary();
    // taken at a beat's last clock, 27 / 3 = 9 beats of three clocks to
    // the skid buffer, and its clock; one result per beat
    EXPECT_EQ(r.min_latency, 3 * 9 + 1);
    EXPECT_EQ(r.max_latency, 3 * 9 + 1);
    EXPECT_LE(r.cycles, 3 * in.size() + 28 + 2 + 201);
    EXPECT_GE(r.cycles, 3 * in.size());
    auto r10 = run_f10(h.top.get(), all_inputs(12), 0.0, 0.0, 8);
    EXPECT_TRUE(r10.ok()) << r10.summary();
    EXPECT_EQ(r10.min_latency, 3 * 4 + 1);
    EXPECT_EQ(r10.max_latency, 3 * 4 + 1);
}

TEST(Sqrt, FoldedRandom27) {
    const auto in = inputs27(size_t(200000 * tb::scale()), tb::seed(29));
    tb::Harness<Top> h;
    auto r = run_f27(h.top.get(), in, 0.25, 0.25, tb::seed(30));
    EXPECT_TRUE(r.ok()) << r.summary();
    std::printf("sqrt R=27 II=3: %s\n", r.summary().c_str());
}

}  // namespace
