// tb_class_tree.cpp — csgrt_class_tree against classify_layout() and
// classify() (model/tree_layout.cpp, model/classify.cpp).
//
// Per configuration: a random post-order program (random_program below, as in
// tree_layout_test.cpp, plus long ADD / AND / SUB chains that balancing
// reshapes), balanced with balance_program() and laid out with layout_tree()
// on the tree's height; random materials (a small set, so BORDER x,x occurs,
// and 1..255); then a stream of events with random flags, event leaf and
// direction (on flags_i, or on flags_alt_i with alt_i and junk on the other),
// random input gaps and stalls (ce low). Each output must equal
// classify_layout() bit for bit, classify() of the balanced program bit for
// bit, and classify() of the original program up to BORDER x,x vs IN x (the
// walk's outcome). Latency must be exactly TREE_HEIGHT + 1 enabled clocks
// (stage 0, the reads by the slot, then one stage per height).
#include "Vtb_class_tree.h"
#include "classify.h"
#include "stream.h"
#include "tree_layout.h"

#include <gtest/gtest.h>

#include <deque>
#include <random>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace {

using namespace csgrt;
using Top = Vtb_class_tree;

std::vector<Instr> random_program(std::mt19937_64& rng, int leaves) {
    std::vector<Instr> prog;
    const int style = int(rng() % 4);   // 0: random, 1..3: a long chain of ADD/AND/SUB
    if (style > 0) {
        const Op op = Op(style);
        prog.push_back({Op::LEAF, 0});
        for (int i = 1; i < leaves; ++i) {
            prog.push_back({Op::LEAF, uint16_t(i)});
            prog.push_back({rng() % 5 == 0 ? Op(1 + rng() % 3) : op, 0});
        }
        return prog;
    }
    int sp = 0, next_leaf = 0;
    while (next_leaf < leaves || sp > 1) {
        if (next_leaf < leaves && (sp < 2 || rng() % 3 != 0)) {
            prog.push_back({Op::LEAF, uint16_t(next_leaf++)});
            ++sp;
        } else {
            prog.push_back({Op(1 + rng() % 3), 0});
            --sp;
        }
    }
    return prog;
}

bool same_outcome(Class a, Class b) {
    const bool hit_a = a.kind == Class::BORDER && a.from != a.to;
    const bool hit_b = b.kind == Class::BORDER && b.from != b.to;
    return hit_a == hit_b && (!hit_a || a == b);
}

uint32_t pack(const Class& c) { return (uint32_t(c.kind) << 16) | (uint32_t(c.from) << 8) | c.to; }
Class unpack(uint32_t v) { return {Class::Kind((v >> 16) & 3), uint8_t(v >> 8), uint8_t(v)}; }

