`default_nettype none
// csgrt_raytree — the ray scheduler for shadows, reflection and refraction: it traces
// each pixel's ray tree through the intersection lanes, bit for bit
// accumulate_fx() of model/raytree.cpp (docs/effects.md, docs/architecture.md).
//
// CONTEXTS pixels are in flight, one context each. A context traces its
// pixel's tree depth first, one colour ray (primary, reflected, ...) at a
// time; the shadow rays of a hit run in parallel. Per colour ray:
//
//   trace -> miss (or a hit point out of range): add rnd(w background)
//         -> hit: ask csgrt_spawn for the hit's children (a shadow ray per
//            light that is not shadowless, the transmitted ray or its total internal reflection,
//            the reflected ray); shadow rays go to the lanes, the others
//            onto the context's stack; when every shadow ray
//            has come back (each leaves the light's colour scaled by what
//            got through, or 0), the hit is shaded (csgrt_shade with those
//            light colours, a shadowless light's own colour, csgrt_contrib)
//            and rnd(w L) is added
//   then the next ray from the stack, or the pixel is done.
//
// The sum of contributions does not depend on the order rays finish in,
// so contexts run independently; finished pixels wait in an output buffer
// of 2 CONTEXTS entries and leave in raster order.
//
// Bounded by construction (no deadlock, no overflow): a context has at
// most one colour ray or MAX_LIGHTS shadow rays in flight, so the ray FIFO
// (RAY_FIFO >= CONTEXTS * max(1, MAX_LIGHTS)) never refuses a ray; the
// spawn request FIFO holds one request per context; a context's stack
// holds at most one pending sibling per level below the current hit plus
// that hit's two children: at most max_trace_level entries (MAX_DEPTH >= the
// scene's max_trace_level, which the compiler checks). Every input is taken as it
// comes: a ray or request always has somewhere to go by these bounds
// (checked in simulation), so the event selection does not look at the
// FIFOs' full flags.
//
// Events, one per clock, in priority order: a contribution (shading done),
// a spawned child, a traced ray, a stack pop, a new pixel from the camera.
// An event is chosen in one clock (E0: the sources' valid bits alone, the
// source's ready, the event's fields into registers) and carried out in
// the next (E1: the context state from those registers), so that the
// choice is a register in front of the state's write enables.
// The stack and the wide queues are block RAM (LUTs are what the FPGA lacks),
// so a pop's entry is read the clock before its event.
// Handshakes: valid/ready everywhere; outputs that leave the module are
// registers or FIFO outputs.
module csgrt_raytree #(
    parameter BITS        = 24,
    parameter TREE_HEIGHT = 8,
    parameter MAX_LIGHTS  = 8,
    parameter CONTEXTS    = 8,       // pixels in flight (a power of two)
    parameter MAX_DEPTH   = 8,       // stack entries per context (>= max_trace_level)
    parameter LOOK_BEHIND = 4,
    parameter SHADOWS     = 1,
    parameter REFLECTION  = 1,
    parameter REFRACTION  = 0,       // transmitted rays (the walker's look-ahead is csgrt_top's)
    parameter DIST_W      = 27,      // shadow distance width (csgrt_spawn's m_dist_o)
    parameter MAT_W       = 154,     // material record (csgrt_scene_loader)
    parameter COL_W       = 31,      // csgrt_shade's linear colour
    parameter SPEC_W      = 26,
    parameter LUT_FILE    = "rtl/srgb_lut.hex",
    parameter II          = 1,       // hit_prep's and contrib's clocks per record: 1, or 3 on a third of the multipliers
    // derived
    parameter NS          = 1 << TREE_HEIGHT,
    parameter CB          = $clog2(CONTEXTS),
    parameter KW          = (MAX_LIGHTS > 1) ? $clog2(MAX_LIGHTS) : 1,
    parameter LBC         = $clog2(LOOK_BEHIND + 1),
    parameter RUN_W       = LBC + LOOK_BEHIND * (TREE_HEIGHT + 2),   // {same_t, entering, slots, count}
    parameter REC_W       = 1 + CB + KW + 48 + 4 + 48 + 5 + DIST_W,  // the ray record, see below
    parameter INFO_W      = 1 + NS + (BITS - 2) + RUN_W              // event-sort info, see below
) (
    input  wire                      clk_i,
    input  wire                      rst_ni,
    input  wire                      start_i,          // a frame starts (pixel order restarts)
    // configuration (steady during a frame)
    input  wire [$clog2(MAX_LIGHTS+1)-1:0] num_lights_i,
    input  wire [MAX_LIGHTS*48-1:0]  light_color_i,
    input  wire [MAX_LIGHTS-1:0]     light_shadowless_i,   // no shadow rays: the light's own colour
    input  wire [3*16-1:0]           background_i,
    input  wire [7:0]                max_trace_i,      // global_settings max_trace_level
    // primary rays from the camera, raster order
    input  wire                      cam_valid_i,
    output wire                      cam_ready_o,
    input  wire [11:0]               cam_x_i,
    input  wire [11:0]               cam_y_i,
    input  wire [3*BITS-1:0]         cam_o_i,
    input  wire [3*BITS-1:0]         cam_d_i,
    // rays to the lanes (csgrt_dispatch); rec comes back with the ray's hit.
    // rec = {tlimit, cross, atten, depth, w, light, ctx, shadow} (shadow at bit 0)
    // info = {run, tlimit (event format, 0: none), flags, secondary} for csgrt_event_sort
    output wire                      ray_valid_o,
    input  wire                      ray_ready_i,
    output wire [REC_W-1:0]          ray_rec_o,
    output wire [3*BITS-1:0]         ray_o_o,
    output wire [3*BITS-1:0]         ray_d_o,
    output wire [INFO_W-1:0]         ray_info_o,
    // traced rays, in the order they were sent
    input  wire                      tr_valid_i,
    output wire                      tr_ready_o,
    input  wire [REC_W-1:0]          tr_rec_i,
    input  wire [3*BITS-1:0]         tr_o_i,
    input  wire [3*BITS-1:0]         tr_d_i,
    input  wire                      tr_hit_i,
    input  wire [BITS-2:0]           tr_t_i,
    input  wire [7:0]                tr_to_i,
    input  wire [10*BITS-1:0]        tr_coef_i,        // the hit leaf's quadric
    input  wire [MAT_W-1:0]          tr_mat_i,         // the shown material's record
    input  wire [1:0]                tr_mat_want_i,    // its {filter != 0, reflection != 0} (csgrt_scene_loader)
    input  wire [NS-1:0]             tr_flags_near_i,  // flags just before the hit crossing
    input  wire [RUN_W-1:0]          tr_run_i,         // the look-behind run
    input  wire [NS-1:0]             tr_flags_after_i,
    input  wire [15:0]               tr_ior_from_i,    // ior_of(BORDER from), ior_of(BORDER to) (REFRACTION)
    input  wire [15:0]               tr_ior_to_i,
    // spawn requests (csgrt_spawn)
    output wire                      sp_valid_o,
    input  wire                      sp_ready_i,
    output wire [3*BITS-1:0]         sp_o_o,
    output wire [3*BITS-1:0]         sp_d_o,
    output wire [BITS-2:0]           sp_t_o,
    output wire [10*BITS-1:0]        sp_coef_o,
    output wire [MAX_LIGHTS-1:0]     sp_lights_o,
    output wire                      sp_reflect_o,
    output wire                      sp_refract_o,
    output wire [15:0]               sp_ior_from_o,
    output wire [15:0]               sp_ior_to_o,
    output wire [CB-1:0]             sp_user_o,
    // spawned children
    input  wire                      ch_valid_i,
    input  wire                      ch_valid_ev_i,    // ch_valid_i from a flip-flop of its own: the event choice's
    input  wire                      ch_valid_rec_i,   // and from another: the pushed record's choice
    output wire                      ch_ready_o,
    input  wire [2:0]                ch_kind_i,        // csgrt_spawn's kinds
    input  wire [KW-1:0]             ch_light_i,
    input  wire [3*BITS-1:0]         ch_p_i,
    input  wire [3*BITS-1:0]         ch_d_i,
    input  wire [DIST_W-1:0]         ch_dist_i,
    input  wire                      ch_lit_i,
    input  wire                      ch_last_i,
    input  wire [CB-1:0]             ch_user_i,
    // shading requests (csgrt_shade, LINEAR_OUT and EXT_LIGHT); tag = context
    output wire                      sh_valid_o,
    input  wire                      sh_ready_i,
    output wire [11:0]               sh_tag_o,
    output wire [3*BITS-1:0]         sh_o_o,
    output wire [3*BITS-1:0]         sh_d_o,
    output wire [BITS-2:0]           sh_t_o,
    output wire [10*BITS-1:0]        sh_coef_o,
    output wire [MAT_W-1:0]          sh_mat_o,
    input  wire [11:0]               lc_tag_i,         // the shade unit's light colour lookup
    input  wire [$clog2(MAX_LIGHTS+1)-1:0] lc_k_i,
    output wire [3*16-1:0]           lc_color_o,
    input  wire                      sr_valid_i,
    output wire                      sr_ready_o,
    input  wire [11:0]               sr_tag_i,
    input  wire [3*COL_W-1:0]        sr_local_i,
    input  wire [3*SPEC_W-1:0]       sr_spec_i,
    // pixels, raster order
    output wire                      pix_valid_o,
    input  wire                      pix_ready_i,
    output wire [11:0]               pix_x_o,
    output wire [11:0]               pix_y_o,
    output wire [23:0]               pix_rgb_o
);
    localparam B   = BITS;
    localparam TW  = B - 1;
    localparam UW  = B - 2;                       // t ahead of the origin (event format)
    localparam P   = CONTEXTS;
    localparam OB  = 2 * CONTEXTS;                // output buffer entries
    localparam OBW = $clog2(OB);
    localparam SPW = $clog2(MAX_DEPTH + 1);
    localparam PW  = $clog2(MAX_LIGHTS + 1);      // shadow rays pending
    localparam NLW = $clog2(MAX_LIGHTS + 1);
    localparam RAY_FIFO_MIN = CONTEXTS * ((MAX_LIGHTS > 1) ? MAX_LIGHTS : 1);
    // twice the bound: from when the events checked the room a clock before
    // their registered push; kept, as one block RAM holds either depth
    localparam RAY_FIFO = 2 << $clog2(RAY_FIFO_MIN);
    localparam [15:0] ONE = 16'd4096;
    // csgrt_spawn's child kinds (rtl/csgrt_spawn.v)
    // (CONTINUE 0 is not asked for: shadow rays continue through csgrt_hit_prep)
    localparam [2:0] K_SHADOW = 3'd1, K_REFRACT = 3'd2, K_TIR = 3'd3, K_REFLECT = 3'd4;
    // material record fields (csgrt_scene_loader)
    localparam M_RGB = 0, M_REFL = 96, M_FILTER = 122;

    // ---- the ray record ---------------------------------------------------------------
    function [REC_W-1:0] rec(input shadow, input [CB-1:0] ctx, input [KW-1:0] light, input [47:0] w,
                             input [3:0] depth, input [47:0] atten, input [4:0] ncross, input [DIST_W-1:0] tlimit);
        rec = {tlimit, ncross, atten, depth, w, light, ctx, shadow};
    endfunction
    // event-sort info: a limit at or beyond the range of t is no limit
    function [INFO_W-1:0] info(input secondary, input [NS-1:0] flags, input [DIST_W-1:0] tlimit, input [RUN_W-1:0] run);
        reg [UW-1:0] tl;
        begin
            tl = (|(tlimit >> UW)) ? {UW{1'b0}} : tlimit[UW-1:0];
            info = {run, tl, flags, secondary};
        end
    endfunction
    // an output buffer slot, a context, as one-hot codes
    function [OB-1:0] slot_onehot(input [OBW-1:0] slot);
        slot_onehot = {{(OB-1){1'b0}}, 1'b1} << slot;
    endfunction
    function [P-1:0] ctx_onehot(input [CB-1:0] ctx);
        ctx_onehot = {{(P-1){1'b0}}, 1'b1} << ctx;
    endfunction

    // ---- context state ---------------------------------------------------------------
    reg [P-1:0]        busy_q, spawning_q, shade_q, pop_q;
    reg [11:0]         x_q     [0:P-1];
    reg [11:0]         y_q     [0:P-1];
    (* mem2reg *) reg [OBW:0] seq_q [0:P-1];   // registers, not a memory (yosys)
    // each context's output buffer slot also one-hot, written with seq_q:
    // ob_set_oh_q (below) chooses a code from these instead of decoding
    // the chosen slot, which was 7 LUT levels from the
    // contribution's context (tools/logic_depth.py 11.67 ns on 3599434's
    // netlist); u_check_ob_valid sees any difference
    (* mem2reg *) reg [OB-1:0] seq_oh_q [0:P-1];
    reg [38:0]         acc_q   [0:P-1];
    reg [PW-1:0]       pend_q  [0:P-1];
    reg [SPW-1:0]      sp_q    [0:P-1];
    // the colour ray's hit, kept for its children and its shading. The wide
    // ones only the shading reads are block RAM, read into the shading's
    // request registers when the request is issued (sh_issue below). A
    // context's hit is written when its colour ray comes back, before its
    // shading is issued, and not again until its contribution is in: a read
    // never meets a write to the same context (no_rw_check).
    reg [47:0]         w_q     [0:P-1];
    reg [3:0]          depth_q [0:P-1];
    reg [47:0]         wr_q    [0:P-1];
    (* ram_style = "block", no_rw_check *) reg [3*B-1:0]  ho_q    [0:P-1];
    (* ram_style = "block", no_rw_check *) reg [3*B-1:0]  hd_q    [0:P-1];
    reg [TW-1:0]       ht_q    [0:P-1];
    (* ram_style = "block", no_rw_check *) reg [10*B-1:0] hcoef_q [0:P-1];
    (* ram_style = "block", no_rw_check *) reg [MAT_W-1:0] hmat_q [0:P-1];
    reg [15:0]         hfilt_q [0:P-1];   // the material's filter, for csgrt_contrib
    reg [NS-1:0]       near_q  [0:P-1];
    reg [NS-1:0]       after_q [0:P-1];   // far side: the transmitted child's flags
    reg [47:0]         wt_q    [0:P-1];   // the transmitted child's weight
    reg [P-1:0]        tx_q;              // the hit has a transmitted child
    reg [RUN_W-1:0]    run_q   [0:P-1];
    // the light colours for shading, scaled by the shadow rays
    reg [47:0]         lcol_q  [0:(P << KW)-1];
    // the stack: {run, flags, depth, w, d, o}. P * MAX_DEPTH entries of some
    // 360 bits at 24 bits: block RAM (LUT RAM took ~360 DPR16X4 and a 4:1 read
    // multiplexer per bit). Its read is registered, so a pop is staged
    // (pop_ram_q, pop_entry_q below). A context's stack is written only while it waits
    // for children and read only while it waits for a pop, never both, so a
    // read never meets a write at the same address (no_rw_check).
    // A push is written a clock late, from registers (stw_*): the write port
    // sits in a block RAM anywhere on the die, and the push's address and
    // data came from the event selection and the context memories in the
    // same clock (the ray tree's critical path out of context). A context's
    // pop comes many clocks after its last push (its children are shaded
    // first), so the late write is never read early.
    localparam SW = RUN_W + NS + 4 + 48 + 6 * B;
    (* ram_style = "block", no_rw_check *)
    reg [SW-1:0]       stack_q [0:P*MAX_DEPTH-1];
    reg                stw_q;
    reg [$clog2(P * MAX_DEPTH)-1:0] stw_addr_q;
    reg [SW-1:0]       stw_data_q;
    // A stacked child's entry. The reflected ray and a total internal
    // reflection stay on the near side (the parent's run and flags before the
    // crossing); the transmitted ray takes the far side's flags, which already
    // hold the look-ahead, so it carries no run. Reflection takes the mirror
    // weight, the other two the transmitted weight.
    wire          ch_far     = ch_kind_i == K_REFRACT;
    wire [SW-1:0] ch_entry   = {ch_far ? {RUN_W{1'b0}} : run_q[ch_user_i],
                                ch_far ? after_q[ch_user_i] : near_q[ch_user_i],
                                depth_q[ch_user_i] + 4'd1,
                                ch_kind_i == K_REFLECT ? wr_q[ch_user_i] : wt_q[ch_user_i],
                                ch_d_i, ch_p_i};
    // the output buffer
    reg [OB-1:0]       ob_valid_q;
    reg [23:0]         ob_xy_q  [0:OB-1];
    reg [38:0]         ob_acc_q [0:OB-1];
    reg [OBW:0]        next_seq_q, retire_q;
    reg                o_valid_q;
    reg  [23:0]        o_xy_q;
    wire               o_adv    = !o_valid_q || pix_ready_i;
    // The retire pointer's slot's valid bit as a register of its own
    // (ob_hv_q = ob_valid_q[retire_q], loaded with its next value below),
    // and retire_q + 1 too (retire1_q): out_take was the valid bits'
    // choice by retire_q, then the handshake, then retire_q's increment and
    // into the pixel registers' 24 enables (tools/logic_depth.py 12.13 ns,
    // 6 LUT levels, the whole netlist's worst path on 21c7cd8). Checked.
    reg                ob_hv_q;
    reg  [OBW-1:0]     retire1_q;
    wire               out_take = ob_hv_q && o_adv;

    // ---- sources -------------------------------------------------------------------------
    // traced rays through csgrt_hit_prep
    localparam TREC_W = REC_W + 6 * B + 10 * B + MAT_W + NS + RUN_W + NS + 1 + TW + 32 + 2;
    wire               hp_valid;
    wire               hp_rec_valid;
    wire               hp_ready;
    wire [TREC_W-1:0]  hp_rec;
    wire [3*B-1:0]     hp_p;
    wire               hp_in_range;
    wire [38:0]        hp_bg;
    wire [47:0]        hp_w_r, hp_w_t, hp_sh_color, hp_sh_atten;
    wire               hp_sh_ends;
    wire [DIST_W-1:0]  hp_sh_tlimit;
    wire               tr_shadow = tr_rec_i[0];
    wire [KW-1:0]      tr_light  = tr_rec_i[1 + CB +: KW];
    wire [47:0]        tr_w      = tr_rec_i[1 + CB + KW +: 48];
    wire [47:0]        tr_atten  = tr_rec_i[1 + CB + KW + 52 +: 48];
    wire [4:0]         tr_cross  = tr_rec_i[1 + CB + KW + 100 +: 5];
    wire [DIST_W-1:0]  tr_tlimit = tr_rec_i[1 + CB + KW + 105 +: DIST_W];
    // The hit's wishes for a reflected and a transmitted child, decided as
    // the traced ray goes into csgrt_hit_prep rather than when it comes out:
    // the depth comparison's carry chain and the material tests were the
    // front of the ray tree's longest path out of context (the record
    // queue's head -> want_spawn -> the spawn request and context flags).
    // (max_trace_i is steady during a frame.)
    wire [3:0]         tr_depth     = tr_rec_i[1 + CB + KW + 48 +: 4];
    wire               tr_deeper    = ({4'd0, tr_depth} < max_trace_i);
    // (The material's two tests come with it from the loader, which made
    // them when the material was written: tested here after the material
    // memory's block-RAM read they were the routed effects build's
    // critical path, docs/fpga.md.)
    wire               tr_want_refl = (REFLECTION != 0) && tr_deeper && tr_mat_want_i[0];
    // accumulate_fx's `transmits`: the shown material lets light through
    wire               tr_want_refr = (REFRACTION != 0) && tr_deeper && tr_mat_want_i[1];
`ifndef SYNTHESIS
    // the loader's bits are the tests of this very record
    csgrt_check_same #(.WIDTH(2), .WHAT("tr_mat_want_i")) u_check_want (
        .clk_i, .rst_ni,
        .copy_i(tr_valid_i ? tr_mat_want_i : 2'b00),
        .orig_i(tr_valid_i ? {tr_mat_i[M_FILTER +: 16] != 16'd0, tr_mat_i[M_REFL +: 16] != 16'd0} : 2'b00));
`endif
    csgrt_hit_prep #(.BITS(B), .MAX_LIGHTS(MAX_LIGHTS), .DIST_W(DIST_W), .REC_W(TREC_W), .II(II)) u_prep (
        .clk_i, .rst_ni, .background_i, .light_color_i,
        .s_valid_i (tr_valid_i), .s_ready_o (tr_ready_o),
        .s_shadow_i (tr_shadow), .s_light_i (tr_light), .s_w_i (tr_w), .s_atten_i (tr_atten),
        .s_cross_i (tr_cross), .s_tlimit_i (tr_tlimit), .s_o_i (tr_o_i), .s_d_i (tr_d_i),
        .s_hit_i (tr_hit_i), .s_t_i (tr_t_i), .s_to_air_i (tr_to_i == 8'd0),
        .s_rgb_i (tr_mat_i[M_RGB +: 48]), .s_filter_i (tr_mat_i[M_FILTER +: 16]),
        .s_reflection_i (tr_mat_i[M_REFL +: 16]),
        .s_rec_i ({tr_want_refr, tr_want_refl, tr_ior_to_i, tr_ior_from_i, tr_t_i, tr_hit_i, tr_flags_after_i, tr_run_i, tr_flags_near_i, tr_mat_i,
                   tr_coef_i, tr_o_i, tr_d_i, tr_rec_i}),
        .m_valid_o (hp_valid), .m_ready_i (hp_ready), .m_rec_o (hp_rec), .m_rec_valid_o (hp_rec_valid),
        .m_p_o (hp_p), .m_in_range_o (hp_in_range), .m_bg_o (hp_bg), .m_w_r_o (hp_w_r), .m_w_t_o (hp_w_t),
        .m_sh_ends_o (hp_sh_ends), .m_sh_color_o (hp_sh_color), .m_sh_atten_o (hp_sh_atten),
        .m_sh_tlimit_o (hp_sh_tlimit));
    wire [REC_W-1:0]  h_rec    = hp_rec[0 +: REC_W];
    wire [3*B-1:0]    h_d      = hp_rec[REC_W +: 3*B];
    wire [3*B-1:0]    h_o      = hp_rec[REC_W + 3*B +: 3*B];
    wire [10*B-1:0]   h_coef   = hp_rec[REC_W + 6*B +: 10*B];
    wire [MAT_W-1:0]  h_mat    = hp_rec[REC_W + 16*B +: MAT_W];
    wire [NS-1:0]     h_near   = hp_rec[REC_W + 16*B + MAT_W +: NS];
    wire [RUN_W-1:0]  h_run    = hp_rec[REC_W + 16*B + MAT_W + NS +: RUN_W];
    wire [NS-1:0]     h_after  = hp_rec[REC_W + 16*B + MAT_W + NS + RUN_W +: NS];
    wire              h_hit    = hp_rec[REC_W + 16*B + MAT_W + 2*NS + RUN_W];
    wire [TW-1:0]     h_t      = hp_rec[REC_W + 16*B + MAT_W + 2*NS + RUN_W + 1 +: TW];
    wire [15:0]       h_ior_from = hp_rec[REC_W + 16*B + MAT_W + 2*NS + RUN_W + 1 + TW +: 16];
    wire [15:0]       h_ior_to   = hp_rec[REC_W + 16*B + MAT_W + 2*NS + RUN_W + 1 + TW + 16 +: 16];
    wire              want_refl  = hp_rec[REC_W + 16*B + MAT_W + 2*NS + RUN_W + 1 + TW + 32];
    wire              want_refr  = hp_rec[REC_W + 16*B + MAT_W + 2*NS + RUN_W + 1 + TW + 33];
    wire              h_shadow = h_rec[0];
    wire [CB-1:0]     h_ctx    = h_rec[1 +: CB];
    wire [KW-1:0]     h_light  = h_rec[1 + CB +: KW];
    wire [47:0]       h_w      = h_rec[1 + CB + KW +: 48];
    wire [3:0]        h_depth  = h_rec[1 + CB + KW + 48 +: 4];
    wire [4:0]        h_cross  = h_rec[1 + CB + KW + 100 +: 5];
    wire unused_hp = ^{h_rec[REC_W-1 -: DIST_W], h_rec[1 + CB + KW + 52 +: 48]};

    // contributions of shaded rays
    wire              ct_valid;
    wire              ct_valid_ch;          // ct_valid's copy, for ch_ready_o alone
    wire              ct_ready;
    wire [CB-1:0]     ct_ctx;
    wire [38:0]       ct_contrib;
    wire [CB-1:0]     sr_ctx = sr_tag_i[CB-1:0];
    wire unused_sr_tag = ^sr_tag_i[11:CB];
    reg  [3*COL_W-1:0] sr_spec_x;
    integer c;
    always @* for (c = 0; c < 3; c = c + 1)
        sr_spec_x[c*COL_W +: COL_W] = {{(COL_W-SPEC_W){1'b0}}, sr_spec_i[c*SPEC_W +: SPEC_W]};
    csgrt_contrib #(.COL_W(COL_W), .TAG_W(CB), .II(II)) u_contrib (
        .clk_i, .rst_ni, .s_valid_i (sr_valid_i), .s_ready_o (sr_ready_o), .s_tag_i (sr_ctx),
        .s_local_i (sr_local_i), .s_spec_i (sr_spec_x), .s_transmits_i (tx_q[sr_ctx]),
        .s_filter_i (hfilt_q[sr_ctx]), .s_w_i (w_q[sr_ctx]),
        .m_valid_o (ct_valid), .m_valid_copy_o (ct_valid_ch), .m_ready_i (ct_ready), .m_tag_o (ct_ctx),
        .m_contrib_o (ct_contrib));

    // ---- the ray FIFO and the spawn request FIFO ------------------------------------------
    wire                rq_push;            // E1 (below)
    reg  [REC_W-1:0]    rq_rec;
    reg  [3*B-1:0]      rq_o, rq_d;
    reg  [INFO_W-1:0]   rq_info;
    wire                rq_room;
    // HEAD_REG 3: the head in fabric registers. Without them the RAM's read
    // port (5.8 ns from clock to output in nextpnr's model) drove the
    // dispatcher's ray queue, another block RAM across the die: e7b3e2f's
    // routed critical path at FREQ 100 (85.56 MHz; 5.83 ns + 5.64 ns of
    // route). The ping-pong rather than one head register (HEAD_REG 1)
    // because ray_ready_i is the dispatcher's, decided there: with the
    // ping-pong it reaches only the head's pointers, not the RAM's read
    // enable or the ~370 head flip-flops' enables. Still a ray per clock;
    // one clock more latency, two words more room.
    csgrt_fifo_block #(.WIDTH(REC_W + 6 * B + INFO_W), .DEPTH(RAY_FIFO), .HEAD_REG(3)) u_rays (
        .clk_i, .rst_ni, .valid_i (rq_push), .ready_o (rq_room), .data_i ({rq_info, rq_d, rq_o, rq_rec}),
        .valid_o (ray_valid_o), .ready_i (ray_ready_i), .data_o ({ray_info_o, ray_d_o, ray_o_o, ray_rec_o}));

    // spawn requests: {iors, refract, ctx, reflect, lights, coef, t, d, o} of the colour ray's hit
    localparam SPQ_W = 3 * B + 3 * B + TW + 10 * B + MAX_LIGHTS + 1 + CB + 1 + 32;
    wire                spq_push;           // E1 (below)
    reg  [SPQ_W-1:0]    spq_data;
    wire                spq_room;
    // the head in a fabric register (HEAD_REG 1): csgrt_spawn tests the
    // request's child flags (lowest, at most one) on the way into its hit
    // queue, and the block RAM's read port (5.8 ns from the clock) in front
    // of that carry chain and the route across was the longest path of the
    // routed BITS 16 H 5 effects build (docs/fpga.md). csgrt_spawn's ready
    // is a function of its registers, as HEAD_REG 1 asks.
    csgrt_fifo_block #(.WIDTH(SPQ_W), .DEPTH(2 * P), .HEAD_REG(1)) u_spawn_q (
        .clk_i, .rst_ni, .valid_i (spq_push), .ready_o (spq_room),
        .data_i (spq_data),
        .valid_o (sp_valid_o), .ready_i (sp_ready_i),
        .data_o ({sp_ior_to_o, sp_ior_from_o, sp_refract_o, sp_user_o, sp_reflect_o, sp_lights_o, sp_coef_o, sp_t_o,
                  sp_d_o, sp_o_o}));

    // ---- event selection ----------------------------------------------------------------
    // a free context and room in the output buffer for a new pixel
    reg  [CB-1:0] free_ctx;
    reg           free_any;
    reg  [CB-1:0] pop_ctx;
    reg           pop_any;
    integer k;
    always @* begin
        free_ctx = {CB{1'b0}};
        free_any = 1'b0;
        pop_ctx  = {CB{1'b0}};
        pop_any  = 1'b0;
        for (k = P - 1; k >= 0; k = k - 1) begin
            if (!busy_q[k]) begin free_ctx = k[CB-1:0]; free_any = 1'b1; end
            if (pop_q[k])   begin pop_ctx  = k[CB-1:0]; pop_any  = 1'b1; end
        end
    end
    // the staged pop, in three steps: first a waiting context and the
    // address of its stack's top entry into registers (pa_*), then the block
    // RAM read at that address (its read register, pop_ram_q), then a fabric
    // register (pop_entry_q) the clock before the pop event uses it. The
    // RAM's ten blocks lie anywhere on the die: the address computed in the
    // clock of the read (the waiting contexts' priority, their stack
    // pointers, the entry index) was the ray tree's longest path out of
    // context (13.7 ns, 6.3 of them the route to a far block), and the
    // RAM's slow read port (5.8 ns) straight into the pushed record the
    // next (10.7 ns). A context waiting for a pop has nothing in flight, so
    // its stack and pointer cannot change while its address and entry wait
    // here; one pop is in these steps at a time, so its context is one
    // register (pop_ctx_q) from the first step to the event.
    localparam STK_AW = $clog2(P * MAX_DEPTH);
    reg               pa_valid_q;
    reg  [STK_AW-1:0] pa_addr_q;
    reg               pr_valid_q;          // pop_ram_q holds the entry
    reg               pop_staged_q;
    reg  [CB-1:0]     pop_ctx_q;
    wire              pop_idle;
    wire              pa_load   = pop_any && pop_idle;
    wire              pop_stage = pa_valid_q;
    wire              pop_fab   = pr_valid_q;
    reg  [SW-1:0]     pop_ram_q, pop_entry_q;
    // room in the output buffer for a new pixel, as a register loaded with
    // the test of the two counters' next values (room_out_q, below): the
    // subtraction and compare of the counters themselves ran into the
    // camera's event and the pushed record (12.02 ns out of context)
    reg          room_out_q;

    // One event per clock; every event may push one ray (and a traced
    // colour ray one spawn request). The bounds above guarantee room in both
    // FIFOs, so the selection does not wait for their full flags: it starts
    // from the sources' valid bits alone, and the room is checked in
    // simulation (below). (With rq_room and spq_room in it, the ray FIFO's
    // full flag ran through this decode and its two ~500-load selects into
    // the pushed record, the longest path of the whole design in
    // tools/logic_depth.py's model.)
    //
    // The event is chosen in E0 and carried out in E1, a clock later, from
    // registers: the kind (ev_*), the fields the state update needs (e_*,
    // loaded on every clock, so no enable hangs on the choice) and, for a
    // contribution, the early sum (ctp_*). With the choice in front of the
    // context memories' write enables and addresses in the same clock, the
    // spawn unit's output valid (209 loads) ran through the priority
    // decode and two to four more LUTs into them (tools/logic_depth.py:
    // 17.73 ns, the whole design's longest path). The state is read in E1
    // only, after the previous event's writes, so events still act one
    // after another; E0 reads no context state but these, each safe:
    //  - a new pixel's free context and room in the output buffer: E0 takes
    //    no new pixel while one is in E1 (its context and sequence number
    //    are then written), and the other events only free contexts (in
    //    csgrt_top the camera's csgrt_hold offers a pixel every other clock
    //    at most, so there this rule never waits; it keeps the module right
    //    for any source);
    //  - the pop: its staged entry is released in E0, and no new pop is
    //    staged while one is in E1 (its stack pointer is then written);
    //  - a child's stack entry (ch_entry) and a shadow ray's record read the
    //    hit's state, written when the hit came back, long before.
    // The pushes into the ray and spawn request FIFOs happen in E1 from
    // the records loaded at the end of E0, the same clock as before.
    reg  ev_ct, ev_ch, ev_hp, ev_pop, ev_cam;
    wire ev0_ct  = ct_valid;
    // (ch_valid_ev_i: the spawn unit's valid bit as a copy of its own;
    // ch_valid_i selects the records below, some 1,000 bits)
    wire ev0_ch  = !ct_valid && ch_valid_ev_i;
    wire ev0_hp  = !ct_valid && !ch_valid_ev_i && hp_valid;
    wire ev0_pop = !ct_valid && !ch_valid_ev_i && !hp_valid && pop_staged_q;
    // E0's shadow ray that ends (its light colour written, its pending
    // count stepped down, its context maybe set to shade)
    wire ev0_sh_end = ev0_hp && h_shadow && hp_sh_ends;
    wire ev0_cam = !ct_valid && !ch_valid_ev_i && !hp_valid && !pop_staged_q && cam_valid_i && free_any && room_out_q
                   && !start_i && !ev_cam;
    always @(posedge clk_i)
        if (!rst_ni) {ev_ct, ev_ch, ev_hp, ev_pop, ev_cam} <= 5'd0;
        else         {ev_ct, ev_ch, ev_hp, ev_pop, ev_cam} <= {ev0_ct, ev0_ch, ev0_hp, ev0_pop, ev0_cam};
    assign pop_idle = !pa_valid_q && !pr_valid_q && !pop_staged_q && !ev_pop;
    // the fields E1 needs, from whichever source E0 took
    reg  [2:0]    e_ch_kind;
    reg  [KW-1:0] e_ch_light;
    reg  [CB-1:0] e_ch_user;
    reg           e_ch_lit, e_ch_last;
    reg  [SW-1:0] e_ch_entry;
    reg  [CB-1:0] e_h_ctx;
    reg  [KW-1:0] e_h_light;
    reg           e_h_shadow, e_h_colour_hit, e_want_spawn, e_sh_ends;
    reg  [47:0]   e_sh_color;
    reg  [CB-1:0] e_free_ctx;
    reg  [23:0]   e_cam_xy;
    always @(posedge clk_i) begin
        e_ch_kind      <= ch_kind_i;
        e_ch_light     <= ch_light_i;
        e_ch_user      <= ch_user_i;
        e_ch_lit       <= ch_lit_i;
        e_ch_last      <= ch_last_i;
        e_ch_entry     <= ch_entry;
        e_h_ctx        <= h_ctx;
        e_h_light      <= h_light;
        e_h_shadow     <= h_shadow;
        e_h_colour_hit <= h_colour_hit;
        e_want_spawn   <= want_spawn;
        e_sh_ends      <= hp_sh_ends;
        e_sh_color     <= hp_sh_color;
        e_free_ctx     <= free_ctx;
        e_cam_xy       <= {cam_y_i, cam_x_i};
    end
    // the output buffer's counters' next values: the pixel sequence
    // restarts at a frame's start and steps with a new pixel; the retire
    // pointer steps with a pixel out (both registers load these; room_out_q
    // tests them)
    wire [OBW:0] next_seq_d = start_i ? retire_q : ev_cam ? next_seq_q + 1'b1 : next_seq_q;
    wire [OBW:0] retire_d   = out_take ? retire_q + 1'b1 : retire_q;
`ifndef SYNTHESIS
    // the simulation checks of this module start at the first reset (the
    // registers hold their power-up values before it)
    reg chk_reset_seen_q = 1'b0;
    always @(posedge clk_i) if (!rst_ni) chk_reset_seen_q <= 1'b1;
    // the bounds, checked: a simulation stops if a push finds its FIFO full
    always @(posedge clk_i)
        if (rst_ni && chk_reset_seen_q && ((rq_push && !rq_room) || (spq_push && !spq_room))) begin
            if (rq_push && !rq_room) $display("ERROR %m: the ray FIFO is full at a push (the header's bound)");
            else $display("ERROR %m: the spawn request FIFO is full at a push (the header's bound)");
            $fatal;
        end
`endif
    assign ct_ready    = 1'b1;          // the contribution event is never refused (first in priority)
    // ev0_ch, from the contribution's valid copy: ch_ready_o goes on into
    // csgrt_spawn's output skid and its beat's enable
    assign ch_ready_o  = !ct_valid_ch && ch_valid_ev_i;
    assign hp_ready    = ev0_hp;
    assign cam_ready_o = ev0_cam;

    // saturating colour sum
    function [38:0] add_sat(input [38:0] a, input [38:0] b);
        reg [13:0] s;
        integer ch;
        begin
            for (ch = 0; ch < 3; ch = ch + 1) begin
                s = {1'b0, a[ch*13 +: 13]} + {1'b0, b[ch*13 +: 13]};
                add_sat[ch*13 +: 13] = (s > 14'd4095) ? 13'd4095 : s[12:0];
            end
        end
    endfunction

    // ---- the shading issue ---------------------------------------------------------------
    reg  [CB-1:0] sh_ctx_q;
    reg           sh_valid_q;
    // The context to shade next, the lowest one waiting (shade_q), as
    // registers of their own (shq_ctx_q, shq_any_q) loaded with the
    // choice over shade_q's next value (shade_d): shq_ctx addresses the
    // four block RAMs of the hit (ho_q, hd_q, hcoef_q, hmat_q), placed
    // across the die, and as a priority encoder of shade_q in front of
    // them it was 232f2b0's routed critical path (four LUTs, then 6.96 ns
    // of route to hd_q's address: 88.68 MHz). A simulation stops if the
    // registers differ from the choice over shade_q.
    wire [P-1:0]  shade_d;
    reg  [CB-1:0] shq_ctx_q;
    reg           shq_any_q;
    function [CB:0] lowest(input [P-1:0] v);   // {any, index of the lowest set bit}
        integer j;
        begin
            lowest = {(CB+1){1'b0}};
            for (j = P - 1; j >= 0; j = j - 1)
                if (v[j]) lowest = {1'b1, j[CB-1:0]};
        end
    endfunction
    always @(posedge clk_i)
        if (!rst_ni) {shq_any_q, shq_ctx_q} <= {(CB+1){1'b0}};
        else         {shq_any_q, shq_ctx_q} <= lowest(shade_d);
    wire [CB-1:0] shq_ctx = shq_ctx_q;
    wire          shq_any = shq_any_q;
    csgrt_check_same #(.WIDTH(CB + 1), .WHAT("shq_any_q / shq_ctx_q (the context to shade next)")) u_check_shq (
        .clk_i, .rst_ni, .copy_i({shq_any_q, shq_ctx_q}), .orig_i(lowest(shade_q)));
    // A request is issued into an empty request register only, so that
    // the issue (which enables the ~540 request registers at BITS 24 and clears the
    // context's bit in shade_q, on the way back to shq_any_q) depends on
    // this block's registers alone. With the shading's ready in it, the
    // loop ran out to csgrt_shade's advance register and back (272e988's
    // FREQ 100 route: shq_any_q, 3.42 ns of route to the issue's LUT
    // beside the shading, 3.47 ns back, shade_d, lowest(): 12.44 ns).
    // At II 3 the shading takes a request at most every third clock
    // (its ready is segment A's advance), and the register refills the
    // clock after it empties, so no request waits longer for it. At II 1
    // the shading can take one every clock and the replacement stays.
    wire sh_issue = shq_any && (!sh_valid_q || (II == 1 && sh_ready_i));
`ifndef SYNTHESIS
    // what the II 3 issue relies on, checked: a simulation stops if the
    // shading's ready is high two clocks running (a request would wait a
    // clock for the register)
    reg sh_ready_prev_q;
    always @(posedge clk_i) sh_ready_prev_q <= rst_ni && sh_ready_i;
    always @(posedge clk_i)
        if (II != 1 && rst_ni && chk_reset_seen_q && sh_ready_prev_q && sh_ready_i) begin
            $display("ERROR %m: the shading's ready is high two clocks running at II 3 (a request waits a clock)");
            $fatal;
        end
`endif
    // shade_q's next value: the issued context cleared, then a context set
    // that is ready for shading (its children all spawned and its shadow
    // rays all back), in the events' order of priority:
    //  - a child of a hit, the last: unless shadow rays are pending or
    //    this child is a lit shadow ray (it is pushed: pend_q counts it);
    //  - a colour ray's hit that wants no children;
    //  - a shadow ray that ends, the context's last pending, its
    //    children all spawned.
    // Made per context, each from its own counter and flag: read at the
    // event's context (P-way multiplexers) and decoded after, the set ran
    // through seven LUT levels into shq_any_q with the priority choice
    // (tools/logic_depth.py 12.52 ns, e_h_ctx -> the pending count's read
    // -> shade_d -> lowest()). A child event (ev_ch) and the hit events
    // (which need !ev_ch) never meet, so the order among them is moot. A
    // simulation check compares the set with the choice written out.
    // The three kinds of event that may set a context to shade are
    // registers loaded in E0 from the event's choice and its source's
    // fields (as hpm_q is): decoded in E1 from ev_hp, ev_ch and the e_*
    // fields, they were two LUT levels at the start of the set, and so of
    // the whole design's longest path on 0adc21f's netlist (ev_hp ->
    // shade_set -> shade_d -> lowest() -> shq_ctx_q, 7 LUT levels,
    // tools/logic_depth.py 11.78 ns). Each implies an event other than a
    // contribution, so the set needs no !ev_ct. Simulation checks compare
    // them with the decodes.
    // (loaded below, after the hit's decisions)
    reg shade_ch_any, shade_hc, shade_sh_any;
    wire [P-1:0] shade_set;
    genvar gk;
    generate
        for (gk = 0; gk < P; gk = gk + 1) begin : g_shade_set
            localparam [CB-1:0] K = gk;
            wire ch_here = e_ch_user == K;
            wire h_here  = e_h_ctx == K;
            assign shade_set[gk] =
                (shade_ch_any && ch_here && pend_q[gk] == {PW{1'b0}}) ||
                (h_here && (shade_hc || (shade_sh_any && pend_q[gk] == {{(PW-1){1'b0}}, 1'b1} && !spawning_q[gk])));
        end
    endgenerate
`ifndef SYNTHESIS
    csgrt_check_same #(.WIDTH(3), .WHAT("shade_ch_any / shade_hc / shade_sh_any (the shading's event kinds)")) u_check_shade_kinds (
        .clk_i, .rst_ni, .copy_i({shade_ch_any, shade_hc, shade_sh_any}),
        .orig_i({ev_ch && e_ch_last && !(e_ch_kind == K_SHADOW && e_ch_lit),
                 !ev_ch && ev_hp && !e_h_shadow && e_h_colour_hit && !e_want_spawn,
                 !ev_ch && ev_hp && e_h_shadow && e_sh_ends}));
    wire shade_ch = shade_ch_any && pend_q[e_ch_user] == {PW{1'b0}};
    wire shade_sh = shade_sh_any && pend_q[e_h_ctx] == {{(PW-1){1'b0}}, 1'b1} && !spawning_q[e_h_ctx];
    wire [P-1:0] shade_set_ref = ev_ct ? {P{1'b0}}
                               : shade_ch ? ctx_onehot(e_ch_user)
                               : (shade_hc || shade_sh) ? ctx_onehot(e_h_ctx) : {P{1'b0}};
    csgrt_check_same #(.WIDTH(P), .WHAT("shade_set (per context)")) u_check_shade_set (
        .clk_i, .rst_ni, .copy_i(shade_set), .orig_i(shade_set_ref));
`endif
    assign shade_d = (shade_q & ~(sh_issue ? ctx_onehot(shq_ctx) : {P{1'b0}})) | shade_set;
    assign sh_valid_o = sh_valid_q;
    assign sh_tag_o   = {{(12-CB){1'b0}}, sh_ctx_q};
    // the block RAMs' read registers: loaded at the issue, held until taken
    reg  [3*B-1:0]  sh_o_q, sh_d_q;
    reg  [10*B-1:0] sh_coef_q;
    reg  [MAT_W-1:0] sh_mat_q;
    always @(posedge clk_i)
        if (sh_issue) begin
            sh_o_q    <= ho_q[shq_ctx];
            sh_d_q    <= hd_q[shq_ctx];
            sh_coef_q <= hcoef_q[shq_ctx];
            sh_mat_q  <= hmat_q[shq_ctx];
        end
    assign sh_o_o     = sh_o_q;
    assign sh_d_o     = sh_d_q;
    assign sh_t_o     = ht_q[sh_ctx_q];
    assign sh_coef_o  = sh_coef_q;
    assign sh_mat_o   = sh_mat_q;
    wire [CB-1:0] lc_ctx = lc_tag_i[CB-1:0];
    wire unused_lc = ^lc_tag_i[11:CB];
    wire [KW-1:0] lc_k = lc_k_i[KW-1:0];
    generate
        if (SHADOWS != 0) begin : g_lc_shadows
            // a shadowless light has no shadow ray and lights with its own colour
            assign lc_color_o = light_shadowless_i[lc_k] ? light_color_i[lc_k * 48 +: 48] : lcol_q[{lc_ctx, lc_k}];
        end else begin : g_lc_plain
            assign lc_color_o = light_color_i[lc_k * 48 +: 48];
            wire unused_lcx = ^{lc_ctx, lcol_q[0], light_shadowless_i};   // lcol_q: written for unlit lights only
        end
        if (NLW > KW) begin : g_lc_hi
            wire unused_lk = ^lc_k_i[NLW-1:KW];
        end
    endgenerate

    // ---- the hit's decisions ---------------------------------------------------------------
    // (want_refl and want_refr come with the record: tr_want_* above)
    wire [MAX_LIGHTS-1:0] light_mask;
    genvar g;
    generate
        for (g = 0; g < MAX_LIGHTS; g = g + 1) begin : g_mask
            assign light_mask[g] = (SHADOWS != 0) && (g < num_lights_i) && !light_shadowless_i[g];
        end
    endgenerate
    wire        h_colour_hit = h_hit && hp_in_range;
    wire        want_spawn   = want_refl || want_refr || (light_mask != {MAX_LIGHTS{1'b0}});
    // the shading's event kinds (shade_set above), loaded in E0
    always @(posedge clk_i)
        if (!rst_ni) {shade_ch_any, shade_hc, shade_sh_any} <= 3'b000;
        else begin
            shade_ch_any <= ev0_ch && ch_last_i && !(ch_kind_i == K_SHADOW && ch_lit_i);
            shade_hc     <= ev0_hp && !h_shadow && h_colour_hit && !want_spawn;
            shade_sh_any <= ev0_sh_end;
        end

    // ---- state updates ---------------------------------------------------------------------
    // entry idx of a context's stack
    // (32-bit arithmetic, the entry index in its low STK_AW bits: the rest is 0)
    /* verilator lint_off UNUSEDSIGNAL */
    function [STK_AW-1:0] stk(input [CB-1:0] ctx, input [SPW-1:0] idx);
        reg [31:0] a;
        begin
            a = ctx * MAX_DEPTH + {{(32-SPW){1'b0}}, idx};
            stk = a[STK_AW-1:0];
        end
    endfunction
    /* verilator lint_on UNUSEDSIGNAL */
    always @(posedge clk_i) begin
        if (pa_load)   pa_addr_q   <= stk(pop_ctx, sp_q[pop_ctx] - 1'b1);
        if (pop_stage) pop_ram_q   <= stack_q[pa_addr_q];
        if (pop_fab)   pop_entry_q <= pop_ram_q;
        if (stw_q) stack_q[stw_addr_q] <= stw_data_q;
    end
`ifndef SYNTHESIS
    // the argument above, checked: a simulation stops if a pop reads an entry still being written
    always @(posedge clk_i)
        if (rst_ni && chk_reset_seen_q && pop_stage && stw_q && stw_addr_q == pa_addr_q) begin
            $display("ERROR %m: a stack pop reads an entry whose push is not yet written");
            $fatal;
        end
`endif

    // A contribution is summed into its pixel a clock before its event: the
    // read of the accumulator, the saturating add and the context's output
    // buffer slot, pixel and pointer test into registers (ctp_*), and the
    // event writes them. In the clock of the event, the choice between the
    // contribution's and the traced ray's context in front of the context
    // memories, the add's carry chain and the output buffer's write were
    // the ray tree's longest path out of context (11.73 ns). A shaded
    // context has nothing else in flight (its children are in, its next
    // colour ray waits for this event), so nothing writes its accumulator,
    // stack pointer, pixel or slot in between; a simulation check compares
    // the registers with the event-time values.
    reg  [CB-1:0]  ctp_ctx_q;
    reg  [38:0]    ctp_sum_q;
    reg            ctp_more_q;          // its stack has a pending child
    reg  [OBW-1:0] ctp_slot_q;
    reg  [23:0]    ctp_xy_q;
    always @(posedge clk_i) begin
        if (ct_valid) begin
            ctp_ctx_q  <= ct_ctx;
            ctp_sum_q  <= add_sat(acc_q[ct_ctx], ct_contrib);
            ctp_more_q <= sp_q[ct_ctx] != {SPW{1'b0}};
            ctp_slot_q <= seq_q[ct_ctx][OBW-1:0];
            ctp_xy_q   <= {y_q[ct_ctx], x_q[ct_ctx]};
        end
    end
`ifndef SYNTHESIS
    reg [38:0] ctp_contrib_q;
    always @(posedge clk_i) if (ct_valid) ctp_contrib_q <= ct_contrib;
    csgrt_check_same #(.WIDTH(39 + 1 + OBW + 24), .WHAT("the contribution's early sum, slot, pixel and stack test")) u_check_ctp (
        .clk_i, .rst_ni,
        .copy_i(ev_ct ? {ctp_sum_q, ctp_more_q, ctp_slot_q, ctp_xy_q} : {(39 + 1 + OBW + 24){1'b0}}),
        .orig_i(ev_ct ? {add_sat(acc_q[ctp_ctx_q], ctp_contrib_q), sp_q[ctp_ctx_q] != {SPW{1'b0}},
                         seq_q[ctp_ctx_q][OBW-1:0], y_q[ctp_ctx_q], x_q[ctp_ctx_q]} : {(39 + 1 + OBW + 24){1'b0}}));
`endif
    // The same for a colour ray's miss, in E0 from the hit at hit_prep's
    // head (hpp_*, loaded on every clock): the accumulator read at the
    // ray's context, the background's saturating add, the stack test and
    // the output buffer slot and pixel. In E1 they went from ev_hp through
    // the context memories' reads and the add into the output buffer's
    // write address and data (tools/logic_depth.py: 14.46 ns). A traced
    // colour ray's context has nothing else in flight, and E1 writes its
    // state only at events of that context (its own pixel started long
    // before the ray reached the head; its contribution and pops come
    // after this event), so the E0 read sees what E1 would; a simulation
    // check compares them.
    reg  [38:0]    hpp_sum_q;
    reg            hpp_more_q;
    reg  [OBW-1:0] hpp_slot_q;
    reg  [23:0]    hpp_xy_q;
    always @(posedge clk_i) begin
        hpp_sum_q  <= add_sat(acc_q[h_ctx], hp_bg);
        hpp_more_q <= sp_q[h_ctx] != {SPW{1'b0}};
        hpp_slot_q <= seq_q[h_ctx][OBW-1:0];
        hpp_xy_q   <= {y_q[h_ctx], x_q[h_ctx]};
    end
`ifndef SYNTHESIS
    reg [38:0] e_hp_bg;
    always @(posedge clk_i) e_hp_bg <= hp_bg;
    csgrt_check_same #(.WIDTH(39 + 1 + OBW + 24), .WHAT("a colour miss's early sum, slot, pixel and stack test")) u_check_hpp (
        .clk_i, .rst_ni,
        .copy_i(ev_hp && !e_h_shadow && !e_h_colour_hit ? {hpp_sum_q, hpp_more_q, hpp_slot_q, hpp_xy_q}
                                                        : {(39 + 1 + OBW + 24){1'b0}}),
        .orig_i(ev_hp && !e_h_shadow && !e_h_colour_hit ? {add_sat(acc_q[e_h_ctx], e_hp_bg), sp_q[e_h_ctx] != {SPW{1'b0}},
                                                           seq_q[e_h_ctx][OBW-1:0], y_q[e_h_ctx], x_q[e_h_ctx]}
                                                        : {(39 + 1 + OBW + 24){1'b0}}));
`endif
    // The output buffer's write: a colour ray that ends its pixel, from a
    // contribution (ev_ct) or a miss (ev_hp), its sum and pixel at its
    // slot. Written as one port, its address and data chosen by ev_ct
    // alone, a register: as two writes under the events' priority, yosys
    // merged them with the miss's whole condition (ev_hp, the kind, the
    // stack test) as the address select, four LUT levels from ev_ct into
    // the distributed RAM's write address (tools/logic_depth.py's longest
    // path, 13.62 ns).
    // A colour ray's miss in E1 (ev_hp, not a shadow ray, no hit) as a
    // register loaded in E0 from the event's choice and the head's fields:
    // decoded from ev_hp and the e_* fields, it was three LUT levels in
    // front of the output buffer's distributed-RAM write enables
    // (tools/logic_depth.py's longest path, 11.82 ns on 9f2f1a7's netlist);
    // a simulation check compares it with that decode.
    reg            hpm_q;
    always @(posedge clk_i)
        if (!rst_ni) hpm_q <= 1'b0;
        else         hpm_q <= ev0_hp && !h_shadow && !h_colour_hit;
`ifndef SYNTHESIS
    csgrt_check_same #(.WHAT("hpm_q (a colour ray's miss event)")) u_check_hpm (
        .clk_i, .rst_ni, .copy_i(hpm_q), .orig_i(ev_hp && !e_h_shadow && !e_h_colour_hit));
`endif
    wire           hp_ends = hpm_q && !hpp_more_q;   // a miss ends its pixel
    // The output buffer's write enable is a register too (ob_we_q), loaded
    // in E0 with the same reads that load ctp_more_q, hpm_q and hpp_more_q:
    // as a decode of those and ev_ct (111 loads) it was three LUT levels in
    // front of the buffer's distributed-RAM write enables (tools/
    // logic_depth.py 11.16 ns on 03fd3dc's netlist). A simulation check
    // compares it with the decode.
    reg            ob_we_q;
    always @(posedge clk_i)
        if (!rst_ni) ob_we_q <= 1'b0;
        else         ob_we_q <= ev0_ct ? sp_q[ct_ctx] == {SPW{1'b0}}
                                       : ev0_hp && !h_shadow && !h_colour_hit && sp_q[h_ctx] == {SPW{1'b0}};
    wire           ob_we   = ob_we_q;
`ifndef SYNTHESIS
    csgrt_check_same #(.WHAT("ob_we_q (the output buffer's write)")) u_check_ob_we (
        .clk_i, .rst_ni, .copy_i(ob_we_q), .orig_i(ev_ct ? !ctp_more_q : hp_ends));
`endif
    wire [OBW-1:0] ob_slot = ev_ct ? ctp_slot_q : hpp_slot_q;
    // The valid bits: set at the slot written, cleared at the retire
    // pointer's slot when the pixel leaves (out_take), the clear last. Per
    // bit, from one-hot slot codes loaded with the slots: bit k is set
    // from its own code bit, and cleared by out_take at slot k, which is
    // ob_valid_q[k] itself at the retire pointer (no OB-way multiplexer).
    // Decoded from ob_slot, each bit's set waited for ev_ct's choice of
    // slot (102 loads) and the decode (tools/logic_depth.py 13.68 ns out of
    // context); a simulation check compares them with that decode.
    // The slot's one-hot code is itself a register (ob_set_oh_q, loaded in
    // E0 beside ob_we_q from the same event choice), so the set is the
    // write enable and the code: as ev_ct's choice between the two
    // events' codes and stack tests, then the retire pointer's 16-way
    // choice of it, it ran 8 LUT levels into ob_hv_q (tools/logic_depth.py
    // 12.52 ns on 911d777's netlist). Checked against the decode of the
    // write's slot.
    reg  [OB-1:0]  ob_set_oh_q;
    always @(posedge clk_i)
        ob_set_oh_q <= ev0_ct ? seq_oh_q[ct_ctx] : seq_oh_q[h_ctx];
    wire [OB-1:0]  ob_set  = ob_we_q ? ob_set_oh_q : {OB{1'b0}};
`ifndef SYNTHESIS
    // (the write's slot decoded: ob_we_q itself is checked above)
    csgrt_check_same #(.WIDTH(OB), .WHAT("ob_set (the output buffer's valid bit set, from ob_set_oh_q)")) u_check_ob_set (
        .clk_i, .rst_ni, .copy_i(ob_set), .orig_i(ob_we ? slot_onehot(ob_slot) : {OB{1'b0}}));
`endif
    wire [OB-1:0]  ob_clr  = (o_adv ? slot_onehot(retire_q[OBW-1:0]) : {OB{1'b0}}) & ob_valid_q;
    // E1's pushes: the records were loaded at the end of E0 (rq_*, spq_data)
    assign rq_push  = (ev_ch && e_ch_kind == K_SHADOW && e_ch_lit) || (ev_hp && e_h_shadow && !e_sh_ends)
                      || ev_pop || ev_cam;
    assign spq_push = ev_hp && !e_h_shadow && e_h_colour_hit && e_want_spawn;
    // A colour ray's hit is written as its record waits at the head of
    // csgrt_hit_prep, on every clock from the record's arrival to the
    // clock E0 takes it, whether or not it is a hit at all: its context has
    // nothing else in flight and reads none of it until its children are
    // spawned, and a miss has no children (the next colour ray of the
    // context, popped or a new pixel's, writes its own hit before anything
    // reads one). The last write, in the clock the event is taken, has the
    // results too (hp_valid). So the write enable is two registers, the
    // record's valid bit and its shadow bit: it waited for the event
    // decision once (these ~1,000 bits at 16 bits hung on it), and then
    // for the hit test on the results (h_colour_hit, behind the results'
    // read pointer: tools/logic_depth.py's longest path, 15.19 ns). A shadow
    // ray's record is never written: its context's hit is the one it
    // shadows.
    wire hit_write = hp_rec_valid && !h_shadow;
    always @(posedge clk_i)
        if (hit_write) begin
            w_q[h_ctx]     <= h_w;
            depth_q[h_ctx] <= h_depth;
            wr_q[h_ctx]    <= hp_w_r;
            ho_q[h_ctx]    <= h_o;
            hd_q[h_ctx]    <= h_d;
            ht_q[h_ctx]    <= h_t;
            hcoef_q[h_ctx] <= h_coef;
            hmat_q[h_ctx]  <= h_mat;
            hfilt_q[h_ctx] <= h_mat[M_FILTER +: 16];
            near_q[h_ctx]  <= h_near;
            run_q[h_ctx]   <= h_run;
            after_q[h_ctx] <= h_after;
            wt_q[h_ctx]    <= hp_w_t;
            tx_q[h_ctx]    <= want_refr;
        end
    // the spawn request of a colour hit, loaded at the end of E0 (pushed in E1)
    always @(posedge clk_i)
        spq_data <= {h_ior_to, h_ior_from, want_refr, h_ctx, want_refl, light_mask, h_coef, h_t, h_d, h_o};
    // The events' state updates. The control state (which contexts are
    // busy, spawning, waiting to be shaded or popped, which output slots
    // are full, the valid bits of the pop and shading stages; the first
    // block below) is reset. The context data (accumulators, pixels, output
    // buffer entries and the two staged context numbers in the second
    // block; stack pointers, pending shadow counts and the stack write in
    // the counters' block; light colours in theirs) is not: every entry
    // is written before it is read (a new pixel writes its accumulator and
    // stack pointer, a colour hit its pending count, each of its lights'
    // shadow rays its light colour before the context is shaded, a retired
    // pixel its output entry before the slot is marked full). With these
    // writes in the reset's else branch, the core's reset (fan-out ~200)
    // ran into all their write enables: the routed critical path of
    // 163537d (80.62 MHz, 10.70 of 12.40 ns routing). The events' registers
    // (ev_*) are reset, so no event writes during a reset but in its first
    // clock, and what that writes is overwritten before it is read.
    always @(posedge clk_i) begin
        if (!rst_ni) begin
            busy_q     <= {P{1'b0}};
            spawning_q <= {P{1'b0}};
            shade_q    <= {P{1'b0}};
            pop_q      <= {P{1'b0}};
            ob_valid_q <= {OB{1'b0}};
            ob_hv_q    <= 1'b0;
            next_seq_q <= {(OBW+1){1'b0}};
            sh_valid_q <= 1'b0;
            pa_valid_q   <= 1'b0;
            pr_valid_q   <= 1'b0;
            pop_staged_q <= 1'b0;
        end else begin
            if (pa_load) pa_valid_q <= 1'b1;
            if (pop_stage) begin
                pa_valid_q <= 1'b0;
                pr_valid_q <= 1'b1;
            end
            if (pop_fab) begin
                pr_valid_q   <= 1'b0;
                pop_staged_q <= 1'b1;
            end
            if (ev0_pop) pop_staged_q <= 1'b0;   // E0 took it
            next_seq_q <= next_seq_d;
            // shading issue
            if (sh_ready_i && sh_valid_q) sh_valid_q <= 1'b0;
            if (sh_issue) sh_valid_q <= 1'b1;
            shade_q <= shade_d;

            if (ev_ct) begin
                // ---- a shaded colour ray's contribution; the ray is done
                if (ctp_more_q) pop_q[ctp_ctx_q] <= 1'b1;
                else            busy_q[ctp_ctx_q] <= 1'b0;   // its output buffer slot: ob_we
            end else if (ev_ch) begin
                // ---- a child of a hit
                if (e_ch_last) begin
                    spawning_q[e_ch_user] <= 1'b0;
                    // (shade_q: shade_set below)
                end
            end else if (ev_hp) begin
                if (!e_h_shadow) begin
                    // ---- a colour ray came back
                    if (!e_h_colour_hit) begin
                        if (hpp_more_q) pop_q[e_h_ctx] <= 1'b1;
                        else            busy_q[e_h_ctx] <= 1'b0;   // its output buffer slot: ob_we
                    end else begin
                        // (the hit itself is written already: hit_write)
                        if (e_want_spawn) spawning_q[e_h_ctx] <= 1'b1;   // requested: spq_push
                        // (else shade_q: shade_set below)
                    end
                end else begin
                    // ---- a shadow ray came back (or goes on: rq_push;
                    // its last one sets shade_q: shade_set below)
                end
            end else if (ev_pop) begin
                // ---- the next colour ray of a context, from its stack (pushed: rq_push)
                pop_q[pop_ctx_q] <= 1'b0;
            end else if (ev_cam) begin
                // ---- a new pixel (its primary ray pushed: rq_push)
                busy_q[e_free_ctx] <= 1'b1;
            end
            // output buffer: a pixel done, a pixel retired; the retire
            // slot's bit after the edge: the next slot's if this one
            // leaves (out_take clears it), else this one's, set or not
            ob_valid_q <= (ob_valid_q | ob_set) & ~ob_clr;
            ob_hv_q    <= out_take ? (ob_valid_q[retire1_q] || ob_set[retire1_q])
                                   : (ob_hv_q || ob_set[retire_q[OBW-1:0]]);
        end
    end
    always @(posedge clk_i) begin
        if (pa_load)  pop_ctx_q <= pop_ctx;
        if (sh_issue) sh_ctx_q  <= shq_ctx;
        if (ob_we) begin
            ob_acc_q[ob_slot] <= ev_ct ? ctp_sum_q : hpp_sum_q;
            ob_xy_q[ob_slot]  <= ev_ct ? ctp_xy_q : hpp_xy_q;
        end
        if (ev_ct) begin
            acc_q[ctp_ctx_q] <= ctp_sum_q;
        end else if (hpm_q) begin
            // a colour ray's miss
            acc_q[e_h_ctx] <= hpp_sum_q;
        end else if (ev_cam) begin
            x_q[e_free_ctx]   <= e_cam_xy[11:0];
            y_q[e_free_ctx]   <= e_cam_xy[23:12];
            seq_q[e_free_ctx] <= next_seq_q;
            seq_oh_q[e_free_ctx] <= slot_onehot(next_seq_q[OBW-1:0]);
            acc_q[e_free_ctx] <= 39'd0;
        end
    end
    // The two counters of a context, its stack pointer (sp_q) and its
    // shadow rays pending (pend_q): each event steps, clears or keeps one
    // counter of one context. The operation and the context are registers
    // loaded in E0, the operation from the choice, the context from the
    // sources' valid bits alone (as rq_rec); E1 reads the counter and
    // writes it. Decoded in E1 from the event registers, the write enables
    // ran through the events' priority and the context's choice (tools/
    // logic_depth.py: 13.46 ns from ev_ct into sp_q's enables).
    //  - sp_q:   +1 a stacked child (its entry pushed, stw_*), -1 a pop,
    //            0 a new pixel;
    //  - pend_q: +1 a lit shadow ray, -1 a shadow ray's end, 0 a colour hit.
    localparam [1:0] C_KEEP = 2'd0, C_INC = 2'd1, C_DEC = 2'd2, C_CLEAR = 2'd3;
    reg  [1:0]    sp_op_q, pend_op_q;
    reg  [CB-1:0] sp_ctx_q;
    reg  [P-1:0]  pend_oh_q;            // the pending counter's context, one-hot
    integer       pc;
    // a child kept on its context's stack (not a shadow ray)
    function stacked(input [2:0] kind);
        stacked = kind == K_REFLECT || kind == K_REFRACT || kind == K_TIR;
    endfunction
    function [SPW-1:0] sp_next(input [1:0] op, input [SPW-1:0] v);
        sp_next = (op == C_INC) ? v + 1'b1 : (op == C_DEC) ? v - 1'b1 : {SPW{1'b0}};
    endfunction
    function [PW-1:0] pend_next(input [1:0] op, input [PW-1:0] v);
        pend_next = (op == C_INC) ? v + 1'b1 : (op == C_DEC) ? v - 1'b1 : {PW{1'b0}};
    endfunction
    always @(posedge clk_i) begin
        if (!rst_ni) begin
            sp_op_q   <= C_KEEP;
            pend_op_q <= C_KEEP;
        end else begin
            sp_op_q   <= (ev0_ch && stacked(ch_kind_i)) ? C_INC : ev0_pop ? C_DEC : ev0_cam ? C_CLEAR : C_KEEP;
            pend_op_q <= (ev0_ch && ch_kind_i == K_SHADOW && ch_lit_i) ? C_INC
                       : ev0_sh_end ? C_DEC
                       : (ev0_hp && !h_shadow && h_colour_hit) ? C_CLEAR : C_KEEP;
        end
        sp_ctx_q   <= ch_valid_i ? ch_user_i : pop_staged_q ? pop_ctx_q : free_ctx;
        if (sp_op_q != C_KEEP)   sp_q[sp_ctx_q]     <= sp_next(sp_op_q, sp_q[sp_ctx_q]);
        // per context, from a one-hot code of the context: each counter
        // steps its own value (read through a P-way multiplexer of a
        // context register and written back through its decode, the read,
        // the step and the write's enable were six LUT levels,
        // tools/logic_depth.py 11.45 ns on 3599434's netlist)
        pend_oh_q <= ch_valid_i ? ctx_onehot(ch_user_i) : ctx_onehot(h_ctx);
        for (pc = 0; pc < P; pc = pc + 1)
            if (pend_op_q != C_KEEP && pend_oh_q[pc]) pend_q[pc] <= pend_next(pend_op_q, pend_q[pc]);
        // a stacked child's entry, pushed a clock later (the stack's write port)
        stw_q <= sp_op_q == C_INC;
        if (sp_op_q == C_INC) begin
            stw_addr_q <= stk(sp_ctx_q, sp_q[sp_ctx_q]);
            stw_data_q <= e_ch_entry;
        end
    end
`ifndef SYNTHESIS
    // the counters' operations as decoded from the event registers
    wire [1:0] sp_op_ev = (ev_ch && stacked(e_ch_kind)) ? C_INC
                        : ev_pop ? C_DEC : ev_cam ? C_CLEAR : C_KEEP;
    wire [1:0] pend_op_ev = (ev_ch && e_ch_kind == K_SHADOW && e_ch_lit) ? C_INC
                          : (ev_hp && e_h_shadow && e_sh_ends) ? C_DEC
                          : (ev_hp && !e_h_shadow && e_h_colour_hit) ? C_CLEAR : C_KEEP;
    wire [CB-1:0] sp_ctx_ev   = ev_ch ? e_ch_user : ev_pop ? pop_ctx_q : e_free_ctx;
    wire [CB-1:0] pend_ctx_ev = ev_ch ? e_ch_user : e_h_ctx;
    csgrt_check_same #(.WIDTH(P), .WHAT("pend_oh_q (the pending counter's context, one-hot)")) u_check_pend_oh (
        .clk_i, .rst_ni, .copy_i(pend_op_q != C_KEEP ? pend_oh_q : {P{1'b0}}),
        .orig_i(pend_op_ev != C_KEEP ? ctx_onehot(pend_ctx_ev) : {P{1'b0}}));
    csgrt_check_same #(.WIDTH(4 + CB), .WHAT("the counters' operations (sp_op_q, sp_ctx_q, pend_op_q)")) u_check_count (
        .clk_i, .rst_ni,
        .copy_i({sp_op_q, sp_op_q != C_KEEP ? sp_ctx_q : {CB{1'b0}}, pend_op_q}),
        .orig_i({sp_op_ev, sp_op_ev != C_KEEP ? sp_ctx_ev : {CB{1'b0}}, pend_op_ev}));
`endif
    // A light's colour for a shaded context: zero for a light a child did
    // not light (its shadow ray is not traced), or what the light's shadow
    // ray brought back. The write's enable, address and data are registers
    // loaded in E0, the enable from the choice, address and data from the
    // sources' valid bits alone (as rq_rec): decoded in E1 from the event
    // registers, the enable ran through the events' priority and the
    // {context, light} address's choice into the LUT RAM's write enables
    // (tools/logic_depth.py: 14.58 ns, six LUT levels from ev_ct).
    reg          lcol_we_q;
    reg [CB+KW-1:0] lcol_addr_q;
    reg [47:0]   lcol_data_q;
    always @(posedge clk_i) begin
        lcol_we_q   <= rst_ni && ((ev0_ch && ch_kind_i == K_SHADOW && !ch_lit_i) || ev0_sh_end);
        lcol_addr_q <= ch_valid_i ? {ch_user_i, ch_light_i} : {h_ctx, h_light};
        lcol_data_q <= ch_valid_i ? 48'd0 : hp_sh_color;
        if (lcol_we_q) lcol_q[lcol_addr_q] <= lcol_data_q;
    end
`ifndef SYNTHESIS
    // the write as decoded from the event registers
    wire lcol_we_ev = (ev_ch && e_ch_kind == K_SHADOW && !e_ch_lit) || (ev_hp && e_h_shadow && e_sh_ends);
    csgrt_check_same #(.WIDTH(1 + CB + KW + 48), .WHAT("the light colour write (lcol_we_q, lcol_addr_q, lcol_data_q)")) u_check_lcol (
        .clk_i, .rst_ni,
        .copy_i(lcol_we_q ? {1'b1, lcol_addr_q, lcol_data_q} : {(1 + CB + KW + 48){1'b0}}),
        .orig_i(lcol_we_ev ? {1'b1, ev_ch ? {e_ch_user, e_ch_light, 48'd0} : {e_h_ctx, e_h_light, e_sh_color}}
                           : {(1 + CB + KW + 48){1'b0}}));
`endif
    // The pixels in flight, next_seq - retire, as a register of its own
    // (in_flight_q): after this clock they are base - out_take, base the
    // count before the pixel out (0 at a frame's start, when the sequence
    // restarts at the retire pointer). Both compares of room_out_q's next
    // value are made on base, from registers, and the pixel out only
    // chooses between them: out_take is the output buffer's valid bit at
    // the retire pointer (an OB-way multiplexer), and with the subtraction
    // and compare behind it that was the ray tree's longest path
    // (tools/logic_depth.py 12.98 ns). base - 1 wraps at 0 as
    // next_seq_d - retire_d does.
    reg  [OBW:0] in_flight_q;
    wire [OBW:0] in_flight_base = start_i ? {(OBW+1){1'b0}} : in_flight_q + {{OBW{1'b0}}, ev_cam};
    wire         room_if_out    = (in_flight_base - 1'b1) < OB[OBW:0];
    wire         room_if_none   = in_flight_base < OB[OBW:0];
    always @(posedge clk_i) begin
        in_flight_q <= !rst_ni ? {(OBW+1){1'b0}} : in_flight_base - {{OBW{1'b0}}, out_take};
        room_out_q  <= !rst_ni || (out_take ? room_if_out : room_if_none);
    end
`ifndef SYNTHESIS
    // the valid bits as decoded from the write's slot and the retire pointer
    reg [OB-1:0] ob_valid_ref_q;
    always @(posedge clk_i) begin
        if (!rst_ni) ob_valid_ref_q <= {OB{1'b0}};
        else begin
            if (ob_we)    ob_valid_ref_q[ob_slot] <= 1'b1;
            if (out_take) ob_valid_ref_q[retire_q[OBW-1:0]] <= 1'b0;
        end
    end
    csgrt_check_same #(.WIDTH(OB), .WHAT("ob_valid_q (set and cleared from one-hot codes)")) u_check_ob_valid (
        .clk_i, .rst_ni, .copy_i(ob_valid_q), .orig_i(ob_valid_ref_q));
    wire [OBW:0] in_flight = next_seq_q - retire_q;
    wire [OBW-1:0] retire_plus1 = retire_q[OBW-1:0] + 1'b1;
    csgrt_check_same #(.WIDTH(1 + OBW), .WHAT("ob_hv_q / retire1_q (the retire slot's valid bit, retire_q + 1)")) u_check_hv (
        .clk_i, .rst_ni, .copy_i({ob_hv_q, retire1_q}), .orig_i({ob_valid_q[retire_q[OBW-1:0]], retire_plus1}));
    csgrt_check_same #(.WIDTH(OBW + 2), .WHAT("in_flight_q / room_out_q")) u_check_room (
        .clk_i, .rst_ni, .copy_i({in_flight_q, room_out_q}), .orig_i({in_flight, in_flight < OB[OBW:0]}));
`endif

    // The pushed ray's record, loaded every clock from the source the event
    // selection would take if it pushes: the sources in the events' order
    // of priority, by their valid bits alone. Whether a ray is pushed at
    // all (rq_push, above) needs the whole decision (the contribution event
    // first, a child's kind and light, a shadow ray's end); the record does
    // not, since the FIFO ignores it without a push. With the decision in
    // front of them, these ~1,000 registers hung on two ~460-load nets of
    // the event decode (tools/logic_depth.py: 18.57 ns, the whole design's
    // longest path).
    // (The first choice reads the child port's valid from a copy of its own,
    // ch_valid_rec_i: ch_valid_i had 408 loads, the first net of a path into
    // the ray FIFO's data, tools/logic_depth.py 10.96 ns on aaa564b.)
    always @(posedge clk_i) begin
        if (ch_valid_rec_i) begin
            // a shadow ray to a light, from the hit's near side
            rq_rec  <= rec(1'b1, ch_user_i, ch_light_i, 48'd0, 4'd0, {3{ONE}}, 5'd0, ch_dist_i);
            rq_o    <= ch_p_i;
            rq_d    <= ch_d_i;
            rq_info <= info(1'b1, near_q[ch_user_i], ch_dist_i, run_q[ch_user_i]);
        end else if (hp_valid) begin
            // a shadow ray through a transparent surface, on the far side
            rq_rec  <= rec(1'b1, h_ctx, h_light, 48'd0, 4'd0, hp_sh_atten, h_cross + 5'd1, hp_sh_tlimit);
            rq_o    <= hp_p;
            rq_d    <= h_d;
            rq_info <= info(1'b1, h_after, hp_sh_tlimit, {RUN_W{1'b0}});
        end else if (pop_staged_q) begin
            // the next colour ray of a context, from its stack
            rq_rec  <= rec(1'b0, pop_ctx_q, {KW{1'b0}}, pop_entry_q[6*B +: 48], pop_entry_q[6*B + 48 +: 4],
                           48'd0, 5'd0, {DIST_W{1'b0}});
            rq_o    <= pop_entry_q[0 +: 3*B];
            rq_d    <= pop_entry_q[3*B +: 3*B];
            rq_info <= info(1'b1, pop_entry_q[6*B + 52 +: NS], {DIST_W{1'b0}},
                            pop_entry_q[6*B + 52 + NS +: RUN_W]);
        end else begin
            // a primary ray
            rq_rec  <= rec(1'b0, free_ctx, {KW{1'b0}}, {3{ONE}}, 4'd1, 48'd0, 5'd0, {DIST_W{1'b0}});
            rq_o    <= cam_o_i;
            rq_d    <= cam_d_i;
            rq_info <= info(1'b0, {NS{1'b0}}, {DIST_W{1'b0}}, {RUN_W{1'b0}});
        end
    end

    // ---- pixels out, in raster order --------------------------------------------------------
    wire [38:0] ob_head  = ob_acc_q[retire_q[OBW-1:0]];
    wire [23:0] code;
    generate
        for (g = 0; g < 3; g = g + 1) begin : g_srgb
            csgrt_srgb #(.LUT_FILE(LUT_FILE)) u_lut (
                .clk_i, .ce_i (o_adv), .idx_i (ob_head[g*13 +: 12]), .code_o (code[g*8 +: 8]));
            wire unused_top = ob_head[g*13 + 12];   // saturated at 4095: bit 12 is 0
        end
    endgenerate
    always @(posedge clk_i) begin
        if (!rst_ni) begin
            o_valid_q <= 1'b0;
            retire_q  <= {(OBW+1){1'b0}};
            retire1_q <= {{(OBW-1){1'b0}}, 1'b1};
        end else if (o_adv) begin
            o_valid_q <= out_take;
            if (out_take) o_xy_q <= ob_xy_q[retire_q[OBW-1:0]];
            retire_q <= retire_d;
            if (out_take) retire1_q <= retire1_q + 1'b1;
        end
    end
    assign pix_valid_o = o_valid_q;
    assign pix_x_o     = o_xy_q[11:0];
    assign pix_y_o     = o_xy_q[23:12];
    assign pix_rgb_o   = {code[7:0], code[15:8], code[23:16]};

    // context and output-buffer indices wrap at CB / OBW bits
    generate
        if (CONTEXTS < 2 || (1 << CB) != CONTEXTS) begin : g_bad_param
            initial begin
                $display("ERROR %m: CONTEXTS must be a power of two >= 2 (make sim / make synth CONTEXTS=N), not %0d",
                         CONTEXTS);
                $finish;
            end
        end
    endgenerate
endmodule
`default_nettype wire
