// classify_test.cpp — every cell of the three combination tables.
//
// Two independent checks: (1) the cells as printed in algorithm.md, written
// out literally; (2) the point-set meaning of a classification: a point is
// classified by the material just before it and just after it along the ray
// (IN m: m,m; OUT: 0,0; BORDER c,d: c,d), and each operator acts on
// materials pointwise (addition: the right operand owns; subtraction: right
// removes; intersection: both present keeps the left). Every cell that can
// occur must equal the operator applied to "before" and "after" separately.
#include "classify.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

using namespace csgrt;

namespace {

const uint8_t L = 1, R = 2, C = 3, D = 4;

struct Sides {
    uint8_t before, after;
};
Sides sides(Class c) {
    switch (c.kind) {
    case Class::OUT: return {0, 0};
    case Class::IN: return {c.to, c.to};
    case Class::BORDER: return {c.from, c.to};
    }
    return {0, 0};
}
uint8_t mat_op(Op op, uint8_t l, uint8_t r) {
    switch (op) {
    case Op::ADD: return r ? r : l;
    case Op::SUB: return r ? 0 : l;
    case Op::AND: return (l && r) ? l : 0;
    default: return 0;
    }
}
Class from_sides(uint8_t b, uint8_t a) {
    if (b == a) return b ? Class::in(b) : Class::out();
    return Class::border(b, a);
}

std::vector<Class> left_values() {
    return {Class::in(L), Class::out(), Class::border(0, L), Class::border(L, 0), Class::border(C, D)};
}
std::vector<Class> right_values() {
    return {Class::in(R), Class::out(), Class::border(0, R), Class::border(R, 0), Class::border(C, D)};
}

}  // namespace

TEST(Tables, EveryCellMatchesPointSetSemantics) {
    int cells = 0;
    for (Op op : {Op::ADD, Op::SUB, Op::AND})
        for (Class l : left_values())
            for (Class r : right_values()) {
                const Class got = combine(op, l, r);
                if (l.kind == Class::BORDER && r.kind == Class::BORDER) {
                    EXPECT_EQ(got, Class::out()) << "cannot-occur cell must be OUT";
                    continue;
                }
                const Sides sl = sides(l), sr = sides(r);
                const Class want = from_sides(mat_op(op, sl.before, sr.before), mat_op(op, sl.after, sr.after));
                EXPECT_EQ(got, want) << "op " << int(op) << " l=" << l.str() << " r=" << r.str()
                                     << " got " << got.str() << " want " << want.str();
                ++cells;
            }
    EXPECT_EQ(cells, 3 * (5 * 5 - 3 * 3));
}

TEST(Tables, AdditionAsPrinted) {
    // rows IN l, OUT, BORDER a,b; columns IN r, OUT, BORDER c,d
    EXPECT_EQ(table_add(Class::in(L), Class::in(R)), Class::in(R));
    EXPECT_EQ(table_add(Class::in(L), Class::out()), Class::in(L));
    EXPECT_EQ(table_add(Class::in(L), Class::border(0, D)), Class::border(L, D));
    EXPECT_EQ(table_add(Class::in(L), Class::border(C, 0)), Class::border(C, L));
    EXPECT_EQ(table_add(Class::in(L), Class::border(C, D)), Class::border(C, D));
    EXPECT_EQ(table_add(Class::out(), Class::in(R)), Class::in(R));
    EXPECT_EQ(table_add(Class::out(), Class::out()), Class::out());
    EXPECT_EQ(table_add(Class::out(), Class::border(C, D)), Class::border(C, D));
    EXPECT_EQ(table_add(Class::border(1, 2), Class::in(R)), Class::in(R));
    EXPECT_EQ(table_add(Class::border(1, 2), Class::out()), Class::border(1, 2));
}

