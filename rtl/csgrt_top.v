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
    parameter NUM_UNITS     = 1,     // intersection lanes (1 today)
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
    output reg  [63:0] stat_pairs_o
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
    wire                   queue_valid, queue_ready;
    wire [RAY_W-1:0]       queue_ray;
    wire                   pair_valid, pair_ready, pair_last;
    wire [3*BITS-1:0]      pair_o, pair_d;
    wire [10*BITS-1:0]     pair_coef;
    wire [LEAF_BITS-1:0]   pair_leaf;
    wire [TREE_HEIGHT-1:0] pair_slot;

    csgrt_dispatch #(.BITS(BITS), .LEAF_BITS(LEAF_BITS), .TREE_HEIGHT(TREE_HEIGHT)) u_dispatch (
        .clk_i, .rst_ni,
        .num_leaves_i (num_leaves),
        .ray_valid_i (cam_valid), .ray_ready_o (cam_ready), .ray_i ({cam_x, cam_y, cam_o, cam_d}),
        .queue_valid_o (queue_valid), .queue_ready_i (queue_ready), .queue_ray_o (queue_ray),
        .leaf_addr_o (leaf_a_addr), .leaf_coef_i (leaf_a_coef), .leaf_slot_i (leaf_a_slot),
        .pair_valid_o (pair_valid), .pair_ready_i (pair_ready),
        .pair_o_o (pair_o), .pair_d_o (pair_d), .pair_coef_o (pair_coef),
        .pair_leaf_o (pair_leaf), .pair_slot_o (pair_slot), .pair_last_o (pair_last)
    );

    // ---------------------------------------------------- intersection unit
    // (verilator public_flat_rd: the simulation harness logs these for
    // mismatch reports, sim/top_sim.h)
    wire              res_valid /*verilator public_flat_rd*/;
    wire              res_ready /*verilator public_flat_rd*/;
    wire [SIDE_W-1:0] res_side /*verilator public_flat_rd*/;
    wire [1:0]        res_count /*verilator public_flat_rd*/;
    wire [1:0]        res_range0 /*verilator public_flat_rd*/;
    wire [1:0]        res_range1 /*verilator public_flat_rd*/;
    wire [BITS-2:0]   res_t0 /*verilator public_flat_rd*/;
    wire [BITS-2:0]   res_t1 /*verilator public_flat_rd*/;
    wire              res_enter0 /*verilator public_flat_rd*/;
    wire              res_enter1 /*verilator public_flat_rd*/;
    wire              res_inside /*verilator public_flat_rd*/;
    wire [BITS-1:0]   res_a;
    wire [BITS+2:0]   res_b;
    wire [BITS+5:0]   res_c;

    csgrt_isect #(.BITS(BITS), .LEAF_WIDTH(SIDE_W)) u_isect (
        .clk_i, .rst_ni,
        .valid_i (pair_valid), .ready_o (pair_ready),
        .o_i (pair_o), .d_i (pair_d), .coef_i (pair_coef), .leaf_i ({pair_last, pair_slot, pair_leaf}),
        .valid_o (res_valid), .ready_i (res_ready), .leaf_o (res_side),
        .count_o (res_count),
        .t0_o (res_t0), .range0_o (res_range0), .enter0_o (res_enter0),
        .t1_o (res_t1), .range1_o (res_range1), .enter1_o (res_enter1),
        .inside_o (res_inside), .a_o (res_a), .b_o (res_b), .c_o (res_c)
    );

    // -------------------------------------------------------------- walk unit
    wire                   hit_valid /*verilator public_flat_rd*/;
    wire                   hit_ready /*verilator public_flat_rd*/;
    wire                   hit_hit /*verilator public_flat_rd*/;
    wire                   hit_entering /*verilator public_flat_rd*/;
    wire [BITS-2:0]        hit_t /*verilator public_flat_rd*/;
    wire [LEAF_BITS-1:0]   hit_leaf /*verilator public_flat_rd*/;
    wire [TREE_HEIGHT-1:0] hit_slot;
    wire [7:0]             hit_from /*verilator public_flat_rd*/;
    wire [7:0]             hit_to /*verilator public_flat_rd*/;
    wire [SLOTS-1:0]       hit_flags_before;
    wire                   hit_payload;

    csgrt_walk_unit #(
        .BITS(BITS), .MAX_LEAVES(MAX_LEAVES), .LEAF_BITS(LEAF_BITS), .TREE_HEIGHT(TREE_HEIGHT),
        .MAT_BITS(8), .PAYLOAD_WIDTH(1)
    ) u_walk (
        .clk_i, .rst_ni,
        .ties_regular_i, .node_op_i (node_op), .slot_mat_i (slot_material), .slot_used_i (slot_used),
        .valid_i (res_valid), .ready_o (res_ready),
        .slot_i (res_side[LEAF_BITS +: TREE_HEIGHT]), .leaf_i (res_side[LEAF_BITS-1:0]),
        .count_i (res_count),
        .t0_i (res_t0), .range0_i (res_range0), .enter0_i (res_enter0),
        .t1_i (res_t1), .range1_i (res_range1), .enter1_i (res_enter1),
        .inside_i (res_inside), .last_i (res_side[SIDE_W-1]), .payload_i (1'b0),
        .valid_o (hit_valid), .ready_i (hit_ready), .hit_o (hit_hit), .t_o (hit_t),
        .leaf_o (hit_leaf), .slot_o (hit_slot), .entering_o (hit_entering),
        .from_o (hit_from), .to_o (hit_to), .flags_before_o (hit_flags_before), .payload_o (hit_payload)
    );

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
                if (pair_valid && pair_ready) stat_pairs_o <= stat_pairs_o + 64'd1;
                if (last_pixel) begin
                    busy_o <= 1'b0;
                    done_o <= 1'b1;
                end
            end
        end
    end

    // Signals this configuration does not use yet: the camera's own frame
    // flags (the frame ends at the last pixel), the intersection unit's
    // coefficients along the ray (debug), the walk unit's tree slot,
    // entering flag, near-side flags and payload (secondary rays, later),
    // and the material's reflection and filter fields (effects, later).
    wire unused_ok = &{1'b0, cam_last, cam_busy, cam_done, res_a, res_b, res_c, hit_slot, hit_entering,
                       hit_flags_before, hit_payload, mat[111:96], num_lights};

    initial begin
        if (NUM_UNITS != 1) begin
            $display("%m: NUM_UNITS = %0d: only one intersection lane is implemented", NUM_UNITS);
            $finish;
        end
    end
endmodule
`default_nettype wire
