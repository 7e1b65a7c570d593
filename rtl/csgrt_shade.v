`default_nettype none
// csgrt_shade — shading and colour output, bit for bit
// srgb_encode_fx(shade_fx(...)) of model/render.cpp per channel
// (docs/numerics.md section 6). One input per pixel (the walker's hit and the
// ray, the hit leaf's coefficients, the shown material), one output per pixel
// {x, y, r, g, b}, in order.
//
// Formats: B = BITS, F = B-3, FC = B-1; PF = 12 (positions, gradient), SF =
// 15 (unit vectors), CF = 12 (colours, finish, light intensity: 16-bit
// unsigned). Internal widths (bounds from numerics.md and shade_fx):
//   ps 18, ds 17, ks 17, g 18, n 17 (|n| < 2^15), dn 18, r 18, lv 18,
//   l 17, ndl 18, cos_r / pow 18, ph 18, diffuse sum 22, specular sum 26.
//
// Segment A, per pixel (one global enable, skid buffer A's ready):
//   A0  mul (2)   t d_i                         3 csgrt_mul (F+2) x B
//   A1  add (1)   p = o + rnd(t d, F); ps, ds, ks aligned
//   A2  mul (2)   ks.A_ij ps_j                   9 csgrt_mul 17 x 18
//   A3  add (1)   g = rnd(A ps + ks.p << PF, SF)
//   A4  mul (2)   g_i^2                          3 csgrt_mul 18 x 18
//   A5  add (1)   |g|^2
//   A6  sqrt(17)  csgrt_sqrt_core
//   A7  add (1)   L = root + 1, numerators g << SF
//   A8  div (17)  three csgrt_div_core (16 quotient bits): n
//   A9  reg (1)   n signed
//   A10 mul (2)   n_i ds_i                       3 csgrt_mul 17 x 17
//   A11 add (1)   face forward (exact sign of n.ds), dn = rnd(ds.n, SF)
//   A12 mul (2)   dn n_i                         3 csgrt_mul 18 x 17
//   A13 add (0)   r = ds - rnd(2 dn n, SF) = ds - rnd(dn n, SF-1); skid A (1)
// Light sequencer: the pixel at skid A's output is issued into segment B
//   once per light (max(1, lights) items; a miss or no light: one item
//   that adds nothing), then popped.
// Segment B, per light item (one global enable, the output skid's ready):
//   B1  add (1)   lv = align(light, F, PF) - ps (the aligned light positions
//                 are registered config; light k by a constant-position mux)
//   B2  mul (2)   lv_i^2                         3 csgrt_mul 18 x 18
//   B3  add (1)   |lv|^2
//   B4  sqrt(17)  csgrt_sqrt_core
//   B5  add (1)   L = root + 1, numerators lv << SF
//   B6  div (17)  three csgrt_div_core: l
//   B7  reg (1)   l signed
//   B8  mul (2)   n_i l_i, r_i l_i               6 csgrt_mul
//   B9  add (1)   ndl = rnd(n.l, SF), cos_r = rnd(r.l, SF), enables
//   B10 pow (20)  pow_fx(cos_r, phong_size): 10 stages of 2 clocks, from
//                 the exponent's LSB; stage k: result = rnd(result base)
//                 if bit k, base = rnd(base^2) (none after the last bit)
//                                                18 csgrt_mul 18 x 18
//   B11 mul (2)   phong pw                       1 csgrt_mul 17 x 18
//   B12 mul (2)   light_c ph, light_c ndl        6 csgrt_mul 17 x 18
//   B13 acc (1)   diff_c += rnd(light_c ndl, SF) if ndl > 0,
//                 spec_c += rnd(light_c ph, CF) if phong > 0 and cos_r > 0
//                 (first item of a pixel restarts the sums; the last item
//                 passes the pixel on)
//   C1  mul (2)   diffuse diff_c                 3 csgrt_mul 17 x 22
//   C2  add (1)   intensity = ambient + rnd(., CF)
//   C3  mul (2)   pigment_c intensity            3 csgrt_mul 17 x 25
//   C4  add (1)   col = rnd(., CF) + spec (miss: background), clamp 0..4095
//   C5  lut (1)   csgrt_srgb x 3;  output skid (1)
// Multipliers: 21 (A) + 34 (B) + 6 (C) = 61 csgrt_mul.
// Without the specular unit (SPECULAR = 0: a scene without phong, or a build
// that shades without highlights, docs/effects.md) A12, A13, B8's r_i l_i,
// B10, B11 and B12's light_c ph are absent (28 csgrt_mul fewer: 33) and the
// specular sums stay 0, as they do with phong = 0; segment B is 22 clocks
// shorter.
// Latency (no back-pressure): 127 clocks from input to output for a miss or
// one light (any BITS: shading widths are fixed; 105 with SPECULAR = 0);
// light k adds k clocks.
// Throughput: segment A one pixel per clock; segment B one light per clock:
// a hit pixel every max(1, lights) clocks, a miss every clock.
// II = 3 (time-shared, csgrt_beat): every stage moves once every three
// running clocks, and the products of a stage (its three axes or channels,
// or the power step's two) share one multiplier (csgrt_mul_vec), the unit
// vectors' divisions one divider and their square roots three result bits
// per stage (csgrt_unit): 25 csgrt_mul (11 without the
// specular unit), 2 csgrt_div_core instead of 6; a pixel or light item
// every third clock; the input is registered first (the shared A0
// multiplier reads it for a whole beat); latency 256 clocks (BITS any,
// one light, no back-pressure). A stage then has a whole beat for its
// logic, which nextpnr times as one clock: the longer add stages (A3, A11,
// B9, B13, C4) and B1's light choice are split by a register in mid-beat
// (csgrt_beat_cut), with the same results and latency.
// Handshake: valid/ready on both sides; s_ready_o is skid A's registered
// ready, never combinational from m_ready_i. Config (lights, background) is
// read when a pixel's items are issued (the light positions through a
// register: one clock earlier); hold it steady while shading.
module csgrt_shade #(
    parameter BITS       = 24,                // coordinate width B (12..32)
    parameter MAX_LIGHTS = 8,                 // point lights (>= 1)
    parameter LUT_FILE   = "rtl/srgb_lut.hex", // sRGB table (csgrt_srgb)
    // For the ray tree (csgrt_raytree): LINEAR_OUT = 1 outputs the linear
    // colour and its phong part (m_local_o, m_spec_o, before the clamp; no
    // sRGB stage: one clock less) instead of m_r/g/b_o; EXT_LIGHT = 1 takes
    // each light's colour from lc_color_i, which the caller drives for the
    // item's tag (the pixel's x field, lc_tag_o) and light (lc_k_o) in the
    // same clock: the light colour scaled by what its shadow ray brought back.
    parameter LINEAR_OUT = 0,
    parameter EXT_LIGHT  = 0,
    // 1: phong highlights (the specular unit); 0: shaded as if every phong
    // were 0, without the hardware that computes highlights
    parameter SPECULAR   = 1,
    // running clocks per beat: 1 = a pixel into segment A and a light item
    // into segment B every clock; 3 = one every third clock, each stage's
    // products on one multiplier serving them in turn (csgrt_mul_vec), the
    // same results
    parameter II         = 1
) (
    input  wire                          clk_i,
    input  wire                          rst_ni,         // synchronous, active low
    // configuration
    input  wire [$clog2(MAX_LIGHTS+1)-1:0] num_lights_i, // 0..MAX_LIGHTS
    input  wire [MAX_LIGHTS*3*BITS-1:0]  light_pos_i,    // light k, axis i at (3k+i)*BITS, F frac
    input  wire [MAX_LIGHTS*3*16-1:0]    light_color_i,  // light k, channel c at (3k+c)*16, 12 frac
    input  wire [3*16-1:0]               background_i,   // r, g, b (r low), 12 frac
    // input stream: one pixel
    input  wire                          s_valid_i,
    output wire                          s_ready_o,
    input  wire [11:0]                   s_x_i,
    input  wire [11:0]                   s_y_i,
    input  wire                          s_hit_i,
    input  wire [BITS-2:0]               s_t_i,          // F+2 bits signed, F frac
    input  wire [3*BITS-1:0]             s_o_i,          // ray origin, F frac
    input  wire [3*BITS-1:0]             s_d_i,          // ray direction, F frac
    input  wire [10*BITS-1:0]            s_coef_i,       // hit leaf, CoefIndex order, FC frac
    input  wire [3*16-1:0]               s_rgb_i,        // pigment, 12 frac
    input  wire [15:0]                   s_ambient_i,
    input  wire [15:0]                   s_diffuse_i,
    input  wire [15:0]                   s_phong_i,
    input  wire [9:0]                    s_phong_size_i, // 1..1023
    // output stream: one pixel
    output wire                          m_valid_o,
    input  wire                          m_ready_i,
    output wire [11:0]                   m_x_o,
    output wire [11:0]                   m_y_o,
    output wire [7:0]                    m_r_o,
    output wire [7:0]                    m_g_o,
    output wire [7:0]                    m_b_o,
    output wire [3*31-1:0]               m_local_o,      // LINEAR_OUT: col_c = rnd(pigment intensity) + spec, 12 frac
    output wire [3*26-1:0]               m_spec_o,       // LINEAR_OUT: spec_c, 12 frac
    // EXT_LIGHT: the light colour of the item being issued
    output wire [11:0]                   lc_tag_o,
    output wire [$clog2(MAX_LIGHTS+1)-1:0] lc_k_o,
    input  wire [3*16-1:0]               lc_color_i
);

    // ---- formats -------------------------------------------------------------
    localparam B    = BITS;
    localparam F    = B - 3;
    localparam FC   = B - 1;
    localparam TW   = F + 2;
    localparam NLW  = $clog2(MAX_LIGHTS + 1);        // light count width
    localparam KW_L = (MAX_LIGHTS > 1) ? $clog2(MAX_LIGHTS) : 1;   // light index width
    localparam PSW  = 18;    // ps, lv: PF bits
    localparam DSW  = 17;    // ds (can be exactly 1.0 after rounding)
    localparam KSW  = 17;    // ks
    localparam GW   = 18;    // g, lv
    localparam QB   = 16;    // quotient bits: SF + 1
    localparam NVW  = QB + 1;   // unit vector, signed
    localparam DNW  = 18;
    localparam RW   = 18;
    localparam NDW  = 18;    // ndl, cos_r, pow values
    localparam DAW  = 22;    // diffuse sum
    localparam SAW  = 26;    // specular sum
    localparam IW   = 25;    // intensity
    localparam CLW  = 31;    // colour before the clamp
    // the reflected view direction r rides along with each pixel and light
    // item; without the specular unit one constant bit holds its place
    localparam RXW  = (SPECULAR != 0) ? 3 * RW : 1;

    // pixel side data: {phong_size, phong, diffuse, ambient, rgb, hit, y, x}
    localparam PIXW = 10 + 16 * 3 + 48 + 1 + 24;
    localparam PX_HIT = 24, PX_RGB = 25, PX_AMB = 73, PX_DIF = 89, PX_PH = 105,
               PX_PHS = 121;
    // The pixel's side data rides along both segments but is read only at
    // their ends, so it waits in RAM delay lines (csgrt_delay_ram, block
    // RAM) instead of a register copy per stage (about 30 of them: 3.5 k
    // flip-flops): segment A's whole (PIXW bits, input to skid A); in
    // segment B the part that segment C reads, {diffuse, ambient, rgb, hit,
    // y, x} (PXCW bits, the low ones), from B1 to C0, while {phong_size,
    // phong} (PXPW bits), which B9 to B11 read, rides with the item. The
    // lines' lengths are the segments' stage counts in advances, with
    // csgrt_unit's latency (the unit vectors' M, S, Q, P, D, O: its
    // header) for A4..A9 and B2..B7.
    localparam PXCW = PX_PH;           // {diffuse, ambient, rgb, hit, y, x}
    localparam PXPW = PIXW - PX_PH;    // {phong_size, phong}
`include "csgrt_unit_latency.vh"
    // csgrt_shade_unit is csgrt_unit with FRAC 15 and 17 square-root stages
    localparam UNIT_LAT = csgrt_unit_latency(15, 17, II);
    // A: u_in (II = 3), A0 2, A1, A2 2, A3, the unit, A10 2, A11, A12 2
    localparam A_PIX_LAT = (II == 1 ? 0 : 1) + 11 + UNIT_LAT;
    // B: B1, the unit, B8 2, B9, B10 and B11 (22 with the specular unit), B12 2, C0
    localparam B_PIX_LAT = 7 + UNIT_LAT + (SPECULAR != 0 ? 22 : 0);

    wire en_a;   // segment A runs: skid A's ready
    wire en_b;   // segments B and C run: the output skid's ready
    // Each segment moves on its beat's advance (every running clock for
    // II = 1, every third for II = 3); the shared multipliers run on every
    // running clock. An item enters a segment and leaves it for a skid
    // only at an advance.
    wire [1:0] ph_a, ph_b;
    wire       adv_a, adv_b;
    wire       last_a, last_b;   // a beat's last clock
    wire       en_a_next, en_b_next, adv_a_q, adv_b_q;
    csgrt_beat #(.II(II)) u_beat_a (.clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en_a), .ce_next_i(en_a_next),
                                    .phase_o(ph_a), .last_o(last_a), .adv_o(adv_a), .adv_q_o(adv_a_q));
    csgrt_beat #(.II(II)) u_beat_b (.clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en_b), .ce_next_i(en_b_next),
                                    .phase_o(ph_b), .last_o(last_b), .adv_o(adv_b), .adv_q_o(adv_b_q));
    // the upstream handshake reads the advance's own register, not the
    // enable net of every stage of segment A (csgrt_beat)
    assign s_ready_o = adv_a_q;

    genvar i, j;

    // =========================================================================
    // Segment A: per pixel
    // =========================================================================
    // ---- input: II = 3 registers the pixel, whose t and d the shared A0
    // multiplier reads for a whole beat (II = 1: straight through) -----------
    wire [PIXW-1:0] s_pix = {s_phong_size_i, s_phong_i, s_diffuse_i, s_ambient_i, s_rgb_i, s_hit_i, s_y_i, s_x_i};
    localparam A0W = 15 * B;
    wire unused_q = ^s_coef_i[9*B +: B];   // the constant term does not enter the gradient
    wire           in_valid;
    wire [A0W-1:0] in_side;   // {coef (9), d, o}
    wire [TW-1:0]  in_t;
    csgrt_delay #(.WIDTH(A0W + TW), .STAGES(II == 1 ? 0 : 1)) u_in (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv_a), .valid_i(s_valid_i),
        .data_i({s_coef_i[0 +: 9*B], s_d_i, s_o_i, s_t_i}), .valid_o(in_valid), .data_o({in_side, in_t}));

    // ---- A0: t d_i ---------------------------------------------------------
    wire [3*(TW+B)-1:0] td;
    csgrt_mul_vec #(.A_WIDTH(TW), .B_WIDTH(B), .N(3), .II(II)) u_mul_a0 (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en_a), .adv_i(adv_a), .phase_i(ph_a),
        .a_i({3{in_t}}), .b_i(in_side[3*B +: 3*B]), .p_o(td));
    wire           a0_valid;
    wire [A0W-1:0] a0_side;
    csgrt_delay #(.WIDTH(A0W), .STAGES(2)) u_dly_a0 (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv_a), .valid_i(in_valid),
        .data_i(in_side), .valid_o(a0_valid), .data_o(a0_side));
    wire [3*B-1:0]  a0_o    = a0_side[0 +: 3*B];
    wire [3*B-1:0]  a0_d    = a0_side[3*B +: 3*B];
    wire [9*B-1:0]  a0_coef = a0_side[6*B +: 9*B];
    // the pixel's side data, from the input to skid A in one RAM line
    wire [PIXW-1:0] a12_pix;
    csgrt_delay_ram #(.WIDTH(PIXW), .STAGES(A_PIX_LAT), .OUT_REG(1)) u_dly_pix_a (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv_a), .data_i(s_pix), .data_o(a12_pix));

    // ---- A1: hit point and the shading copies --------------------------------
    localparam PW = B + 2;   // p = o + rnd(t d, F), exact (|p| < 6)
    wire [3*PSW-1:0] ps_d;
    wire [3*DSW-1:0] ds_d;
    wire [9*KSW-1:0] ks_d;   // q is not needed for the gradient
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_a1
            wire [TW+B-1:0] prod = td[i*(TW+B) +: TW+B];
            wire [TW+B-1:0] prod_r = prod + {{(TW+B-F){1'b0}}, 1'b1, {(F-1){1'b0}}};
            wire [PW-1:0]   tdr = prod_r[F +: PW];   // |t d| < 2: fits
            wire unused_td = ^prod_r[F-1:0];
            wire [B-1:0]    o = a0_o[i*B +: B];
            wire [PW-1:0]   p = {{2{o[B-1]}}, o} + tdr;
            csgrt_align #(.IN_W(PW), .OUT_W(PSW), .FROM(F), .TO(12)) u_ps (.v_i(p), .v_o(ps_d[i*PSW +: PSW]));
            csgrt_align #(.IN_W(B), .OUT_W(DSW), .FROM(F), .TO(15)) u_ds (
                .v_i(a0_d[i*B +: B]), .v_o(ds_d[i*DSW +: DSW]));
        end
        for (i = 0; i < 9; i = i + 1) begin : g_ks
            csgrt_align #(.IN_W(B), .OUT_W(KSW), .FROM(FC), .TO(15)) u_ks (
                .v_i(a0_coef[i*B +: B]), .v_o(ks_d[i*KSW +: KSW]));
        end
    endgenerate
    reg              a1_valid_q;
    reg [3*PSW-1:0]  a1_ps_q;
    reg [3*DSW-1:0]  a1_ds_q;
    reg [9*KSW-1:0]  a1_ks_q;
    always @(posedge clk_i) begin
        if (!rst_ni) a1_valid_q <= 1'b0;
        else if (adv_a) a1_valid_q <= a0_valid;
        if (adv_a) begin
            a1_ps_q  <= ps_d;
            a1_ds_q  <= ds_d;
            a1_ks_q  <= ks_d;
        end
    end

    // ---- A2: gradient products ks.A_ij ps_j ----------------------------------
    localparam GPW = KSW + PSW;   // 35
    wire [9*GPW-1:0] gp;
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_a2_row
            // row i: the coefficients A_i0, A_i1, A_i2 (CoefIndex order)
            wire [3*KSW-1:0] ks_row;
            for (j = 0; j < 3; j = j + 1) begin : g_a2_col
                localparam CI = (i == j) ? i : (i + j == 1) ? 3 : (i + j == 2) ? 4 : 5;
                assign ks_row[j*KSW +: KSW] = a1_ks_q[CI*KSW +: KSW];
            end
            csgrt_mul_vec #(.A_WIDTH(KSW), .B_WIDTH(PSW), .N(3), .II(II)) u_mul (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en_a), .adv_i(adv_a), .phase_i(ph_a),
                .a_i(ks_row), .b_i(a1_ps_q), .p_o(gp[3*i*GPW +: 3*GPW]));
        end
    endgenerate
    localparam A2W = 3 * KSW;
    wire           a2_valid;
    wire [A2W-1:0] a2_side;
    csgrt_delay #(.WIDTH(A2W), .STAGES(2)) u_dly_a2 (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv_a), .valid_i(a1_valid_q),
        .data_i(a1_ks_q[6*KSW +: 3*KSW]), .valid_o(a2_valid), .data_o(a2_side));
    wire [3*KSW-1:0] a2_kp  = a2_side;
    // {ds, ps} wait for the unit vector n (A2 .. A9) in one RAM line rather
    // than riding through A2, A3 and the unit's stages (csgrt_unit carries
    // a sideband in flip-flops and two RAM lines of its own)
    localparam PDW = 3 * PSW + 3 * DSW;   // {ds, ps}
    wire [PDW-1:0]   a9_side;
    csgrt_delay_ram #(.WIDTH(PDW), .STAGES(3 + UNIT_LAT), .OUT_REG(1)) u_dly_pd (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv_a), .data_i({a1_ds_q, a1_ps_q}), .data_o(a9_side));

    // ---- A3: g = rnd(A ps + ks.p << PF, SF) ----------------------------------
    localparam GSW = GPW + 3;   // exact sum
    wire [3*GW-1:0] g_d;
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_a3
            wire [GPW-1:0] p0 = gp[(3*i+0)*GPW +: GPW];
            wire [GPW-1:0] p1 = gp[(3*i+1)*GPW +: GPW];
            wire [GPW-1:0] p2 = gp[(3*i+2)*GPW +: GPW];
            wire [KSW-1:0] kp = a2_kp[i*KSW +: KSW];
            // the products' sum, then (after a beat cut) the rest
            wire [GSW-1:0] sp_d = {{3{p0[GPW-1]}}, p0} + {{3{p1[GPW-1]}}, p1} + {{3{p2[GPW-1]}}, p2};
            wire [GSW-1:0] sp;
            csgrt_beat_cut #(.WIDTH(GSW), .II(II)) u_cut (
                .clk_i(clk_i), .rst_ni(rst_ni), .adv_i(adv_a), .live_i(1'b1), .d_i(sp_d), .q_o(sp));
            wire [GSW-1:0] s = sp + {{(GSW-KSW-12){kp[KSW-1]}}, kp, 12'd0}
                             + {{(GSW-15){1'b0}}, 1'b1, 14'd0};
            wire unused_s = ^{s[14:0], s[GSW-1:15+GW]};
            assign g_d[i*GW +: GW] = s[15 +: GW];
        end
    endgenerate
    reg             a3_valid_q;
    reg [3*GW-1:0]  a3_g_q;
    always @(posedge clk_i) begin
        if (!rst_ni) a3_valid_q <= 1'b0;
        else if (adv_a) a3_valid_q <= a2_valid;
        if (adv_a) begin
            a3_g_q   <= g_d;
        end
    end

    // ---- A4..A9: n = unit(g) -------------------------------------------------
    localparam A4W = PDW;
    wire             a9_valid;
    wire [3*NVW-1:0] a9_n;
    wire             a9_user;   // nothing rides through the unit (u_dly_pd)
    csgrt_shade_unit #(.VW(GW), .USER_WIDTH(1), .II(II)) u_unit_n (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en_a), .adv_i(adv_a), .phase_i(ph_a), .valid_i(a3_valid_q),
        .v_i(a3_g_q), .user_i(1'b0),
        .valid_o(a9_valid), .u_o(a9_n), .user_o(a9_user));
    wire unused_a9_user = a9_user;
    wire [3*DSW-1:0] a9_ds = a9_side[3*PSW +: 3*DSW];

    // ---- A10: n_i ds_i -------------------------------------------------------
    localparam NDPW = NVW + DSW;   // 34
    wire [3*NDPW-1:0] nds;
    csgrt_mul_vec #(.A_WIDTH(NVW), .B_WIDTH(DSW), .N(3), .II(II)) u_mul_a10 (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en_a), .adv_i(adv_a), .phase_i(ph_a),
        .a_i(a9_n), .b_i(a9_ds), .p_o(nds));
    wire             a10_valid;
    wire [3*NVW-1:0] a10_n;
    wire [A4W-1:0]   a10_side;
    csgrt_delay #(.WIDTH(3 * NVW + A4W), .STAGES(2)) u_dly_a10 (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv_a), .valid_i(a9_valid),
        .data_i({a9_side, a9_n}), .valid_o(a10_valid), .data_o({a10_side, a10_n}));

    // ---- A11: face the ray, dn = rnd(ds.n, SF) --------------------------------
    localparam NDSW = NDPW + 2;
    wire [NDSW-1:0] nd_d = {{2{nds[NDPW-1]}}, nds[0 +: NDPW]} + {{2{nds[2*NDPW-1]}}, nds[NDPW +: NDPW]}
                         + {{2{nds[3*NDPW-1]}}, nds[2*NDPW +: NDPW]};
    wire [NDSW-1:0] nd;   // the dot product, after a beat cut
    csgrt_beat_cut #(.WIDTH(NDSW), .II(II)) u_cut_a11 (
        .clk_i(clk_i), .rst_ni(rst_ni), .adv_i(adv_a), .live_i(1'b1), .d_i(nd_d), .q_o(nd));
    // exact sign of the full dot product: flip when n.ds > 0
    wire            flip = !nd[NDSW-1] && (nd != {NDSW{1'b0}});
    // ds . n after the flip, rounded: flip ? -nd + h : nd + h with -nd =
    // ~nd + 1, as one adder (h = 2^14, whose low bits are free for the 1)
    wire [NDSW-1:0] ndf_r = (nd ^ {NDSW{flip}}) + {{(NDSW-15){1'b0}}, 1'b1, 13'd0, flip};
    wire unused_ndf = ^{ndf_r[14:0], ndf_r[NDSW-1:15+DNW]};
    wire [3*NVW-1:0] nf_d;
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_a11
            wire [NVW-1:0] n = a10_n[i*NVW +: NVW];
            assign nf_d[i*NVW +: NVW] = flip ? {NVW{1'b0}} - n : n;
        end
    endgenerate
    reg             a11_valid_q;
    reg [3*NVW-1:0] a11_n_q;
    reg [DNW-1:0]   a11_dn_q;
    reg [A4W-1:0]   a11_side_q;
    always @(posedge clk_i) begin
        if (!rst_ni) a11_valid_q <= 1'b0;
        else if (adv_a) a11_valid_q <= a10_valid;
        if (adv_a) begin
            a11_n_q    <= nf_d;
            a11_dn_q   <= ndf_r[15 +: DNW];
            a11_side_q <= a10_side;
        end
    end

    // ---- A12: dn n_i; A13: r = ds - rnd(2 dn n, SF) ---------------------------
    wire             a12_valid;
    wire [3*NVW-1:0] a12_n;
    wire [A4W-1:0]   a12_side;
    csgrt_delay #(.WIDTH(3 * NVW + A4W), .STAGES(2)) u_dly_a12 (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv_a), .valid_i(a11_valid_q),
        .data_i({a11_side_q, a11_n_q}), .valid_o(a12_valid), .data_o({a12_side, a12_n}));
    wire [3*PSW-1:0] a12_ps  = a12_side[0 +: 3*PSW];
    wire [3*DSW-1:0] a12_ds  = a12_side[3*PSW +: 3*DSW];
    wire [RXW-1:0]   r_d;
    generate
        if (SPECULAR != 0) begin : g_a12
            localparam DNPW = DNW + NVW;   // 35
            wire [3*DNPW-1:0] dnn;
            csgrt_mul_vec #(.A_WIDTH(DNW), .B_WIDTH(NVW), .N(3), .II(II)) u_mul (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en_a), .adv_i(adv_a), .phase_i(ph_a),
                .a_i({3{a11_dn_q}}), .b_i(a11_n_q), .p_o(dnn));
            for (i = 0; i < 3; i = i + 1) begin : g_a13
                // rnd(2 x, 15) = rnd(x, 14)
                wire [DNPW-1:0] pr = dnn[i*DNPW +: DNPW] + {{(DNPW-14){1'b0}}, 1'b1, 13'd0};
                wire unused_pr = ^{pr[13:0], pr[DNPW-1:14+RW]};
                wire [DSW-1:0]  ds = a12_ds[i*DSW +: DSW];
                assign r_d[i*RW +: RW] = {ds[DSW-1], ds} - pr[14 +: RW];
            end
        end else begin : g_no_a12
            assign r_d = 1'b0;
            wire unused_dn = ^{a11_dn_q, a12_ds};
        end
    endgenerate

    // ---- skid A ------------------------------------------------------------------
    localparam SKAW = PIXW + 3 * PSW + 3 * NVW + RXW;
    wire             ska_valid;
    wire             ska_ready;
    wire [SKAW-1:0]  ska_data;
    csgrt_skid #(.WIDTH(SKAW)) u_skid_a (
        .clk_i(clk_i), .rst_ni(rst_ni),
        .valid_i(a12_valid && last_a), .ready_o(en_a), .ready_next_o(en_a_next), .data_i({a12_pix, r_d, a12_n, a12_ps}),
        .valid_o(ska_valid), .ready_i(ska_ready), .data_o(ska_data));
    wire [3*PSW-1:0] sq_ps  = ska_data[0 +: 3*PSW];
    wire [3*NVW-1:0] sq_n   = ska_data[3*PSW +: 3*NVW];
    wire [RXW-1:0]   sq_r   = ska_data[3*PSW+3*NVW +: RXW];
    wire [PIXW-1:0]  sq_pix = ska_data[3*PSW+3*NVW+RXW +: PIXW];

    // =========================================================================
    // Light sequencer
    // =========================================================================
    reg  [KW_L-1:0] k_q;   // light of the next item
    // whether the scene has lights, a register of its own: num_lights_i
    // is static while items flow (as for k_end_q below), and its compare
    // with zero was the first two LUT levels of a path through sq_last
    // into skid A's ready and on to every register it enables
    // (tools/logic_depth.py 12.49 ns, the loader's num_lights_o -> the
    // ray tree's sh_ready_i)
    reg             lights_q;
    always @(posedge clk_i) lights_q <= num_lights_i != {NLW{1'b0}};
    csgrt_check_same #(.WHAT("lights_q (the scene has lights)")) u_check_lights (
        .clk_i(clk_i), .rst_ni(rst_ni), .copy_i(ska_valid && lights_q),
        .orig_i(ska_valid && (num_lights_i != {NLW{1'b0}})));
    wire            sq_use  = sq_pix[PX_HIT] && lights_q;
    // last item: the last light, or the only item of a miss / a scene without lights.
    // The counter's test k_q + 1 >= num_lights_i is a register of its own
    // (k_end_q), loaded every clock with the test of k_q's next value: the
    // test's carry chain lay between k_q and skid A's ready, which enables
    // its ~300 output registers (tools/logic_depth.py). num_lights_i is
    // static while items flow; the register follows a change a clock later.
    // issue and skid A's ready read segment B's advance from its own
    // register (adv_b_q, equal to adv_b), not the net that enables every
    // register of segments B and C (~7,000 loads)
    wire            issue   = adv_b_q && ska_valid;
    reg             k_end_q;
    wire            sq_last = !sq_use || k_end_q;
    assign ska_ready = adv_b_q && sq_last;
    wire [KW_L-1:0] k_d     = !rst_ni ? {KW_L{1'b0}} :
                              !issue  ? k_q :
                              sq_last ? {KW_L{1'b0}} : k_q + {{(KW_L-1){1'b0}}, 1'b1};
    wire [NLW:0]    nl_x    = {1'b0, num_lights_i};
    function automatic k_end(input [KW_L-1:0] k);   // k + 1 >= num_lights_i
        k_end = {{(NLW+1-KW_L){1'b0}}, k} + {{NLW{1'b0}}, 1'b1} >= nl_x;
    endfunction
    // k_q one-hot (k_oh_q), stepped as k_q is, for B1's choice of the
    // light: the choice by k_q's compares hung on its ~250 loads and took
    // five LUT levels into the beat cut (tools/logic_depth.py 11.43 ns)
    reg  [MAX_LIGHTS-1:0] k_oh_q;
    localparam [MAX_LIGHTS-1:0] K_OH_FIRST = 1;
    wire [MAX_LIGHTS-1:0] k_oh_d = !rst_ni ? K_OH_FIRST :
                                   !issue  ? k_oh_q :
                                   sq_last ? K_OH_FIRST : k_oh_q << 1;
    always @(posedge clk_i) begin
        k_q     <= k_d;
        k_oh_q  <= k_oh_d;
        k_end_q <= k_end(k_d);
    end
    csgrt_check_same #(.WIDTH(MAX_LIGHTS), .WHAT("k_oh_q (k_q one-hot)")) u_check_k_oh (
        .clk_i(clk_i), .rst_ni(rst_ni), .copy_i(k_oh_q), .orig_i(K_OH_FIRST << k_q));
    // checked while an item waits in skid A (the only time it is read)
    csgrt_check_same #(.WHAT("k_end_q")) u_check_k_end (
        .clk_i(clk_i), .rst_ni(rst_ni), .copy_i(ska_valid && k_end_q), .orig_i(ska_valid && k_end(k_q)));

    // =========================================================================
    // Segment B: per light item
    // =========================================================================
    // ---- B1: lv = align(light, F, PF) - ps ------------------------------------
    // The light positions are static configuration: every light's aligned
    // position is registered (lpa_q, one clock behind light_pos_i), and the
    // item's light is chosen from those registers by a mux over the constant
    // positions k (no index arithmetic), so B1 is k_q -> mux -> subtract.
    // The light colour likewise (from light_color_i directly). The chosen
    // position goes through a beat cut before the subtract: k_q moves only
    // at an advance and lpa_q is static, so the choice is steady for the
    // beat (k_q's net, the mux and the subtract's carry chain were the
    // routed 45509c3 build's critical path). The skid's sq_ps is not: a
    // pixel can arrive in mid-beat, so the subtract stays behind the cut.
    wire [3*GW-1:0]  lv_d;
    reg  [MAX_LIGHTS*3*PSW-1:0] lpa_q;   // light k, axis i at (3k+i)*PSW, PF frac
    generate
        for (j = 0; j < MAX_LIGHTS * 3; j = j + 1) begin : g_lpa
            wire [PSW-1:0] lpa;
            csgrt_align #(.IN_W(B), .OUT_W(PSW), .FROM(F), .TO(12)) u_lp (
                .v_i(light_pos_i[j*B +: B]), .v_o(lpa));
            always @(posedge clk_i) lpa_q[j*PSW +: PSW] <= lpa;
        end
    endgenerate
    reg [3*PSW-1:0] lpa_sel;
    reg [47:0]      lcol_sel;
    integer kl;
    always @* begin
        lpa_sel  = {(3*PSW){1'b0}};
        lcol_sel = 48'd0;
        // an AND-OR over the lights, selected by k_oh_q
        for (kl = 0; kl < MAX_LIGHTS; kl = kl + 1) begin
            lpa_sel  = lpa_sel  | (lpa_q[kl*3*PSW +: 3*PSW] & {(3*PSW){k_oh_q[kl]}});
            lcol_sel = lcol_sel | (light_color_i[kl*48 +: 48] & {48{k_oh_q[kl]}});
        end
    end
    wire [3*PSW-1:0] lpa_cut;
    csgrt_beat_cut #(.WIDTH(3*PSW), .II(II)) u_cut_b1 (
        .clk_i(clk_i), .rst_ni(rst_ni), .adv_i(adv_b), .live_i(ska_valid), .d_i(lpa_sel), .q_o(lpa_cut));
    wire [3*16-1:0]  lcol_d = (EXT_LIGHT != 0) ? lc_color_i : lcol_sel;
    assign lc_tag_o = sq_pix[11:0];
    assign lc_k_o   = {{($clog2(MAX_LIGHTS+1)-KW_L){1'b0}}, k_q};
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_b1
            assign lv_d[i*GW +: GW] = lpa_cut[i*PSW +: PSW] - sq_ps[i*PSW +: PSW];
        end
    endgenerate
    // item flags: {use, last, first}; of the pixel's side data only
    // {phong_size, phong} (the rest waits in u_dly_pix_b)
    localparam XBW = 48 + 3 * NVW + RXW + PXPW + 3;
    reg             b1_valid_q;
    reg [3*GW-1:0]  b1_lv_q;
    always @(posedge clk_i) begin
        if (!rst_ni) b1_valid_q <= 1'b0;
        else if (adv_b) b1_valid_q <= ska_valid;
        if (adv_b) b1_lv_q <= lv_d;
    end
    // the rest of the item waits for the unit vector l (B1 .. B7) in one
    // RAM line rather than riding through B1 and the unit's stages
    wire [XBW-1:0]   b7_x;
    csgrt_delay_ram #(.WIDTH(XBW), .STAGES(1 + UNIT_LAT), .OUT_REG(1)) u_dly_xb (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv_b),
        .data_i({sq_use, sq_last, (k_q == {KW_L{1'b0}}), sq_pix[PX_PH +: PXPW], sq_r, sq_n, lcol_d}), .data_o(b7_x));

    // ---- B2..B7: l = unit(lv) ------------------------------------------------
    wire             b7_valid;
    wire [3*NVW-1:0] b7_l;
    wire             b7_user;   // nothing rides through the unit (u_dly_xb)
    csgrt_shade_unit #(.VW(GW), .USER_WIDTH(1), .II(II)) u_unit_l (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en_b), .adv_i(adv_b), .phase_i(ph_b), .valid_i(b1_valid_q),
        .v_i(b1_lv_q), .user_i(1'b0),
        .valid_o(b7_valid), .u_o(b7_l), .user_o(b7_user));
    wire unused_b7_user = b7_user;
    wire [47:0]      b7_lcol = b7_x[0 +: 48];
    wire [3*NVW-1:0] b7_n    = b7_x[48 +: 3*NVW];
    wire [RXW-1:0]   b7_r    = b7_x[48+3*NVW +: RXW];
    wire [PXPW-1:0]  b7_php  = b7_x[48+3*NVW+RXW +: PXPW];   // {phong_size, phong}
    wire [2:0]       b7_fl   = b7_x[48+3*NVW+RXW+PXPW +: 3];

    // ---- B8: n_i l_i, r_i l_i ---------------------------------------------------
    localparam NLPW = 2 * NVW;     // 34
    localparam RLPW = RW + NVW;    // 35
    wire [3*NLPW-1:0] nl_p;
    wire [3*RLPW-1:0] rl_p;
    csgrt_mul_vec #(.A_WIDTH(NVW), .B_WIDTH(NVW), .N(3), .II(II)) u_mul_b8n (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en_b), .adv_i(adv_b), .phase_i(ph_b),
        .a_i(b7_n), .b_i(b7_l), .p_o(nl_p));
    generate
        if (SPECULAR != 0) begin : g_b8r
            csgrt_mul_vec #(.A_WIDTH(RW), .B_WIDTH(NVW), .N(3), .II(II)) u_mul (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en_b), .adv_i(adv_b), .phase_i(ph_b),
                .a_i(b7_r), .b_i(b7_l), .p_o(rl_p));
        end else begin : g_no_b8r
            assign rl_p = {(3*RLPW){1'b0}};   // cos_r = 0: no highlight
            wire unused_r = ^b7_r;
        end
    endgenerate
    localparam X2W = 48 + PXPW + 3;   // {flags, {phong_size, phong}, lcol}
    wire           b8_valid;
    wire [X2W-1:0] b8_x;
    csgrt_delay #(.WIDTH(X2W), .STAGES(2)) u_dly_b8 (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv_b), .valid_i(b7_valid),
        .data_i({b7_fl, b7_php, b7_lcol}), .valid_o(b8_valid), .data_o(b8_x));
    wire [15:0]     b8_ph  = b8_x[48 +: 16];   // phong
    wire            b8_use = b8_x[48+PXPW+2];

    // ---- B9: ndl, cos_r and the enables -----------------------------------------
    localparam NLSW = NLPW + 2;
    localparam RLSW = RLPW + 2;
    // the products' sums, then (after a beat cut) the rounding and the tests
    wire [NLSW-1:0] ndl_p = {{2{nl_p[NLPW-1]}}, nl_p[0 +: NLPW]} + {{2{nl_p[2*NLPW-1]}}, nl_p[NLPW +: NLPW]}
                          + {{2{nl_p[3*NLPW-1]}}, nl_p[2*NLPW +: NLPW]};
    wire [RLSW-1:0] cr_p  = {{2{rl_p[RLPW-1]}}, rl_p[0 +: RLPW]} + {{2{rl_p[2*RLPW-1]}}, rl_p[RLPW +: RLPW]}
                          + {{2{rl_p[3*RLPW-1]}}, rl_p[2*RLPW +: RLPW]};
    wire [NLSW-1:0] ndl_c;
    wire [RLSW-1:0] cr_c;
    csgrt_beat_cut #(.WIDTH(NLSW + RLSW), .II(II)) u_cut_b9 (
        .clk_i(clk_i), .rst_ni(rst_ni), .adv_i(adv_b), .live_i(1'b1), .d_i({cr_p, ndl_p}), .q_o({cr_c, ndl_c}));
    wire [NLSW-1:0] ndl_s = ndl_c + {{(NLSW-15){1'b0}}, 1'b1, 14'd0};
    wire [RLSW-1:0] cr_s  = cr_c + {{(RLSW-15){1'b0}}, 1'b1, 14'd0};
    wire [NLSW-16:0] ndl_full = ndl_s[NLSW-1:15];
    wire [RLSW-16:0] cr_full  = cr_s[RLSW-1:15];
    wire unused_b9 = ^{ndl_s[14:0], cr_s[14:0]};
    wire ndl_pos = !ndl_full[NLSW-16] && (ndl_full != {(NLSW-15){1'b0}});
    wire cr_pos  = !cr_full[RLSW-16] && (cr_full != {(RLSW-15){1'b0}});
    wire ph_pos  = (b8_ph != 16'd0);
    reg            b9_valid_q;
    reg [NDW-1:0]  b9_ndl_q, b9_cr_q;
    reg            b9_den_q, b9_sen_q;
    reg [X2W-1:0]  b9_x_q;
    always @(posedge clk_i) begin
        if (!rst_ni) b9_valid_q <= 1'b0;
        else if (adv_b) b9_valid_q <= b8_valid;
        if (adv_b) begin
            b9_ndl_q <= ndl_full[NDW-1:0];
            b9_cr_q  <= cr_full[NDW-1:0];
            b9_den_q <= b8_use && ndl_pos;
            b9_sen_q <= b8_use && ph_pos && cr_pos;
            b9_x_q   <= b8_x;
        end
    end
    wire unused_b9_top = ^{ndl_full[NLSW-16:NDW], cr_full[RLSW-16:NDW]};

    // ---- B10: pw = pow_fx(cos_r, phong_size, SF); B11: ph = rnd(phong pw, SF) ------
    // (the specular unit: without it the item goes from B9 to B12 directly)
    localparam PSDW = NDW + 2 + X2W;   // {enables, ndl, x} through the stages
    wire            b11_valid;
    wire [PSDW-1:0] b11_side;
    wire [NDW-1:0]  b11_ph;
    generate
        if (SPECULAR != 0) begin : g_phong
            // stage k: res = bit k ? rnd(res * base, SF) : res; base = rnd(base^2, SF)
            localparam NPOW = 10;
            localparam PPW  = 2 * NDW;
            // The stages compute on res, base and one exponent bit each;
            // the rest of the item ({enables, ndl, x}, PSDW bits) waits
            // for B10 in one RAM delay line of the stages' 2 NPOW advances
            // (csgrt_delay_ram; 20 copies of it in flip-flops were 4,780
            // of csgrt_shade's registers at BITS 24), its valid bit and the
            // exponent's bits riding along the stages.
            wire [(NPOW+1)*NDW-1:0]  pw_res, pw_base;
            wire [(NPOW+1)*NPOW-1:0] pw_exp;
            wire [NPOW:0]            pw_valid;
            wire [PSDW-1:0]          b9_side = {b9_sen_q, b9_den_q, b9_ndl_q, b9_x_q};
            assign pw_res[0 +: NDW]    = {{(NDW-16){1'b0}}, 1'b1, 15'd0};   // 1.0
            assign pw_base[0 +: NDW]   = b9_cr_q;
            assign pw_exp[0 +: NPOW]   = b9_x_q[48 + PX_PHS - PX_PH +: NPOW];   // phong_size's bits
            assign pw_valid[0]         = b9_valid_q;
            for (i = 0; i < NPOW; i = i + 1) begin : g_pow
                wire [NDW-1:0]  res_in  = pw_res[i*NDW +: NDW];
                wire [NDW-1:0]  base_in = pw_base[i*NDW +: NDW];
                wire [NDW-1:0]  res_dly;
                wire [NPOW-1:0] exp_dly;
                wire [NDW-1:0]  base_dly;
                csgrt_delay #(.WIDTH(NPOW + 2 * NDW), .STAGES(2)) u_dly (
                    .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv_b), .valid_i(pw_valid[i]),
                    .data_i({pw_exp[i*NPOW +: NPOW], base_in, res_in}), .valid_o(pw_valid[i+1]),
                    .data_o({exp_dly, base_dly, res_dly}));
                wire            bit_k = exp_dly[i];
                // the stage's products, {base^2, res base}, on one
                // csgrt_mul_vec: stage 0 multiplies the result by 1.0, which
                // is exact (res = base), and the square after the last
                // exponent bit is never used
                localparam integer NPR = (i == 0 || i == NPOW - 1) ? 1 : 2;
                wire [NPR*NDW-1:0] pa, pb;
                wire [NPR*PPW-1:0] pp;   // {base^2, res base}, or the one of them
                if (i == 0) begin : g_ops_b
                    assign pa = base_in;
                    assign pb = base_in;
                end else if (i == NPOW - 1) begin : g_ops_r
                    assign pa = res_in;
                    assign pb = base_in;
                end else begin : g_ops_rb
                    assign pa = {base_in, res_in};
                    assign pb = {base_in, base_in};
                end
                csgrt_mul_vec #(.A_WIDTH(NDW), .B_WIDTH(NDW), .N(NPR), .II(II)) u_mul (
                    .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en_b), .adv_i(adv_b), .phase_i(ph_b),
                    .a_i(pa), .b_i(pb), .p_o(pp));
                if (i == 0) begin : g_first
                    assign pw_res[(i+1)*NDW +: NDW] = bit_k ? base_dly : res_dly;
                    wire unused_res = ^res_in;
                end else begin : g_res
                    wire [PPW-1:0] prr = pp[0 +: PPW] + {{(PPW-15){1'b0}}, 1'b1, 14'd0};
                    wire unused_prr = ^{prr[14:0], prr[PPW-1:15+NDW]};
                    assign pw_res[(i+1)*NDW +: NDW] = bit_k ? prr[15 +: NDW] : res_dly;
                end
                if (i == NPOW - 1) begin : g_last
                    assign pw_base[(i+1)*NDW +: NDW] = base_dly;
                end else begin : g_base
                    wire [PPW-1:0] pbr = pp[(NPR-1)*PPW +: PPW] + {{(PPW-15){1'b0}}, 1'b1, 14'd0};
                    wire unused_pbr = ^{pbr[14:0], pbr[PPW-1:15+NDW]};
                    assign pw_base[(i+1)*NDW +: NDW] = pbr[15 +: NDW];
                end
                assign pw_exp[(i+1)*NPOW +: NPOW] = exp_dly;
                if (i != 0 && i != NPOW - 1) begin : g_mid
                    wire unused_bd = ^base_dly;
                end
            end
            wire [NDW-1:0]  b10_pw    = pw_res[NPOW*NDW +: NDW];
            wire [PSDW-1:0] b10_side;
            // ends in a fabric register: B11's multiplier reads it (OUT_REG)
            csgrt_delay_ram #(.WIDTH(PSDW), .STAGES(2 * NPOW), .OUT_REG(1)) u_dly_side (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv_b), .data_i(b9_side), .data_o(b10_side));
            wire            b10_valid = pw_valid[NPOW];
            wire unused_pw_base = ^{pw_base[NPOW*NDW +: NDW], pw_exp[NPOW*NPOW +: NPOW]};
            wire [15:0]     b10_ph    = b10_side[48 +: 16];   // phong

            // ---- B11: ph = rnd(phong pw, SF) ----------------------------------------------
            localparam PHPW = 17 + NDW;   // 35
            wire [PHPW-1:0] php;
            csgrt_mul_vec #(.A_WIDTH(17), .B_WIDTH(NDW), .N(1), .II(II)) u_mul_ph (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en_b), .adv_i(adv_b), .phase_i(ph_b),
                .a_i({1'b0, b10_ph}), .b_i(b10_pw), .p_o(php));
            csgrt_delay #(.WIDTH(PSDW), .STAGES(2)) u_dly_b11 (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv_b), .valid_i(b10_valid),
                .data_i(b10_side), .valid_o(b11_valid), .data_o(b11_side));
            wire [PHPW-1:0] phr = php + {{(PHPW-15){1'b0}}, 1'b1, 14'd0};
            wire unused_phr = ^{phr[14:0], phr[PHPW-1:15+NDW]};
            assign b11_ph = phr[15 +: NDW];
        end else begin : g_no_phong
            assign b11_valid = b9_valid_q;
            assign b11_side  = {b9_sen_q, b9_den_q, b9_ndl_q, b9_x_q};
            assign b11_ph    = {NDW{1'b0}};
            wire unused_cr = ^b9_cr_q;
        end
    endgenerate
    wire [47:0]     b11_lcol = b11_side[0 +: 48];
    wire [NDW-1:0]  b11_ndl  = b11_side[X2W +: NDW];

    // ---- B12: light_c ph, light_c ndl ---------------------------------------------
    localparam LPW = 17 + NDW;   // 35
    wire [3*LPW-1:0] lsp, ldp;
    wire [3*17-1:0]  b11_lc17;   // the light colour, channels as 17-bit signed
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_b12
            assign b11_lc17[i*17 +: 17] = {1'b0, b11_lcol[i*16 +: 16]};
        end
        if (SPECULAR != 0) begin : g_b12s
            csgrt_mul_vec #(.A_WIDTH(17), .B_WIDTH(NDW), .N(3), .II(II)) u_mul (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en_b), .adv_i(adv_b), .phase_i(ph_b),
                .a_i(b11_lc17), .b_i({3{b11_ph}}), .p_o(lsp));
        end else begin : g_no_b12s
            assign lsp = {(3*LPW){1'b0}};
            wire unused_ph = ^b11_ph;
        end
    endgenerate
    csgrt_mul_vec #(.A_WIDTH(17), .B_WIDTH(NDW), .N(3), .II(II)) u_mul_b12d (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en_b), .adv_i(adv_b), .phase_i(ph_b),
        .a_i(b11_lc17), .b_i({3{b11_ndl}}), .p_o(ldp));
    localparam X3W = 2 + 3;   // {enables, flags}
    wire           b12_valid;
    wire [X3W-1:0] b12_x;
    csgrt_delay #(.WIDTH(X3W), .STAGES(2)) u_dly_b12 (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv_b), .valid_i(b11_valid),
        .data_i({b11_side[PSDW-1 -: 2], b11_side[48 + PXPW +: 3]}), .valid_o(b12_valid), .data_o(b12_x));
    wire            b12_first = b12_x[0];
    wire            b12_last  = b12_x[1];
    wire            b12_den   = b12_x[3];
    wire            b12_sen   = b12_x[4];
    wire unused_b12 = ^{b12_x[2], b11_side[48 +: PXPW]};

    // ---- B13: accumulate per pixel ---------------------------------------------------
    reg [3*DAW-1:0] dacc_q;
    reg [3*SAW-1:0] sacc_q;
    wire [3*DAW-1:0] dsum;
    wire [3*SAW-1:0] ssum;
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_acc
            wire [LPW-1:0] dp = ldp[i*LPW +: LPW] + {{(LPW-15){1'b0}}, 1'b1, 14'd0};   // rnd(., SF)
            wire [LPW-1:0] sp = lsp[i*LPW +: LPW] + {{(LPW-12){1'b0}}, 1'b1, 11'd0};   // rnd(., CF)
            wire unused_dp = ^{dp[14:0], dp[LPW-1:15+DAW-3], sp[11:0]};
            // terms are non-negative (light colours >= 0, ndl > 0, ph > 0)
            wire [DAW-1:0] dt_d = b12_den ? {3'b000, dp[15 +: DAW-3]} : {DAW{1'b0}};
            wire [SAW-1:0] st_d = b12_sen ? {{(SAW-(LPW-12)){1'b0}}, sp[LPW-1:12]} : {SAW{1'b0}};
            // the terms, after a beat cut: the rounding before it, the sums after
            wire [DAW-1:0] dt;
            wire [SAW-1:0] st;
            csgrt_beat_cut #(.WIDTH(DAW + SAW), .II(II)) u_cut (
                .clk_i(clk_i), .rst_ni(rst_ni), .adv_i(adv_b), .live_i(1'b1), .d_i({st_d, dt_d}), .q_o({st, dt}));
            assign dsum[i*DAW +: DAW] = (b12_first ? {DAW{1'b0}} : dacc_q[i*DAW +: DAW]) + dt;
            // without the specular unit the sum is constant 0 (no register left)
            assign ssum[i*SAW +: SAW] = (SPECULAR == 0) ? {SAW{1'b0}}
                                      : (b12_first ? {SAW{1'b0}} : sacc_q[i*SAW +: SAW]) + st;
        end
    endgenerate
    reg              c0_valid_q;
    // what segment C reads of the pixel, from B1 to here in one RAM line
    // (every light item of a pixel writes it; C0 takes the last one's)
    wire [PXCW-1:0]  c0_pix;
    csgrt_delay_ram #(.WIDTH(PXCW), .STAGES(B_PIX_LAT), .OUT_REG(1)) u_dly_pix_b (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv_b), .data_i(sq_pix[0 +: PXCW]), .data_o(c0_pix));
    always @(posedge clk_i) begin
        if (!rst_ni) c0_valid_q <= 1'b0;
        else if (adv_b) c0_valid_q <= b12_valid && b12_last;
        if (adv_b && b12_valid) begin
            dacc_q <= dsum;
            sacc_q <= ssum;
        end
    end

    // =========================================================================
    // Segment C: colour
    // =========================================================================
    // ---- C1: diffuse diff_c --------------------------------------------------------
    localparam DDPW = 17 + DAW;
    wire [3*DDPW-1:0] ddp;
    csgrt_mul_vec #(.A_WIDTH(17), .B_WIDTH(DAW), .N(3), .II(II)) u_mul_c1 (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en_b), .adv_i(adv_b), .phase_i(ph_b),
        .a_i({3{1'b0, c0_pix[PX_DIF +: 16]}}), .b_i(dacc_q), .p_o(ddp));
    wire             c1_valid;
    wire [PXCW-1:0]  c1_pix;
    wire [3*SAW-1:0] c1_spec;
    csgrt_delay #(.WIDTH(PXCW + 3 * SAW), .STAGES(2)) u_dly_c1 (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv_b), .valid_i(c0_valid_q),
        .data_i({sacc_q, c0_pix}), .valid_o(c1_valid), .data_o({c1_spec, c1_pix}));

    // ---- C2: intensity = ambient + rnd(diffuse diff_c, CF) -----------------------------
    wire [3*IW-1:0] int_d;
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_c2
            wire [DDPW-1:0] pr = ddp[i*DDPW +: DDPW] + {{(DDPW-12){1'b0}}, 1'b1, 11'd0};
            wire unused_pr = ^{pr[11:0], pr[DDPW-1:12+IW]};
            assign int_d[i*IW +: IW] = {{(IW-16){1'b0}}, c1_pix[PX_AMB +: 16]} + pr[12 +: IW];
        end
    endgenerate
    reg              c2_valid_q;
    reg [3*IW-1:0]   c2_int_q;
    reg [PXCW-1:0]   c2_pix_q;
    reg [3*SAW-1:0]  c2_spec_q;
    always @(posedge clk_i) begin
        if (!rst_ni) c2_valid_q <= 1'b0;
        else if (adv_b) c2_valid_q <= c1_valid;
        if (adv_b) begin
            c2_int_q  <= int_d;
            c2_pix_q  <= c1_pix;
            c2_spec_q <= c1_spec;
        end
    end

    // ---- C3: pigment_c intensity_c -----------------------------------------------------
    localparam CPW = 17 + IW;
    wire [3*CPW-1:0] cp;
    wire [3*17-1:0]  c2_rgb17;   // the pigment, channels as 17-bit signed
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_c3
            assign c2_rgb17[i*17 +: 17] = {1'b0, c2_pix_q[PX_RGB + i*16 +: 16]};
        end
    endgenerate
    csgrt_mul_vec #(.A_WIDTH(17), .B_WIDTH(IW), .N(3), .II(II)) u_mul_c3 (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en_b), .adv_i(adv_b), .phase_i(ph_b),
        .a_i(c2_rgb17), .b_i(c2_int_q), .p_o(cp));
    wire             c3_valid;
    wire [PXCW-1:0]  c3_pix;
    wire [3*SAW-1:0] c3_spec;
    csgrt_delay #(.WIDTH(PXCW + 3 * SAW), .STAGES(2)) u_dly_c3 (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv_b), .valid_i(c2_valid_q),
        .data_i({c2_spec_q, c2_pix_q}), .valid_o(c3_valid), .data_o({c3_spec, c3_pix}));

    // ---- C4: colour, background for a miss, clamp to [0, 4095] ---------------------------
    wire [3*12-1:0] idx_d;
    wire [3*CLW-1:0] col_lin;   // the hit's colour before the clamp (LINEAR_OUT)
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_c4
            wire [CPW-1:0] pr = cp[i*CPW +: CPW] + {{(CPW-12){1'b0}}, 1'b1, 11'd0};
            wire unused_pr = ^{pr[11:0]};
            // the rounded product, after a beat cut: the sum and clamp after it
            wire [CPW-13:0] prc;
            csgrt_beat_cut #(.WIDTH(CPW - 12), .II(II)) u_cut (
                .clk_i(clk_i), .rst_ni(rst_ni), .adv_i(adv_b), .live_i(1'b1), .d_i(pr[CPW-1:12]), .q_o(prc));
            wire [CLW-1:0] col_hit = {{(CLW-(CPW-12)){prc[CPW-13]}}, prc}
                                   + {{(CLW-SAW){1'b0}}, c3_spec[i*SAW +: SAW]};
            assign col_lin[i*CLW +: CLW] = col_hit;
            wire [CLW-1:0] col = c3_pix[PX_HIT] ? col_hit
                               : {{(CLW-16){1'b0}}, background_i[i*16 +: 16]};
            assign idx_d[i*12 +: 12] = col[CLW-1] ? 12'd0
                                     : (col[CLW-2:12] != {(CLW-13){1'b0}}) ? 12'd4095 : col[11:0];
        end
    endgenerate
    generate
        if (LINEAR_OUT != 0) begin : g_linear
            // ---- C4: the linear colour and its phong part, registered ------------------
            reg               c4_valid_q;
            reg [23:0]        c4_xy_q;
            reg [3*CLW-1:0]   c4_col_q;
            reg [3*SAW-1:0]   c4_spec_q;
            always @(posedge clk_i) begin
                if (!rst_ni) c4_valid_q <= 1'b0;
                else if (adv_b) c4_valid_q <= c3_valid;
                if (adv_b) begin
                    c4_col_q  <= col_lin;
                    c4_spec_q <= c3_spec;
                    c4_xy_q   <= c3_pix[0 +: 24];
                end
            end
            wire unused_idx = ^idx_d;
            csgrt_skid #(.WIDTH(24 + 3 * CLW + 3 * SAW)) u_skid_out (
                .clk_i(clk_i), .rst_ni(rst_ni),
                .valid_i(c4_valid_q && last_b), .ready_o(en_b), .ready_next_o(en_b_next), .data_i({c4_spec_q, c4_col_q, c4_xy_q}),
                .valid_o(m_valid_o), .ready_i(m_ready_i), .data_o({m_spec_o, m_local_o, m_y_o, m_x_o}));
            assign {m_r_o, m_g_o, m_b_o} = 24'd0;
        end else begin : g_srgb
        reg            c4_valid_q;
        reg [23:0]     c4_xy_q;
        reg [35:0]     c4_idx_q;
        always @(posedge clk_i) begin
            if (!rst_ni) c4_valid_q <= 1'b0;
            else if (adv_b) c4_valid_q <= c3_valid;
            if (adv_b) begin
                c4_idx_q <= idx_d;
                c4_xy_q  <= c3_pix[0 +: 24];
            end
        end
        wire unused_c3 = ^c3_pix[PXCW-1:25];

        // ---- C5: sRGB tables ---------------------------------------------------------------
        wire [23:0] code;
        reg         c5_valid_q;
        reg [23:0]  c5_xy_q;
        for (i = 0; i < 3; i = i + 1) begin : g_c5
            csgrt_srgb #(.LUT_FILE(LUT_FILE)) u_lut (
                .clk_i(clk_i), .ce_i(adv_b), .idx_i(c4_idx_q[i*12 +: 12]), .code_o(code[i*8 +: 8]));
        end
        always @(posedge clk_i) begin
            if (!rst_ni) c5_valid_q <= 1'b0;
            else if (adv_b) c5_valid_q <= c4_valid_q;
            if (adv_b) c5_xy_q <= c4_xy_q;
        end

        // ---- output skid --------------------------------------------------------------------
        csgrt_skid #(.WIDTH(48)) u_skid_out (
            .clk_i(clk_i), .rst_ni(rst_ni),
            .valid_i(c5_valid_q && last_b), .ready_o(en_b), .ready_next_o(en_b_next), .data_i({code, c5_xy_q}),
            .valid_o(m_valid_o), .ready_i(m_ready_i), .data_o({m_b_o, m_g_o, m_r_o, m_y_o, m_x_o}));
        assign m_local_o = {3*CLW{1'b0}};
        assign m_spec_o  = {3*SAW{1'b0}};
        wire unused_lin = ^col_lin;
        end
    endgenerate

    generate
        if (BITS < 12 || BITS > 32 || MAX_LIGHTS < 1) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_shade needs 12 <= BITS <= 32 and MAX_LIGHTS >= 1");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
