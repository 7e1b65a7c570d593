`default_nettype none
// tb_walk — Verilator top for tb_walk.cpp: csgrt_walk_unit (event_sort +
// walker) at BITS 16 and 24, TREE_HEIGHT 8, MAX_LEAVES 64, one clock each;
// mon_* observe the sorted ray between event_sort and walker (ray loads and
// event pops) for the bench's diagnostics.
module tb_walk (
    input  wire b16_clk_i,
    input  wire b16_rst_ni,
    input  wire b16_ties_regular_i,
    input  wire [511:0] b16_node_op_i,
    input  wire [2047:0] b16_slot_mat_i,
    input  wire [255:0] b16_slot_used_i,
    input  wire b16_valid_i,
    output wire b16_ready_o,
    input  wire [7:0] b16_slot_i,
    input  wire [5:0] b16_leaf_i,
    input  wire [1:0] b16_count_i,
    input  wire [14:0] b16_t0_i,
    input  wire [1:0] b16_range0_i,
    input  wire b16_enter0_i,
    input  wire [14:0] b16_t1_i,
    input  wire [1:0] b16_range1_i,
    input  wire b16_enter1_i,
    input  wire b16_inside_i,
    input  wire b16_last_i,
    input  wire [31:0] b16_payload_i,
    output wire b16_valid_o,
    input  wire b16_ready_i,
    output wire b16_hit_o,
    output wire [14:0] b16_t_o,
    output wire [5:0] b16_leaf_o,
    output wire [7:0] b16_slot_o,
    output wire b16_entering_o,
    output wire [7:0] b16_from_o,
    output wire [7:0] b16_to_o,
    output wire [255:0] b16_flags_before_o,
    output wire [31:0] b16_payload_o,
    output wire b16_mon_load_o,
    output wire [255:0] b16_mon_flags_o,
    output wire b16_mon_pop_o,
    output wire [14:0] b16_mon_t_o,
    output wire [5:0] b16_mon_leaf_o,
    output wire [7:0] b16_mon_slot_o,
    output wire b16_mon_ent_o,
    input  wire b24_clk_i,
    input  wire b24_rst_ni,
    input  wire b24_ties_regular_i,
    input  wire [511:0] b24_node_op_i,
    input  wire [2047:0] b24_slot_mat_i,
    input  wire [255:0] b24_slot_used_i,
    input  wire b24_valid_i,
    output wire b24_ready_o,
    input  wire [7:0] b24_slot_i,
    input  wire [5:0] b24_leaf_i,
    input  wire [1:0] b24_count_i,
    input  wire [22:0] b24_t0_i,
    input  wire [1:0] b24_range0_i,
    input  wire b24_enter0_i,
    input  wire [22:0] b24_t1_i,
    input  wire [1:0] b24_range1_i,
    input  wire b24_enter1_i,
    input  wire b24_inside_i,
    input  wire b24_last_i,
    input  wire [31:0] b24_payload_i,
    output wire b24_valid_o,
    input  wire b24_ready_i,
    output wire b24_hit_o,
    output wire [22:0] b24_t_o,
    output wire [5:0] b24_leaf_o,
    output wire [7:0] b24_slot_o,
    output wire b24_entering_o,
    output wire [7:0] b24_from_o,
    output wire [7:0] b24_to_o,
    output wire [255:0] b24_flags_before_o,
    output wire [31:0] b24_payload_o,
    output wire b24_mon_load_o,
    output wire [255:0] b24_mon_flags_o,
    output wire b24_mon_pop_o,
    output wire [22:0] b24_mon_t_o,
    output wire [5:0] b24_mon_leaf_o,
    output wire [7:0] b24_mon_slot_o,
    output wire b24_mon_ent_o
);
    csgrt_walk_unit #(.BITS(16), .MAX_LEAVES(64), .LEAF_BITS(6), .TREE_HEIGHT(8), .MAT_BITS(8), .PAYLOAD_WIDTH(32)) u_b16 (
        .clk_i(b16_clk_i), .rst_ni(b16_rst_ni), .ties_regular_i(b16_ties_regular_i), .node_op_i(b16_node_op_i), .slot_mat_i(b16_slot_mat_i), .slot_used_i(b16_slot_used_i), .valid_i(b16_valid_i), .ready_o(b16_ready_o), .slot_i(b16_slot_i), .leaf_i(b16_leaf_i), .count_i(b16_count_i), .t0_i(b16_t0_i), .range0_i(b16_range0_i), .enter0_i(b16_enter0_i), .t1_i(b16_t1_i), .range1_i(b16_range1_i), .enter1_i(b16_enter1_i), .inside_i(b16_inside_i), .last_i(b16_last_i), .payload_i(b16_payload_i), .valid_o(b16_valid_o), .ready_i(b16_ready_i), .hit_o(b16_hit_o), .t_o(b16_t_o), .leaf_o(b16_leaf_o), .slot_o(b16_slot_o), .entering_o(b16_entering_o), .from_o(b16_from_o), .to_o(b16_to_o), .flags_before_o(b16_flags_before_o), .payload_o(b16_payload_o));
    assign b16_mon_load_o = u_b16.u_walk.load;
    assign b16_mon_flags_o = u_b16.u_sort.ray_flags_o;
    assign b16_mon_pop_o = u_b16.u_walk.ev_pop_o;
    assign b16_mon_t_o = u_b16.u_sort.ev_t_o;
    assign b16_mon_leaf_o = u_b16.u_sort.ev_leaf_o;
    assign b16_mon_slot_o = u_b16.u_sort.ev_slot_o;
    assign b16_mon_ent_o = u_b16.u_sort.ev_entering_o;
    csgrt_walk_unit #(.BITS(24), .MAX_LEAVES(64), .LEAF_BITS(6), .TREE_HEIGHT(8), .MAT_BITS(8), .PAYLOAD_WIDTH(32)) u_b24 (
        .clk_i(b24_clk_i), .rst_ni(b24_rst_ni), .ties_regular_i(b24_ties_regular_i), .node_op_i(b24_node_op_i), .slot_mat_i(b24_slot_mat_i), .slot_used_i(b24_slot_used_i), .valid_i(b24_valid_i), .ready_o(b24_ready_o), .slot_i(b24_slot_i), .leaf_i(b24_leaf_i), .count_i(b24_count_i), .t0_i(b24_t0_i), .range0_i(b24_range0_i), .enter0_i(b24_enter0_i), .t1_i(b24_t1_i), .range1_i(b24_range1_i), .enter1_i(b24_enter1_i), .inside_i(b24_inside_i), .last_i(b24_last_i), .payload_i(b24_payload_i), .valid_o(b24_valid_o), .ready_i(b24_ready_i), .hit_o(b24_hit_o), .t_o(b24_t_o), .leaf_o(b24_leaf_o), .slot_o(b24_slot_o), .entering_o(b24_entering_o), .from_o(b24_from_o), .to_o(b24_to_o), .flags_before_o(b24_flags_before_o), .payload_o(b24_payload_o));
    assign b24_mon_load_o = u_b24.u_walk.load;
    assign b24_mon_flags_o = u_b24.u_sort.ray_flags_o;
    assign b24_mon_pop_o = u_b24.u_walk.ev_pop_o;
    assign b24_mon_t_o = u_b24.u_sort.ev_t_o;
    assign b24_mon_leaf_o = u_b24.u_sort.ev_leaf_o;
    assign b24_mon_slot_o = u_b24.u_sort.ev_slot_o;
    assign b24_mon_ent_o = u_b24.u_sort.ev_entering_o;
endmodule
`default_nettype wire
