`default_nettype none
// tb_class_tree — Verilator top for tb_class_tree.cpp: csgrt_class_tree at
// TREE_HEIGHT 8 and 3, one clock each.
module tb_class_tree (
    input  wire h8_clk_i,
    input  wire h8_rst_ni,
    input  wire h8_ce_i,
    input  wire [511:0] h8_node_op_i,
    input  wire [2047:0] h8_slot_mat_i,
    input  wire [255:0] h8_slot_used_i,
    input  wire h8_valid_i,
    input  wire [255:0] h8_flags_i,
    input  wire [7:0] h8_slot_i,
    input  wire h8_entering_i,
    input  wire [15:0] h8_tag_i,
    output wire h8_valid_o,
    output wire [17:0] h8_class_o,
    output wire [15:0] h8_tag_o,
    input  wire h3_clk_i,
    input  wire h3_rst_ni,
    input  wire h3_ce_i,
    input  wire [15:0] h3_node_op_i,
    input  wire [63:0] h3_slot_mat_i,
    input  wire [7:0] h3_slot_used_i,
    input  wire h3_valid_i,
    input  wire [7:0] h3_flags_i,
    input  wire [2:0] h3_slot_i,
    input  wire h3_entering_i,
    input  wire [15:0] h3_tag_i,
    output wire h3_valid_o,
    output wire [17:0] h3_class_o,
    output wire [15:0] h3_tag_o
);
    csgrt_class_tree #(.TREE_HEIGHT(8), .MAT_BITS(8), .TAG_WIDTH(16)) u_h8 (.clk_i(h8_clk_i), .rst_ni(h8_rst_ni), .ce_i(h8_ce_i), .node_op_i(h8_node_op_i), .slot_mat_i(h8_slot_mat_i), .slot_used_i(h8_slot_used_i), .valid_i(h8_valid_i), .flags_i(h8_flags_i), .slot_i(h8_slot_i), .entering_i(h8_entering_i), .tag_i(h8_tag_i), .valid_o(h8_valid_o), .class_o(h8_class_o), .tag_o(h8_tag_o));
    csgrt_class_tree #(.TREE_HEIGHT(3), .MAT_BITS(8), .TAG_WIDTH(16)) u_h3 (.clk_i(h3_clk_i), .rst_ni(h3_rst_ni), .ce_i(h3_ce_i), .node_op_i(h3_node_op_i), .slot_mat_i(h3_slot_mat_i), .slot_used_i(h3_slot_used_i), .valid_i(h3_valid_i), .flags_i(h3_flags_i), .slot_i(h3_slot_i), .entering_i(h3_entering_i), .tag_i(h3_tag_i), .valid_o(h3_valid_o), .class_o(h3_class_o), .tag_o(h3_tag_o));
endmodule
`default_nettype wire
