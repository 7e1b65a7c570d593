`default_nettype none
// csgrt_contrib — a shaded ray's contribution to its pixel, bit for bit
// accumulate_fx() in model/raytree.cpp (docs/effects.md, "Colour"):
//
//   L       = local                                          (no transmitted child)
//           = rnd((1 - filter) (local - spec), 12) + spec    (a transmitted child)
//   contrib = min(rnd(w L, 12), 4095)
//
// local and spec are csgrt_shade's linear outputs (12 fraction bits,
// non-negative); the pixel's sum of contributions saturates at 4095 as the
// model's clamp of the sum does (every term is non-negative).
//
// Pipeline (global stall: the output skid's registered ready):
//   C0 mul (2)  (1 - filter) (local - spec)
//   C1 reg (1)  L
//   C2 mul (2)  w L
//   skid (1)
// Latency 6 clocks, one record per clock. Multipliers: 6.
// II = 3 (time-shared, csgrt_beat): a record every third clock, the three
// channels of each product on one multiplier (csgrt_weigh, 2 multipliers),
// the record registered on entry (the shared multiplier reads it for a
// whole beat); latency 7 beats.
module csgrt_contrib #(
    parameter COL_W = 31,    // local colour bits (csgrt_shade's CLW)
    parameter TAG_W = 3,
    parameter II    = 1      // running clocks per record: 1 or 3
) (
    input  wire               clk_i,
    input  wire               rst_ni,
    input  wire               s_valid_i,
    output wire               s_ready_o,
    input  wire [TAG_W-1:0]   s_tag_i,
    input  wire [3*COL_W-1:0] s_local_i,
    input  wire [3*COL_W-1:0] s_spec_i,     // spec <= local per channel
    input  wire               s_transmits_i,
    input  wire [15:0]        s_filter_i,   // <= 4096
    input  wire [3*16-1:0]    s_w_i,
    output wire               m_valid_o,
    output wire               m_valid_copy_o, // m_valid_o from a register of its own (below)
    input  wire               m_ready_i,
    output wire [TAG_W-1:0]   m_tag_o,
    output wire [3*13-1:0]    m_contrib_o
);
    localparam DP = 16 + COL_W - 11;   // rnd((1 - f) diff)
    localparam LW = COL_W + 1;         // L
    localparam CP = 16 + LW - 11;      // rnd(w L)

    wire       en;    // the pipeline runs: the output skid's ready
    wire [1:0] ph;
    wire       adv;   // the beat's advance: every register but the multipliers' moves on it
    wire       last;  // the beat's last clock: an item leaves for the output skid only then
    wire       en_next, adv_q;
    csgrt_beat #(.II(II)) u_beat (.clk_i, .rst_ni, .ce_i(en), .ce_next_i(en_next), .phase_o(ph), .last_o(last),
                                  .adv_o(adv), .adv_q_o(adv_q));
    // the upstream handshake reads the advance's own register, not the
    // enable net of every stage (csgrt_beat)
    assign s_ready_o = adv_q;

    // ---- input: registered for II = 3 (steady for the shared multiplier's beat) ----
    localparam IW = TAG_W + 6 * COL_W + 1 + 16 + 48;
    wire          i_valid;
    wire [IW-1:0] i_rec;
    csgrt_delay #(.WIDTH(IW), .STAGES(II == 1 ? 0 : 1)) u_in (
        .clk_i, .rst_ni, .ce_i(adv), .valid_i(s_valid_i),
        .data_i({s_w_i, s_filter_i, s_transmits_i, s_spec_i, s_local_i, s_tag_i}),
        .valid_o(i_valid), .data_o(i_rec));
    wire [TAG_W-1:0]   i_tag    = i_rec[0 +: TAG_W];
    wire [3*COL_W-1:0] i_local  = i_rec[TAG_W +: 3*COL_W];
    wire [3*COL_W-1:0] i_spec   = i_rec[TAG_W + 3*COL_W +: 3*COL_W];
    wire               i_tr     = i_rec[TAG_W + 6*COL_W];
    wire [15:0]        i_filter = i_rec[TAG_W + 6*COL_W + 1 +: 16];
    wire [47:0]        i_w      = i_rec[TAG_W + 6*COL_W + 17 +: 48];

    reg [3*COL_W-1:0] diff;
    integer c;
    always @* for (c = 0; c < 3; c = c + 1) diff[c*COL_W +: COL_W] = i_local[c*COL_W +: COL_W] - i_spec[c*COL_W +: COL_W];
    wire [15:0] keep = 16'd4096 - i_filter;

    // ---- C0 ----------------------------------------------------------------------
    localparam UW0 = TAG_W + 3 * COL_W + 3 * COL_W + 1 + 48;
    wire [3*DP-1:0] kd;
    wire            c0_valid;
    wire [UW0-1:0]  c0_u;
    csgrt_weigh #(.A_WIDTH(16), .B_WIDTH(COL_W), .USER_WIDTH(UW0), .II(II)) u_keep (
        .clk_i, .rst_ni, .ce_i(en), .adv_i(adv), .phase_i(ph), .valid_i(i_valid), .a_i({3{keep}}), .b_i(diff),
        .user_i({i_w, i_tr, i_spec, i_local, i_tag}),
        .valid_o(c0_valid), .p_o(kd), .user_o(c0_u));
    wire [TAG_W-1:0]   c0_tag   = c0_u[0 +: TAG_W];
    wire [3*COL_W-1:0] c0_local = c0_u[TAG_W +: 3*COL_W];
    wire [3*COL_W-1:0] c0_spec  = c0_u[TAG_W + 3*COL_W +: 3*COL_W];
    wire               c0_tr    = c0_u[TAG_W + 6*COL_W];
    wire [47:0]        c0_w     = c0_u[TAG_W + 6*COL_W + 1 +: 48];

    // ---- C1: L --------------------------------------------------------------------
    reg              c1_valid_q;
    reg [3*LW-1:0]   c1_l_q;
    reg [47:0]       c1_w_q;
    reg [TAG_W-1:0]  c1_tag_q;
    // its own loop variable (one shared with the other always blocks is a
    // variable with several drivers to yosys)
    reg [3*LW-1:0]   l_d;
    integer c_l;
    always @* for (c_l = 0; c_l < 3; c_l = c_l + 1)
        l_d[c_l*LW +: LW] = c0_tr
            ? kd[c_l*DP +: LW] + {1'b0, c0_spec[c_l*COL_W +: COL_W]}   // kd <= diff: fits LW
            : {1'b0, c0_local[c_l*COL_W +: COL_W]};
    always @(posedge clk_i) begin
        if (!rst_ni) c1_valid_q <= 1'b0;
        else if (adv) c1_valid_q <= c0_valid;
        if (adv) begin
            c1_l_q   <= l_d;
            c1_w_q   <= c0_w;
            c1_tag_q <= c0_tag;
        end
    end
    wire unused_kd;
    generate
        genvar k;
        wire [2:0] kd_hi;
        for (k = 0; k < 3; k = k + 1) begin : g_kd
            assign kd_hi[k] = ^kd[k*DP + LW +: DP - LW];
        end
        assign unused_kd = ^kd_hi;
    endgenerate

    // ---- C2: w L ------------------------------------------------------------------
    wire [3*CP-1:0]  wl;
    wire             c2_valid;
    wire [TAG_W-1:0] c2_tag;
    csgrt_weigh #(.A_WIDTH(16), .B_WIDTH(LW), .USER_WIDTH(TAG_W), .II(II)) u_w (
        .clk_i, .rst_ni, .ce_i(en), .adv_i(adv), .phase_i(ph), .valid_i(c1_valid_q), .a_i(c1_w_q), .b_i(c1_l_q), .user_i(c1_tag_q),
        .valid_o(c2_valid), .p_o(wl), .user_o(c2_tag));
    reg [38:0] contrib;
    integer c_out;
    always @* for (c_out = 0; c_out < 3; c_out = c_out + 1)
        contrib[c_out*13 +: 13] = (|wl[c_out*CP + 12 +: CP - 12]) ? 13'd4095 : wl[c_out*CP +: 13];

    csgrt_skid #(.WIDTH(TAG_W + 39)) u_skid (
        .clk_i, .rst_ni, .valid_i(c2_valid && last), .ready_o(en), .ready_next_o(en_next), .data_i({contrib, c2_tag}),
        .valid_o(m_valid_o), .ready_i(m_ready_i), .data_o({m_contrib_o, m_tag_o}));
    // The output's valid bit again, loaded with the skid's next value (its
    // skid register is full exactly while en is low), as csgrt_spawn's
    // m_valid_copy_o: the ray tree gives the child rays' port its ready
    // from it, while m_valid_o decides the tree's events (96 loads, the
    // first net of a path through csgrt_spawn's output skid into its beat,
    // tools/logic_depth.py 11.19 ns on aaa564b's netlist). keep: yosys
    // would merge the two.
    reg valid_copy_q;
    (* keep *) always @(posedge clk_i)
        valid_copy_q <= rst_ni && ((m_ready_i || !m_valid_o) ? (!en || (c2_valid && last)) : m_valid_o);
    assign m_valid_copy_o = valid_copy_q;
    csgrt_check_same #(.WHAT("m_valid_copy_o")) u_check_valid_copy (
        .clk_i, .rst_ni, .copy_i(valid_copy_q), .orig_i(m_valid_o));
endmodule
`default_nettype wire