TEST(Tables, SubtractionAsPrinted) {
    EXPECT_EQ(table_sub(Class::in(L), Class::in(R)), Class::out());
    EXPECT_EQ(table_sub(Class::in(L), Class::out()), Class::in(L));
    EXPECT_EQ(table_sub(Class::in(L), Class::border(0, D)), Class::border(L, 0));
    EXPECT_EQ(table_sub(Class::in(L), Class::border(C, 0)), Class::border(0, L));
    EXPECT_EQ(table_sub(Class::in(L), Class::border(C, D)), Class::out());
    EXPECT_EQ(table_sub(Class::out(), Class::in(R)), Class::out());
    EXPECT_EQ(table_sub(Class::out(), Class::out()), Class::out());
    EXPECT_EQ(table_sub(Class::out(), Class::border(C, D)), Class::out());
    EXPECT_EQ(table_sub(Class::border(1, 2), Class::in(R)), Class::out());
    EXPECT_EQ(table_sub(Class::border(1, 2), Class::out()), Class::border(1, 2));
}

TEST(Tables, IntersectionAsPrinted) {
    EXPECT_EQ(table_and(Class::in(L), Class::in(R)), Class::in(L));
    EXPECT_EQ(table_and(Class::in(L), Class::out()), Class::out());
    EXPECT_EQ(table_and(Class::in(L), Class::border(0, D)), Class::border(0, L));
    EXPECT_EQ(table_and(Class::in(L), Class::border(C, 0)), Class::border(L, 0));
    EXPECT_EQ(table_and(Class::in(L), Class::border(C, D)), Class::in(L));
    EXPECT_EQ(table_and(Class::out(), Class::in(R)), Class::out());
    EXPECT_EQ(table_and(Class::out(), Class::out()), Class::out());
    EXPECT_EQ(table_and(Class::out(), Class::border(C, D)), Class::out());
    EXPECT_EQ(table_and(Class::border(1, 2), Class::in(R)), Class::border(1, 2));
    EXPECT_EQ(table_and(Class::border(1, 2), Class::out()), Class::out());
}

TEST(Tables, ProgramClassifiesATree) {
    // (leaf0 - leaf1) ++ leaf2 with materials 1, 2, 3
    const std::vector<Instr> prog = {{Op::LEAF, 0}, {Op::LEAF, 1}, {Op::SUB, 0}, {Op::LEAF, 2}, {Op::ADD, 0}};
    const uint8_t mats[3] = {1, 2, 3};
    uint8_t flags[3] = {1, 0, 0};
    // entering leaf 2 while inside leaf 0 only: border from 1 into 3
    EXPECT_EQ(classify(prog, flags, mats, 2, true), Class::border(1, 3));
    // entering the cutter while inside leaf 0: border 1 -> air
    EXPECT_EQ(classify(prog, flags, mats, 1, true), Class::border(1, 0));
    flags[1] = 1;
    // leaving leaf 0 inside the cutter: nothing visible
    EXPECT_EQ(classify(prog, flags, mats, 0, false), Class::out());
    EXPECT_EQ(stack_depth(prog), 2);
}

TEST(Tables, IncrementalTreeEqualsTheProgram) {
    // random trees, flags and events: ClassTree (the walk's classifier)
    // must give exactly what the post-order program gives
    std::mt19937 rng(5);
    for (int trial = 0; trial < 2000; ++trial) {
        const int leaves = 1 + int(rng() % 12);
        std::vector<Instr> prog;
        int sp = 0, next_leaf = 0;
        while (next_leaf < leaves || sp > 1) {
            if (next_leaf < leaves && (sp < 2 || rng() % 2)) {
                prog.push_back({Op::LEAF, uint16_t(next_leaf++)});
                ++sp;
            } else {
                prog.push_back({Op(1 + rng() % 3), 0});
                --sp;
            }
        }
        std::vector<uint8_t> mats(leaves), flags(leaves);
        for (auto& m : mats) m = uint8_t(1 + rng() % 3);
        for (auto& f : flags) f = rng() % 2;
        ClassTree tree(prog);
        tree.reset(flags.data(), mats.data());
        for (int step = 0; step < 30; ++step) {
            const int leaf = int(rng() % leaves);
            const bool entering = rng() % 2;
            ASSERT_EQ(tree.classify(leaf, entering), classify(prog, flags.data(), mats.data(), leaf, entering));
            flags[leaf] = rng() % 2;
            tree.set_flag(leaf, flags[leaf]);
        }
    }
}
