`default_nettype none
// csgrt_hit_prep — the arithmetic the ray tree needs for one traced ray,
// before csgrt_raytree decides what comes next (model/raytree.cpp,
// accumulate_fx and shadow_fx; docs/effects.md):
//
//   p          = o + rnd(t d, F) and whether it lies in [-4, 4)^3
//                (hit_point_fx; out of range, a hit counts as a miss)
//   colour rays:   bg_c = min(rnd(w background), 4095)   the miss contribution
//                  w_r  = rnd(w reflection)               reflected child's weight
//                  w_t  = rnd(w rnd(filter pigment))      transmitted child's weight
//   shadow rays:   the attenuation after this crossing and whether the ray
//                  ends here, and the light colour scaled by the final
//                  attenuation, sc = rnd(light colour atten):
//                    miss                         -> ends, atten
//                    into an opaque material      -> ends, 0
//                    into air / a transparent one -> atten' = atten (air) or
//                                                    rnd(atten rnd(filter pigment));
//                                                    ends with atten' if p is out of
//                                                    range or tlimit - t <= 0, with 0
//                                                    after the 16th crossing;
//                                                    else goes on from p with atten'
//                                                    and tlimit - t
//
// All weights are unsigned 12-fraction-bit colours, at most 1.0 for ray
// weights and attenuations (the compiler's limits), 16-bit fields.
// The shown material (m_mat) is the one the ray enters, or the one it
// leaves when it enters air; for a shadow ray only `to` matters, and when
// `to` is not air it is the shown material.
//
// Pipeline (global stall: the output skid's registered ready):
//   X0 mul (2)  t d_i; filter pigment; w background; w reflection
//   X1 reg (1)  p, in range; ft = rnd(filter pigment)
//   X2 mul (2)  w ft; atten ft
//   X3 reg (1)  the shadow ray's decision and final attenuation
//   X4 mul (2)  light colour x attenuation
//   skid (1)   csgrt_pingpong
// Latency 9 clocks; one record per clock. The record's other fields (ray,
// hit, material, flags) wait in a FIFO beside the pipeline and come out
// with the results. Multipliers: 3 + 9 + 6 + 3 = 21.
// II = 3 (time-shared, csgrt_beat): a record every third clock, the three
// axes or channels of each product on one multiplier (csgrt_mul_vec,
// csgrt_weigh: 7 multipliers), the operands registered on entry (the
// shared multipliers read them for a whole beat); latency 10 beats.
module csgrt_hit_prep #(
    parameter BITS       = 24,
    parameter MAX_LIGHTS = 8,
    parameter DIST_W     = 27,    // shadow ray distance / t limit (unsigned, F fraction bits)
    parameter REC_W      = 8,     // the record waiting beside the pipeline
    parameter MAX_CROSS  = 16,    // crossings a shadow ray follows (model: kMaxShadowCrossings)
    parameter II         = 1      // running clocks per record: 1 or 3
) (
    input  wire                      clk_i,
    input  wire                      rst_ni,
    input  wire [3*16-1:0]           background_i,
    input  wire [MAX_LIGHTS*48-1:0]  light_color_i,
    // one traced ray
    input  wire                      s_valid_i,
    output wire                      s_ready_o,
    input  wire                      s_shadow_i,       // 0: colour ray, 1: shadow ray
    input  wire [KW-1:0]             s_light_i,        // shadow ray: its light
    input  wire [3*16-1:0]           s_w_i,            // colour ray: weight
    input  wire [3*16-1:0]           s_atten_i,        // shadow ray: attenuation so far
    input  wire [4:0]                s_cross_i,        // shadow ray: crossings so far (0 for the first)
    input  wire [DIST_W-1:0]         s_tlimit_i,       // shadow ray: distance left to the light
    input  wire [3*BITS-1:0]         s_o_i,
    input  wire [3*BITS-1:0]         s_d_i,
    input  wire                      s_hit_i,
    input  wire [BITS-2:0]           s_t_i,            // >= 0 on a hit
    input  wire                      s_to_air_i,       // BORDER x, 0
    input  wire [3*16-1:0]           s_rgb_i,          // shown material
    input  wire [15:0]               s_filter_i,
    input  wire [15:0]               s_reflection_i,
    input  wire [REC_W-1:0]          s_rec_i,
    // results
    output wire                      m_valid_o,
    input  wire                      m_ready_i,
    output wire [REC_W-1:0]          m_rec_o,
    output wire                      m_rec_valid_o,   // m_rec_o holds the next record (often before m_valid_o)
    output wire [3*BITS-1:0]         m_p_o,
    output wire                      m_in_range_o,
    output wire [3*13-1:0]           m_bg_o,          // colour ray: rnd(w background), saturated at 4095
    output wire [3*16-1:0]           m_w_r_o,
    output wire [3*16-1:0]           m_w_t_o,
    output wire                      m_sh_ends_o,     // shadow ray: it ends here
    output wire [3*16-1:0]           m_sh_color_o,    // ... with this scaled light colour
    output wire [3*16-1:0]           m_sh_atten_o,    // ... or goes on with this attenuation
    output wire [DIST_W-1:0]         m_sh_tlimit_o    // ... and this distance left
);
    localparam B  = BITS;
    localparam F  = B - 3;
    localparam TW = B - 1;
    localparam KW = (MAX_LIGHTS > 1) ? $clog2(MAX_LIGHTS) : 1;
    localparam PW = B + 2;                    // o + rnd(t d): |p| < 6 before the range check

    wire       en;    // the pipeline runs: the output skid's ready
    wire [1:0] ph;
    wire       adv;   // the beat's advance: every register but the multipliers' moves on it
    wire       last;  // the beat's last clock: an item leaves for the output skid only then
    wire       en_next, adv_q;
    csgrt_beat #(.II(II)) u_beat (.clk_i, .rst_ni, .ce_i(en), .ce_next_i(en_next), .phase_o(ph), .last_o(last),
                                  .adv_o(adv), .adv_q_o(adv_q));
    wire fifo_ready;
    // the upstream handshake reads the advance's own register, not the
    // enable net of every stage (csgrt_beat)
    assign s_ready_o = adv_q && fifo_ready;
    wire take = s_valid_i && s_ready_o;

    genvar i;

    // ---- input: registered for II = 3 (steady for the shared multipliers' beat) ----
    // {x word: tlimit, t, cross, light, atten, w, o, opaque, to_air, hit, shadow; d, rgb, filter, reflection}
    localparam XW = DIST_W + TW + 5 + KW + 48 + 48 + 3 * B + 4;
    localparam IW = XW + 3 * B + 48 + 16 + 16;
    wire          s_opaque = !s_to_air_i && (s_filter_i == 16'd0);
    wire [IW-1:0] s_word = {s_reflection_i, s_filter_i, s_rgb_i, s_d_i,
                            s_tlimit_i, s_t_i, s_cross_i, s_light_i, s_atten_i, s_w_i, s_o_i,
                            s_opaque, s_to_air_i, s_hit_i, s_shadow_i};
    wire          i_valid;
    wire [IW-1:0] i_word;
    csgrt_delay #(.WIDTH(IW), .STAGES(II == 1 ? 0 : 1)) u_in (
        .clk_i, .rst_ni, .ce_i(adv), .valid_i(take), .data_i(s_word),
        .valid_o(i_valid), .data_o(i_word));
    wire [XW-1:0]  i_x          = i_word[0 +: XW];
    wire [TW-1:0]  i_t          = i_x[4 + 3*B + 96 + KW + 5 +: TW];
    wire [47:0]    i_w          = i_x[4 + 3*B +: 48];
    wire [3*B-1:0] i_d          = i_word[XW +: 3*B];
    wire [47:0]    i_rgb        = i_word[XW + 3*B +: 48];
    wire [15:0]    i_filter     = i_word[XW + 3*B + 48 +: 16];
    wire [15:0]    i_reflection = i_word[XW + 3*B + 64 +: 16];

    // ---- X0: products ----------------------------------------------------------
    wire [3*(TW+B)-1:0] td;
    csgrt_mul_vec #(.A_WIDTH(TW), .B_WIDTH(B), .N(3), .II(II)) u_td (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en), .adv_i(adv), .phase_i(ph), .a_i({3{i_t}}), .b_i(i_d), .p_o(td));
    localparam WP = 21;   // rnd(16-bit x 16-bit, 12)
    wire [3*WP-1:0] ft_w, bg_w, wr_w;
    wire unused_v0, unused_v1, unused_u0, unused_u1;
    csgrt_weigh #(.A_WIDTH(16), .B_WIDTH(16), .II(II)) u_ft (
        .clk_i, .rst_ni, .ce_i(en), .adv_i(adv), .phase_i(ph), .valid_i(i_valid), .a_i({3{i_filter}}), .b_i(i_rgb),
        .user_i(1'b0), .valid_o(unused_v0), .p_o(ft_w), .user_o(unused_u0));
    csgrt_weigh #(.A_WIDTH(16), .B_WIDTH(16), .II(II)) u_bg (
        .clk_i, .rst_ni, .ce_i(en), .adv_i(adv), .phase_i(ph), .valid_i(i_valid), .a_i(i_w), .b_i(background_i),
        .user_i(1'b0), .valid_o(unused_v1), .p_o(bg_w), .user_o(unused_u1));
    wire          x0_valid;
    wire [XW-1:0] x0_x;
    csgrt_weigh #(.A_WIDTH(16), .B_WIDTH(16), .USER_WIDTH(XW), .II(II)) u_wr (
        .clk_i, .rst_ni, .ce_i(en), .adv_i(adv), .phase_i(ph), .valid_i(i_valid), .a_i(i_w), .b_i({3{i_reflection}}),
        .user_i(i_x), .valid_o(x0_valid), .p_o(wr_w), .user_o(x0_x));
    wire [3*B-1:0] x0_o = x0_x[4 +: 3*B];

    // ---- X1: hit point, range, ft --------------------------------------------------
    wire [3*B-1:0] p_d;
    wire [2:0]     p_ok;
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_p
            wire [TW+B-1:0] prod   = td[i*(TW+B) +: TW+B];
            wire [TW+B-1:0] prod_r = prod + {{(TW+B-F){1'b0}}, 1'b1, {(F-1){1'b0}}};
            wire [PW-1:0]   tdr    = prod_r[F +: PW];     // |t d| < 2
            wire unused_td = ^prod_r[F-1:0];
            wire [B-1:0]    o      = x0_o[i*B +: B];
            wire [PW-1:0]   p      = {{2{o[B-1]}}, o} + tdr;
            // in [-4, 4): the three bits above B-1 equal the sign bit of a B-bit value
            assign p_ok[i] = (p[PW-1:B-1] == {3{p[B-1]}});
            assign p_d[i*B +: B] = p[B-1:0];
        end
    endgenerate
    function [15:0] sat16(input [WP-1:0] v);   // weights and colours stay below 16
        sat16 = (|v[WP-1:16]) ? 16'hffff : v[15:0];
    endfunction
    function [12:0] sat4095(input [WP-1:0] v);
        sat4095 = (|v[WP-1:12]) ? 13'd4095 : v[12:0];
    endfunction
    reg           x1_valid_q;
    reg [XW-1:0]  x1_x_q;
    reg [3*B-1:0] x1_p_q;
    reg           x1_in_range_q;
    reg [47:0]    x1_ft_q, x1_wr_q;
    reg [38:0]    x1_bg_q;
    // each always block has its own loop variable (one shared by several
    // blocks is a variable with several drivers to yosys)
    integer c;
    reg [47:0] ft_sat, wr_sat;
    reg [38:0] bg_sat;
    integer c_x1;
    always @* for (c_x1 = 0; c_x1 < 3; c_x1 = c_x1 + 1) begin
        ft_sat[c_x1*16 +: 16] = sat16(ft_w[c_x1*WP +: WP]);
        wr_sat[c_x1*16 +: 16] = sat16(wr_w[c_x1*WP +: WP]);
        bg_sat[c_x1*13 +: 13] = sat4095(bg_w[c_x1*WP +: WP]);
    end
    always @(posedge clk_i) begin
        if (!rst_ni) x1_valid_q <= 1'b0;
        else if (adv) x1_valid_q <= x0_valid;
        if (adv) begin
            x1_x_q        <= x0_x;
            x1_p_q        <= p_d;
            x1_in_range_q <= &p_ok;
            x1_ft_q       <= ft_sat;
            x1_wr_q       <= wr_sat;
            x1_bg_q       <= bg_sat;
        end
    end
    localparam XO = 4 + 3 * B;   // where w starts in the pipeline word
    wire [47:0] x1_w     = x1_x_q[XO +: 48];
    wire [47:0] x1_atten = x1_x_q[XO + 48 +: 48];

    // ---- X2: w ft, atten ft --------------------------------------------------------
    localparam YW = XW + 3 * B + 1 + 48 + 39;   // {x, p, in_range, w_r, bg}
    wire [3*WP-1:0] wt_w, at_w;
    wire            x2_valid;
    wire [YW-1:0]   x2_y;
    // The shadow ray's distance left to its light, subtracted at X1 and
    // carried through u_at with the word: at X2 its carry chain and zero
    // test ran into the decision and across the die to x3_term_q (the ray
    // tree's longest path out of context, 10.52 ns).
    wire [TW-1:0]     x1_t      = x1_x_q[XO + 101 + KW +: TW];
    wire [DIST_W-1:0] x1_tlimit = x1_x_q[XO + 101 + KW + TW +: DIST_W];
    wire [DIST_W:0]   x1_left   = {1'b0, x1_tlimit} - {{(DIST_W+1-TW){1'b0}}, x1_t};
    wire              x1_left_le0 = x1_left[DIST_W] || (x1_left == {(DIST_W+1){1'b0}});
    wire [DIST_W-1:0] left;
    wire              left_le0;
    wire unused_v2, unused_u2;
    csgrt_weigh #(.A_WIDTH(16), .B_WIDTH(16), .II(II)) u_wt (
        .clk_i, .rst_ni, .ce_i(en), .adv_i(adv), .phase_i(ph), .valid_i(x1_valid_q), .a_i(x1_w), .b_i(x1_ft_q), .user_i(1'b0),
        .valid_o(unused_v2), .p_o(wt_w), .user_o(unused_u2));
    csgrt_weigh #(.A_WIDTH(16), .B_WIDTH(16), .USER_WIDTH(YW + DIST_W + 1), .II(II)) u_at (
        .clk_i, .rst_ni, .ce_i(en), .adv_i(adv), .phase_i(ph), .valid_i(x1_valid_q), .a_i(x1_atten), .b_i(x1_ft_q),
        .user_i({x1_left_le0, x1_left[DIST_W-1:0], x1_bg_q, x1_wr_q, x1_in_range_q, x1_p_q, x1_x_q}),
        .valid_o(x2_valid), .p_o(at_w), .user_o({left_le0, left, x2_y}));
    wire [XW-1:0]     x2_x        = x2_y[0 +: XW];
    wire              x2_in_range = x2_y[XW + 3*B];
    wire              x2_shadow   = x2_x[0];
    wire              x2_hit      = x2_x[1];
    wire              x2_to_air   = x2_x[2];
    wire              x2_opaque   = x2_x[3];
    wire [47:0]       x2_atten    = x2_x[XO + 48 +: 48];
    wire [KW-1:0]     x2_light    = x2_x[XO + 96 +: KW];
    wire [4:0]        x2_cross    = x2_x[XO + 96 + KW +: 5];
    wire unused_x2 = ^x2_x[4 +: 3*B + 48];   // o and w: used before, output from the record FIFO
    wire unused_x2t = ^x2_x[XW-1:XO + 101 + KW];   // t and tlimit: subtracted at X1 (left)

    // ---- X3: the shadow ray's decision -------------------------------------------
    reg  [47:0] atten_next;
    always @* begin
        for (c = 0; c < 3; c = c + 1) atten_next[c*16 +: 16] = sat16(at_w[c*WP +: WP]);
        if (x2_to_air) atten_next = x2_atten;
    end
    // opaque: entering a material whose filter is 0 (tested on the filter:
    // a black transparent pigment gives ft = 0 too, and lets nothing through
    // by the product, not by this rule)
    reg               x3_valid_q, x3_ends_q;
    reg  [47:0]       x3_term_q, x3_atten_q;
    reg  [DIST_W-1:0] x3_tlimit_q;
    reg  [KW-1:0]     x3_light_q;
    reg  [YW-1:0]     x3_y_q;
    reg  [47:0]       x3_wt_q;
    reg               ends;
    reg  [47:0]       term;
    always @* begin
        ends = 1'b1;
        term = 48'd0;
        if (!x2_hit) begin
            term = x2_atten;
        end else if (x2_opaque) begin
            term = 48'd0;
        end else if (!x2_in_range || left_le0) begin
            term = atten_next;
        end else if ({27'd0, x2_cross} + 32'd1 >= MAX_CROSS) begin
            term = 48'd0;
        end else begin
            ends = 1'b0;
        end
    end
    reg [47:0] wt_sat;
    integer c_x3;
    always @* for (c_x3 = 0; c_x3 < 3; c_x3 = c_x3 + 1) wt_sat[c_x3*16 +: 16] = sat16(wt_w[c_x3*WP +: WP]);
    always @(posedge clk_i) begin
        if (!rst_ni) x3_valid_q <= 1'b0;
        else if (adv) x3_valid_q <= x2_valid;
        if (adv) begin
            x3_ends_q   <= ends || !x2_shadow;
            x3_term_q   <= term;
            x3_atten_q  <= atten_next;
            x3_tlimit_q <= left;
            x3_light_q  <= x2_light;
            x3_y_q      <= x2_y;
            x3_wt_q     <= wt_sat;
        end
    end

    // ---- X4: light colour x final attenuation ----------------------------------------
    localparam ZW = YW + 48 + 48 + DIST_W + 1;
    wire [3*WP-1:0] sc_w;
    wire            x4_valid;
    wire [ZW-1:0]   x4_z;
    wire [47:0]     lc = light_color_i[x3_light_q * 48 +: 48];
    csgrt_weigh #(.A_WIDTH(16), .B_WIDTH(16), .USER_WIDTH(ZW), .II(II)) u_sc (
        .clk_i, .rst_ni, .ce_i(en), .adv_i(adv), .phase_i(ph), .valid_i(x3_valid_q), .a_i(lc), .b_i(x3_term_q),
        .user_i({x3_ends_q, x3_tlimit_q, x3_atten_q, x3_wt_q, x3_y_q}),
        .valid_o(x4_valid), .p_o(sc_w), .user_o(x4_z));
    reg [47:0] sc;
    integer c_sc;
    always @* for (c_sc = 0; c_sc < 3; c_sc = c_sc + 1) sc[c_sc*16 +: 16] = sat16(sc_w[c_sc*WP +: WP]);

    // ---- output skid, and the record FIFO --------------------------------------------
    localparam OW = ZW + 48;
    wire [OW-1:0] out_w;
    wire          out_valid;
    // csgrt_pingpong, not csgrt_skid: m_ready_i is the ray tree's event
    // choice, decided late in the clock from the spawn unit's valid; with
    // a skid's output register it went on into every result bit's enable
    // (some 300 at 16 bits), and from there through ready_next_o into the
    // beat (tools/logic_depth.py's second-longest path, 14.66 ns). Here it
    // moves two pointers.
    csgrt_pingpong #(.WIDTH(OW)) u_skid (
        .clk_i, .rst_ni, .valid_i(x4_valid && last), .ready_o(en), .ready_next_o(en_next), .data_i({sc, x4_z}),
        .valid_o(out_valid), .ready_i(m_ready_i), .data_o(out_w));
    wire          rec_valid;
    // the record is about a thousand bits wide at 24 bits: block RAM, not LUT
    // RAM; its head in a fabric register, every enable from registers
    // (HEAD_REG 2), because the ray tree's spawn decision starts from the
    // record's material fields (the block RAM's read port alone took 5.8 of
    // a 100 MHz clock's 10 ns) and its event selection decides the pop late
    // in the clock (docs/fpga.md); a record per hit needs no more than a
    // word every 2 clocks. (Until the head register, the ray's context,
    // kind, light and hit bit, which address the ray tree's context memories,
    // waited in a LUT-RAM queue of their own beside this one.)
    csgrt_fifo_block #(.WIDTH(REC_W), .DEPTH(16), .HEAD_REG(2)) u_rec (
        .clk_i, .rst_ni, .valid_i(take), .ready_o(fifo_ready), .data_i(s_rec_i),
        .valid_o(rec_valid), .ready_i(m_valid_o && m_ready_i), .data_o(m_rec_o));
    // A hit is offered when its results and its record are both at the
    // heads (the record arrives first, but its head refills a clock after
    // each take). m_valid_o is a register (m_valid_q): the two heads'
    // valid bits a clock ago, unless that clock took the pair. A pair
    // stays until it is taken, so a pair offered is at the heads; one that
    // arrives is offered a clock later, and none is lost after a take (the
    // record's head is empty in that clock). m_valid_o fans out into the
    // ray tree's event choice and its records' selects (~110 loads), and
    // as the AND of the two heads it was the first LUT of the whole
    // design's longest path (tools/logic_depth.py 12.90 ns).
    reg m_valid_q;
    always @(posedge clk_i)
        m_valid_q <= rst_ni && out_valid && rec_valid && !(m_valid_q && m_ready_i);
    assign m_valid_o = m_valid_q;
    csgrt_check_same #(.WHAT("m_valid_q (offered only while both heads hold the pair)")) u_check_offer (
        .clk_i, .rst_ni, .copy_i(m_valid_q && !(out_valid && rec_valid)), .orig_i(1'b0));
    assign m_rec_valid_o = rec_valid;

    wire [YW-1:0] o_y = out_w[0 +: YW];
    assign m_p_o         = o_y[XW +: 3*B];
    assign m_in_range_o  = o_y[XW + 3*B];
    assign m_w_r_o       = o_y[XW + 3*B + 1 +: 48];
    assign m_bg_o        = o_y[XW + 3*B + 49 +: 39];
    assign m_w_t_o       = out_w[YW +: 48];
    assign m_sh_atten_o  = out_w[YW + 48 +: 48];
    assign m_sh_tlimit_o = out_w[YW + 96 +: DIST_W];
    assign m_sh_ends_o   = out_w[YW + 96 + DIST_W];
    assign m_sh_color_o  = out_w[ZW +: 48];
endmodule
`default_nettype wire
