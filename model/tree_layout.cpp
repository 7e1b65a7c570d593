// tree_layout.cpp — balancing and layout of the classification tree.
#include "tree_layout.h"

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <stdexcept>

namespace csgrt {

namespace {

struct TNode {
    Op op;
    int leaf = -1;
    int l = -1, r = -1;
};

struct Tree {
    std::vector<TNode> n;
    int root = -1;

    explicit Tree(const std::vector<Instr>& program) {
        std::vector<int> st;
        for (const Instr& ins : program) {
            TNode t;
            t.op = ins.op;
            if (ins.op == Op::LEAF) {
                t.leaf = ins.arg;
            } else {
                t.r = st.back();
                st.pop_back();
                t.l = st.back();
                st.pop_back();
            }
            st.push_back(int(n.size()));
            n.push_back(t);
        }
        root = st.empty() ? -1 : st.back();
    }
    int add(Op op, int l, int r) {
        n.push_back({op, -1, l, r});
        return int(n.size()) - 1;
    }
    int height(int i) const { return n[i].op == Op::LEAF ? 0 : 1 + std::max(height(n[i].l), height(n[i].r)); }
    void emit(int i, std::vector<Instr>& out) const {
        if (n[i].op == Op::LEAF) {
            out.push_back({Op::LEAF, uint16_t(n[i].leaf)});
            return;
        }
        emit(n[i].l, out);
        emit(n[i].r, out);
        out.push_back({n[i].op, 0});
    }
};

// Operands of a maximal chain of one associative operator, in order.
void chain(const Tree& t, int i, Op op, std::vector<int>& out) {
    if (t.n[i].op == op) {
        chain(t, t.n[i].l, op, out);
        chain(t, t.n[i].r, op, out);
    } else {
        out.push_back(i);
    }
}

// An order-preserving tree of minimal height over operands of the given
// heights: interval dynamic programming for short chains, halving for long
// ones.
int build_chain(Tree& t, Op op, const std::vector<int>& ops) {
    const int n = int(ops.size());
    if (n == 1) return ops[0];
    if (n > 48) {
        const std::vector<int> left(ops.begin(), ops.begin() + n / 2), right(ops.begin() + n / 2, ops.end());
        const int l = build_chain(t, op, left);
        const int r = build_chain(t, op, right);
        return t.add(op, l, r);
    }
    std::vector<std::vector<int>> H(n, std::vector<int>(n, 0)), split(n, std::vector<int>(n, -1));
    for (int i = 0; i < n; ++i) H[i][i] = t.height(ops[i]);
    for (int len = 2; len <= n; ++len)
        for (int i = 0; i + len - 1 < n; ++i) {
            const int j = i + len - 1;
            H[i][j] = 1 << 30;
            // the lowest split height; among equals the one nearest the middle
            const int mid2 = i + j - 1;   // twice the middle split
            for (int k = i; k < j; ++k) {
                const int h = 1 + std::max(H[i][k], H[k + 1][j]);
                const bool nearer = split[i][j] < 0 || std::abs(2 * k - mid2) < std::abs(2 * split[i][j] - mid2);
                if (h < H[i][j] || (h == H[i][j] && nearer)) H[i][j] = h, split[i][j] = k;
            }
        }
    std::function<int(int, int)> make = [&](int i, int j) -> int {
        if (i == j) return ops[i];
        const int k = split[i][j];
        const int l = make(i, k);
        const int r = make(k + 1, j);
        return t.add(op, l, r);
    };
    return make(0, n - 1);
}

// Balances every original node once (the SUB rule looks at a node's
// operands twice, so results are memoised).
struct Balancer {
    Tree& t;
    std::vector<int> memo;
    explicit Balancer(Tree& tree) : t(tree), memo(tree.n.size(), -1) {}

    int run(int i) {
        if (i < int(memo.size())) {
            if (memo[i] < 0) memo[i] = balance_node(i);
            return memo[i];
        }
        return balance_node(i);
    }