// Port access for the instance of height H.
#define TREE_PORTS(H)                                                                        \
    struct P##H {                                                                            \
        static constexpr int kH = H;                                                         \
        Top* t;                                                                              \
        uint8_t& clk() { return t->h##H##_clk_i; }                                           \
        uint8_t& rst() { return t->h##H##_rst_ni; }                                          \
        uint8_t& ce() { return t->h##H##_ce_i; }                                             \
        uint8_t& valid() { return t->h##H##_valid_i; }                                       \
        uint8_t& entering() { return t->h##H##_entering_i; }                                 \
        void set_slot(int s) { t->h##H##_slot_i = s; }                                       \
        void set_tag(int g) { t->h##H##_tag_i = uint16_t(g); }                               \
        template <class F> void cfg(F f) { f(t->h##H##_node_op_i, t->h##H##_slot_mat_i, t->h##H##_slot_used_i); } \
        template <class F> void flags(F f) { f(t->h##H##_flags_i, t->h##H##_flags_alt_i); }  \
        uint8_t& alt() { return t->h##H##_alt_i; }                                           \
        bool out_valid() { return t->h##H##_valid_o; }                                       \
        uint32_t out_class() { return t->h##H##_class_o; }                                   \
        bool out_border() { return t->h##H##_border_o; }                                    \
        int out_tag() { return t->h##H##_tag_o; }                                           \
    };
TREE_PORTS(8)
TREE_PORTS(3)
TREE_PORTS(2)
TREE_PORTS(1)

template <class W>
void put(W& w, int lsb, int width, uint64_t v) {
    if constexpr (std::is_integral<W>::value)
        w = W((uint64_t(w) & ~(tb::mask(width) << lsb)) | ((v & tb::mask(width)) << lsb));
    else
        tb::set_bits(w, lsb, width, v);
}

template <class P>
void run(int configs, int events_per_config, uint64_t seed) {
    constexpr int H = P::kH, NS = 1 << H;
    tb::Harness<Top> h;
    P p{h.top.get()};
    std::mt19937_64 rng(seed);
    auto tick = [&] {
        p.clk() = 1;
        h.top->eval();
        p.clk() = 0;
        h.top->eval();
    };
    p.rst() = 0;
    p.ce() = 1;
    p.valid() = 0;
    for (int i = 0; i < 3; ++i) tick();
    p.rst() = 1;
    uint64_t checked = 0, mismatches = 0, hits = 0, border_same = 0, skipped = 0;
    int max_lat = 0, min_lat = 1 << 30;
    for (int c = 0; c < configs; ++c) {
        const int max_leaves = std::min(64, NS);
        const int leaves = 1 + int(rng() % max_leaves);
        const std::vector<Instr> prog = random_program(rng, leaves);
        const std::vector<Instr> bal = balance_program(prog);
        TreeLayout lay;
        try {
            lay = layout_tree(bal, H, leaves);
        } catch (const std::runtime_error&) {
            ++skipped;
            continue;
        }
        std::vector<uint8_t> mats(leaves);
        const bool few = rng() % 2;
        for (auto& m : mats) m = uint8_t(few ? 1 + rng() % 3 : 1 + rng() % 255);
        p.cfg([&](auto& ops, auto& smat, auto& used) {
            for (int i = 0; i < NS; ++i) put(ops, 2 * i, 2, uint64_t(lay.node_op[i]));
            for (int s = 0; s < NS; ++s) {
                put(smat, 8 * s, 8, rng() & 0xff);   // empty slots: junk material
                put(used, s, 1, 0);
            }
            for (int l = 0; l < leaves; ++l) {
                put(smat, 8 * lay.leaf_slot[l], 8, mats[l]);
                put(used, lay.leaf_slot[l], 1, 1);
            }
        });
        // the configuration's clock of notice (csgrt_class_tree's header)
        p.ce() = 1;
        p.valid() = 0;
        tick();
        struct Want {
            Class c;
            uint64_t cyc;
            std::string what;
        };
        std::deque<Want> want;
        uint64_t enabled = 0;
        int sent = 0;
        while (sent < events_per_config || !want.empty()) {
            const bool ce = rng() % 8 != 0;
            const bool send = ce && sent < events_per_config && rng() % 4 != 0;
            p.ce() = ce;
            p.valid() = send;
            std::vector<uint8_t> flags(leaves);
            if (send) {
                for (auto& f : flags) f = rng() % 2;
                const int leaf = int(rng() % leaves);
                const bool ent = rng() % 2;
                // the event's flags on flags_alt_i with alt_i, else on
                // flags_i; junk on the other and in empty slots
                const bool alt = rng() % 2;
                p.alt() = alt;
                p.flags([&](auto& main, auto& other) {
                    auto& w = alt ? other : main;
                    auto& junk = alt ? main : other;
                    for (int s = 0; s < NS; ++s) {
                        put(w, s, 1, rng() & 1);
                        put(junk, s, 1, rng() & 1);
                    }
                    for (int l = 0; l < leaves; ++l) put(w, lay.leaf_slot[l], 1, flags[l]);
                });
                p.set_slot(lay.leaf_slot[leaf]);
                p.entering() = ent;
                p.set_tag(sent);
                const Class a = classify_layout(lay, flags.data(), mats.data(), leaves, leaf, ent);
                const Class b = classify(bal, flags.data(), mats.data(), leaf, ent);
                const Class o = classify(prog, flags.data(), mats.data(), leaf, ent);
                EXPECT_EQ(a, b) << "model: classify_layout vs classify(balanced)";
                EXPECT_TRUE(same_outcome(a, o)) << "model: balanced vs original " << a.str() << " " << o.str();
                if (a.kind == Class::BORDER && a.from != a.to) ++hits;
                if (a.kind == Class::BORDER && a.from == a.to) ++border_same;
                want.push_back({a, enabled, "config " + std::to_string(c) + " leaves " + std::to_string(leaves) +
                                                " event leaf " + std::to_string(leaf) + (ent ? " entering" : " leaving")});
                ++sent;
            }
            h.top->eval();
            if (ce && p.out_valid()) {
                if (want.empty()) {
                    ++mismatches;
                    ADD_FAILURE() << "H=" << H << ": extra output";
                } else {
                    const Want& w = want.front();
                    const int lat = int(enabled - w.cyc);
                    max_lat = std::max(max_lat, lat);
                    min_lat = std::min(min_lat, lat);
                    ++checked;
                    const bool crossing = w.c.kind == Class::BORDER && w.c.from != w.c.to;
                    if (p.out_class() != pack(w.c) || p.out_border() != crossing ||
                        p.out_tag() != int((sent - int(want.size())) & 0xffff)) {
                        if (++mismatches < 10)
                            ADD_FAILURE() << "H=" << H << " " << w.what << ": DUT " << unpack(p.out_class()).str()
                                          << " border " << p.out_border() << " tag " << p.out_tag()
                                          << ", model " << w.c.str();
                    }
                    want.pop_front();
                }
            }
            tick();
            if (ce) ++enabled;
        }
    }
    EXPECT_EQ(mismatches, 0u);
    EXPECT_EQ(min_lat, H + 1);
    EXPECT_EQ(max_lat, H + 1);
    std::printf("class_tree H=%d: %llu events compared (%llu hits, %llu BORDER x,x), %llu mismatches, latency %d..%d, "
                "%llu configs too tall skipped\n",
                H, (unsigned long long)checked, (unsigned long long)hits, (unsigned long long)border_same,
                (unsigned long long)mismatches, min_lat, max_lat, (unsigned long long)skipped);
}

int scaled(int n) { return std::max(10, int(n * tb::scale())); }

TEST(ClassTree, Height8) { run<P8>(scaled(300), 200, tb::seed(81)); }
TEST(ClassTree, Height3) { run<P3>(scaled(2000), 50, tb::seed(31)); }
// the path's edge cases: one inner height, the root alone
TEST(ClassTree, Height2) { run<P2>(scaled(1000), 50, tb::seed(21)); }
TEST(ClassTree, Height1) { run<P1>(scaled(500), 50, tb::seed(11)); }

}  // namespace
