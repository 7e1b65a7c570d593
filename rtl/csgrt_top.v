`default_nettype none
// csgrt_top — the exact CSG ray tracer: scene image in, pixels out, equal bit
// for bit to the golden model's fixed path (docs/architecture.md).
//
//   scene words -> loader -> camera -> dispatch -> isect -> walk unit
//                                          |                   |
//                                       ray queue ------> lookup -> shade -> pixels
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
    parameter LUT_FILE      = "rtl/srgb_lut.hex",
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
    input  wire        ties_regular_i,  // tie policy: 0 paper, 1 regular
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
    localparam RAY_W = 24 + 6 * BITS;          // {x, y, o, d}
    localparam SIDE_W = 1 + TREE_HEIGHT + LEAF_BITS;   // {last, slot, leaf} beside a pair
    localparam MAT_W = 7 * 16 + 10;

    // ------------------------------------------------------------------ scene
    wire [11:0]               width, height;
    wire [LEAF_BITS:0]        num_leaves;
    wire [3:0]                num_lights;
    wire [3*BITS-1:0]         cam_origin;
    wire [3*64-1:0]           cam_base, cam_dx, cam_dy;
    wire [3*16-1:0]           background;
    wire [MAX_LIGHTS*3*BITS-1:0] light_pos;
    wire [MAX_LIGHTS*3*16-1:0]   light_col;
    wire [2*SLOTS-1:0]        node_op;
    wire [8*SLOTS-1:0]        slot_material;
    wire [SLOTS-1:0]          slot_used;
    wire [LEAF_BITS-1:0]      leaf_a_addr, leaf_b_addr;
    wire [10*BITS-1:0]        leaf_a_coef, leaf_b_coef;
    wire [TREE_HEIGHT-1:0]    leaf_a_slot;
    wire [7:0]                mat_addr;
    wire [MAT_W-1:0]          mat;

    csgrt_scene_loader #(
        .BITS(BITS), .MAX_LEAVES(MAX_LEAVES), .TREE_HEIGHT(TREE_HEIGHT),
        .MAX_LIGHTS(MAX_LIGHTS), .MAX_MATERIALS(MAX_MATERIALS)
    ) u_loader (
        .clk_i, .rst_ni,
        .word_valid_i (load_valid_i), .word_ready_o (load_ready_o), .word_i (load_word_i),
        .loaded_o, .error_o (load_error_o),
        .width_o (width), .height_o (height), .num_leaves_o (num_leaves), .num_lights_o (num_lights),
        .cam_origin_o (cam_origin), .cam_base_o (cam_base), .cam_dx_o (cam_dx), .cam_dy_o (cam_dy),
        .background_o (background), .light_pos_o (light_pos), .light_col_o (light_col),
        .node_op_o (node_op), .slot_material_o (slot_material), .slot_used_o (slot_used),
        .leaf_a_addr_i (leaf_a_addr), .leaf_a_coef_o (leaf_a_coef), .leaf_a_slot_o (leaf_a_slot),
        .leaf_b_addr_i (leaf_b_addr), .leaf_b_coef_o (leaf_b_coef),
        .mat_addr_i (mat_addr), .mat_o (mat)
    );

    // ----------------------------------------------------------------- camera
    wire              cam_valid, cam_ready, cam_last, cam_busy, cam_done;
    wire [11:0]       cam_x, cam_y;
    wire [3*BITS-1:0] cam_o, cam_d;
    wire              start = start_i && loaded_o && (load_error_o == 4'd0) && !busy_o;

    csgrt_camera #(.BITS(BITS)) u_camera (
        .clk_i, .rst_ni,
        .origin_i (cam_origin), .base_i (cam_base), .dx_i (cam_dx), .dy_i (cam_dy),
        .width_i (width), .height_i (height),
        .start_i (start), .busy_o (cam_busy), .done_o (cam_done),
        .m_valid_o (cam_valid), .m_ready_i (cam_ready),
        .m_x_o (cam_x), .m_y_o (cam_y), .m_o_o (cam_o), .m_d_o (cam_d), .m_last_o (cam_last)
    );

    // --------------------------------------------------------------- dispatch
    localparam U = NUM_UNITS;
    wire                   queue_valid, queue_ready;
    wire [RAY_W-1:0]       queue_ray;
    wire [U-1:0]           pair_valid, pair_ready;
    wire                   pair_last;
    wire [U*3*BITS-1:0]    pair_o, pair_d;
    wire [10*BITS-1:0]     pair_coef;
    wire [LEAF_BITS-1:0]   pair_leaf;
    wire [TREE_HEIGHT-1:0] pair_slot;

    csgrt_dispatch #(.BITS(BITS), .LEAF_BITS(LEAF_BITS), .TREE_HEIGHT(TREE_HEIGHT), .NUM_UNITS(U)) u_dispatch (
        .clk_i, .rst_ni,
        .num_leaves_i (num_leaves),
        .ray_valid_i (cam_valid), .ray_ready_o (cam_ready), .ray_i ({cam_x, cam_y, cam_o, cam_d}),
        .ray_last_i (cam_last),
        .queue_valid_o (queue_valid), .queue_ready_i (queue_ready), .queue_ray_o (queue_ray),
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
            wire [SLOTS-1:0]       w_flags_before;
            wire                   w_payload;

            csgrt_isect #(.BITS(BITS), .LEAF_WIDTH(SIDE_W)) u_isect (
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

            csgrt_walk_unit #(
                .BITS(BITS), .MAX_LEAVES(MAX_LEAVES), .LEAF_BITS(LEAF_BITS), .TREE_HEIGHT(TREE_HEIGHT),
                .MAT_BITS(8), .PAYLOAD_WIDTH(1)
            ) u_walk (
                .clk_i, .rst_ni,
                .ties_regular_i, .node_op_i (node_op), .slot_mat_i (slot_material), .slot_used_i (slot_used),
                .valid_i (l_res_valid[k]), .ready_o (l_res_ready[k]),
                .slot_i (l_res_side[k*SIDE_W + LEAF_BITS +: TREE_HEIGHT]),
                .leaf_i (l_res_side[k*SIDE_W +: LEAF_BITS]),
                .count_i (l_res_count[2*k +: 2]),
                .t0_i (l_res_t0[k*(BITS-1) +: BITS-1]), .range0_i (l_res_range0[2*k +: 2]),
                .enter0_i (l_res_enter0[k]),
                .t1_i (l_res_t1[k*(BITS-1) +: BITS-1]), .range1_i (l_res_range1[2*k +: 2]),
                .enter1_i (l_res_enter1[k]),
                .inside_i (l_res_inside[k]), .last_i (l_res_side[k*SIDE_W + SIDE_W-1]), .payload_i (1'b0),
                .valid_o (w_valid[k]), .ready_i (w_ready[k]), .hit_o (w_hit[k]), .t_o (w_t[k*(BITS-1) +: BITS-1]),
                .leaf_o (w_leaf[k*LEAF_BITS +: LEAF_BITS]), .slot_o (w_slot), .entering_o (w_entering[k]),
                .from_o (w_from[8*k +: 8]), .to_o (w_to[8*k +: 8]), .flags_before_o (w_flags_before),
                .payload_o (w_payload)
            );

            // Not used yet: the coefficients along the ray (debug), the hit's
            // tree slot, near-side flags and payload (secondary rays, later).
            wire unused_lane = &{1'b0, res_a, res_b, res_c, w_slot, w_flags_before, w_payload};
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
    // Hit records back in ray order: ray n comes from lane n mod U.
    localparam LW = (U > 1) ? $clog2(U) : 1;
    reg  [LW-1:0] merge_lane_q;
    wire [31:0]   merge_lane = {{(32-LW){1'b0}}, merge_lane_q};
    wire hit_valid    /*verilator public_flat_rd*/ = w_valid[merge_lane];
    wire hit_ready    /*verilator public_flat_rd*/;
    wire hit_hit      /*verilator public_flat_rd*/ = w_hit[merge_lane];
    wire hit_entering /*verilator public_flat_rd*/ = w_entering[merge_lane];
    wire [BITS-2:0]      hit_t    /*verilator public_flat_rd*/ = w_t[merge_lane*(BITS-1) +: BITS-1];
    wire [LEAF_BITS-1:0] hit_leaf /*verilator public_flat_rd*/ = w_leaf[merge_lane*LEAF_BITS +: LEAF_BITS];
    wire [7:0]           hit_from /*verilator public_flat_rd*/ = w_from[merge_lane*8 +: 8];
    wire [7:0]           hit_to   /*verilator public_flat_rd*/ = w_to[merge_lane*8 +: 8];
    assign w_ready = hit_ready ? ({{(U-1){1'b0}}, 1'b1} << merge_lane) : {U{1'b0}};

    always @(posedge clk_i) begin
        if (!rst_ni || start)
            merge_lane_q <= {LW{1'b0}};
        else if (hit_valid && hit_ready)
            merge_lane_q <= (merge_lane + 32'd1 == U) ? {LW{1'b0}} : merge_lane_q + 1'b1;
    end

    // ---------------------------------------------------- shading lookup
    // Joins each hit record with its ray from the queue (both in ray order)
    // and reads the hit leaf's coefficients and the shown material (the one
    // the ray enters, or the one it leaves when it enters air).
    reg                l_valid_q, l_hit_q;
    reg [BITS-2:0]     l_t_q;
    reg [RAY_W-1:0]    l_ray_q;
    reg [LEAF_BITS-1:0] l_leaf_q;
    reg [7:0]          l_mat_q;
    wire               shade_ready;
    wire               l_advance = !l_valid_q || shade_ready;
    wire [7:0]         shown_mat = (hit_to != 8'd0) ? hit_to : hit_from;

    assign hit_ready   = l_advance && queue_valid;
    assign queue_ready = l_advance && hit_valid;
    assign leaf_b_addr = l_advance ? hit_leaf : l_leaf_q;    // hold the read while waiting
    assign mat_addr    = l_advance ? shown_mat : l_mat_q;

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
        end
    end

    // -------------------------------------------------------------- shading
    wire [7:0] pix_r, pix_g, pix_b;
    csgrt_shade #(.BITS(BITS), .MAX_LIGHTS(MAX_LIGHTS), .LUT_FILE(LUT_FILE)) u_shade (
        .clk_i, .rst_ni,
        .num_lights_i (num_lights[$clog2(MAX_LIGHTS+1)-1:0]), .light_pos_i (light_pos),
        .light_color_i (light_col), .background_i (background),
        .s_valid_i (l_valid_q), .s_ready_o (shade_ready),
        .s_x_i (l_ray_q[RAY_W-1 -: 12]), .s_y_i (l_ray_q[RAY_W-13 -: 12]),
        .s_hit_i (l_hit_q), .s_t_i (l_t_q),
        .s_o_i (l_ray_q[6*BITS-1:3*BITS]), .s_d_i (l_ray_q[3*BITS-1:0]),
        .s_coef_i (leaf_b_coef),
        .s_rgb_i (mat[47:0]), .s_ambient_i (mat[63:48]), .s_diffuse_i (mat[79:64]),
        .s_phong_i (mat[95:80]), .s_phong_size_i (mat[121:112]),
        .m_valid_o (pix_valid_o), .m_ready_i (pix_ready_i),
        .m_x_o (pix_x_o), .m_y_o (pix_y_o), .m_r_o (pix_r), .m_g_o (pix_g), .m_b_o (pix_b)
    );
    assign pix_rgb_o = {pix_r, pix_g, pix_b};

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

    // Signals this configuration does not use yet: the camera's own frame
    // flags (the frame ends at the last pixel), the hit's entering flag and
    // the material's reflection field (effects, later).
    wire unused_ok = &{1'b0, cam_busy, cam_done, hit_entering, mat[111:96], num_lights};
endmodule
`default_nettype wire
