// classify.h — point classifications and the three combination tables of
// Wyvill & Trotman (algorithm.md section 3), and the post-order program that
// classifies a point against the whole CSG tree by table look-ups.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace csgrt {

// OUT, IN m, or BORDER from,to. Material 0 is air. Fits in 2 + 2*8 bits,
// which is how the RTL carries it.
struct Class {
    enum Kind : uint8_t { OUT = 0, IN = 1, BORDER = 2 };
    Kind kind = OUT;
    uint8_t from = 0;   // BORDER: material the ray leaves
    uint8_t to = 0;     // BORDER: material the ray enters; IN: the material

    static Class out() { return {}; }
    static Class in(uint8_t m) { return {IN, 0, m}; }
    static Class border(uint8_t f, uint8_t t) { return {BORDER, f, t}; }
    bool operator==(const Class& o) const { return kind == o.kind && from == o.from && to == o.to; }
    bool operator!=(const Class& o) const { return !(*this == o); }
    std::string str() const;
};

// One instruction of the post-order classification program. LEAF pushes the
// classification of leaf `arg`; the others pop r, pop l, push table(l, r).
enum class Op : uint8_t { LEAF = 0, ADD = 1, SUB = 2, AND = 3 };
struct Instr {
    Op op;
    uint16_t arg;   // leaf index for LEAF, 0 otherwise
};

// The tables. Cells the paper marks "cannot occur" (both operands BORDER)
// return OUT in model and RTL alike.
Class table_add(Class l, Class r);   // l ++ r, asymmetric addition (r owns)
Class table_sub(Class l, Class r);   // l - r
Class table_and(Class l, Class r);   // l & r = l - (l - r), keeps l's material
Class combine(Op op, Class l, Class r);

// Classify the point of an event on `hit_leaf` against the tree: that leaf
// answers BORDER 0,m (entering) or BORDER m,0 (leaving); every other leaf
// answers from its flag (IN m or OUT). `flags` and `leaf_material` are
// indexed by leaf. The stack never exceeds `max_depth` (checked by the
// compiler, see stack_depth()).
Class classify(const std::vector<Instr>& program, const uint8_t* flags,
               const uint8_t* leaf_material, int hit_leaf, bool entering);

// The same classification, incrementally: the tree behind a program, with
// each node's classification for the current flags ("steady" values, never
// BORDER). Classifying an event then combines the BORDER of its leaf with
// the steady values of the siblings along the path to the root, which is
// exactly what the program computes (every node off that path holds its
// steady value), in depth rather than program-length steps. The model's
// walk uses it for speed; classify_test.cpp checks it against classify().
class ClassTree {
  public:
    ClassTree() = default;
    explicit ClassTree(const std::vector<Instr>& program);
    // Sets every leaf's flag and recomputes all steady values.
    void reset(const uint8_t* flags, const uint8_t* leaf_material);
    // The same state as reset(), reached from the current one by set_flag()
    // on the leaves whose flag differs (a full reset the first time, or when
    // the materials differ).
    void update(const uint8_t* flags, const uint8_t* leaf_material);
    Class classify(int hit_leaf, bool entering) const;
    // Sets one leaf's flag and updates its ancestors.
    void set_flag(int leaf, bool in);
    // Identifies the tree's shape (the program it was built from): copies
    // share it, every tree built from a program gets a new one. A walk that
    // reuses a working tree copies the prototype only when the id differs.
    uint64_t shape_id() const { return shape_id_; }

  private:
    struct Node {
        Op op;
        int left = -1, right = -1, parent = -1;
        int leaf = -1;
    };
    Class leaf_class(int leaf, bool in) const { return in ? Class::in(material_[leaf]) : Class::out(); }
    std::vector<Node> nodes_;
    std::vector<int> leaf_node_;
    std::vector<uint8_t> material_;
    std::vector<Class> steady_;
    int root_ = -1;
    uint64_t shape_id_ = 0;
    bool initialised_ = false;   // reset() has run
};

// Largest stack depth the program reaches.
int stack_depth(const std::vector<Instr>& program);

constexpr int kMaxStackDepth = 32;   // hardware limit of the classifier stack

}  // namespace csgrt
