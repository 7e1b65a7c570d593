// classify.cpp — the combination tables and the classification program.
// Each table is written row by row as in algorithm.md section 3, so that a
// reader can check it against the paper cell by cell.
#include "classify.h"

#include <atomic>
#include <cstring>

namespace csgrt {

std::string Class::str() const {
    switch (kind) {
    case OUT: return "OUT";
    case IN: return "IN " + std::to_string(to);
    case BORDER: return "BORDER " + std::to_string(from) + "," + std::to_string(to);
    }
    return "?";
}

static inline Class table_add_i(Class l, Class r) {
    if (r.kind == Class::IN) return r;                       // right operand owns
    if (r.kind == Class::OUT) return l;
    // r is BORDER c,d
    if (l.kind == Class::OUT) return r;
    if (l.kind == Class::IN) {
        if (r.from == 0) return Class::border(l.to, r.to);   // c = 0: BORDER l,d
        if (r.to == 0) return Class::border(r.from, l.to);   // d = 0: BORDER c,l
        return r;                                            // BORDER c,d
    }
    return Class::out();                                     // cannot occur
}

static inline Class table_sub_i(Class l, Class r) {
    if (r.kind == Class::IN) return Class::out();
    if (r.kind == Class::OUT) return l;
    // r is BORDER c,d
    if (l.kind == Class::IN) {
        if (r.from == 0) return Class::border(l.to, 0);      // entering the cutter
        if (r.to == 0) return Class::border(0, l.to);        // leaving the cutter
        return Class::out();
    }
    return Class::out();                                     // OUT row; BORDER row cannot occur
}

static inline Class table_and_i(Class l, Class r) {
    if (l.kind == Class::OUT) return Class::out();
    if (r.kind == Class::OUT) return Class::out();
    if (r.kind == Class::IN) return l;                       // IN l, or BORDER a,b
    // r is BORDER c,d
    if (l.kind == Class::IN) {
        if (r.from == 0) return Class::border(0, l.to);
        if (r.to == 0) return Class::border(l.to, 0);
        return l;                                            // IN l
    }
    return Class::out();                                     // cannot occur
}

static inline Class combine_i(Op op, Class l, Class r) {
    switch (op) {
    case Op::ADD: return table_add_i(l, r);
    case Op::SUB: return table_sub_i(l, r);
    case Op::AND: return table_and_i(l, r);
    case Op::LEAF: break;
    }
    return Class::out();
}

// combine() of two steady values (IN or OUT, never BORDER), the only cells
// reset() and set_flag() meet: the tables' IN/OUT rows and columns.
static inline Class combine_steady(Op op, Class l, Class r) {
    switch (op) {
    case Op::ADD: return r.kind == Class::IN ? r : l;
    case Op::SUB: return r.kind == Class::IN ? Class::out() : l;
    case Op::AND: return (l.kind == Class::OUT || r.kind == Class::OUT) ? Class::out() : l;
    case Op::LEAF: break;
    }
    return Class::out();
}

Class table_add(Class l, Class r) { return table_add_i(l, r); }
Class table_sub(Class l, Class r) { return table_sub_i(l, r); }
Class table_and(Class l, Class r) { return table_and_i(l, r); }
Class combine(Op op, Class l, Class r) { return combine_i(op, l, r); }

Class classify(const std::vector<Instr>& program, const uint8_t* flags,
               const uint8_t* leaf_material, int hit_leaf, bool entering) {
    Class stack[kMaxStackDepth];
    int sp = 0;
    for (const Instr& ins : program) {
        if (ins.op == Op::LEAF) {
            const int leaf = ins.arg;
            const uint8_t m = leaf_material[leaf];
            Class c;
            if (leaf == hit_leaf)
                c = entering ? Class::border(0, m) : Class::border(m, 0);
            else
                c = flags[leaf] ? Class::in(m) : Class::out();
            stack[sp++] = c;
        } else {
            const Class r = stack[--sp];
            const Class l = stack[--sp];
            stack[sp++] = combine(ins.op, l, r);
        }
    }
    return sp > 0 ? stack[sp - 1] : Class::out();
}

ClassTree::ClassTree(const std::vector<Instr>& program) {
    static std::atomic<uint64_t> next_id{1};
    shape_id_ = next_id.fetch_add(1);
    std::vector<int> stack;
    for (const Instr& ins : program) {
        Node n;
        n.op = ins.op;
        if (ins.op == Op::LEAF) {
            n.leaf = ins.arg;
            if (int(leaf_node_.size()) <= ins.arg) leaf_node_.resize(ins.arg + 1, -1);
            leaf_node_[ins.arg] = int(nodes_.size());
        } else {
            n.right = stack.back();
            stack.pop_back();
            n.left = stack.back();
            stack.pop_back();
            nodes_[n.left].parent = nodes_[n.right].parent = int(nodes_.size());
        }
        stack.push_back(int(nodes_.size()));
        nodes_.push_back(n);
    }
    root_ = stack.empty() ? -1 : stack.back();
    steady_.resize(nodes_.size());
    material_.resize(leaf_node_.size());
}

void ClassTree::reset(const uint8_t* flags, const uint8_t* leaf_material) {
    for (size_t l = 0; l < material_.size(); ++l) material_[l] = leaf_material[l];
    initialised_ = true;
    // nodes are in post-order: children before parents
    for (size_t i = 0; i < nodes_.size(); ++i) {
        const Node& n = nodes_[i];
        steady_[i] = n.op == Op::LEAF ? leaf_class(n.leaf, flags[n.leaf])
                                      : combine_steady(n.op, steady_[n.left], steady_[n.right]);
    }
}

void ClassTree::update(const uint8_t* flags, const uint8_t* leaf_material) {
    if (!initialised_ || (!material_.empty() && std::memcmp(material_.data(), leaf_material, material_.size()) != 0)) {
        reset(flags, leaf_material);
        return;
    }
    for (size_t l = 0; l < leaf_node_.size(); ++l) {
        if (leaf_node_[l] < 0) continue;
        const bool in = steady_[leaf_node_[l]].kind == Class::IN;
        if (in != bool(flags[l])) set_flag(int(l), flags[l]);
    }
}

Class ClassTree::classify(int hit_leaf, bool entering) const {
    if (root_ < 0) return Class::out();
    const uint8_t m = material_[hit_leaf];
    Class c = entering ? Class::border(0, m) : Class::border(m, 0);
    for (int child = leaf_node_[hit_leaf], p = nodes_[child].parent; p >= 0; child = p, p = nodes_[p].parent) {
        const Node& n = nodes_[p];
        c = (n.left == child) ? combine_i(n.op, c, steady_[n.right]) : combine_i(n.op, steady_[n.left], c);
        // Once the path's value equals the node's steady value, every node
        // above combines exactly the steady values again: the answer is the
        // root's steady value (set_flag and reset keep steady_ exact).
        if (c == steady_[p]) return steady_[root_];
    }
    return c;
}

void ClassTree::set_flag(int leaf, bool in) {
    int i = leaf_node_[leaf];
    steady_[i] = leaf_class(leaf, in);
    for (int p = nodes_[i].parent; p >= 0; p = nodes_[p].parent) {
        const Class v = combine_steady(nodes_[p].op, steady_[nodes_[p].left], steady_[nodes_[p].right]);
        if (v == steady_[p]) break;   // nothing above changes either
        steady_[p] = v;
    }
}

int stack_depth(const std::vector<Instr>& program) {
    int sp = 0, max_sp = 0;
    for (const Instr& ins : program) {
        sp += (ins.op == Op::LEAF) ? 1 : -1;
        if (sp > max_sp) max_sp = sp;
    }
    return max_sp;
}

}  // namespace csgrt
