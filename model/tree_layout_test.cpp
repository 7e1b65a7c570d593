// tree_layout_test.cpp — balancing keeps the meaning of the tree; the layout
// classifies exactly like the program.
#include "compile.h"
#include "parse.h"
#include "tree_layout.h"

#include <gtest/gtest.h>

#include <random>

using namespace csgrt;

namespace {

std::vector<Instr> random_program(std::mt19937& rng, int leaves) {
    std::vector<Instr> prog;
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

// What the walk makes of a classification: a hit with its border, or none.
bool same_outcome(Class a, Class b) {
    const bool hit_a = a.kind == Class::BORDER && a.from != a.to;
    const bool hit_b = b.kind == Class::BORDER && b.from != b.to;
    return hit_a == hit_b && (!hit_a || a == b);
}

}  // namespace

TEST(TreeLayout, BalancingKeepsEveryOutcome) {
    std::mt19937 rng(21);
    for (int trial = 0; trial < 3000; ++trial) {
        const int leaves = 1 + int(rng() % 24);
        const std::vector<Instr> prog = random_program(rng, leaves);
        const std::vector<Instr> bal = balance_program(prog);
        ASSERT_LE(tree_height(bal), tree_height(prog));
        std::vector<uint8_t> mats(leaves), flags(leaves);
        for (int step = 0; step < 40; ++step) {
            for (auto& m : mats) m = uint8_t(1 + rng() % 3);
            for (auto& f : flags) f = rng() % 2;
            const int leaf = int(rng() % leaves);
            const bool entering = rng() % 2;
            const Class a = classify(prog, flags.data(), mats.data(), leaf, entering);
            const Class b = classify(bal, flags.data(), mats.data(), leaf, entering);
            ASSERT_TRUE(same_outcome(a, b)) << a.str() << " vs " << b.str();
        }
    }
}

TEST(TreeLayout, BalancingMakesLongChainsShallow) {
    std::vector<Instr> chain = {{Op::LEAF, 0}};
    for (int i = 1; i < 64; ++i) {
        chain.push_back({Op::LEAF, uint16_t(i)});
        chain.push_back({i % 2 ? Op::ADD : Op::ADD, 0});
    }
    EXPECT_EQ(tree_height(chain), 63);
    EXPECT_EQ(tree_height(balance_program(chain)), 6);
    // a - b - c - d - e: a - (b ++ c ++ d ++ e)
    std::vector<Instr> sub = {{Op::LEAF, 0}};
    for (int i = 1; i < 5; ++i) sub.push_back({Op::LEAF, uint16_t(i)}), sub.push_back({Op::SUB, 0});
    EXPECT_EQ(tree_height(balance_program(sub)), 3);
}

TEST(TreeLayout, LayoutClassifiesLikeTheProgram) {
    std::mt19937 rng(22);
    for (int trial = 0; trial < 2000; ++trial) {
        const int leaves = 1 + int(rng() % 20);
        const std::vector<Instr> prog = balance_program(random_program(rng, leaves));
        const int h = tree_height(prog) + int(rng() % 3);
        const TreeLayout lay = layout_tree(prog, h, leaves);
        // slots keep leaf order
        for (int l = 1; l < leaves; ++l) ASSERT_LT(lay.leaf_slot[l - 1], lay.leaf_slot[l]);
        std::vector<uint8_t> mats(leaves), flags(leaves);
        for (int step = 0; step < 20; ++step) {
            for (auto& m : mats) m = uint8_t(1 + rng() % 3);
            for (auto& f : flags) f = rng() % 2;
            const int leaf = int(rng() % leaves);
            const bool entering = rng() % 2;
            ASSERT_EQ(classify_layout(lay, flags.data(), mats.data(), leaves, leaf, entering),
                      classify(prog, flags.data(), mats.data(), leaf, entering));
        }
    }
}

TEST(TreeLayout, TooTallATreeIsAClearError) {
    const Scene s = parse_scene_string(
        "camera { location <0,0,-5> look_at 0 }\n"
        "union { sphere { 0, 1 } difference { box { -1, 1 } intersection { sphere { 0, 1.2 } "
        "cylinder { -2*x, 2*x, 0.5 } } } }\n",
        "tall.pov");
    CompileOptions o;
    o.tree_height = 3;
    try {
        compile_scene(s, o);
        FAIL() << "expected an error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("TREE_HEIGHT = 3"), std::string::npos) << e.what();
    }
    o.tree_height = 8;
    EXPECT_NO_THROW(compile_scene(s, o));
    o.max_leaves = 8;
    try {
        compile_scene(s, o);
        FAIL() << "expected an error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("MAX_LEAVES = 8"), std::string::npos) << e.what();
    }
}
