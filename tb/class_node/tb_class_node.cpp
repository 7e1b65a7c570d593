// tb_class_node.cpp — csgrt_class_node against combine() (model/classify.cpp):
// every operator (PASS = the left child) over every pair of a representative
// set of classifications: OUT, IN m and BORDER a,b with m, a, b in
// {0, 1, 2, 255} (21 classes, 1764 cases), then random materials.
#include "Vtb_class_node.h"
#include "classify.h"
#include "stream.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace {

using csgrt::Class;

uint32_t pack(const Class& c) { return (uint32_t(c.kind) << 16) | (uint32_t(c.from) << 8) | c.to; }
Class unpack(uint32_t v) { return {Class::Kind((v >> 16) & 3), uint8_t(v >> 8), uint8_t(v)}; }

Class expect(int op, const Class& l, const Class& r) {
    return op == 0 ? l : csgrt::combine(csgrt::Op(op), l, r);
}

struct Checker {
    tb::Harness<Vtb_class_node> h;
    uint64_t checked = 0, failed = 0;
    void check(int op, const Class& l, const Class& r) {
        Vtb_class_node* t = h.top.get();
        t->op_i = uint8_t(op);
        t->l_i = pack(l);
        t->r_i = pack(r);
        t->eval();
        const Class want = expect(op, l, r);
        ++checked;
        if (t->c_o != pack(want)) {
            ++failed;
            ADD_FAILURE() << "op " << op << " l " << l.str() << " r " << r.str() << ": DUT " << unpack(t->c_o).str()
                          << " (0x" << std::hex << t->c_o << std::dec << "), model " << want.str();
        }
    }
};

std::vector<Class> representative() {
    const uint8_t mats[] = {0, 1, 2, 255};
    std::vector<Class> v{Class::out()};
    for (uint8_t m : mats) v.push_back(Class::in(m));
    for (uint8_t a : mats)
        for (uint8_t b : mats) v.push_back(Class::border(a, b));
    return v;
}

TEST(ClassNode, AllOpsRepresentativeClasses) {
    Checker c;
    const std::vector<Class> cls = representative();
    for (int op = 0; op < 4; ++op)
        for (const Class& l : cls)
            for (const Class& r : cls) c.check(op, l, r);
    EXPECT_EQ(c.failed, 0u);
    std::printf("class_node: %llu cases (4 ops x %zu x %zu classes), %llu mismatches\n",
                (unsigned long long)c.checked, cls.size(), cls.size(), (unsigned long long)c.failed);
}

TEST(ClassNode, RandomMaterials) {
    Checker c;
    std::mt19937_64 rng(tb::seed(7));
    auto rnd = [&]() -> Class {
        const uint8_t a = uint8_t(rng() % 4 == 0 ? 0 : rng()), b = uint8_t(rng() % 4 == 0 ? 0 : rng());
        switch (rng() % 3) {
            case 0: return Class::out();
            case 1: return Class::in(b);
            default: return Class::border(rng() % 8 == 0 ? b : a, b);
        }
    };
    for (int i = 0; i < 100000; ++i) c.check(int(rng() % 4), rnd(), rnd());
    EXPECT_EQ(c.failed, 0u);
    std::printf("class_node random: %llu cases, %llu mismatches\n", (unsigned long long)c.checked,
                (unsigned long long)c.failed);
}

}  // namespace