    int balance_node(int i) {
        const Op op = t.n[i].op;
        if (op == Op::LEAF) return i;
        if (op == Op::ADD || op == Op::AND) {
            std::vector<int> ops;
            chain(t, i, op, ops);
            for (int& o : ops) o = run(o);
            return build_chain(t, op, ops);
        }
        // SUB: ((a - b1) - b2) - ... = a - (b1 ++ b2 ++ ...); a cutter that is
        // itself a union contributes its operands.
        std::vector<int> cutters;
        int base = i;
        while (t.n[base].op == Op::SUB) {
            std::vector<int> c;
            chain(t, t.n[base].r, Op::ADD, c);
            cutters.insert(cutters.begin(), c.begin(), c.end());
            base = t.n[base].l;
        }
        const int a = run(base);
        for (int& c : cutters) c = run(c);
        const int grouped = t.add(Op::SUB, a, build_chain(t, Op::ADD, cutters));
        // A tall late cutter is better left where it was: keep this node's own
        // shape (with balanced operands) when grouping would not be shorter, so
        // that balancing never makes a tree taller.
        const int kept = t.add(Op::SUB, run(t.n[i].l), run(t.n[i].r));
        return t.height(grouped) < t.height(kept) ? grouped : kept;
    }
};

}  // namespace

std::vector<Instr> balance_program(const std::vector<Instr>& program) {
    if (program.empty()) return program;
    Tree t(program);
    const int root = Balancer(t).run(t.root);
    std::vector<Instr> out;
    t.emit(root, out);
    return out;
}

int tree_height(const std::vector<Instr>& program) {
    if (program.empty()) return 0;
    const Tree t(program);
    return t.height(t.root);
}

TreeLayout layout_tree(const std::vector<Instr>& program, int height, int num_leaves) {
    TreeLayout lay;
    lay.height = height;
    lay.node_op.assign(size_t(1) << height, LayoutOp::PASS);
    lay.leaf_slot.assign(num_leaves, -1);
    if (program.empty()) return lay;
    const Tree t(program);
    const int h = t.height(t.root);
    if (h > height)
        throw std::runtime_error("the CSG tree has height " + std::to_string(h) +
                                 " after balancing, more than the hardware's classification tree (TREE_HEIGHT = " +
                                 std::to_string(height) + ")");
    // place node i with its root at heap position pos on level lvl
    std::function<void(int, int, int)> place = [&](int i, int pos, int lvl) {
        if (lvl == 0) {
            lay.leaf_slot[t.n[i].leaf] = pos - (1 << height);
            return;
        }
        if (t.n[i].op == Op::LEAF || t.height(i) < lvl) {
            lay.node_op[pos] = LayoutOp::PASS;
            place(i, 2 * pos, lvl - 1);
            return;
        }
        lay.node_op[pos] = LayoutOp(uint8_t(t.n[i].op));   // ADD/SUB/AND share codes 1..3
        place(t.n[i].l, 2 * pos, lvl - 1);
        place(t.n[i].r, 2 * pos + 1, lvl - 1);
    };
    place(t.root, 1, height);
    return lay;
}

Class classify_layout(const TreeLayout& lay, const uint8_t* flags, const uint8_t* leaf_material, int num_leaves,
                      int hit_leaf, bool entering) {
    const int slots = 1 << lay.height;
    std::vector<Class> level(slots, Class::out());   // empty slots are OUT
    for (int l = 0; l < num_leaves; ++l) {
        const uint8_t m = leaf_material[l];
        Class c = flags[l] ? Class::in(m) : Class::out();
        if (l == hit_leaf) c = entering ? Class::border(0, m) : Class::border(m, 0);
        level[lay.leaf_slot[l]] = c;
    }
    for (int lvl = 1; lvl <= lay.height; ++lvl) {
        const int first = slots >> lvl;   // heap index of the first node on this level
        std::vector<Class> up(first);
        for (int k = 0; k < first; ++k) {
            const LayoutOp op = lay.node_op[first + k];
            up[k] = op == LayoutOp::PASS ? level[2 * k] : combine(Op(uint8_t(op)), level[2 * k], level[2 * k + 1]);
        }
        level.swap(up);
    }
    return level[0];
}

}  // namespace csgrt
