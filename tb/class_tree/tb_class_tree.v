`default_nettype none
// tb_class_tree — Verilator top for tb_class_tree.cpp: csgrt_class_tree at
// TREE_HEIGHT 8, 3, 2 and 1 (the path's edge cases), one clock each. Each
// instance's ports are h<H>_<port> (TREE_PORTS in tb_class_tree.cpp). The
// sibling slot's flag (sib_flag_i) is read here from the flags, as
// csgrt_walker reads it ahead from its banks.

// the top's ports of the instance of height H (2^H = NS slots)
`define TB_TREE_PORTS(H, NS) \
    input  wire h``H``_clk_i, \
    input  wire h``H``_rst_ni, \
    input  wire h``H``_ce_i, \
    input  wire [2*NS-1:0] h``H``_node_op_i, \
    input  wire [8*NS-1:0] h``H``_slot_mat_i, \
    input  wire [NS-1:0] h``H``_slot_used_i, \
    input  wire h``H``_valid_i, \
    input  wire [NS-1:0] h``H``_flags_i, \
    input  wire [NS-1:0] h``H``_flags_alt_i, \
    input  wire h``H``_alt_i, \
    input  wire [H-1:0] h``H``_slot_i, \
    input  wire h``H``_entering_i, \
    input  wire [15:0] h``H``_tag_i, \
    output wire h``H``_valid_o, \
    output wire [17:0] h``H``_class_o, \
    output wire h``H``_border_o, \
    output wire [15:0] h``H``_tag_o

// the instance of height H on those ports
`define TB_TREE(H) \
    csgrt_class_tree #(.TREE_HEIGHT(H), .MAT_BITS(8), .TAG_WIDTH(16)) u_h``H ( \
        .clk_i(h``H``_clk_i), .rst_ni(h``H``_rst_ni), .ce_i(h``H``_ce_i), \
        .node_op_i(h``H``_node_op_i), .slot_mat_i(h``H``_slot_mat_i), .slot_used_i(h``H``_slot_used_i), \
        .valid_i(h``H``_valid_i), .flags_i(h``H``_flags_i), \
        .flags_alt_i(h``H``_flags_alt_i), .alt_i(h``H``_alt_i), \
        .sib_flag_i(h``H``_alt_i ? h``H``_flags_alt_i[h``H``_slot_i ^ {{(H-1){1'b0}}, 1'b1}] \
                                 : h``H``_flags_i[h``H``_slot_i ^ {{(H-1){1'b0}}, 1'b1}]), .slot_i(h``H``_slot_i), \
        .entering_i(h``H``_entering_i), .tag_i(h``H``_tag_i), \
        .valid_o(h``H``_valid_o), .class_o(h``H``_class_o), .border_o(h``H``_border_o), .tag_o(h``H``_tag_o));

module tb_class_tree (
    `TB_TREE_PORTS(8, 256),
    `TB_TREE_PORTS(3, 8),
    `TB_TREE_PORTS(2, 4),
    `TB_TREE_PORTS(1, 2)
);
    `TB_TREE(8)
    `TB_TREE(3)
    `TB_TREE(2)
    `TB_TREE(1)
endmodule

`undef TB_TREE_PORTS
`undef TB_TREE
`default_nettype wire
