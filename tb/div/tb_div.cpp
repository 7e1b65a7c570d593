// tb_div.cpp — csgrt_div against sdiv_trunc() / div_overflows()
// (model/fixed.h): quotient (when not overflowing), overflow flag, sign of
// the saturation ((n < 0) != (d < 0)) and the sideband tag, in order.
// Config x (10/8/5 bits): every numerator and denominator, d = 0 included.
// Configs m and l (the dividers of csgrt_isect at BITS 12 and 24): corners
// around the overflow boundary and the extreme values, plus random operands
// of random bit lengths (1,000,000 for l). Random gaps and back-pressure;
// a back-to-back run checks latency QUOT_BITS + 2 and full throughput.
// Configs x3 and l3: x and l with II = 3 (csgrt_div_core FOLD = 3), every
// operand pair of x3, corners and 200,000 random pairs of l3; latency
// 3 (ceil(QUOT_BITS / 3) + 1) + 1 and one result per three clocks.
#include "Vtb_div.h"
#include "fixed.h"
#include "stream.h"

#include <gtest/gtest.h>

#include <vector>

namespace {

using Top = Vtb_div;
using csgrt::i128;

struct Op {
    int64_t n, d;
};

#define DIV_PORTS(T, NW, DW, QB)                                                                      \
    constexpr int NW_##T = NW, DW_##T = DW, QB_##T = QB;                                              \
    tb::StreamResult run_##T(Top* t, const std::vector<Op>& in, double gap, double stall, uint64_t seed) { \
        tb::StreamPorts p{&t->T##_clk_i, &t->T##_rst_ni, &t->T##_valid_i,                             \
                          &t->T##_ready_o, &t->T##_valid_o, &t->T##_ready_i};                         \
        return tb::run_stream(                                                                        \
            t, p, in.size(),                                                                          \
            [&](size_t i) {                                                                           \
                t->T##_num_i = uint64_t(in[i].n) & tb::mask(NW);                                      \
                t->T##_den_i = uint64_t(in[i].d) & tb::mask(DW);                                      \
                t->T##_user_i = uint16_t(i);                                                          \
            },                                                                                        \
            [&](size_t i) { return check(in[i], QB, tb::sext(t->T##_quot_o, QB + 1), t->T##_ovf_o,     \
                                         t->T##_neg_o, t->T##_user_o, uint16_t(i)); },                 \
            gap, stall, seed);                                                                        \
    }

std::string check(const Op& op, int qb, int64_t quot, bool ovf, bool neg, uint16_t tag, uint16_t want_tag) {
    i128 q = 0;
    const bool ok = csgrt::sdiv_trunc(op.n, op.d, qb, q);
    const bool want_neg = (op.n < 0) != (op.d < 0);
    const int64_t want_q = ok ? int64_t(q) : 0;
    if (ok == !ovf && want_neg == neg && want_q == quot && tag == want_tag) return "";
    std::ostringstream s;
    s << op.n << " / " << op.d << ": DUT q=" << quot << " ovf=" << ovf << " neg=" << neg << " tag=" << tag
      << ", model q=" << want_q << " ovf=" << !ok << " neg=" << want_neg;
    return s.str();
}

DIV_PORTS(x, 10, 8, 5)
DIV_PORTS(m, 28, 17, 10)
DIV_PORTS(l, 52, 29, 22)
DIV_PORTS(x3, 10, 8, 5)
DIV_PORTS(l3, 52, 29, 22)

int64_t smin(int w) { return -(int64_t(1) << (w - 1)); }
int64_t smax(int w) { return (int64_t(1) << (w - 1)) - 1; }

// Corner operands for widths nw/dw and qb quotient bits.
std::vector<Op> corners(int nw, int dw, int qb) {
    std::vector<Op> v;
    std::vector<int64_t> ds = {0, 1, -1, 2, -2, 3, -3, smax(dw), smin(dw), smin(dw) + 1, smax(dw) - 1};
    for (int b = 1; b < dw - 1; ++b) ds.push_back(int64_t(1) << b), ds.push_back(-(int64_t(1) << b) - 1);
    std::vector<int64_t> ns = {0, 1, -1, smax(nw), smin(nw), smin(nw) + 1};
    for (int64_t d : ds) {
        for (int64_t n : ns) v.push_back({n, d});
        const int64_t ad = d < 0 ? -d : d;
        if (ad == 0 || ad > (smax(nw) >> qb)) continue;
        const int64_t lim = ad << qb;   // the overflow boundary |n| = |d| 2^qb
        for (int64_t n : {lim, lim - 1, lim + 1, lim - ad, lim - ad + 1, ad, ad - 1})
            for (int s : {1, -1})
                if (n <= smax(nw)) v.push_back({s * n, d});
    }
    return v;
}

// Random operands: random bit lengths and signs, so that quotients cover
// every magnitude and the overflow boundary.
std::vector<Op> randoms(int nw, int dw, int qb, size_t count, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::vector<Op> v;
    v.reserve(count);
    for (size_t i = 0; i < count; ++i) {
        int64_t d;
        do {
            d = tb::sext(rng() & tb::mask(1 + int(rng() % dw)), dw);
            if (rng() & 1) d = tb::sext(uint64_t(-d), dw);
        } while (d == 0 && (rng() & 7));
        int64_t n;
        if (rng() % 4 == 0) {
            // near the overflow boundary
            const int64_t ad = d < 0 ? -d : d;
            n = tb::sext(uint64_t((ad << qb) + int64_t(rng() % 5) - 2), nw);
            if (rng() & 1) n = tb::sext(uint64_t(-n), nw);
        } else {
            n = tb::sext(rng() & tb::mask(1 + int(rng() % nw)), nw);
        }
        v.push_back({n, d});
    }
    return v;
}

TEST(Div, Exhaustive_10_8_5) {
    std::vector<Op> in;
    for (int64_t n = smin(10); n <= smax(10); ++n)
        for (int64_t d = smin(8); d <= smax(8); ++d) in.push_back({n, d});
    tb::Harness<Top> h;
    auto r = run_x(h.top.get(), in, 0.3, 0.3, tb::seed(11));
    EXPECT_TRUE(r.ok()) << r.summary();
    std::printf("div 10/8/5: %s\n", r.summary().c_str());
}

TEST(Div, LatencyAndThroughput) {
    tb::Harness<Top> h;
    auto in = randoms(NW_l, DW_l, QB_l, 1000, 12);
    auto r = run_l(h.top.get(), in, 0.0, 0.0, 13);
    EXPECT_TRUE(r.ok()) << r.summary();
    EXPECT_EQ(r.min_latency, QB_l + 2);
    EXPECT_EQ(r.max_latency, QB_l + 2);
    EXPECT_LE(r.cycles, in.size() + QB_l + 4 + 201);
}

TEST(Div, Random_28_17_10) {
    auto in = corners(NW_m, DW_m, QB_m);
    auto rnd = randoms(NW_m, DW_m, QB_m, size_t(200000 * tb::scale()), tb::seed(14));
    in.insert(in.end(), rnd.begin(), rnd.end());
    tb::Harness<Top> h;
    auto r = run_m(h.top.get(), in, 0.25, 0.25, tb::seed(15));
    EXPECT_TRUE(r.ok()) << r.summary();
    std::printf("div 28/17/10: %s\n", r.summary().c_str());
}

TEST(Div, Random_52_29_22) {
    auto in = corners(NW_l, DW_l, QB_l);
    auto rnd = randoms(NW_l, DW_l, QB_l, size_t(1000000 * tb::scale()), tb::seed(16));
    in.insert(in.end(), rnd.begin(), rnd.end());
    size_t ovf = 0;
    for (const Op& op : in) {
        i128 q;
        ovf += !csgrt::sdiv_trunc(op.n, op.d, QB_l, q);
    }
    tb::Harness<Top> h;
    auto r = run_l(h.top.get(), in, 0.25, 0.25, tb::seed(17));
    EXPECT_TRUE(r.ok()) << r.summary();
    std::printf("div 52/29/22: %s (%zu overflowing)\n", r.summary().c_str(), ovf);
}

TEST(Div, FoldedExhaustive_10_8_5) {
    std::vector<Op> in;
    for (int64_t n = smin(10); n <= smax(10); ++n)
        for (int64_t d = smin(8); d <= smax(8); ++d) in.push_back({n, d});
    tb::Harness<Top> h;
    auto r = run_x3(h.top.get(), in, 0.3, 0.3, tb::seed(18));
    EXPECT_TRUE(r.ok()) << r.summary();
    std::printf("div 10/8/5 II=3: %s\n", r.summary().c_str());
}

TEST(Div, FoldedLatencyAndThroughput) {
    tb::Harness<Top> h;
    auto in = randoms(NW_l3, DW_l3, QB_l3, 1000, 19);
    auto r = run_l3(h.top.get(), in, 0.0, 0.0, 20);
    EXPECT_TRUE(r.ok()) << r.summary();
    // taken at a beat's last clock, ceil(22 / 3) + 1 = 9 beats of three
    // clocks to the skid buffer, and its clock
    const int latency = 3 * ((QB_l3 + 2) / 3 + 1) + 1;
    EXPECT_EQ(r.min_latency, latency);
    EXPECT_EQ(r.max_latency, latency);
    EXPECT_LE(r.cycles, 3 * in.size() + latency + 2 + 201);
    EXPECT_GE(r.cycles, 3 * in.size());
}

TEST(Div, FoldedRandom_52_29_22) {
    auto in = corners(NW_l3, DW_l3, QB_l3);
    auto rnd = randoms(NW_l3, DW_l3, QB_l3, size_t(200000 * tb::scale()), tb::seed(21));
    in.insert(in.end(), rnd.begin(), rnd.end());
    tb::Harness<Top> h;
    auto r = run_l3(h.top.get(), in, 0.25, 0.25, tb::seed(22));
    EXPECT_TRUE(r.ok()) << r.summary();
    std::printf("div 52/29/22 II=3: %s\n", r.summary().c_str());
}

}  // namespace
