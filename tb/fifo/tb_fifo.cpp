// tb_fifo.cpp — the queues' contracts (rtl/csgrt_fifo.v, rtl/csgrt_fifo_block.v,
// and the one-word slice rtl/csgrt_hold.v: latency 1, one word, a word per 2 clocks):
// every word comes out once, in order, under random input gaps and random
// output back-pressure (tb::run_stream); the latency from acceptance to
// valid_o is 1 clock for csgrt_fifo, 2 for csgrt_fifo_block and 3 for it with
// HEAD_REG 1, 2 or 3; with the output held off they take DEPTH, DEPTH + 1,
// DEPTH + 2 (HEAD_REG 1, 2) and DEPTH + 3 (HEAD_REG 3, a two-word csgrt_pingpong after the
// read register) words and then refuse; and a full queue drains at one word
// per clock (with HEAD_REG 2 one word per 2 clocks, the price of its
// registered enables). The two-word slices csgrt_skid and csgrt_pingpong
// meet the same contract (latency 1, two words, a word per clock), and
// under one random stream of valid, ready and data they agree on every
// handshake output at every clock, ready_next_o included.
#include "Vtb_fifo.h"
#include "stream.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <random>
#include <vector>

namespace {

using Top = Vtb_fifo;
constexpr int kWidth = 40;   // tb_fifo.v WIDTH
constexpr int kDepth = 8;    // tb_fifo.v DEPTH
constexpr uint64_t kMask = (uint64_t(1) << kWidth) - 1;

struct Dut {
    tb::StreamPorts ports;
    uint64_t* data_i;
    uint64_t* data_o;
    int latency;    // clocks from acceptance to valid_o, the queue empty
    int capacity;   // words taken with the output held off
    int period;     // clocks per word when nothing waits
};

Dut lut(Top* t) {
    return {{&t->clk_i, &t->rst_ni, &t->lut_valid_i, &t->lut_ready_o, &t->lut_valid_o, &t->lut_ready_i},
            &t->lut_data_i, &t->lut_data_o, 1, kDepth, 1};
}
Dut blk(Top* t) {
    return {{&t->clk_i, &t->rst_ni, &t->blk_valid_i, &t->blk_ready_o, &t->blk_valid_o, &t->blk_ready_i},
            &t->blk_data_i, &t->blk_data_o, 2, kDepth + 1, 1};
}
Dut hr1(Top* t) {
    return {{&t->clk_i, &t->rst_ni, &t->hr1_valid_i, &t->hr1_ready_o, &t->hr1_valid_o, &t->hr1_ready_i},
            &t->hr1_data_i, &t->hr1_data_o, 3, kDepth + 2, 1};
}
Dut hr2(Top* t) {
    return {{&t->clk_i, &t->rst_ni, &t->hr2_valid_i, &t->hr2_ready_o, &t->hr2_valid_o, &t->hr2_ready_i},
            &t->hr2_data_i, &t->hr2_data_o, 3, kDepth + 2, 2};
}
Dut hr3(Top* t) {
    return {{&t->clk_i, &t->rst_ni, &t->hr3_valid_i, &t->hr3_ready_o, &t->hr3_valid_o, &t->hr3_ready_i},
            &t->hr3_data_i, &t->hr3_data_o, 3, kDepth + 3, 1};
}

Dut skid(Top* t) {
    return {{&t->clk_i, &t->rst_ni, &t->skid_valid_i, &t->skid_ready_o, &t->skid_valid_o, &t->skid_ready_i},
            &t->skid_data_i, &t->skid_data_o, 1, 2, 1};
}
Dut pp(Top* t) {
    return {{&t->clk_i, &t->rst_ni, &t->pp_valid_i, &t->pp_ready_o, &t->pp_valid_o, &t->pp_ready_i},
            &t->pp_data_i, &t->pp_data_o, 1, 2, 1};
}

Dut hold(Top* t) {
    return {{&t->clk_i, &t->rst_ni, &t->hold_valid_i, &t->hold_ready_o, &t->hold_valid_o, &t->hold_ready_i},
            &t->hold_data_i, &t->hold_data_o, 1, 1, 2};
}

std::vector<uint64_t> words(size_t n, uint64_t s) {
    std::mt19937_64 rng(s);
    std::vector<uint64_t> w(n);
    for (auto& x : w) x = rng() & kMask;
    return w;
}

void tick(Top* t) {
    t->clk_i = 1;
    t->eval();
    t->clk_i = 0;
    t->eval();
}
void reset(Top* t) {
    t->lut_valid_i = t->blk_valid_i = t->hr1_valid_i = t->hr2_valid_i = t->hr3_valid_i = t->hold_valid_i = 0;
    t->lut_ready_i = t->blk_ready_i = t->hr1_ready_i = t->hr2_ready_i = t->hr3_ready_i = t->hold_ready_i = 0;
    t->skid_valid_i = t->pp_valid_i = t->skid_ready_i = t->pp_ready_i = 0;
    t->clk_i = 0;
    t->rst_ni = 0;
    t->eval();
    for (int i = 0; i < 4; ++i) tick(t);
    t->rst_ni = 1;
    t->eval();
}

void stream(Dut (*pick)(Top*), const char* name) {
    const size_t n = size_t(20000 * tb::scale()) + 100;
    const std::vector<uint64_t> w = words(n, tb::seed(7));
    struct Mix { double gap, stall; };
    for (const Mix m : {Mix{0.0, 0.0}, Mix{0.5, 0.0}, Mix{0.0, 0.5}, Mix{0.3, 0.7}, Mix{0.8, 0.2}}) {
        tb::Harness<Top> h;
        Top* t = h.top.get();
        const Dut d = pick(t);
        const tb::StreamResult r = tb::run_stream(
            t, d.ports, n, [&](size_t i) { *d.data_i = w[i]; },
            [&](size_t i) -> std::string {
                if ((*d.data_o & kMask) == w[i]) return "";
                return "got " + std::to_string(*d.data_o & kMask) + ", want " + std::to_string(w[i]);
            },
            m.gap, m.stall, tb::seed(11));
        std::printf("[ fifo     ] %-17s gap %.1f stall %.1f: %s\n", name, m.gap, m.stall, r.summary().c_str());
        EXPECT_TRUE(r.ok()) << r.summary();
        EXPECT_EQ(r.received, n);
        // never earlier than the latency; exactly it when nothing holds the output
        EXPECT_GE(r.min_latency, d.latency) << name;
        // (a queue slower than its input fills up: then a word waits for
        // the words ahead of it, at most a full queue's worth)
        if (m.stall == 0.0 && d.period == 1) EXPECT_EQ(r.max_latency, d.latency) << name;
        if (m.stall == 0.0) EXPECT_LE(r.max_latency, d.latency + d.capacity * d.period) << name;
        if (m.gap == 0.0 && m.stall == 0.0) {
            // no gaps, no back-pressure: a word per `period` clocks after the first
            EXPECT_LE(r.cycles, n * d.period + d.latency + 201) << name;
            EXPECT_GT(r.cycles, n * d.period - 1) << name << ": faster than its period";
        }
    }
}

TEST(Fifo, LutRamStreamsInOrder) { stream(lut, "csgrt_fifo"); }
TEST(Fifo, BlockRamStreamsInOrder) { stream(blk, "csgrt_fifo_block"); }
TEST(Fifo, BlockRamHeadReg1StreamsInOrder) { stream(hr1, "fifo_block HR 1"); }
TEST(Fifo, BlockRamHeadReg2StreamsInOrder) { stream(hr2, "fifo_block HR 2"); }
TEST(Fifo, BlockRamHeadReg3StreamsInOrder) { stream(hr3, "fifo_block HR 3"); }
TEST(Fifo, HoldStreamsInOrder) { stream(hold, "csgrt_hold"); }
TEST(Fifo, SkidStreamsInOrder) { stream(skid, "csgrt_skid"); }
TEST(Fifo, PingpongStreamsInOrder) { stream(pp, "csgrt_pingpong"); }

// With ready_i low the queue takes exactly its capacity, then refuses; then
// it gives the words back in order at one per clock.
void fill_and_drain(Dut (*pick)(Top*), const char* name) {
    tb::Harness<Top> h;
    Top* t = h.top.get();
    const Dut d = pick(t);
    reset(t);
    const std::vector<uint64_t> w = words(64, 3);
    int taken = 0;
    for (int c = 0; c < 40; ++c) {
        *d.ports.valid_i = 1;
        *d.data_i = w[taken];
        t->eval();
        if (*d.ports.ready_o) ++taken;
        tick(t);
    }
    *d.ports.valid_i = 0;
    t->eval();
    EXPECT_EQ(taken, d.capacity) << name;
    EXPECT_FALSE(*d.ports.ready_o) << name << ": full, yet ready";
    EXPECT_TRUE(*d.ports.valid_o) << name;
    *d.ports.ready_i = 1;
    int got = 0, clocks = 0;
    for (; got < taken && clocks < taken * d.period; ++clocks) {
        t->eval();
        if (*d.ports.valid_o) {
            EXPECT_EQ(*d.data_o & kMask, w[got]) << name << " word " << got;
            ++got;
        } else {
            // a gap only where the period allows one: never two in a row
            EXPECT_TRUE(d.period > 1 && clocks > 0) << name << ": a gap while draining, word " << got;
        }
        tick(t);
    }
    EXPECT_EQ(got, taken) << name << ": drained too slowly";
    t->eval();
    EXPECT_FALSE(*d.ports.valid_o) << name << ": a word more than was put in";
    std::printf("[ fifo     ] %-17s took %d words with the output held off, drained them in %d clocks\n", name,
                taken, clocks);
}

TEST(Fifo, LutRamCapacity) { fill_and_drain(lut, "csgrt_fifo"); }
TEST(Fifo, BlockRamCapacity) { fill_and_drain(blk, "csgrt_fifo_block"); }
TEST(Fifo, BlockRamHeadReg1Capacity) { fill_and_drain(hr1, "fifo_block HR 1"); }
TEST(Fifo, BlockRamHeadReg2Capacity) { fill_and_drain(hr2, "fifo_block HR 2"); }
TEST(Fifo, BlockRamHeadReg3Capacity) { fill_and_drain(hr3, "fifo_block HR 3"); }
TEST(Fifo, HoldCapacity) { fill_and_drain(hold, "csgrt_hold"); }
TEST(Fifo, SkidCapacity) { fill_and_drain(skid, "csgrt_skid"); }
TEST(Fifo, PingpongCapacity) { fill_and_drain(pp, "csgrt_pingpong"); }

// csgrt_pingpong replaces csgrt_skid where the consumer's ready comes late:
// the two must be interchangeable, so both get the same valid_i, data_i and
// ready_i at every clock (the producer offering words as a valid/ready
// source does: a word stays offered until taken), with resets now and then,
// and every output must agree.
TEST(Fifo, PingpongBehavesAsSkid) {
    tb::Harness<Top> h;
    Top* t = h.top.get();
    reset(t);
    std::mt19937_64 rng(tb::seed(23));
    const long clocks = long(200000 * tb::scale()) + 1000;
    bool offered = false;
    uint64_t word = 0;
    long moved = 0;
    for (long c = 0; c < clocks; ++c) {
        const bool in_reset = (rng() % 5000) == 0;
        t->rst_ni = !in_reset;
        if (!offered && rng() % 4 != 0) {
            offered = true;
            word = rng() & kMask;
        }
        t->skid_valid_i = t->pp_valid_i = offered;
        t->skid_data_i = t->pp_data_i = word;
        t->skid_ready_i = t->pp_ready_i = (rng() % 3 != 0);
        t->eval();
        ASSERT_EQ(t->skid_ready_o, t->pp_ready_o) << "clock " << c;
        ASSERT_EQ(t->skid_ready_next_o, t->pp_ready_next_o) << "clock " << c;
        ASSERT_EQ(t->skid_valid_o, t->pp_valid_o) << "clock " << c;
        if (t->skid_valid_o) ASSERT_EQ(t->skid_data_o & kMask, t->pp_data_o & kMask) << "clock " << c;
        if (!in_reset && offered && t->skid_ready_o) offered = false;
        if (!in_reset && t->skid_valid_o && t->skid_ready_i) ++moved;
        tick(t);
    }
    // the stream moved (neither side stuck at empty or full)
    EXPECT_GT(moved, clocks / 3);
    std::printf("[ fifo     ] csgrt_pingpong and csgrt_skid agreed for %ld clocks, %ld words\n", clocks, moved);
}

}  // namespace
