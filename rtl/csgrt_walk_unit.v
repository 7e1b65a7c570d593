`default_nettype none
// csgrt_walk_unit — the block between the intersection unit and the shader:
// csgrt_event_sort (origin flags, events ahead in key order, double
// buffered) followed by csgrt_walker (validity, classification tree, first
// BORDER x,y with x != y). Matches trace_primary_fx() of model/trace.cpp
// given the leaf results of intersect_fx() in candidate order.
//
// Input: one leaf result per transaction (see csgrt_event_sort), the ray's
// last leaf marked, a per-ray payload taken from the last leaf. Output: one
// record per ray, in ray order (see csgrt_walker). Latency and throughput:
// event_sort (leaf -> fill bank 3 clocks (its pre-stage, its input stage), handover 1) plus the walker
// (load 1, one event per clock, TREE_HEIGHT + 1 tree stages, output skid 1).
// Both sides valid/ready; ready_o and valid_o are registers' functions
// (with SECONDARY = 1 ready_o also depends on info_valid_i).
//
// Secondary rays (SECONDARY = 1; SECONDARY = 0 builds none of it, ties
// info_ready_o and the new outputs to 0 and ignores the new inputs; same
// latency and throughput either way). Matches trace_secondary_fx() too
// (TraceOptions::t_limit_fx; no look-ahead):
//   cpos_i             per leaf result: c > 0 (csgrt_isect's c_o > 0)
//   info_*             one record per ray (primary or secondary), read with
//                      every leaf of the ray: it must be valid when the
//                      ray's first leaf is accepted (ready_o is low while
//                      info_valid_i is low) and is popped with the ray's
//                      last leaf (info_ready_o = valid_i && ready_o &&
//                      last_i). info_secondary_i, the inherited flags, the
//                      t limit and the parent's look-behind run: see
//                      csgrt_event_sort.
//   flags_after_o, lb_*_o  beside each hit record (valid with valid_o):
//                      the flags just after the hit crossing and the
//                      look-behind run, see csgrt_walker. With flags_before_o
//                      they form the info record of the hit's children:
//                      near side (shadow, reflected) {flags_before_o, lb_*_o},
//                      far side {flags_after_o, lb_count 0}.
// The refraction look-ahead (LOOK_AHEAD = 1, needs SECONDARY = 1): see
// csgrt_walker; mat_clear_i and the query port q_*/a_* pass through to it.
// The query's point needs the ray's origin and direction: info_o_i,
// info_d_i (read with the ray's info record) ride with the ray through the
// sorter to the walker and come out as q_o_o, q_d_o beside the query.
module csgrt_walk_unit #(
    parameter BITS          = 24,   // coordinate width B; t is B-1 bits
    parameter MAX_LEAVES    = 64,   // leaves per ray
    parameter LEAF_BITS     = 6,    // leaf index width (2^LEAF_BITS >= MAX_LEAVES)
    parameter TREE_HEIGHT   = 8,    // 2^TREE_HEIGHT classification slots
    parameter MAT_BITS      = 8,    // material index width
    parameter PAYLOAD_WIDTH = 1,    // per-ray sideband (>= 1)
    parameter SECONDARY     = 0,    // 1: secondary rays (info stream, run, flags after)
    parameter LOOK_BEHIND   = 4,    // look-behind entries (kLookBehind), >= 1
    parameter LOOK_AHEAD    = 0,    // 1: the refraction look-ahead (csgrt_walker)
    parameter SORT_INSERTS  = 1     // events the sorter inserts per clock, 1 or 2 (csgrt_event_sort)
) (
    input  wire                     clk_i,
    input  wire                     rst_ni,           // synchronous, active low
    // configuration
    input  wire                     ties_regular_i,   // 0 paper, 1 regular
    input  wire [2*(1<<TREE_HEIGHT)-1:0]        node_op_i,
    input  wire [MAT_BITS*(1<<TREE_HEIGHT)-1:0] slot_mat_i,
    input  wire [(1<<TREE_HEIGHT)-1:0]          slot_used_i,
    // leaf results (csgrt_isect + the pair's slot, leaf, last, ray payload)
    input  wire                     valid_i,
    output wire                     ready_o,
    input  wire [TREE_HEIGHT-1:0]   slot_i,
    input  wire [LEAF_BITS-1:0]     leaf_i,
    input  wire [1:0]               count_i,
    input  wire [BITS-2:0]          t0_i,
    input  wire [1:0]               range0_i,
    input  wire                     enter0_i,
    input  wire [BITS-2:0]          t1_i,
    input  wire [1:0]               range1_i,
    input  wire                     enter1_i,
    input  wire                     inside_i,
    input  wire                     last_i,
    input  wire [PAYLOAD_WIDTH-1:0] payload_i,
    input  wire                     cpos_i,           // c > 0 (SECONDARY)
    // per-ray info (SECONDARY; csgrt_event_sort)
    input  wire                     info_valid_i,
    output wire                     info_ready_o,
    input  wire                     info_secondary_i,
    input  wire [(1<<TREE_HEIGHT)-1:0]          info_flags_i,
    input  wire [BITS-3:0]                      info_tlimit_i,
    input  wire [$clog2(LOOK_BEHIND+1)-1:0]     info_lb_count_i,
    input  wire [LOOK_BEHIND*TREE_HEIGHT-1:0]   info_lb_slot_i,
    input  wire [LOOK_BEHIND-1:0]               info_lb_entering_i,
    input  wire [LOOK_BEHIND-1:0]               info_lb_same_t_i,
    // hit records
    output wire                     valid_o,
    input  wire                     ready_i,
    output wire                     hit_o,
    output wire [BITS-2:0]          t_o,
    output wire [LEAF_BITS-1:0]     leaf_o,
    output wire [TREE_HEIGHT-1:0]   slot_o,
    output wire                     entering_o,
    output wire [MAT_BITS-1:0]      from_o,
    output wire [MAT_BITS-1:0]      to_o,
    output wire [(1<<TREE_HEIGHT)-1:0] flags_before_o,
    output wire [PAYLOAD_WIDTH-1:0] payload_o,
    // beside the hit record (SECONDARY; csgrt_walker)
    output wire [(1<<TREE_HEIGHT)-1:0]          flags_after_o,
    output wire [$clog2(LOOK_BEHIND+1)-1:0]     lb_count_o,
    output wire [LOOK_BEHIND*TREE_HEIGHT-1:0]   lb_slot_o,
    output wire [LOOK_BEHIND-1:0]               lb_entering_o,
    output wire [LOOK_BEHIND-1:0]               lb_same_t_o,
    // the look-ahead (LOOK_AHEAD; csgrt_walker)
    input  wire [(1<<MAT_BITS)-1:0]             mat_clear_i,
    input  wire [3*BITS-1:0]        info_o_i,
    input  wire [3*BITS-1:0]        info_d_i,
    output wire                     q_valid_o,
    input  wire                     q_ready_i,
    output wire [BITS-2:0]          q_t_o,
    output wire [LEAF_BITS-1:0]     q_leaf_o,
    output wire [PAYLOAD_WIDTH-1:0] q_payload_o,
    output wire [3*BITS-1:0]        q_o_o,
    output wire [3*BITS-1:0]        q_d_o,
    input  wire                     a_valid_i,
    output wire                     a_ready_o,
    input  wire                     a_nonpos_i
);

    localparam NS = 1 << TREE_HEIGHT;
    // with the look-ahead the ray's o and d ride above the payload
    localparam OD = (LOOK_AHEAD != 0) ? 6 * BITS : 0;
    localparam PW = PAYLOAD_WIDTH + OD;

    wire                     ray_valid, ray_done, ev_valid, ev_last, ev_entering, ev_same_t, ev_next_same_t, ev_pop;
    wire [NS-1:0]            ray_flags;
    wire [PW-1:0]            ray_payload;
    wire [PW-1:0]            sort_payload_in, walk_payload, walk_q_payload;
    wire [BITS-2:0]          ev_t;
    wire [LEAF_BITS-1:0]     ev_leaf;
    wire [TREE_HEIGHT-1:0]   ev_slot, ev_next_slot, ev_slot_tree;

    csgrt_event_sort #(
        .BITS(BITS), .MAX_LEAVES(MAX_LEAVES), .LEAF_BITS(LEAF_BITS),
        .TREE_HEIGHT(TREE_HEIGHT), .PAYLOAD_WIDTH(PW),
        .SECONDARY(SECONDARY), .LOOK_BEHIND(LOOK_BEHIND), .INSERTS(SORT_INSERTS)
    ) u_sort (
        .clk_i(clk_i), .rst_ni(rst_ni), .ties_regular_i(ties_regular_i),
        .valid_i(valid_i), .ready_o(ready_o), .slot_i(slot_i), .leaf_i(leaf_i), .count_i(count_i),
        .t0_i(t0_i), .range0_i(range0_i), .enter0_i(enter0_i),
        .t1_i(t1_i), .range1_i(range1_i), .enter1_i(enter1_i),
        .inside_i(inside_i), .last_i(last_i), .payload_i(sort_payload_in), .cpos_i(cpos_i),
        .info_valid_i(info_valid_i), .info_ready_o(info_ready_o), .info_secondary_i(info_secondary_i),
        .info_flags_i(info_flags_i), .info_tlimit_i(info_tlimit_i), .info_lb_count_i(info_lb_count_i),
        .info_lb_slot_i(info_lb_slot_i), .info_lb_entering_i(info_lb_entering_i),
        .info_lb_same_t_i(info_lb_same_t_i),
        .ray_valid_o(ray_valid), .ray_flags_o(ray_flags), .ray_payload_o(ray_payload), .ray_done_i(ray_done),
        .ev_valid_o(ev_valid), .ev_last_o(ev_last), .ev_t_o(ev_t), .ev_leaf_o(ev_leaf), .ev_slot_o(ev_slot),
        .ev_entering_o(ev_entering), .ev_same_t_o(ev_same_t), .ev_next_slot_o(ev_next_slot), .ev_next_same_t_o(ev_next_same_t), .ev_pop_i(ev_pop),
        .ev_slot_tree_o(ev_slot_tree));

    csgrt_walker #(
        .BITS(BITS), .LEAF_BITS(LEAF_BITS), .TREE_HEIGHT(TREE_HEIGHT),
        .MAT_BITS(MAT_BITS), .PAYLOAD_WIDTH(PW),
        .SECONDARY(SECONDARY), .LOOK_BEHIND(LOOK_BEHIND), .LOOK_AHEAD(LOOK_AHEAD)
    ) u_walk (
        .clk_i(clk_i), .rst_ni(rst_ni),
        .node_op_i(node_op_i), .slot_mat_i(slot_mat_i), .slot_used_i(slot_used_i),
        .ray_valid_i(ray_valid), .ray_flags_i(ray_flags), .ray_payload_i(ray_payload), .ray_done_o(ray_done),
        .ev_valid_i(ev_valid), .ev_last_i(ev_last), .ev_t_i(ev_t), .ev_leaf_i(ev_leaf), .ev_slot_i(ev_slot),
        .ev_entering_i(ev_entering), .ev_same_t_i(ev_same_t), .ev_next_slot_i(ev_next_slot), .ev_next_same_t_i(ev_next_same_t), .ev_pop_o(ev_pop),
        .ev_slot_tree_i(ev_slot_tree),
        .valid_o(valid_o), .ready_i(ready_i), .hit_o(hit_o), .t_o(t_o), .leaf_o(leaf_o), .slot_o(slot_o),
        .entering_o(entering_o), .from_o(from_o), .to_o(to_o), .flags_before_o(flags_before_o),
        .payload_o(walk_payload), .flags_after_o(flags_after_o), .lb_count_o(lb_count_o), .lb_slot_o(lb_slot_o),
        .lb_entering_o(lb_entering_o), .lb_same_t_o(lb_same_t_o),
        .mat_clear_i(mat_clear_i), .q_valid_o(q_valid_o), .q_ready_i(q_ready_i), .q_t_o(q_t_o),
        .q_leaf_o(q_leaf_o), .q_payload_o(walk_q_payload), .a_valid_i(a_valid_i), .a_ready_o(a_ready_o),
        .a_nonpos_i(a_nonpos_i));

    assign payload_o   = walk_payload[PAYLOAD_WIDTH-1:0];
    assign q_payload_o = walk_q_payload[PAYLOAD_WIDTH-1:0];
    generate
        if (LOOK_AHEAD != 0) begin : g_od
            assign sort_payload_in = {info_o_i, info_d_i, payload_i};
            assign {q_o_o, q_d_o}  = walk_q_payload[PW-1:PAYLOAD_WIDTH];
            // the records' copy of o and d: not needed after the walk
            wire unused_od = ^walk_payload[PW-1:PAYLOAD_WIDTH];
        end else begin : g_no_od
            assign sort_payload_in = payload_i;
            assign q_o_o = {(3*BITS){1'b0}};
            assign q_d_o = {(3*BITS){1'b0}};
            wire unused_od = ^{info_o_i, info_d_i};
        end
    endgenerate
endmodule

`default_nettype wire
