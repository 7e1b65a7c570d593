`default_nettype none
// csgrt_top — the exact CSG ray tracer: scene image in, pixels out, equal bit
// for bit to the golden model's fixed path (docs/architecture.md).
//
//   scene words -> loader -> camera -> dispatch -> isect -> walk unit
//                                          |                   |
//                                       ray queue ------> lookup -> shade -> pixels
//
// Phong highlights are the specular unit of csgrt_shade (SPECULAR; without
// it a scene is shaded as if no material had phong).
// With shadows, reflection or refraction (SHADOWS, REFLECTION, REFRACTION;
// a build has only the units its parameters ask for) the camera's rays and
// the secondary rays go through csgrt_raytree, which schedules each pixel's
// ray tree (with REFRACTION the walker also runs the look-ahead of
// algorithm.md section 6, its geometric test in a csgrt_quadric_at):
//
//   camera -> raytree -> dispatch -> isect -> walk unit -> lookup -> raytree
//               |  ^                                                 |  ^
//               |  +-- spawn (children of a hit) <-------------------+  |
//               +---> shade (linear, scaled light colours) -> contrib --+
//               +---> pixels
//
// Handshakes: the scene image enters as 32-bit words (load_*), one per
// clock; after loaded_o, a start_i pulse renders one frame; pixels leave on
// a valid/ready stream in raster order and nothing is lost or duplicated
// under back-pressure. done_o pulses after the last pixel is accepted.
// Statistics for the simulation driver: stat_cycles_o counts clocks from
// start to the last pixel, stat_pairs_o the ray-primitive pairs issued to
// the intersection unit.
module csgrt_top #(
    parameter BITS          = 24,    // coordinate width B (12..32)
    parameter MAX_LEAVES    = 64,    // leaf half-spaces per scene
    parameter TREE_HEIGHT   = 8,     // classification tree: 2^TREE_HEIGHT slots
    parameter MAX_LIGHTS    = 8,     // point lights
    parameter MAX_MATERIALS = 255,   // materials besides air
    parameter NUM_UNITS     = 1,     // intersection lanes, each an isect + walk unit
    parameter ISECT_II      = 1,     // clocks per ray-primitive pair of each intersection unit: 1, or 3 (a third of
                                     // its multipliers and their wiring: the 24-bit builds' congestion, docs/fpga.md)
    parameter LUT_FILE      = "rtl/srgb_lut.hex",
    // effects (docs/effects.md): absent from the netlist when 0
    parameter SHADOWS       = 0,     // shadow rays to every light
    parameter REFLECTION    = 0,     // mirror reflection
    parameter REFRACTION    = 0,     // transmitted rays, total internal reflection, the look-ahead
    parameter SPECULAR      = 1,     // phong highlights (0: shaded as if every phong were 0)
    parameter CONTEXTS      = 8,     // pixels in flight in the ray tree
    parameter MAX_DEPTH     = 8,     // ray tree depth the stack holds (>= max_trace_level)
    parameter SORT_INSERTS  = 1,     // events each lane's sorter inserts per clock: 1, or 2 (more logic, 0-3 % fewer cycles)
    parameter SHARE_II      = 3,     // clocks per item of the blocks off the intersection unit's rate (camera, shading, the ray tree's
                                     // arithmetic, the secondary rays' children): 3 (a third of their multipliers, ~1 % more cycles), or 1
    // derived
    parameter LEAF_BITS     = $clog2(MAX_LEAVES),
    parameter SLOTS         = 1 << TREE_HEIGHT
) (
    input  wire        clk_i,
    input  wire        rst_ni,          // synchronous, active low
    // scene image
    input  wire        load_valid_i,
    output wire        load_ready_o,
    input  wire [31:0] load_word_i,
    output wire        loaded_o,
    output wire [3:0]  load_error_o,    // csgrt_scene_loader's codes, 0: none
    // control
    input  wire        start_i,         // one-clock pulse after loaded_o
    input  wire        ties_regular_i,  // tie policy: 0 paper, 1 regular (taken with start_i)
    output reg         busy_o,
    output reg         done_o,
    // pixels, raster order
    output wire        pix_valid_o,
    input  wire        pix_ready_i,
    output wire [11:0] pix_x_o,
    output wire [11:0] pix_y_o,
    output wire [23:0] pix_rgb_o,       // {r, g, b}
    // statistics
    output reg  [63:0] stat_cycles_o,
    output reg  [63:0] stat_pairs_o     // pairs issued, summed over the lanes
);
    localparam EFFECTS = (SHADOWS != 0) || (REFLECTION != 0) || (REFRACTION != 0);
    localparam LA      = (REFRACTION != 0);   // the walker's look-ahead
    localparam OD_W    = LA ? 6 * BITS : 0;   // a ray's o and d in its info word (the look-ahead's test)
    localparam LOOK_BEHIND = 4;                // model: kLookBehind
    localparam LBC    = $clog2(LOOK_BEHIND + 1);
    localparam RUN_W  = LBC + LOOK_BEHIND * (TREE_HEIGHT + 2);   // {same_t, entering, slots, count}
    localparam DIST_W = BITS + 1;              // csgrt_spawn's shadow distance (F+4 bits)
    localparam CB     = $clog2(CONTEXTS);
    localparam KW     = (MAX_LIGHTS > 1) ? $clog2(MAX_LIGHTS) : 1;
    localparam REC_W  = 1 + CB + KW + 48 + 4 + 48 + 5 + DIST_W;  // csgrt_raytree's ray record
    localparam RT_INFO_W = 1 + SLOTS + (BITS - 2) + RUN_W;   // csgrt_raytree's info word
    localparam INFO_W = EFFECTS ? RT_INFO_W + OD_W : 0;
    localparam INFO_P = EFFECTS ? INFO_W : 1;
    localparam PAY_W  = EFFECTS ? REC_W : 24;  // what a ray carries beside o, d: record, or {x, y}
    localparam RAY_W  = PAY_W + 6 * BITS;      // {payload, o, d}
    localparam SIDE_W = 1 + TREE_HEIGHT + LEAF_BITS;   // {last, slot, leaf} beside a pair
    localparam MAT_W = 9 * 16 + 10;

    // ------------------------------------------------------------------ scene
    wire [11:0]               width, height;
    wire [LEAF_BITS:0]        num_leaves;
    wire [3:0]                num_lights;
    wire [7:0]                max_trace;
    wire [3*BITS-1:0]         cam_origin;
    wire [3*64-1:0]           cam_base, cam_dx, cam_dy;
    wire [3*16-1:0]           background;
    wire [MAX_LIGHTS*3*BITS-1:0] light_pos;
    wire [MAX_LIGHTS*3*16-1:0]   light_col;
    wire [MAX_LIGHTS-1:0]        light_shadowless;
    wire [2*SLOTS-1:0]        node_op;
    wire [8*SLOTS-1:0]        slot_material;
    wire [SLOTS-1:0]          slot_used;
    wire [LEAF_BITS-1:0]      leaf_a_addr, leaf_b_addr;
    wire [10*BITS-1:0]        leaf_a_coef, leaf_b_coef;
    wire [TREE_HEIGHT-1:0]    leaf_a_slot;
    wire [7:0]                mat_addr;
    wire [MAT_W-1:0]          mat;
    wire [1:0]                mat_want;   // mat's {filter != 0, reflection != 0}
    wire [LEAF_BITS-1:0]      leaf_c_addr;
    wire [10*BITS-1:0]        leaf_c_coef;
    wire [7:0]                ior_a_addr, ior_b_addr;
    wire [15:0]               ior_a, ior_b;
    wire [255:0]              mat_clear;

    csgrt_scene_loader #(
        .BITS(BITS), .MAX_LEAVES(MAX_LEAVES), .TREE_HEIGHT(TREE_HEIGHT),
        .MAX_LIGHTS(MAX_LIGHTS), .MAX_MATERIALS(MAX_MATERIALS)
    ) u_loader (
        .clk_i, .rst_ni,
        .word_valid_i (load_valid_i), .word_ready_o (load_ready_o), .word_i (load_word_i),
        .loaded_o, .error_o (load_error_o),
        .width_o (width), .height_o (height), .num_leaves_o (num_leaves), .num_lights_o (num_lights),
        .max_trace_o (max_trace),
        .cam_origin_o (cam_origin), .cam_base_o (cam_base), .cam_dx_o (cam_dx), .cam_dy_o (cam_dy),
        .background_o (background), .light_pos_o (light_pos), .light_col_o (light_col),
        .light_shadowless_o (light_shadowless),
        .node_op_o (node_op), .slot_material_o (slot_material), .slot_used_o (slot_used),
        .leaf_a_addr_i (leaf_a_addr), .leaf_a_coef_o (leaf_a_coef), .leaf_a_slot_o (leaf_a_slot),
        .leaf_b_addr_i (leaf_b_addr), .leaf_b_coef_o (leaf_b_coef),
        .mat_addr_i (mat_addr), .mat_o (mat), .mat_want_o (mat_want),
        .leaf_c_addr_i (leaf_c_addr), .leaf_c_coef_o (leaf_c_coef),
        .ior_a_addr_i (ior_a_addr), .ior_a_o (ior_a), .ior_b_addr_i (ior_b_addr), .ior_b_o (ior_b),
        .mat_clear_o (mat_clear)
    );

    // ----------------------------------------------------------------- camera
    wire              cam_valid, cam_ready, cam_last, cam_busy, cam_done;
    wire [11:0]       cam_x, cam_y;
    wire [3*BITS-1:0] cam_o, cam_d;
    wire              start = start_i && loaded_o && (load_error_o == 4'd0) && !busy_o;   // the frame is accepted
    // The units start a clock after the frame is accepted (start_q): the
    // accept is two LUT levels of the controller's pulse and the loader's
    // flags, and what the start reaches (the camera's configuration
    // registers, the ray tree's pixel order, ~700 loads) then hangs on a
    // flip-flop instead (tools/logic_depth.py). The frame's cycle count
    // (stat_cycles_o, from the accept) includes that clock.
    reg               start_q;
    always @(posedge clk_i) start_q <= start && rst_ni;
    // The tie policy of the frame, taken when it starts: the event sorter's
    // keys (every cell's comparator) then depend on a register, not on an
    // input pin (in Verilator, logic that hangs on an input is evaluated
    // on every eval() call: it was a fifth of the simulation time).
    reg               ties_regular_q;
    always @(posedge clk_i)
        if (!rst_ni) ties_regular_q <= 1'b0;
        else if (start) ties_regular_q <= ties_regular_i;

    csgrt_camera #(.BITS(BITS), .II(SHARE_II)) u_camera (
        .clk_i, .rst_ni,
        .origin_i (cam_origin), .base_i (cam_base), .dx_i (cam_dx), .dy_i (cam_dy),
        .width_i (width), .height_i (height),
        .start_i (start_q), .busy_o (cam_busy), .done_o (cam_done),
        .m_valid_o (cam_valid), .m_ready_i (cam_ready),
        .m_x_o (cam_x), .m_y_o (cam_y), .m_o_o (cam_o), .m_d_o (cam_d), .m_last_o (cam_last)
    );

    // --------------------------------------------------------------- dispatch
    localparam U = NUM_UNITS;
    wire                   queue_valid, queue_ready;
    wire [RAY_W-1:0]       queue_ray;
    localparam GW = $clog2(NUM_UNITS + 1);
    wire                   group_valid, group_ready;
    wire [GW-1:0]          group_size;
    wire [U-1:0]           pair_valid, pair_ready;
    wire                   pair_last;
    wire [U*3*BITS-1:0]    pair_o, pair_d;
    wire [10*BITS-1:0]     pair_coef;
    wire [LEAF_BITS-1:0]   pair_leaf;
    wire [TREE_HEIGHT-1:0] pair_slot;

    // rays into the dispatcher: the camera's, or the ray tree's
    wire                   d_valid, d_ready, d_last;
    wire [RAY_W-1:0]       d_ray;
    wire [INFO_P-1:0]      d_info;
    wire [U-1:0]           lane_info_valid, lane_info_ready;
    wire [U*INFO_P-1:0]    lane_info;

    csgrt_dispatch #(.BITS(BITS), .LEAF_BITS(LEAF_BITS), .TREE_HEIGHT(TREE_HEIGHT), .NUM_UNITS(U),
                     .RAY_W(RAY_W), .INFO_W(INFO_W)) u_dispatch (
        .clk_i, .rst_ni,
        .num_leaves_i (num_leaves),
        .ray_valid_i (d_valid), .ray_ready_o (d_ready), .ray_i (d_ray),
        .ray_last_i (d_last), .info_i (d_info),
        .info_valid_o (lane_info_valid), .info_ready_i (lane_info_ready), .info_o (lane_info),
        .queue_valid_o (queue_valid), .queue_ready_i (queue_ready), .queue_ray_o (queue_ray),
        .group_valid_o (group_valid), .group_ready_i (group_ready), .group_size_o (group_size),
        .leaf_addr_o (leaf_a_addr), .leaf_coef_i (leaf_a_coef), .leaf_slot_i (leaf_a_slot),
        .pair_valid_o (pair_valid), .pair_ready_i (pair_ready),
        .pair_o_o (pair_o), .pair_d_o (pair_d), .pair_coef_o (pair_coef),
        .pair_leaf_o (pair_leaf), .pair_slot_o (pair_slot), .pair_last_o (pair_last)
    );

    // ------------------------------------------- lanes: isect + walk unit
    // Lane k traces rays k, k+U, k+2U, ... ; the merge below takes their hit
    // records back in ray order.
    wire [U-1:0]             w_valid, w_ready, w_hit, w_entering;
    wire [U*(BITS-1)-1:0]    w_t;
    wire [U*LEAF_BITS-1:0]   w_leaf;
    wire [U*8-1:0]           w_from, w_to;
    wire [U*SLOTS-1:0]       w_near, w_after;
    wire [U*RUN_W-1:0]       w_run;
    wire [U-1:0]             l_res_valid, l_res_ready;
    wire [U*SIDE_W-1:0]      l_res_side;
    wire [U*2-1:0]           l_res_count, l_res_range0, l_res_range1;
    wire [U*(BITS-1)-1:0]    l_res_t0, l_res_t1;
    wire [U-1:0]             l_res_enter0, l_res_enter1, l_res_inside;

    genvar k;
    generate
        for (k = 0; k < U; k = k + 1) begin : g_unit
            wire [BITS-1:0]        res_a;
            wire [BITS+2:0]        res_b;
            wire [BITS+5:0]        res_c;
            wire [TREE_HEIGHT-1:0] w_slot;
            wire                   w_payload;
            // the ray's info word (csgrt_raytree's info(): {run, tlimit, flags, secondary})
            wire [INFO_P-1:0]      inf = lane_info[k*INFO_P +: INFO_P];
            wire                   inf_secondary, inf_valid;
            wire [SLOTS-1:0]       inf_flags;
            wire [BITS-3:0]        inf_tlimit;
            wire [RUN_W-1:0]       inf_run;
            wire [6*BITS-1:0]      inf_od;         // {o, d} (the look-ahead's test)
            wire                   inf_ready;
            if (EFFECTS) begin : g_info
                assign {inf_run, inf_tlimit, inf_flags, inf_secondary} = inf[RT_INFO_W-1:0];
                assign inf_valid = lane_info_valid[k];
                assign lane_info_ready[k] = inf_ready;
                if (LA) begin : g_od
                    assign inf_od = inf[INFO_P-1 -: 6*BITS];
                end else begin : g_no_od
                    assign inf_od = {(6*BITS){1'b0}};
                end
            end else begin : g_no_info
                assign {inf_run, inf_tlimit, inf_flags, inf_secondary} = {(RUN_W + BITS - 2 + SLOTS + 1){1'b0}};
                assign inf_od = {(6*BITS){1'b0}};
                assign inf_valid = 1'b0;
                assign lane_info_ready[k] = 1'b0;
                wire unused_inf = ^{inf, lane_info_valid[k], inf_ready};
            end

            csgrt_isect #(.BITS(BITS), .LEAF_WIDTH(SIDE_W), .II(ISECT_II)) u_isect (
                .clk_i, .rst_ni,
                .valid_i (pair_valid[k]), .ready_o (pair_ready[k]),
                .o_i (pair_o[k*3*BITS +: 3*BITS]), .d_i (pair_d[k*3*BITS +: 3*BITS]), .coef_i (pair_coef),
                .leaf_i ({pair_last, pair_slot, pair_leaf}),
                .valid_o (l_res_valid[k]), .ready_i (l_res_ready[k]), .leaf_o (l_res_side[k*SIDE_W +: SIDE_W]),
                .count_o (l_res_count[2*k +: 2]),
                .t0_o (l_res_t0[k*(BITS-1) +: BITS-1]), .range0_o (l_res_range0[2*k +: 2]),
                .enter0_o (l_res_enter0[k]),
                .t1_o (l_res_t1[k*(BITS-1) +: BITS-1]), .range1_o (l_res_range1[2*k +: 2]),
                .enter1_o (l_res_enter1[k]),
                .inside_o (l_res_inside[k]), .a_o (res_a), .b_o (res_b), .c_o (res_c)
            );
            // Q at the ray's origin is positive (the look-behind of secondary rays)
            wire cpos = !res_c[BITS+5] && (res_c != {(BITS+6){1'b0}});
            wire                 w_q_valid, w_q_ready, w_a_valid, w_a_ready, w_a_nonpos, w_q_payload;
            wire [BITS-2:0]      w_q_t;
            wire [LEAF_BITS-1:0] w_q_leaf;
            wire [3*BITS-1:0]    w_q_o, w_q_d;

            csgrt_walk_unit #(
                .BITS(BITS), .MAX_LEAVES(MAX_LEAVES), .LEAF_BITS(LEAF_BITS), .TREE_HEIGHT(TREE_HEIGHT),
                .MAT_BITS(8), .PAYLOAD_WIDTH(1), .SECONDARY(EFFECTS ? 1 : 0), .LOOK_BEHIND(LOOK_BEHIND),
                .LOOK_AHEAD(LA ? 1 : 0), .SORT_INSERTS(SORT_INSERTS)
            ) u_walk (
                .clk_i, .rst_ni,
                .ties_regular_i (ties_regular_q), .node_op_i (node_op), .slot_mat_i (slot_material), .slot_used_i (slot_used),
                .valid_i (l_res_valid[k]), .ready_o (l_res_ready[k]),
                .slot_i (l_res_side[k*SIDE_W + LEAF_BITS +: TREE_HEIGHT]),
                .leaf_i (l_res_side[k*SIDE_W +: LEAF_BITS]),
                .count_i (l_res_count[2*k +: 2]),
                .t0_i (l_res_t0[k*(BITS-1) +: BITS-1]), .range0_i (l_res_range0[2*k +: 2]),
                .enter0_i (l_res_enter0[k]),
                .t1_i (l_res_t1[k*(BITS-1) +: BITS-1]), .range1_i (l_res_range1[2*k +: 2]),
                .enter1_i (l_res_enter1[k]),
                .inside_i (l_res_inside[k]), .last_i (l_res_side[k*SIDE_W + SIDE_W-1]), .payload_i (1'b0),
                .cpos_i (cpos),
                .info_valid_i (inf_valid), .info_ready_o (inf_ready), .info_secondary_i (inf_secondary),
                .info_flags_i (inf_flags), .info_tlimit_i (inf_tlimit),
                .info_lb_count_i (inf_run[0 +: LBC]),
                .info_lb_slot_i (inf_run[LBC +: LOOK_BEHIND*TREE_HEIGHT]),
                .info_lb_entering_i (inf_run[LBC + LOOK_BEHIND*TREE_HEIGHT +: LOOK_BEHIND]),
                .info_lb_same_t_i (inf_run[LBC + LOOK_BEHIND*(TREE_HEIGHT+1) +: LOOK_BEHIND]),
                .valid_o (w_valid[k]), .ready_i (w_ready[k]), .hit_o (w_hit[k]), .t_o (w_t[k*(BITS-1) +: BITS-1]),
                .leaf_o (w_leaf[k*LEAF_BITS +: LEAF_BITS]), .slot_o (w_slot), .entering_o (w_entering[k]),
                .from_o (w_from[8*k +: 8]), .to_o (w_to[8*k +: 8]), .flags_before_o (w_near[k*SLOTS +: SLOTS]),
                .payload_o (w_payload), .flags_after_o (w_after[k*SLOTS +: SLOTS]),
                .lb_count_o (w_run[k*RUN_W +: LBC]),
                .lb_slot_o (w_run[k*RUN_W + LBC +: LOOK_BEHIND*TREE_HEIGHT]),
                .lb_entering_o (w_run[k*RUN_W + LBC + LOOK_BEHIND*TREE_HEIGHT +: LOOK_BEHIND]),
                .lb_same_t_o (w_run[k*RUN_W + LBC + LOOK_BEHIND*(TREE_HEIGHT+1) +: LOOK_BEHIND]),
                // the look-ahead (LOOK_AHEAD = 0 ignores these)
                .mat_clear_i (mat_clear), .info_o_i (inf_od[6*BITS-1:3*BITS]), .info_d_i (inf_od[3*BITS-1:0]),
                .q_valid_o (w_q_valid), .q_ready_i (w_q_ready), .q_t_o (w_q_t),
                .q_leaf_o (w_q_leaf), .q_payload_o (w_q_payload), .q_o_o (w_q_o), .q_d_o (w_q_d),
                .a_valid_i (w_a_valid), .a_ready_o (w_a_ready), .a_nonpos_i (w_a_nonpos)
            );
            if (LA && k == 0) begin : g_beyond
                // "the hit point already lies beyond the surface": the
                // walker's query, the leaf's coefficients from read port C
                // (registered: valid the clock after the walker raises the
                // query; the leaf is steady while the walker waits)
                reg             coef_ok_q;
                wire [BITS+7:0] q_val;
                wire            qa_s_ready;
                always @(posedge clk_i) coef_ok_q <= rst_ni && w_q_valid && !w_q_ready;
                assign leaf_c_addr = w_q_leaf;
                assign w_q_ready   = qa_s_ready && coef_ok_q;
                csgrt_quadric_at #(.BITS(BITS), .USER_WIDTH(1)) u_beyond (
                    .clk_i, .rst_ni,
                    .s_valid_i (w_q_valid && coef_ok_q), .s_ready_o (qa_s_ready),
                    .s_o_i (w_q_o), .s_d_i (w_q_d), .s_t_i (w_q_t), .s_coef_i (leaf_c_coef), .s_user_i (1'b0),
                    .m_valid_o (w_a_valid), .m_ready_i (w_a_ready), .m_q_o (q_val),
                    /* verilator lint_off PINCONNECTEMPTY */
                    .m_user_o ()
                    /* verilator lint_on PINCONNECTEMPTY */
                );
                assign w_a_nonpos = q_val[BITS+7] || (q_val == {(BITS+8){1'b0}});
            end else begin : g_no_beyond
                assign w_q_ready  = 1'b0;
                assign w_a_valid  = 1'b0;
                assign w_a_nonpos = 1'b0;
                if (k == 0) begin : g_port_c
                    assign leaf_c_addr = {LEAF_BITS{1'b0}};
                end
                wire unused_beyond = ^{w_q_o, w_q_d, w_q_valid, w_q_t, w_q_leaf, w_a_ready};
            end

            // Not used: the coefficients along the ray (debug) but c's sign,
            // the hit's tree slot and the payload; the look-ahead's query port.
            wire unused_lane = &{1'b0, res_a, res_b, w_slot, w_payload, w_q_payload};
        end
    endgenerate

    // Lane 0's results, readable by the simulation harness for mismatch
    // reports (sim/top_sim.h; with one lane these are all the results).
    wire              res_valid  /*verilator public_flat_rd*/ = l_res_valid[0];
    wire              res_ready  /*verilator public_flat_rd*/ = l_res_ready[0];
    wire [SIDE_W-1:0] res_side   /*verilator public_flat_rd*/ = l_res_side[SIDE_W-1:0];
    wire [1:0]        res_count  /*verilator public_flat_rd*/ = l_res_count[1:0];
    wire [1:0]        res_range0 /*verilator public_flat_rd*/ = l_res_range0[1:0];
    wire [1:0]        res_range1 /*verilator public_flat_rd*/ = l_res_range1[1:0];
    wire [BITS-2:0]   res_t0     /*verilator public_flat_rd*/ = l_res_t0[BITS-2:0];
    wire [BITS-2:0]   res_t1     /*verilator public_flat_rd*/ = l_res_t1[BITS-2:0];
    wire              res_enter0 /*verilator public_flat_rd*/ = l_res_enter0[0];
    wire              res_enter1 /*verilator public_flat_rd*/ = l_res_enter1[0];
    wire              res_inside /*verilator public_flat_rd*/ = l_res_inside[0];

    // ---------------------------------------------------------------- merge
    // Hit records back in ray order: a group's ray k comes from lane k, the
    // group's size from the dispatcher's group queue.
    localparam LW = (U > 1) ? $clog2(U) : 1;
    reg  [LW-1:0] merge_lane_q;
    wire [31:0]   merge_lane = {{(32-LW){1'b0}}, merge_lane_q};
    wire          group_end  = merge_lane + 32'd1 == {{(32-GW){1'b0}}, group_size};   // the group's last lane
    wire hit_valid    /*verilator public_flat_rd*/ = w_valid[merge_lane] && group_valid;
    wire hit_ready    /*verilator public_flat_rd*/;
    wire hit_hit      /*verilator public_flat_rd*/ = w_hit[merge_lane];
    wire hit_entering /*verilator public_flat_rd*/ = w_entering[merge_lane];
    wire [BITS-2:0]      hit_t    /*verilator public_flat_rd*/ = w_t[merge_lane*(BITS-1) +: BITS-1];
    wire [LEAF_BITS-1:0] hit_leaf /*verilator public_flat_rd*/ = w_leaf[merge_lane*LEAF_BITS +: LEAF_BITS];
    wire [7:0]           hit_from /*verilator public_flat_rd*/ = w_from[merge_lane*8 +: 8];
    wire [7:0]           hit_to   /*verilator public_flat_rd*/ = w_to[merge_lane*8 +: 8];
    wire [SLOTS-1:0]     hit_near  = w_near[merge_lane*SLOTS +: SLOTS];
    wire [SLOTS-1:0]     hit_after = w_after[merge_lane*SLOTS +: SLOTS];
    wire [RUN_W-1:0]     hit_run   = w_run[merge_lane*RUN_W +: RUN_W];
    assign w_ready     = (hit_ready && group_valid) ? ({{(U-1){1'b0}}, 1'b1} << merge_lane) : {U{1'b0}};
    assign group_ready = hit_valid && hit_ready && group_end;

    always @(posedge clk_i) begin
        if (!rst_ni || start_q)
            merge_lane_q <= {LW{1'b0}};
        else if (hit_valid && hit_ready)
            merge_lane_q <= group_end ? {LW{1'b0}} : merge_lane_q + 1'b1;
    end

    // ---------------------------------------------------- shading lookup
    // Joins each hit record with its ray from the queue (both in ray order)
    // and reads the hit leaf's coefficients and the shown material (the one
    // the ray enters, or the one it leaves when it enters air).
    reg                l_valid_q, l_hit_q;
    reg [BITS-2:0]     l_t_q;
    reg [RAY_W-1:0]    l_ray_q;
    reg [LEAF_BITS-1:0] l_leaf_q;
    reg [7:0]          l_mat_q, l_to_q, l_from_q;
    reg [SLOTS-1:0]    l_near_q, l_after_q;
    reg [RUN_W-1:0]    l_run_q;
    wire               l_ready;       // the next stage takes the record
    wire               l_advance = !l_valid_q || l_ready;
    wire [7:0]         shown_mat = (hit_to != 8'd0) ? hit_to : hit_from;

    assign hit_ready   = l_advance && queue_valid;
    assign queue_ready = l_advance && hit_valid;
    assign leaf_b_addr = l_advance ? hit_leaf : l_leaf_q;    // hold the read while waiting
    assign mat_addr    = l_advance ? shown_mat : l_mat_q;
    assign ior_a_addr  = l_advance ? hit_from : l_from_q;     // ior_of(BORDER from), (to): refraction
    assign ior_b_addr  = l_advance ? hit_to : l_to_q;

    always @(posedge clk_i) begin
        if (!rst_ni) begin
            l_valid_q <= 1'b0;
        end else if (l_advance) begin
            l_valid_q <= hit_valid && queue_valid;
            l_hit_q   <= hit_hit;
            l_t_q     <= hit_t;
            l_ray_q   <= queue_ray;
            l_leaf_q  <= hit_leaf;
            l_mat_q   <= shown_mat;
            l_to_q    <= hit_to;
            l_from_q  <= hit_from;
            l_near_q  <= hit_near;
            l_after_q <= hit_after;
            l_run_q   <= hit_run;
        end
    end

    // -------------------------------------------------------------- shading
    wire [7:0] pix_r, pix_g, pix_b;
    generate
        if (!EFFECTS) begin : g_local
            // primary rays with local shading: the camera feeds the dispatcher
            assign d_valid   = cam_valid;
            assign cam_ready = d_ready;
            assign d_ray     = {cam_x, cam_y, cam_o, cam_d};
            assign d_last    = cam_last;
            assign d_info    = {INFO_P{1'b0}};

            wire unused_eff = ^{hit_entering, l_to_q, l_near_q, l_after_q, l_run_q, mat[MAT_W-1:96], mat_want, max_trace,
                                l_from_q, ior_a, ior_b, mat_clear, leaf_c_coef,
                                light_shadowless};   // every light is unshadowed here
            csgrt_shade #(.BITS(BITS), .MAX_LIGHTS(MAX_LIGHTS), .LUT_FILE(LUT_FILE), .SPECULAR(SPECULAR),
                          .II(SHARE_II)) u_shade (
                .clk_i, .rst_ni,
                .num_lights_i (num_lights[$clog2(MAX_LIGHTS+1)-1:0]), .light_pos_i (light_pos),
                .light_color_i (light_col), .background_i (background),
                .s_valid_i (l_valid_q), .s_ready_o (l_ready),
                .s_x_i (l_ray_q[RAY_W-1 -: 12]), .s_y_i (l_ray_q[RAY_W-13 -: 12]),
                .s_hit_i (l_hit_q), .s_t_i (l_t_q),
                .s_o_i (l_ray_q[6*BITS-1:3*BITS]), .s_d_i (l_ray_q[3*BITS-1:0]),
                .s_coef_i (leaf_b_coef),
                .s_rgb_i (mat[47:0]), .s_ambient_i (mat[63:48]), .s_diffuse_i (mat[79:64]),
                .s_phong_i (mat[95:80]), .s_phong_size_i (mat[121:112]),
                .m_valid_o (pix_valid_o), .m_ready_i (pix_ready_i),
                .m_x_o (pix_x_o), .m_y_o (pix_y_o), .m_r_o (pix_r), .m_g_o (pix_g), .m_b_o (pix_b),
                /* verilator lint_off PINCONNECTEMPTY */
                .m_local_o (), .m_spec_o (), .lc_tag_o (), .lc_k_o (),
                /* verilator lint_on PINCONNECTEMPTY */
                .lc_color_i (48'd0)
            );
            assign pix_rgb_o = {pix_r, pix_g, pix_b};
        end else begin : g_raytree
            // the ray tree: secondary rays, shading after the shadow rays
            wire [REC_W-1:0]  rt_rec;
            wire [3*BITS-1:0] rt_o, rt_d;
            wire [RT_INFO_W-1:0] rt_info;
            assign d_ray  = {rt_rec, rt_o, rt_d};
            if (LA) begin : g_info_od
                assign d_info = {rt_o, rt_d, rt_info};   // o, d for the look-ahead's test
            end else begin : g_info_plain
                assign d_info = rt_info;
                wire unused_rf = ^{ior_a, ior_b, mat_clear, leaf_c_coef};
            end
            assign d_last = 1'b0;   // one lane: every group is full

            wire                   sp_valid, sp_ready, sp_reflect, sp_refract;
            wire [15:0]            sp_ior_from, sp_ior_to;
            wire [3*BITS-1:0]      sp_o, sp_d;
            wire [BITS-2:0]        sp_t;
            wire [10*BITS-1:0]     sp_coef;
            wire [MAX_LIGHTS-1:0]  sp_lights;
            wire [CB-1:0]          sp_user;
            wire                   ch_valid, ch_valid_ev, ch_valid_rec, ch_ready, ch_lit, ch_last, ch_in_range;
            wire [2:0]             ch_kind;
            wire [KW-1:0]          ch_light;
            wire [3*BITS-1:0]      ch_p, ch_d;
            wire [DIST_W-1:0]      ch_dist;
            wire [CB-1:0]          ch_user;
            wire                   sh_valid, sh_ready;
            wire [11:0]            sh_tag;
            wire [3*BITS-1:0]      sh_o, sh_d;
            wire [BITS-2:0]        sh_t;
            wire [10*BITS-1:0]     sh_coef;
            wire [MAT_W-1:0]       sh_mat;
            wire [11:0]            lc_tag;
            wire [$clog2(MAX_LIGHTS+1)-1:0] lc_k;
            wire [47:0]            lc_color;
            wire                   sr_valid, sr_ready;
            wire [11:0]            sr_tag, sr_y;
            wire [3*31-1:0]        sr_local;
            wire [3*26-1:0]        sr_spec;

            // The camera's rays reach the ray tree through a register slice
            // of their own (csgrt_hold): the ray tree takes a new pixel last
            // in its event priority (after a contribution, a child ray from
            // csgrt_spawn, a hit, a stack pop), so its cam_ready_o is a
            // decode of those sources' valid bits from across the die. It
            // reached the camera's output skid and stage enable
            // (csgrt_beat): the longest path of the routed BITS 16 H 5
            // effects build once the spawn queue's read was registered
            // (14.71 ns, 12.48 of them routing; docs/fpga.md). Through a
            // two-word skid buffer instead, the decode still reached the
            // buffer's word registers' enables, placed beside the camera
            // (13.00 ns). The slice's ready_o and its data enable are its
            // full bit, so the decode reaches that one flip-flop only. One
            // clock more of latency per primary ray; a ray every 2 clocks
            // at most, more than the ray tree takes.
            wire                   cs_valid, cs_ready;
            wire [11:0]            cs_x, cs_y;
            wire [3*BITS-1:0]      cs_o, cs_d;
            csgrt_hold #(.WIDTH(24 + 6 * BITS)) u_cam_hold (
                .clk_i, .rst_ni,
                .valid_i (cam_valid), .ready_o (cam_ready), .data_i ({cam_x, cam_y, cam_o, cam_d}),
                .valid_o (cs_valid), .ready_i (cs_ready), .data_o ({cs_x, cs_y, cs_o, cs_d}));

            // The hit record reaches the ray tree through a register slice
            // (csgrt_hold) with the shading lookup's reads: the material
            // comes from a block RAM whose output is not registered (5.6 ns
            // from clock to data on the ECP5), and went on through a LUT
            // and across the die into the hit preparation's record FIFO,
            // another block RAM: the routed critical path of 26aefb0's
            // BITS 16 H 5 effects build (docs/fpga.md, item 13). The
            // lookup's ready is then the slice's full bit. One clock more
            // per hit record, and a record every 2 clocks at most: each is
            // a whole ray's walk.
            localparam TRW = REC_W + 6 * BITS + 1 + (BITS - 1) + 8 + 10 * BITS + MAT_W + 2
                           + 2 * SLOTS + RUN_W + 32;
            wire                   tr_valid, tr_ready;
            wire [REC_W-1:0]       tr_rec;
            wire [3*BITS-1:0]      tr_o, tr_d;
            wire                   tr_hit;
            wire [BITS-2:0]        tr_t;
            wire [7:0]             tr_to;
            wire [10*BITS-1:0]     tr_coef;
            wire [MAT_W-1:0]       tr_mat;
            wire [1:0]             tr_mat_want;
            wire [SLOTS-1:0]       tr_near, tr_after;
            wire [RUN_W-1:0]       tr_run;
            wire [15:0]            tr_ior_from, tr_ior_to;
            csgrt_hold #(.WIDTH(TRW)) u_hit_hold (
                .clk_i, .rst_ni,
                .valid_i (l_valid_q), .ready_o (l_ready),
                .data_i ({l_ray_q[RAY_W-1 -: REC_W], l_ray_q[6*BITS-1:0], l_hit_q, l_t_q, l_to_q, leaf_b_coef,
                          mat, mat_want, l_near_q, l_after_q, l_run_q, ior_a, ior_b}),
                .valid_o (tr_valid), .ready_i (tr_ready),
                .data_o ({tr_rec, tr_o, tr_d, tr_hit, tr_t, tr_to, tr_coef,
                          tr_mat, tr_mat_want, tr_near, tr_after, tr_run, tr_ior_from, tr_ior_to}));

            csgrt_raytree #(
                .BITS(BITS), .TREE_HEIGHT(TREE_HEIGHT), .MAX_LIGHTS(MAX_LIGHTS), .CONTEXTS(CONTEXTS),
                .MAX_DEPTH(MAX_DEPTH), .LOOK_BEHIND(LOOK_BEHIND), .SHADOWS(SHADOWS), .REFLECTION(REFLECTION),
                .REFRACTION(REFRACTION),
                .DIST_W(DIST_W), .MAT_W(MAT_W), .COL_W(31), .SPEC_W(26), .LUT_FILE(LUT_FILE), .II(SHARE_II)
            ) u_raytree (
                .clk_i, .rst_ni, .start_i (start_q),
                .num_lights_i (num_lights[$clog2(MAX_LIGHTS+1)-1:0]), .light_color_i (light_col),
                .light_shadowless_i (light_shadowless),
                .background_i (background), .max_trace_i (max_trace),
                .cam_valid_i (cs_valid), .cam_ready_o (cs_ready), .cam_x_i (cs_x), .cam_y_i (cs_y),
                .cam_o_i (cs_o), .cam_d_i (cs_d),
                .ray_valid_o (d_valid), .ray_ready_i (d_ready), .ray_rec_o (rt_rec), .ray_o_o (rt_o),
                .ray_d_o (rt_d), .ray_info_o (rt_info),
                .tr_valid_i (tr_valid), .tr_ready_o (tr_ready), .tr_rec_i (tr_rec),
                .tr_o_i (tr_o), .tr_d_i (tr_d),
                .tr_hit_i (tr_hit), .tr_t_i (tr_t), .tr_to_i (tr_to), .tr_coef_i (tr_coef),
                .tr_mat_i (tr_mat), .tr_mat_want_i (tr_mat_want), .tr_flags_near_i (tr_near), .tr_run_i (tr_run),
                .tr_flags_after_i (tr_after), .tr_ior_from_i (tr_ior_from), .tr_ior_to_i (tr_ior_to),
                .sp_valid_o (sp_valid), .sp_ready_i (sp_ready), .sp_o_o (sp_o), .sp_d_o (sp_d), .sp_t_o (sp_t),
                .sp_coef_o (sp_coef), .sp_lights_o (sp_lights), .sp_reflect_o (sp_reflect), .sp_user_o (sp_user),
                .sp_refract_o (sp_refract), .sp_ior_from_o (sp_ior_from), .sp_ior_to_o (sp_ior_to),
                .ch_valid_i (ch_valid), .ch_valid_ev_i (ch_valid_ev), .ch_valid_rec_i (ch_valid_rec), .ch_ready_o (ch_ready), .ch_kind_i (ch_kind), .ch_light_i (ch_light),
                .ch_p_i (ch_p), .ch_d_i (ch_d), .ch_dist_i (ch_dist), .ch_lit_i (ch_lit), .ch_last_i (ch_last),
                .ch_user_i (ch_user),
                .sh_valid_o (sh_valid), .sh_ready_i (sh_ready), .sh_tag_o (sh_tag), .sh_o_o (sh_o), .sh_d_o (sh_d),
                .sh_t_o (sh_t), .sh_coef_o (sh_coef), .sh_mat_o (sh_mat),
                .lc_tag_i (lc_tag), .lc_k_i (lc_k), .lc_color_o (lc_color),
                .sr_valid_i (sr_valid), .sr_ready_o (sr_ready), .sr_tag_i (sr_tag), .sr_local_i (sr_local),
                .sr_spec_i (sr_spec),
                .pix_valid_o (pix_valid_o), .pix_ready_i (pix_ready_i), .pix_x_o (pix_x_o), .pix_y_o (pix_y_o),
                .pix_rgb_o (pix_rgb_o)
            );

            csgrt_spawn #(.BITS(BITS), .MAX_LIGHTS(MAX_LIGHTS), .USER_WIDTH(CB), .SHADOWS(SHADOWS),
                          .REFLECTION(REFLECTION), .REFRACTION(REFRACTION), .II(SHARE_II)) u_spawn (
                .clk_i, .rst_ni, .light_pos_i (light_pos),
                .s_valid_i (sp_valid), .s_ready_o (sp_ready), .s_o_i (sp_o), .s_d_i (sp_d), .s_t_i (sp_t),
                .s_coef_i (sp_coef), .s_ior_from_i (sp_ior_from), .s_ior_to_i (sp_ior_to), .s_lights_i (sp_lights),
                .s_reflect_i (sp_reflect), .s_refract_i (sp_refract), .s_continue_i (1'b0), .s_user_i (sp_user),
                .m_valid_o (ch_valid), .m_valid_copy_o (ch_valid_ev), .m_valid_rec_o (ch_valid_rec), .m_ready_i (ch_ready), .m_kind_o (ch_kind), .m_light_o (ch_light),
                .m_o_o (ch_p), .m_in_range_o (ch_in_range), .m_d_o (ch_d), .m_dist_o (ch_dist), .m_lit_o (ch_lit),
                .m_last_o (ch_last), .m_user_o (ch_user)
            );
            wire unused_ch = ^{ch_in_range, sr_y, hit_entering, l_mat_q, cam_last};

            csgrt_shade #(.BITS(BITS), .MAX_LIGHTS(MAX_LIGHTS), .LUT_FILE(LUT_FILE),
                          .LINEAR_OUT(1), .EXT_LIGHT(1), .SPECULAR(SPECULAR), .II(SHARE_II)) u_shade (
                .clk_i, .rst_ni,
                .num_lights_i (num_lights[$clog2(MAX_LIGHTS+1)-1:0]), .light_pos_i (light_pos),
                .light_color_i (light_col), .background_i (background),
                .s_valid_i (sh_valid), .s_ready_o (sh_ready),
                .s_x_i (sh_tag), .s_y_i (12'd0), .s_hit_i (1'b1), .s_t_i (sh_t),
                .s_o_i (sh_o), .s_d_i (sh_d), .s_coef_i (sh_coef),
                .s_rgb_i (sh_mat[47:0]), .s_ambient_i (sh_mat[63:48]), .s_diffuse_i (sh_mat[79:64]),
                .s_phong_i (sh_mat[95:80]), .s_phong_size_i (sh_mat[121:112]),
                .m_valid_o (sr_valid), .m_ready_i (sr_ready),
                .m_x_o (sr_tag), .m_y_o (sr_y), .m_r_o (pix_r), .m_g_o (pix_g), .m_b_o (pix_b),
                .m_local_o (sr_local), .m_spec_o (sr_spec), .lc_tag_o (lc_tag), .lc_k_o (lc_k),
                .lc_color_i (lc_color)
            );
            wire unused_pix = ^{pix_r, pix_g, pix_b, sh_mat[MAT_W-1:122], sh_mat[111:96]};
        end
    endgenerate


    generate
        if (NUM_UNITS > 1 && REFRACTION != 0) begin : g_bad_param
            // the look-ahead's quadric test (csgrt_quadric_at) answers lane 0 only
            initial begin
                $display("ERROR %m: REFRACTION needs NUM_UNITS = 1 (the look-ahead's quadric test serves one lane)");
                $finish;
            end
        end
    endgenerate

    // ---------------------------------------------------- frame and statistics
    reg [63:0] pairs_now;   // pairs handed to the lanes in this clock
    integer u;
    always @* begin
        pairs_now = 64'd0;
        for (u = 0; u < U; u = u + 1) pairs_now = pairs_now + {63'd0, pair_valid[u] && pair_ready[u]};
    end

    wire last_pixel = pix_valid_o && pix_ready_i && pix_x_o == width - 12'd1 && pix_y_o == height - 12'd1;
    always @(posedge clk_i) begin
        if (!rst_ni) begin
            busy_o        <= 1'b0;
            done_o        <= 1'b0;
            stat_cycles_o <= 64'd0;
            stat_pairs_o  <= 64'd0;
        end else begin
            done_o <= 1'b0;
            if (start) begin
                busy_o        <= 1'b1;
                stat_cycles_o <= 64'd0;
                stat_pairs_o  <= 64'd0;
            end else if (busy_o) begin
                stat_cycles_o <= stat_cycles_o + 64'd1;
                stat_pairs_o <= stat_pairs_o + pairs_now;
                if (last_pixel) begin
                    busy_o <= 1'b0;
                    done_o <= 1'b1;
                end
            end
        end
    end

    // Not used: the camera's own frame flags (the frame ends at the last
    // pixel) and the light count's high bits beyond MAX_LIGHTS.
    wire unused_ok = &{1'b0, cam_busy, cam_done, num_lights};
endmodule
`default_nettype wire
