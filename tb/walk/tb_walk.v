`default_nettype none
// tb_walk — Verilator top for tb_walk.cpp: csgrt_walk_unit (event_sort +
// walker) at BITS 16 and 24, TREE_HEIGHT 8, MAX_LEAVES 64, one clock each:
// b16, b24 with SECONDARY = 0 (as csgrt_top builds it) and s16, s24 with
// SECONDARY = 1, LOOK_BEHIND 4 (secondary rays), l16, l24 with LOOK_AHEAD = 1
// too (the refraction look-ahead; its query port answered by the bench).
// The event sorter inserts one event per clock (SORT_INSERTS = 1, csgrt_top's
// default) in b16, l16 and l24 and two in b24, s16 and s24, so that both
// insertion arrays meet every test (Walk.BackToBack's clocks per ray are
// b24's: the two-insert sorter's). mon_* observe the sorted
// ray between event_sort and walker (ray loads and event pops) for the
// bench's diagnostics. The configuration (ties, tree layout) is static
// during a run (set before reset) and registered here on the instance's
// clock: logic behind a top-level input is re-evaluated by every eval() of
// the model, so unregistered it would make each test pay for all four
// instances' key comparators and classification trees.
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
    output wire b24_mon_ent_o,
    input  wire s16_clk_i,
    input  wire s16_rst_ni,
    input  wire s16_ties_regular_i,
    input  wire [511:0] s16_node_op_i,
    input  wire [2047:0] s16_slot_mat_i,
    input  wire [255:0] s16_slot_used_i,
    input  wire s16_valid_i,
    output wire s16_ready_o,
    input  wire [7:0] s16_slot_i,
    input  wire [5:0] s16_leaf_i,
    input  wire [1:0] s16_count_i,
    input  wire [14:0] s16_t0_i,
    input  wire [1:0] s16_range0_i,
    input  wire s16_enter0_i,
    input  wire [14:0] s16_t1_i,
    input  wire [1:0] s16_range1_i,
    input  wire s16_enter1_i,
    input  wire s16_inside_i,
    input  wire s16_last_i,
    input  wire [31:0] s16_payload_i,
    input  wire s16_cpos_i,
    input  wire s16_info_valid_i,
    output wire s16_info_ready_o,
    input  wire s16_info_secondary_i,
    input  wire [255:0] s16_info_flags_i,
    input  wire [13:0] s16_info_tlimit_i,
    input  wire [2:0] s16_info_lb_count_i,
    input  wire [31:0] s16_info_lb_slot_i,
    input  wire [3:0] s16_info_lb_entering_i,
    input  wire [3:0] s16_info_lb_same_t_i,
    output wire s16_valid_o,
    input  wire s16_ready_i,
    output wire s16_hit_o,
    output wire [14:0] s16_t_o,
    output wire [5:0] s16_leaf_o,
    output wire [7:0] s16_slot_o,
    output wire s16_entering_o,
    output wire [7:0] s16_from_o,
    output wire [7:0] s16_to_o,
    output wire [255:0] s16_flags_before_o,
    output wire [31:0] s16_payload_o,
    output wire [255:0] s16_flags_after_o,
    output wire [2:0] s16_lb_count_o,
    output wire [31:0] s16_lb_slot_o,
    output wire [3:0] s16_lb_entering_o,
    output wire [3:0] s16_lb_same_t_o,
    output wire s16_mon_load_o,
    output wire [255:0] s16_mon_flags_o,
    output wire s16_mon_pop_o,
    output wire [14:0] s16_mon_t_o,
    output wire [5:0] s16_mon_leaf_o,
    output wire [7:0] s16_mon_slot_o,
    output wire s16_mon_ent_o,
    input  wire s24_clk_i,
    input  wire s24_rst_ni,
    input  wire s24_ties_regular_i,
    input  wire [511:0] s24_node_op_i,
    input  wire [2047:0] s24_slot_mat_i,
    input  wire [255:0] s24_slot_used_i,
    input  wire s24_valid_i,
    output wire s24_ready_o,
    input  wire [7:0] s24_slot_i,
    input  wire [5:0] s24_leaf_i,
    input  wire [1:0] s24_count_i,
    input  wire [22:0] s24_t0_i,
    input  wire [1:0] s24_range0_i,
    input  wire s24_enter0_i,
    input  wire [22:0] s24_t1_i,
    input  wire [1:0] s24_range1_i,
    input  wire s24_enter1_i,
    input  wire s24_inside_i,
    input  wire s24_last_i,
    input  wire [31:0] s24_payload_i,
    input  wire s24_cpos_i,
    input  wire s24_info_valid_i,
    output wire s24_info_ready_o,
    input  wire s24_info_secondary_i,
    input  wire [255:0] s24_info_flags_i,
    input  wire [21:0] s24_info_tlimit_i,
    input  wire [2:0] s24_info_lb_count_i,
    input  wire [31:0] s24_info_lb_slot_i,
    input  wire [3:0] s24_info_lb_entering_i,
    input  wire [3:0] s24_info_lb_same_t_i,
    output wire s24_valid_o,
    input  wire s24_ready_i,
    output wire s24_hit_o,
    output wire [22:0] s24_t_o,
    output wire [5:0] s24_leaf_o,
    output wire [7:0] s24_slot_o,
    output wire s24_entering_o,
    output wire [7:0] s24_from_o,
    output wire [7:0] s24_to_o,
    output wire [255:0] s24_flags_before_o,
    output wire [31:0] s24_payload_o,
    output wire [255:0] s24_flags_after_o,
    output wire [2:0] s24_lb_count_o,
    output wire [31:0] s24_lb_slot_o,
    output wire [3:0] s24_lb_entering_o,
    output wire [3:0] s24_lb_same_t_o,
    output wire s24_mon_load_o,
    output wire [255:0] s24_mon_flags_o,
    output wire s24_mon_pop_o,
    output wire [22:0] s24_mon_t_o,
    output wire [5:0] s24_mon_leaf_o,
    output wire [7:0] s24_mon_slot_o,
    output wire s24_mon_ent_o,
    input  wire l16_clk_i,
    input  wire l16_rst_ni,
    input  wire l16_ties_regular_i,
    input  wire [511:0] l16_node_op_i,
    input  wire [2047:0] l16_slot_mat_i,
    input  wire [255:0] l16_slot_used_i,
    input  wire l16_valid_i,
    output wire l16_ready_o,
    input  wire [7:0] l16_slot_i,
    input  wire [5:0] l16_leaf_i,
    input  wire [1:0] l16_count_i,
    input  wire [14:0] l16_t0_i,
    input  wire [1:0] l16_range0_i,
    input  wire l16_enter0_i,
    input  wire [14:0] l16_t1_i,
    input  wire [1:0] l16_range1_i,
    input  wire l16_enter1_i,
    input  wire l16_inside_i,
    input  wire l16_last_i,
    input  wire [31:0] l16_payload_i,
    input  wire l16_cpos_i,
    input  wire l16_info_valid_i,
    output wire l16_info_ready_o,
    input  wire l16_info_secondary_i,
    input  wire [255:0] l16_info_flags_i,
    input  wire [13:0] l16_info_tlimit_i,
    input  wire [2:0] l16_info_lb_count_i,
    input  wire [31:0] l16_info_lb_slot_i,
    input  wire [3:0] l16_info_lb_entering_i,
    input  wire [3:0] l16_info_lb_same_t_i,
    output wire l16_valid_o,
    input  wire l16_ready_i,
    output wire l16_hit_o,
    output wire [14:0] l16_t_o,
    output wire [5:0] l16_leaf_o,
    output wire [7:0] l16_slot_o,
    output wire l16_entering_o,
    output wire [7:0] l16_from_o,
    output wire [7:0] l16_to_o,
    output wire [255:0] l16_flags_before_o,
    output wire [31:0] l16_payload_o,
    output wire [255:0] l16_flags_after_o,
    output wire [2:0] l16_lb_count_o,
    output wire [31:0] l16_lb_slot_o,
    output wire [3:0] l16_lb_entering_o,
    output wire [3:0] l16_lb_same_t_o,
    output wire l16_mon_load_o,
    output wire [255:0] l16_mon_flags_o,
    output wire l16_mon_pop_o,
    output wire [14:0] l16_mon_t_o,
    output wire [5:0] l16_mon_leaf_o,
    output wire [7:0] l16_mon_slot_o,
    output wire l16_mon_ent_o,
    input  wire [255:0] l16_mat_clear_i,
    output wire l16_q_valid_o,
    input  wire l16_q_ready_i,
    output wire [14:0] l16_q_t_o,
    output wire [5:0] l16_q_leaf_o,
    output wire [31:0] l16_q_payload_o,
    input  wire l16_a_valid_i,
    output wire l16_a_ready_o,
    input  wire l16_a_nonpos_i,
    input  wire l24_clk_i,
    input  wire l24_rst_ni,
    input  wire l24_ties_regular_i,
    input  wire [511:0] l24_node_op_i,
    input  wire [2047:0] l24_slot_mat_i,
    input  wire [255:0] l24_slot_used_i,
    input  wire l24_valid_i,
    output wire l24_ready_o,
    input  wire [7:0] l24_slot_i,
    input  wire [5:0] l24_leaf_i,
    input  wire [1:0] l24_count_i,
    input  wire [22:0] l24_t0_i,
    input  wire [1:0] l24_range0_i,
    input  wire l24_enter0_i,
    input  wire [22:0] l24_t1_i,
    input  wire [1:0] l24_range1_i,
    input  wire l24_enter1_i,
    input  wire l24_inside_i,
    input  wire l24_last_i,
    input  wire [31:0] l24_payload_i,
    input  wire l24_cpos_i,
    input  wire l24_info_valid_i,
    output wire l24_info_ready_o,
    input  wire l24_info_secondary_i,
    input  wire [255:0] l24_info_flags_i,
    input  wire [21:0] l24_info_tlimit_i,
    input  wire [2:0] l24_info_lb_count_i,
    input  wire [31:0] l24_info_lb_slot_i,
    input  wire [3:0] l24_info_lb_entering_i,
    input  wire [3:0] l24_info_lb_same_t_i,
    output wire l24_valid_o,
    input  wire l24_ready_i,
    output wire l24_hit_o,
    output wire [22:0] l24_t_o,
    output wire [5:0] l24_leaf_o,
    output wire [7:0] l24_slot_o,
    output wire l24_entering_o,
    output wire [7:0] l24_from_o,
    output wire [7:0] l24_to_o,
    output wire [255:0] l24_flags_before_o,
    output wire [31:0] l24_payload_o,
    output wire [255:0] l24_flags_after_o,
    output wire [2:0] l24_lb_count_o,
    output wire [31:0] l24_lb_slot_o,
    output wire [3:0] l24_lb_entering_o,
    output wire [3:0] l24_lb_same_t_o,
    output wire l24_mon_load_o,
    output wire [255:0] l24_mon_flags_o,
    output wire l24_mon_pop_o,
    output wire [22:0] l24_mon_t_o,
    output wire [5:0] l24_mon_leaf_o,
    output wire [7:0] l24_mon_slot_o,
    output wire l24_mon_ent_o,
    input  wire [255:0] l24_mat_clear_i,
    output wire l24_q_valid_o,
    input  wire l24_q_ready_i,
    output wire [22:0] l24_q_t_o,
    output wire [5:0] l24_q_leaf_o,
    output wire [31:0] l24_q_payload_o,
    input  wire l24_a_valid_i,
    output wire l24_a_ready_o,
    input  wire l24_a_nonpos_i
);
    reg         b16_ties_regular_q;
    reg [511:0] b16_node_op_q;
    reg [2047:0] b16_slot_mat_q;
    reg [255:0] b16_slot_used_q;
    always @(posedge b16_clk_i) begin
        b16_ties_regular_q <= b16_ties_regular_i;
        b16_node_op_q <= b16_node_op_i;
        b16_slot_mat_q <= b16_slot_mat_i;
        b16_slot_used_q <= b16_slot_used_i;
    end
    csgrt_walk_unit #(.BITS(16), .MAX_LEAVES(64), .LEAF_BITS(6), .TREE_HEIGHT(8), .MAT_BITS(8), .PAYLOAD_WIDTH(32), .SECONDARY(0), .LOOK_BEHIND(4), .SORT_INSERTS(1)) u_b16 (
        .clk_i(b16_clk_i), .rst_ni(b16_rst_ni), .ties_regular_i(b16_ties_regular_q), .node_op_i(b16_node_op_q), .slot_mat_i(b16_slot_mat_q), .slot_used_i(b16_slot_used_q), .valid_i(b16_valid_i), .ready_o(b16_ready_o), .slot_i(b16_slot_i), .leaf_i(b16_leaf_i), .count_i(b16_count_i), .t0_i(b16_t0_i), .range0_i(b16_range0_i), .enter0_i(b16_enter0_i), .t1_i(b16_t1_i), .range1_i(b16_range1_i), .enter1_i(b16_enter1_i), .inside_i(b16_inside_i), .last_i(b16_last_i), .payload_i(b16_payload_i), .valid_o(b16_valid_o), .ready_i(b16_ready_i), .hit_o(b16_hit_o), .t_o(b16_t_o), .leaf_o(b16_leaf_o), .slot_o(b16_slot_o), .entering_o(b16_entering_o), .from_o(b16_from_o), .to_o(b16_to_o), .flags_before_o(b16_flags_before_o), .payload_o(b16_payload_o),
        // SECONDARY = 0: the secondary-ray inputs tied, their (constant 0) outputs open
        .cpos_i(1'b0), .info_valid_i(1'b0), .info_secondary_i(1'b0), .info_flags_i(256'd0), .info_tlimit_i(14'd0),
        .info_lb_count_i(3'd0), .info_lb_slot_i(32'd0), .info_lb_entering_i(4'd0), .info_lb_same_t_i(4'd0),
        /* verilator lint_off PINCONNECTEMPTY */
        .info_ready_o(), .flags_after_o(), .lb_count_o(), .lb_slot_o(), .lb_entering_o(), .lb_same_t_o(),
        .mat_clear_i(256'd0), .info_o_i(48'd0), .info_d_i(48'd0), .q_valid_o(), .q_ready_i(1'b0), .q_t_o(), .q_leaf_o(), .q_payload_o(), .a_valid_i(1'b0),
        .a_ready_o(), .a_nonpos_i(1'b0), .q_o_o(), .q_d_o()
        /* verilator lint_on PINCONNECTEMPTY */
    );
    assign b16_mon_load_o = u_b16.u_walk.load;
    assign b16_mon_flags_o = u_b16.u_sort.ray_flags_o;
    assign b16_mon_pop_o = u_b16.u_walk.ev_pop_o;
    assign b16_mon_t_o = u_b16.u_sort.ev_t_o;
    assign b16_mon_leaf_o = u_b16.u_sort.ev_leaf_o;
    assign b16_mon_slot_o = u_b16.u_sort.ev_slot_o;
    assign b16_mon_ent_o = u_b16.u_sort.ev_entering_o;
    reg         b24_ties_regular_q;
    reg [511:0] b24_node_op_q;
    reg [2047:0] b24_slot_mat_q;
    reg [255:0] b24_slot_used_q;
    always @(posedge b24_clk_i) begin
        b24_ties_regular_q <= b24_ties_regular_i;
        b24_node_op_q <= b24_node_op_i;
        b24_slot_mat_q <= b24_slot_mat_i;
        b24_slot_used_q <= b24_slot_used_i;
    end
    csgrt_walk_unit #(.BITS(24), .MAX_LEAVES(64), .LEAF_BITS(6), .TREE_HEIGHT(8), .MAT_BITS(8), .PAYLOAD_WIDTH(32), .SECONDARY(0), .LOOK_BEHIND(4), .SORT_INSERTS(2)) u_b24 (
        .clk_i(b24_clk_i), .rst_ni(b24_rst_ni), .ties_regular_i(b24_ties_regular_q), .node_op_i(b24_node_op_q), .slot_mat_i(b24_slot_mat_q), .slot_used_i(b24_slot_used_q), .valid_i(b24_valid_i), .ready_o(b24_ready_o), .slot_i(b24_slot_i), .leaf_i(b24_leaf_i), .count_i(b24_count_i), .t0_i(b24_t0_i), .range0_i(b24_range0_i), .enter0_i(b24_enter0_i), .t1_i(b24_t1_i), .range1_i(b24_range1_i), .enter1_i(b24_enter1_i), .inside_i(b24_inside_i), .last_i(b24_last_i), .payload_i(b24_payload_i), .valid_o(b24_valid_o), .ready_i(b24_ready_i), .hit_o(b24_hit_o), .t_o(b24_t_o), .leaf_o(b24_leaf_o), .slot_o(b24_slot_o), .entering_o(b24_entering_o), .from_o(b24_from_o), .to_o(b24_to_o), .flags_before_o(b24_flags_before_o), .payload_o(b24_payload_o),
        // SECONDARY = 0: the secondary-ray inputs tied, their (constant 0) outputs open
        .cpos_i(1'b0), .info_valid_i(1'b0), .info_secondary_i(1'b0), .info_flags_i(256'd0), .info_tlimit_i(22'd0),
        .info_lb_count_i(3'd0), .info_lb_slot_i(32'd0), .info_lb_entering_i(4'd0), .info_lb_same_t_i(4'd0),
        /* verilator lint_off PINCONNECTEMPTY */
        .info_ready_o(), .flags_after_o(), .lb_count_o(), .lb_slot_o(), .lb_entering_o(), .lb_same_t_o(),
        .mat_clear_i(256'd0), .info_o_i(72'd0), .info_d_i(72'd0), .q_valid_o(), .q_ready_i(1'b0), .q_t_o(), .q_leaf_o(), .q_payload_o(), .a_valid_i(1'b0),
        .a_ready_o(), .a_nonpos_i(1'b0), .q_o_o(), .q_d_o()
        /* verilator lint_on PINCONNECTEMPTY */
    );
    assign b24_mon_load_o = u_b24.u_walk.load;
    assign b24_mon_flags_o = u_b24.u_sort.ray_flags_o;
    assign b24_mon_pop_o = u_b24.u_walk.ev_pop_o;
    assign b24_mon_t_o = u_b24.u_sort.ev_t_o;
    assign b24_mon_leaf_o = u_b24.u_sort.ev_leaf_o;
    assign b24_mon_slot_o = u_b24.u_sort.ev_slot_o;
    assign b24_mon_ent_o = u_b24.u_sort.ev_entering_o;
    reg         s16_ties_regular_q;
    reg [511:0] s16_node_op_q;
    reg [2047:0] s16_slot_mat_q;
    reg [255:0] s16_slot_used_q;
    always @(posedge s16_clk_i) begin
        s16_ties_regular_q <= s16_ties_regular_i;
        s16_node_op_q <= s16_node_op_i;
        s16_slot_mat_q <= s16_slot_mat_i;
        s16_slot_used_q <= s16_slot_used_i;
    end
    csgrt_walk_unit #(.BITS(16), .MAX_LEAVES(64), .LEAF_BITS(6), .TREE_HEIGHT(8), .MAT_BITS(8), .PAYLOAD_WIDTH(32), .SECONDARY(1), .LOOK_BEHIND(4), .SORT_INSERTS(2)) u_s16 (
        .clk_i(s16_clk_i), .rst_ni(s16_rst_ni), .ties_regular_i(s16_ties_regular_q), .node_op_i(s16_node_op_q), .slot_mat_i(s16_slot_mat_q), .slot_used_i(s16_slot_used_q), .valid_i(s16_valid_i), .ready_o(s16_ready_o), .slot_i(s16_slot_i), .leaf_i(s16_leaf_i), .count_i(s16_count_i), .t0_i(s16_t0_i), .range0_i(s16_range0_i), .enter0_i(s16_enter0_i), .t1_i(s16_t1_i), .range1_i(s16_range1_i), .enter1_i(s16_enter1_i), .inside_i(s16_inside_i), .last_i(s16_last_i), .payload_i(s16_payload_i), .valid_o(s16_valid_o), .ready_i(s16_ready_i), .hit_o(s16_hit_o), .t_o(s16_t_o), .leaf_o(s16_leaf_o), .slot_o(s16_slot_o), .entering_o(s16_entering_o), .from_o(s16_from_o), .to_o(s16_to_o), .flags_before_o(s16_flags_before_o), .payload_o(s16_payload_o), .cpos_i(s16_cpos_i), .info_valid_i(s16_info_valid_i), .info_ready_o(s16_info_ready_o), .info_secondary_i(s16_info_secondary_i), .info_flags_i(s16_info_flags_i), .info_tlimit_i(s16_info_tlimit_i), .info_lb_count_i(s16_info_lb_count_i), .info_lb_slot_i(s16_info_lb_slot_i), .info_lb_entering_i(s16_info_lb_entering_i), .info_lb_same_t_i(s16_info_lb_same_t_i), .flags_after_o(s16_flags_after_o), .lb_count_o(s16_lb_count_o), .lb_slot_o(s16_lb_slot_o), .lb_entering_o(s16_lb_entering_o), .lb_same_t_o(s16_lb_same_t_o), .mat_clear_i(256'd0), .info_o_i(48'd0), .info_d_i(48'd0), .q_ready_i(1'b0), .a_valid_i(1'b0), .a_nonpos_i(1'b0),
        // LOOK_AHEAD = 0: the look-ahead's (constant 0) outputs open
        /* verilator lint_off PINCONNECTEMPTY */
        .q_valid_o(), .q_t_o(), .q_leaf_o(), .q_payload_o(), .a_ready_o(), .q_o_o(), .q_d_o()
        /* verilator lint_on PINCONNECTEMPTY */
    );
    assign s16_mon_load_o = u_s16.u_walk.load;
    assign s16_mon_flags_o = u_s16.u_sort.ray_flags_o;
    assign s16_mon_pop_o = u_s16.u_walk.ev_pop_o;
    assign s16_mon_t_o = u_s16.u_sort.ev_t_o;
    assign s16_mon_leaf_o = u_s16.u_sort.ev_leaf_o;
    assign s16_mon_slot_o = u_s16.u_sort.ev_slot_o;
    assign s16_mon_ent_o = u_s16.u_sort.ev_entering_o;
    reg         s24_ties_regular_q;
    reg [511:0] s24_node_op_q;
    reg [2047:0] s24_slot_mat_q;
    reg [255:0] s24_slot_used_q;
    always @(posedge s24_clk_i) begin
        s24_ties_regular_q <= s24_ties_regular_i;
        s24_node_op_q <= s24_node_op_i;
        s24_slot_mat_q <= s24_slot_mat_i;
        s24_slot_used_q <= s24_slot_used_i;
    end
    csgrt_walk_unit #(.BITS(24), .MAX_LEAVES(64), .LEAF_BITS(6), .TREE_HEIGHT(8), .MAT_BITS(8), .PAYLOAD_WIDTH(32), .SECONDARY(1), .LOOK_BEHIND(4), .SORT_INSERTS(2)) u_s24 (
        .clk_i(s24_clk_i), .rst_ni(s24_rst_ni), .ties_regular_i(s24_ties_regular_q), .node_op_i(s24_node_op_q), .slot_mat_i(s24_slot_mat_q), .slot_used_i(s24_slot_used_q), .valid_i(s24_valid_i), .ready_o(s24_ready_o), .slot_i(s24_slot_i), .leaf_i(s24_leaf_i), .count_i(s24_count_i), .t0_i(s24_t0_i), .range0_i(s24_range0_i), .enter0_i(s24_enter0_i), .t1_i(s24_t1_i), .range1_i(s24_range1_i), .enter1_i(s24_enter1_i), .inside_i(s24_inside_i), .last_i(s24_last_i), .payload_i(s24_payload_i), .valid_o(s24_valid_o), .ready_i(s24_ready_i), .hit_o(s24_hit_o), .t_o(s24_t_o), .leaf_o(s24_leaf_o), .slot_o(s24_slot_o), .entering_o(s24_entering_o), .from_o(s24_from_o), .to_o(s24_to_o), .flags_before_o(s24_flags_before_o), .payload_o(s24_payload_o), .cpos_i(s24_cpos_i), .info_valid_i(s24_info_valid_i), .info_ready_o(s24_info_ready_o), .info_secondary_i(s24_info_secondary_i), .info_flags_i(s24_info_flags_i), .info_tlimit_i(s24_info_tlimit_i), .info_lb_count_i(s24_info_lb_count_i), .info_lb_slot_i(s24_info_lb_slot_i), .info_lb_entering_i(s24_info_lb_entering_i), .info_lb_same_t_i(s24_info_lb_same_t_i), .flags_after_o(s24_flags_after_o), .lb_count_o(s24_lb_count_o), .lb_slot_o(s24_lb_slot_o), .lb_entering_o(s24_lb_entering_o), .lb_same_t_o(s24_lb_same_t_o), .mat_clear_i(256'd0), .info_o_i(72'd0), .info_d_i(72'd0), .q_ready_i(1'b0), .a_valid_i(1'b0), .a_nonpos_i(1'b0),
        // LOOK_AHEAD = 0: the look-ahead's (constant 0) outputs open
        /* verilator lint_off PINCONNECTEMPTY */
        .q_valid_o(), .q_t_o(), .q_leaf_o(), .q_payload_o(), .a_ready_o(), .q_o_o(), .q_d_o()
        /* verilator lint_on PINCONNECTEMPTY */
    );
    assign s24_mon_load_o = u_s24.u_walk.load;
    assign s24_mon_flags_o = u_s24.u_sort.ray_flags_o;
    assign s24_mon_pop_o = u_s24.u_walk.ev_pop_o;
    assign s24_mon_t_o = u_s24.u_sort.ev_t_o;
    assign s24_mon_leaf_o = u_s24.u_sort.ev_leaf_o;
    assign s24_mon_slot_o = u_s24.u_sort.ev_slot_o;
    assign s24_mon_ent_o = u_s24.u_sort.ev_entering_o;
    reg         l16_ties_regular_q;
    reg [511:0] l16_node_op_q;
    reg [2047:0] l16_slot_mat_q;
    reg [255:0] l16_slot_used_q;
    reg [255:0] l16_mat_clear_q;
    always @(posedge l16_clk_i) begin
        l16_ties_regular_q <= l16_ties_regular_i;
        l16_node_op_q <= l16_node_op_i;
        l16_slot_mat_q <= l16_slot_mat_i;
        l16_slot_used_q <= l16_slot_used_i;
        l16_mat_clear_q <= l16_mat_clear_i;
    end
    csgrt_walk_unit #(.BITS(16), .MAX_LEAVES(64), .LEAF_BITS(6), .TREE_HEIGHT(8), .MAT_BITS(8), .PAYLOAD_WIDTH(32), .SECONDARY(1), .LOOK_BEHIND(4), .LOOK_AHEAD(1), .SORT_INSERTS(1)) u_l16 (
        .clk_i(l16_clk_i), .rst_ni(l16_rst_ni), .ties_regular_i(l16_ties_regular_q), .node_op_i(l16_node_op_q), .slot_mat_i(l16_slot_mat_q), .slot_used_i(l16_slot_used_q), .valid_i(l16_valid_i), .ready_o(l16_ready_o), .slot_i(l16_slot_i), .leaf_i(l16_leaf_i), .count_i(l16_count_i), .t0_i(l16_t0_i), .range0_i(l16_range0_i), .enter0_i(l16_enter0_i), .t1_i(l16_t1_i), .range1_i(l16_range1_i), .enter1_i(l16_enter1_i), .inside_i(l16_inside_i), .last_i(l16_last_i), .payload_i(l16_payload_i), .valid_o(l16_valid_o), .ready_i(l16_ready_i), .hit_o(l16_hit_o), .t_o(l16_t_o), .leaf_o(l16_leaf_o), .slot_o(l16_slot_o), .entering_o(l16_entering_o), .from_o(l16_from_o), .to_o(l16_to_o), .flags_before_o(l16_flags_before_o), .payload_o(l16_payload_o), .cpos_i(l16_cpos_i), .info_valid_i(l16_info_valid_i), .info_ready_o(l16_info_ready_o), .info_secondary_i(l16_info_secondary_i), .info_flags_i(l16_info_flags_i), .info_tlimit_i(l16_info_tlimit_i), .info_lb_count_i(l16_info_lb_count_i), .info_lb_slot_i(l16_info_lb_slot_i), .info_lb_entering_i(l16_info_lb_entering_i), .info_lb_same_t_i(l16_info_lb_same_t_i), .flags_after_o(l16_flags_after_o), .lb_count_o(l16_lb_count_o), .lb_slot_o(l16_lb_slot_o), .lb_entering_o(l16_lb_entering_o), .lb_same_t_o(l16_lb_same_t_o), .mat_clear_i(l16_mat_clear_q), .info_o_i(48'd0), .info_d_i(48'd0), .q_valid_o(l16_q_valid_o), .q_ready_i(l16_q_ready_i), .q_t_o(l16_q_t_o), .q_leaf_o(l16_q_leaf_o), .q_payload_o(l16_q_payload_o), .a_valid_i(l16_a_valid_i), .a_ready_o(l16_a_ready_o), .a_nonpos_i(l16_a_nonpos_i),
        // o and d are not needed here: the bench answers by the ray's number
        /* verilator lint_off PINCONNECTEMPTY */
        .q_o_o(), .q_d_o()
        /* verilator lint_on PINCONNECTEMPTY */
    );
    assign l16_mon_load_o = u_l16.u_walk.load;
    assign l16_mon_flags_o = u_l16.u_sort.ray_flags_o;
    assign l16_mon_pop_o = u_l16.u_walk.ev_pop_o;
    assign l16_mon_t_o = u_l16.u_sort.ev_t_o;
    assign l16_mon_leaf_o = u_l16.u_sort.ev_leaf_o;
    assign l16_mon_slot_o = u_l16.u_sort.ev_slot_o;
    assign l16_mon_ent_o = u_l16.u_sort.ev_entering_o;
    reg         l24_ties_regular_q;
    reg [511:0] l24_node_op_q;
    reg [2047:0] l24_slot_mat_q;
    reg [255:0] l24_slot_used_q;
    reg [255:0] l24_mat_clear_q;
    always @(posedge l24_clk_i) begin
        l24_ties_regular_q <= l24_ties_regular_i;
        l24_node_op_q <= l24_node_op_i;
        l24_slot_mat_q <= l24_slot_mat_i;
        l24_slot_used_q <= l24_slot_used_i;
        l24_mat_clear_q <= l24_mat_clear_i;
    end
    csgrt_walk_unit #(.BITS(24), .MAX_LEAVES(64), .LEAF_BITS(6), .TREE_HEIGHT(8), .MAT_BITS(8), .PAYLOAD_WIDTH(32), .SECONDARY(1), .LOOK_BEHIND(4), .LOOK_AHEAD(1), .SORT_INSERTS(1)) u_l24 (
        .clk_i(l24_clk_i), .rst_ni(l24_rst_ni), .ties_regular_i(l24_ties_regular_q), .node_op_i(l24_node_op_q), .slot_mat_i(l24_slot_mat_q), .slot_used_i(l24_slot_used_q), .valid_i(l24_valid_i), .ready_o(l24_ready_o), .slot_i(l24_slot_i), .leaf_i(l24_leaf_i), .count_i(l24_count_i), .t0_i(l24_t0_i), .range0_i(l24_range0_i), .enter0_i(l24_enter0_i), .t1_i(l24_t1_i), .range1_i(l24_range1_i), .enter1_i(l24_enter1_i), .inside_i(l24_inside_i), .last_i(l24_last_i), .payload_i(l24_payload_i), .valid_o(l24_valid_o), .ready_i(l24_ready_i), .hit_o(l24_hit_o), .t_o(l24_t_o), .leaf_o(l24_leaf_o), .slot_o(l24_slot_o), .entering_o(l24_entering_o), .from_o(l24_from_o), .to_o(l24_to_o), .flags_before_o(l24_flags_before_o), .payload_o(l24_payload_o), .cpos_i(l24_cpos_i), .info_valid_i(l24_info_valid_i), .info_ready_o(l24_info_ready_o), .info_secondary_i(l24_info_secondary_i), .info_flags_i(l24_info_flags_i), .info_tlimit_i(l24_info_tlimit_i), .info_lb_count_i(l24_info_lb_count_i), .info_lb_slot_i(l24_info_lb_slot_i), .info_lb_entering_i(l24_info_lb_entering_i), .info_lb_same_t_i(l24_info_lb_same_t_i), .flags_after_o(l24_flags_after_o), .lb_count_o(l24_lb_count_o), .lb_slot_o(l24_lb_slot_o), .lb_entering_o(l24_lb_entering_o), .lb_same_t_o(l24_lb_same_t_o), .mat_clear_i(l24_mat_clear_q), .info_o_i(72'd0), .info_d_i(72'd0), .q_valid_o(l24_q_valid_o), .q_ready_i(l24_q_ready_i), .q_t_o(l24_q_t_o), .q_leaf_o(l24_q_leaf_o), .q_payload_o(l24_q_payload_o), .a_valid_i(l24_a_valid_i), .a_ready_o(l24_a_ready_o), .a_nonpos_i(l24_a_nonpos_i),
        // o and d are not needed here: the bench answers by the ray's number
        /* verilator lint_off PINCONNECTEMPTY */
        .q_o_o(), .q_d_o()
        /* verilator lint_on PINCONNECTEMPTY */
    );
    assign l24_mon_load_o = u_l24.u_walk.load;
    assign l24_mon_flags_o = u_l24.u_sort.ray_flags_o;
    assign l24_mon_pop_o = u_l24.u_walk.ev_pop_o;
    assign l24_mon_t_o = u_l24.u_sort.ev_t_o;
    assign l24_mon_leaf_o = u_l24.u_sort.ev_leaf_o;
    assign l24_mon_slot_o = u_l24.u_sort.ev_slot_o;
    assign l24_mon_ent_o = u_l24.u_sort.ev_entering_o;
endmodule
`default_nettype wire
