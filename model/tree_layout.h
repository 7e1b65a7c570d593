// tree_layout.h — reshaping the CSG tree for hardware: balancing associative
// chains (so the tree is shallow) and laying the tree out on a complete
// binary tree, one level per pipeline stage of the RTL's classifier.
#pragma once

#include "classify.h"

#include <string>
#include <vector>

namespace csgrt {

// Re-associates chains without changing leaf order or meaning:
//   a ++ b ++ c ++ ...   and  a & b & c & ...   into balanced trees,
//   ((a - b) - c) - ...  into a - (b ++ c ++ ...), the cutters balanced.
// Classification results are the same up to BORDER x,x versus IN x, which
// the walk treats alike (neither is a hit); tree_layout_test.cpp checks it.
std::vector<Instr> balance_program(const std::vector<Instr>& program);

// Height of the tree (a single leaf has height 0).
int tree_height(const std::vector<Instr>& program);

// The tree on a complete binary tree of the given height: node_op[i] for
// heap positions i = 1 .. 2^height - 1 (root 1, children 2i and 2i+1; index
// 0 unused), and leaf_slot[leaf] in 0 .. 2^height - 1 (slot s sits under
// position 2^height + s). A node whose subtree is shallower than its level
// becomes PASS nodes that forward their left child.
enum class LayoutOp : uint8_t { PASS = 0, ADD = 1, SUB = 2, AND = 3 };
struct TreeLayout {
    int height = 0;
    std::vector<LayoutOp> node_op;
    std::vector<int> leaf_slot;
};
// Throws std::runtime_error when the tree is taller than `height`.
TreeLayout layout_tree(const std::vector<Instr>& program, int height, int num_leaves);

// Classification by the layout (what the RTL computes), for tests.
Class classify_layout(const TreeLayout& layout, const uint8_t* flags, const uint8_t* leaf_material,
                      int num_leaves, int hit_leaf, bool entering);

}  // namespace csgrt
