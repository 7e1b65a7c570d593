`default_nettype none
// csgrt_isect — ray-quadric intersection, bit for bit intersect_fx() of
// model/trace.cpp: for one ray (o, d) and one quadric
// Q(x) = x'Ax + 2p'x + q, the coefficients along the ray Q(t) = a t^2 +
// 2 b t + c, up to two events (t, range, entering), and whether the line is
// inside at t = -infinity.
//
// Formats (model/fixed.h, struct Formats), B = BITS, F = B-3, FC = B-1:
//   o_i, d_i     3 x B bits signed, F fraction bits (|o| < 4, |d| = 1)
//   coef_i       10 x B bits signed, FC fraction bits, CoefIndex order
//                (model/compile.h): A00 A11 A22 A01 A02 A12 P0 P1 P2 Q,
//                coefficient k at coef_i[k*B +: B]
//   a_o b_o c_o  F fraction bits: AW = F+3, BW = F+6, CW = F+9 bits signed,
//                from the bounds |a| < 4, |b| < 32, |c| < 256 that hold for
//                unit directions and coefficients in (-1, 1)
//   t0_o t1_o    TW = F+2 bits signed, F fraction bits (|t| < 2), 0 unless
//                the range is Finite
//   range*_o     2'd0 NegInf, 2'd1 Finite, 2'd2 PosInf (enum TRange)
//   count_o      0, 1 or 2 events; events past count_o carry the model's
//                values too (defaults t = 0, Finite, leaving)
// Internal widths: u, w B+2 bits; the discriminant b^2 - a c 2F+13 bits
// signed (< 2^(2F+12) when not negative: F+6 square-root stages); qq =
// -(b + sgn(b) s) F+8 bits; dividers with F+1 quotient bits, numerators
// 2F+10 bits, denominators F+8 bits. Every product is exact (csgrt_mul);
// stage 1 sums are exact at 2B+2 bits and stage 2 sums at 2B+5 bits, so
// only the documented bounds on a, b, c limit the inputs.
//
// Pipeline (every rounding is round half up: add 2^(k-1), shift right
// arithmetically; every division truncates toward zero and saturates):
//   P0 mul  (3)  A d and A o products, 18 multipliers B x B (each with a
//                fabric register after it, as P2's and P4's; above 18
//                bits also one behind each MULT18X18D tile: 4 clocks)
//   P1 add  (1)  u = rnd(A d, FC), w = rnd(A o + p<<F, FC), w + rnd(p, FC-F)
//   P2 mul  (3)  d.u, d.w, o.(w + rnd(p)) products, 9 multipliers (4 above 18 bits)
//   P3 add  (1)  a = rnd(d.u, F), b = rnd(d.w, F), c = rnd(o.(w+p'), F) + rnd(q, FC-F)
//   P4 mul  (3)  b*b, a*c (4 above 18 bits)
//   P5 add  (1)  disc = b*b - a*c, the flags a == 0, b == 0, b < 0, c <= 0, a < 0
//   P6 sqrt (F+6) s = floor(sqrt(disc)) (csgrt_sqrt_core)
//   P7 add  (1)  qq = -(b + sgn(b) s) with sgn(0) = +1; divider operands:
//                  a != 0: t_first = (qq << F) / a, t_second = (c << F) / qq
//                  a == 0: t = -(c << F) / (2 b)     (linear along the ray)
//   P8 div  (F+2) two csgrt_div_core in lock step
//   P9 t    (1)  saturation to NegInf/PosInf, the sign, qq == 0 (double
//                root: second event = first)
//   P10 out (0)  drop of an equal pair, count; into the skid
//   skid    (1)  csgrt_skid
// Latency: 2F+23 clocks without back-pressure up to 18 bits (BITS 12: 41,
// 16: 49), 2F+26 above (24: 68, 32: 84). Throughput: one ray-primitive
// pair per clock.
//
// II = 3 (time-shared, csgrt_beat): every stage moves once every three
// running clocks (a beat), and each multiplier serves three products in
// turn (csgrt_mul_vec): P0's 18 products on 6 multipliers (row i of A
// times d, row i times o), P2's 9 on 3 (d.u, d.w, o.(w + rnd(p))), P4's
// two on one (b*b and a*c, operands sign-extended to BW x CW bits; both
// products are exact in it). 10 multipliers where II = 1 has 29: at
// BITS 24 about a third of the MULT18X18D blocks and of their operand
// wiring, the routing congestion of the 24-bit builds (docs/fpga.md).
// The square root and the dividers find three result bits per stage, one
// per running clock (csgrt_sqrt_core and csgrt_div_core FOLD = 3): a third
// of their stages, registers and compare-subtract logic. The arithmetic is
// the same, so are the results, bit for bit. An input register holds the
// pair for the beat in which P0 reads it, and P0, P2, P4 take two beats
// (csgrt_mul_vec), P6 ceil((F+6)/3), P8 ceil((F+1)/3) + 1: latency
// 3 (13 + ceil((F+6)/3) + ceil((F+1)/3)) + 1 clocks without back-pressure
// (BITS 16: 76, 24: 91; tb/isect checks it); throughput one pair per three
// clocks.
// Handshake: valid/ready on both sides, a transaction moves when valid and
// ready are both high at a rising edge. All stages advance on one global
// enable, the output skid buffer's registered ready, which is also ready_o:
// a register output, no combinational path from ready_i. leaf_i is a
// sideband carried alongside unchanged.
module csgrt_isect #(
    parameter BITS       = 24,   // coordinate / direction / coefficient width B (12..32)
    parameter LEAF_WIDTH = 10,   // sideband (leaf index) width (>= 1)
    parameter II         = 1     // clocks per pair: 1, or 3 (a third of the multipliers, above)
) (
    input  wire                  clk_i,
    input  wire                  rst_ni,     // synchronous, active low
    // input stream: one ray-primitive pair
    input  wire                  valid_i,
    output wire                  ready_o,
    input  wire [3*BITS-1:0]     o_i,        // origin x, y, z (x in the low bits)
    input  wire [3*BITS-1:0]     d_i,        // direction x, y, z
    input  wire [10*BITS-1:0]    coef_i,     // quadric, CoefIndex order
    input  wire [LEAF_WIDTH-1:0] leaf_i,
    // output stream: the leaf's events
    output wire                  valid_o,
    input  wire                  ready_i,
    output wire [LEAF_WIDTH-1:0] leaf_o,
    output wire [1:0]            count_o,
    output wire [BITS-2:0]       t0_o,       // TW = F+2 = BITS-1 bits
    output wire [1:0]            range0_o,
    output wire                  enter0_o,
    output wire [BITS-2:0]       t1_o,
    output wire [1:0]            range1_o,
    output wire                  enter1_o,
    output wire                  inside_o,   // inside at t = -infinity
    output wire [BITS-1:0]       a_o,        // AW = F+3 = BITS bits
    output wire [BITS+2:0]       b_o,        // BW = F+6 = BITS+3 bits
    output wire [BITS+5:0]       c_o         // CW = F+9 = BITS+6 bits
);

    // ---- formats -----------------------------------------------------------
    localparam B    = BITS;
    localparam F    = B - 3;        // fraction bits of o, d, t, a, b, c
    localparam FC   = B - 1;        // fraction bits of the coefficients
    localparam LW   = LEAF_WIDTH;
    localparam UW   = B + 2;        // u = A d, w = A o + p (exact bound over all inputs)
    localparam WPW  = B + 3;        // w + rnd(p, FC-F)
    localparam PRW  = B - 1;        // rnd(p, 2), rnd(q, 2)
    localparam S1W  = 2 * B + 2;    // stage-1 sums (|sum| < 2^(2B))
    localparam S2W  = 2 * B + 5;    // stage-2 sums (|sum| < 2^(2B+3))
    localparam AW   = F + 3;        // |a| < 4
    localparam BW   = F + 6;        // |b| < 32
    localparam CW   = F + 9;        // |c| < 256
    localparam DSW  = 2 * F + 13;   // b^2 - a c, signed
    localparam SQ   = F + 6;        // square-root stages: disc < 2^(2F+12)
    localparam QQW  = F + 8;        // qq, |qq| < 2^(F+7)
    localparam QB   = F + 1;        // quotient bits: |t| < 2
    localparam NUMW = 2 * F + 10;   // divider numerators: -(c << F)
    localparam DENW = F + 8;        // divider denominators: qq
    localparam TW   = F + 2;        // t, signed
    localparam RND_FC = {{(S1W-FC){1'b0}}, 1'b1, {(FC-1){1'b0}}};   // 2^(FC-1)
    localparam RND_F  = {{(S2W-F){1'b0}}, 1'b1, {(F-1){1'b0}}};     // 2^(F-1)

    localparam [1:0] R_NEGINF = 2'd0, R_FINITE = 2'd1, R_POSINF = 2'd2;

    wire en;        // the pipeline runs: the output skid buffer's ready
    wire en_next;   // en after the next rising edge (csgrt_skid's ready_next_o)
    // Every stage moves on the beat's advance adv (II = 1: adv = en, every
    // running clock; II = 3: every third); the shared multipliers run on
    // every running clock. An item leaves for the skid only at an advance.
    wire [1:0] phase;
    wire       last, adv, adv_q;
    csgrt_beat #(.II(II)) u_beat (.clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en), .ce_next_i(en_next),
                                  .phase_o(phase), .last_o(last), .adv_o(adv), .adv_q_o(adv_q));
    // ready_o is adv again, from a register of its own (csgrt_beat's
    // adv_q, loaded with the advance's next value): adv is the enable of
    // every stage (about 7,000 flip-flops), and the dispatcher's issue
    // logic read that net (tools/logic_depth.py); csgrt_beat stops a
    // simulation if the two differ
    assign ready_o = adv_q;
    // Above 18 bits the products are sums of MULT18X18D tiles, and each
    // tile gets a register before their sum (csgrt_mul TILE_REG): the
    // first routed 24-bit build's critical path was a P0 tile -> 5.63 ns
    // of route across the die -> the tiles' sum (docs/fpga.md). A clock
    // more per product stage with II = 1; none with II = 3 (csgrt_mul_vec).
    localparam TREG = (B > 18) ? 1 : 0;
    localparam MUL_LAT = (II == 1) ? 3 + TREG : 2;   // a product stage, in advances

    // ---- input: II = 3 registers the pair, which P0's shared multipliers
    // read for a whole beat (II = 1: straight through) ----------------------
    wire             in_valid;
    wire [3*B-1:0]   in_o, in_d;
    wire [10*B-1:0]  in_coef;
    wire [LW-1:0]    in_leaf;
    csgrt_delay #(.WIDTH(16 * B + LW), .STAGES(II == 1 ? 0 : 1)) u_in (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .valid_i(valid_i),
        .data_i({leaf_i, coef_i, d_i, o_i}), .valid_o(in_valid), .data_o({in_leaf, in_coef, in_d, in_o}));

    // ---- P0: A d and A o ---------------------------------------------------
    // Every multiplier of the unit (P0, P2, P4) hands its product over
    // through a fabric register (csgrt_mul's OUT_REG): the sums behind them
    // then start at flip-flops the placer can put beside them, not at the
    // blocks' output registers in the DSP columns. P3's three-product sums,
    // straight from the blocks, were the routed critical path of 1ac57bd (a
    // block's output -> 4.4 ns of route -> the tiles' sum -> the sum of
    // three: 84.00 MHz, docs/fpga.md); P1's sums and P5's subtract have the
    // same form.
    // A(i,j) -> coefficient index: diagonal i, (0,1) 3, (0,2) 4, (1,2) 5
    // (both P0 forms below take A's entries from here)
    function automatic integer coef_of(input integer row, input integer col);
        coef_of = (row == col) ? row : (row + col == 1) ? 3 : (row + col == 2) ? 4 : 5;
    endfunction
    wire [9*2*B-1:0] pu, pw;   // products (3i+j), 2B bits each
    genvar i, j;
    generate
        if (II == 1) begin : g_p0_each
            wire unused_phase = ^phase;   // always 0 (csgrt_beat)
            for (i = 0; i < 3; i = i + 1) begin : g_p0_row
                for (j = 0; j < 3; j = j + 1) begin : g_p0_col
                    localparam CI = coef_of(i, j);
                    wire unused_vu, unused_vw;
                    csgrt_mul #(.A_WIDTH(B), .B_WIDTH(B), .OUT_REG(1), .TILE_REG(TREG)) u_mul_u (
                        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .valid_i(in_valid),
                        .a_i(in_coef[CI*B +: B]), .b_i(in_d[j*B +: B]),
                        .valid_o(unused_vu), .p_o(pu[(3*i+j)*2*B +: 2*B]));
                    csgrt_mul #(.A_WIDTH(B), .B_WIDTH(B), .OUT_REG(1), .TILE_REG(TREG)) u_mul_w (
                        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .valid_i(in_valid),
                        .a_i(in_coef[CI*B +: B]), .b_i(in_o[j*B +: B]),
                        .valid_o(unused_vw), .p_o(pw[(3*i+j)*2*B +: 2*B]));
                end
            end
        end else begin : g_p0_shared
            // row i of A times d and times o, one multiplier each; the
            // beat's gather register is the fabric register OUT_REG gives
            // the II = 1 products
            for (i = 0; i < 3; i = i + 1) begin : g_p0_row
                wire [3*B-1:0] row = {in_coef[coef_of(i, 2)*B +: B], in_coef[coef_of(i, 1)*B +: B],
                                      in_coef[coef_of(i, 0)*B +: B]};
                csgrt_mul_vec #(.A_WIDTH(B), .B_WIDTH(B), .N(3), .II(II), .TILE_REG(TREG)) u_mul_u (
                    .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en), .adv_i(adv), .phase_i(phase),
                    .a_i(row), .b_i(in_d), .p_o(pu[3*i*2*B +: 3*2*B]));
                csgrt_mul_vec #(.A_WIDTH(B), .B_WIDTH(B), .N(3), .II(II), .TILE_REG(TREG)) u_mul_w (
                    .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en), .adv_i(adv), .phase_i(phase),
                    .a_i(row), .b_i(in_o), .p_o(pw[3*i*2*B +: 3*2*B]));
            end
        end
    endgenerate

    // side data in step with the multipliers: o, d, p, q, leaf
    localparam SD0W = 3 * B + 3 * B + 3 * B + B + LW;
    wire            p0_valid;
    wire [SD0W-1:0] p0_side;
    csgrt_delay #(.WIDTH(SD0W), .STAGES(MUL_LAT)) u_dly0 (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .valid_i(in_valid),
        .data_i({in_leaf, in_coef[9*B +: B], in_coef[6*B +: 3*B], in_d, in_o}),
        .valid_o(p0_valid), .data_o(p0_side));
    wire [3*B-1:0] p0_o    = p0_side[0 +: 3*B];
    wire [3*B-1:0] p0_d    = p0_side[3*B +: 3*B];
    wire [3*B-1:0] p0_p    = p0_side[6*B +: 3*B];
    wire [B-1:0]   p0_q    = p0_side[9*B +: B];
    wire [LW-1:0]  p0_leaf = p0_side[10*B +: LW];

    // ---- P1: u, w, w + rnd(p) ----------------------------------------------
    wire [3*UW-1:0]  u_d, w_d;
    wire [3*WPW-1:0] wp_d;
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_p1
            wire [2*B-1:0] pu0 = pu[(3*i+0)*2*B +: 2*B];
            wire [2*B-1:0] pu1 = pu[(3*i+1)*2*B +: 2*B];
            wire [2*B-1:0] pu2 = pu[(3*i+2)*2*B +: 2*B];
            wire [2*B-1:0] pw0 = pw[(3*i+0)*2*B +: 2*B];
            wire [2*B-1:0] pw1 = pw[(3*i+1)*2*B +: 2*B];
            wire [2*B-1:0] pw2 = pw[(3*i+2)*2*B +: 2*B];
            wire [B-1:0]   p   = p0_p[i*B +: B];
            // exact sums (FC+F fraction bits) plus the rounding half
            wire [S1W-1:0] su = {{(S1W-2*B){pu0[2*B-1]}}, pu0} + {{(S1W-2*B){pu1[2*B-1]}}, pu1}
                              + {{(S1W-2*B){pu2[2*B-1]}}, pu2} + RND_FC;
            // w = rnd(A o + p << F, FC) and w + rnd(p, FC-F) as two sums of
            // the same products, side by side, not one after the other (the
            // second sum was the routed effects build's critical path): with
            // m = p + 2, since RND_FC = 2 << F,
            //   A o + p << F + RND_FC           = A o + m << F
            //   and rnd(p, 2) = floor(m / 4), so
            //   (A o + m << F) + rnd(p, 2) << FC = A o + (m + 4 floor(m / 4)) << F
            // (FC = F + 2); floor(x / 2^FC) of the second is w + rnd(p, 2).
            // m and m2 come from a register while the products' sum runs.
            wire [S1W-1:0] sp = {{(S1W-2*B){pw0[2*B-1]}}, pw0} + {{(S1W-2*B){pw1[2*B-1]}}, pw1}
                              + {{(S1W-2*B){pw2[2*B-1]}}, pw2};
            wire [B:0]     m  = {p[B-1], p} + {{(B-1){1'b0}}, 2'b10};
            wire [B+1:0]   m2 = {m[B], m} + {m[B], m[B:2], 2'b00};
            wire [S1W-1:0] sw  = sp + {{(S1W-B-1-F){m[B]}}, m, {F{1'b0}}};
            wire [S1W-1:0] swp = sp + {{(S1W-B-2-F){m2[B+1]}}, m2, {F{1'b0}}};
            wire [UW-1:0]  w = sw[FC +: UW];
            // dropped LSBs, and sign copies above the exact bound (swp's
            // top is WPW wide: S1W = FC + WPW)
            wire unused_p1 = ^{su[FC-1:0], su[S1W-1:FC+UW], sw[FC-1:0], sw[S1W-1:FC+UW], swp[FC-1:0]};
            assign u_d[i*UW +: UW]    = su[FC +: UW];
            assign w_d[i*UW +: UW]    = w;
            assign wp_d[i*WPW +: WPW] = swp[FC +: WPW];
        end
    endgenerate
    // rnd(q, 2)
    wire [B:0]     qr_full = {p0_q[B-1], p0_q} + {{(B-1){1'b0}}, 2'b10};
    wire           unused_qr = ^qr_full[1:0];

    reg            p1_valid_q;
    reg [3*UW-1:0] p1_u_q, p1_w_q;
    reg [3*WPW-1:0] p1_wp_q;
    reg [3*B-1:0]  p1_o_q, p1_d_q;
    reg [PRW-1:0]  p1_qr_q;
    reg [LW-1:0]   p1_leaf_q;
    always @(posedge clk_i) begin
        if (!rst_ni) p1_valid_q <= 1'b0;
        else if (adv) p1_valid_q <= p0_valid;
        if (adv) begin
            p1_u_q    <= u_d;
            p1_w_q    <= w_d;
            p1_wp_q   <= wp_d;
            p1_o_q    <= p0_o;
            p1_d_q    <= p0_d;
            p1_qr_q   <= qr_full[B:2];
            p1_leaf_q <= p0_leaf;
        end
    end

    // ---- P2: d.u, d.w, o.(w + rnd(p)) --------------------------------------
    wire [3*(B+UW)-1:0]  pa, pb;
    wire [3*(B+WPW)-1:0] pc;
    generate
        if (II == 1) begin : g_p2_each
            for (i = 0; i < 3; i = i + 1) begin : g_p2
                wire unused_va, unused_vb, unused_vc;
                csgrt_mul #(.A_WIDTH(B), .B_WIDTH(UW), .OUT_REG(1), .TILE_REG(TREG)) u_mul_a (
                    .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .valid_i(p1_valid_q),
                    .a_i(p1_d_q[i*B +: B]), .b_i(p1_u_q[i*UW +: UW]),
                    .valid_o(unused_va), .p_o(pa[i*(B+UW) +: B+UW]));
                csgrt_mul #(.A_WIDTH(B), .B_WIDTH(UW), .OUT_REG(1), .TILE_REG(TREG)) u_mul_b (
                    .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .valid_i(p1_valid_q),
                    .a_i(p1_d_q[i*B +: B]), .b_i(p1_w_q[i*UW +: UW]),
                    .valid_o(unused_vb), .p_o(pb[i*(B+UW) +: B+UW]));
                csgrt_mul #(.A_WIDTH(B), .B_WIDTH(WPW), .OUT_REG(1), .TILE_REG(TREG)) u_mul_c (
                    .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .valid_i(p1_valid_q),
                    .a_i(p1_o_q[i*B +: B]), .b_i(p1_wp_q[i*WPW +: WPW]),
                    .valid_o(unused_vc), .p_o(pc[i*(B+WPW) +: B+WPW]));
            end
        end else begin : g_p2_shared
            // each dot product's three terms on one multiplier
            csgrt_mul_vec #(.A_WIDTH(B), .B_WIDTH(UW), .N(3), .II(II), .TILE_REG(TREG)) u_mul_a (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en), .adv_i(adv), .phase_i(phase),
                .a_i(p1_d_q), .b_i(p1_u_q), .p_o(pa));
            csgrt_mul_vec #(.A_WIDTH(B), .B_WIDTH(UW), .N(3), .II(II), .TILE_REG(TREG)) u_mul_b (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en), .adv_i(adv), .phase_i(phase),
                .a_i(p1_d_q), .b_i(p1_w_q), .p_o(pb));
            csgrt_mul_vec #(.A_WIDTH(B), .B_WIDTH(WPW), .N(3), .II(II), .TILE_REG(TREG)) u_mul_c (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en), .adv_i(adv), .phase_i(phase),
                .a_i(p1_o_q), .b_i(p1_wp_q), .p_o(pc));
        end
    endgenerate
    wire          p2_valid;
    wire [PRW-1:0] p2_qr;
    wire [LW-1:0] p2_leaf;
    csgrt_delay #(.WIDTH(PRW + LW), .STAGES(MUL_LAT)) u_dly2 (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .valid_i(p1_valid_q),
        .data_i({p1_leaf_q, p1_qr_q}), .valid_o(p2_valid), .data_o({p2_leaf, p2_qr}));

    // ---- P3: a, b, c ---------------------------------------------------------
    localparam PAW = B + UW;    // 2B+2
    localparam PCW = B + WPW;   // 2B+3
    wire [PAW-1:0] pa0 = pa[0*PAW +: PAW], pa1 = pa[1*PAW +: PAW], pa2 = pa[2*PAW +: PAW];
    wire [PAW-1:0] pb0 = pb[0*PAW +: PAW], pb1 = pb[1*PAW +: PAW], pb2 = pb[2*PAW +: PAW];
    wire [PCW-1:0] pc0 = pc[0*PCW +: PCW], pc1 = pc[1*PCW +: PCW], pc2 = pc[2*PCW +: PCW];
    wire [S2W-1:0] sa = {{(S2W-PAW){pa0[PAW-1]}}, pa0} + {{(S2W-PAW){pa1[PAW-1]}}, pa1}
                      + {{(S2W-PAW){pa2[PAW-1]}}, pa2} + RND_F;
    wire [S2W-1:0] sb = {{(S2W-PAW){pb0[PAW-1]}}, pb0} + {{(S2W-PAW){pb1[PAW-1]}}, pb1}
                      + {{(S2W-PAW){pb2[PAW-1]}}, pb2} + RND_F;
    // c = rnd(o.(w+p'), F) + rnd(q, FC-F) in one sum: rnd(x, F) + r =
    // floor((x + (r << F) + 2^(F-1)) / 2^F), and (r << F) + 2^(F-1) is a
    // concatenation, no adder (as a separate add after the sum it was one
    // more carry chain on the stage's path)
    wire [S2W-1:0] sc = {{(S2W-PCW){pc0[PCW-1]}}, pc0} + {{(S2W-PCW){pc1[PCW-1]}}, pc1}
                      + {{(S2W-PCW){pc2[PCW-1]}}, pc2}
                      + {{(S2W-PRW-F){p2_qr[PRW-1]}}, p2_qr, 1'b1, {(F-1){1'b0}}};
    wire [CW-1:0]  c_d = sc[F +: CW];
    // dropped LSBs, and the bits above the bounds on a, b, c
    wire unused_p3 = ^{sa[F-1:0], sa[S2W-1:F+AW], sb[F-1:0], sb[S2W-1:F+BW], sc[F-1:0], sc[S2W-1:F+CW]};

    reg          p3_valid_q;
    reg [AW-1:0] p3_a_q;
    reg [BW-1:0] p3_b_q;
    reg [CW-1:0] p3_c_q;
    reg [LW-1:0] p3_leaf_q;
    always @(posedge clk_i) begin
        if (!rst_ni) p3_valid_q <= 1'b0;
        else if (adv) p3_valid_q <= p2_valid;
        if (adv) begin
            p3_a_q    <= sa[F +: AW];
            p3_b_q    <= sb[F +: BW];
            p3_c_q    <= c_d;
            p3_leaf_q <= p2_leaf;
        end
    end

    // ---- P4: b*b, a*c --------------------------------------------------------
    wire [2*BW-1:0]   p4_bb;
    wire [AW+CW-1:0]  p4_ac;
    generate
        if (II == 1) begin : g_p4_each
            wire unused_vbb, unused_vac;
            csgrt_mul #(.A_WIDTH(BW), .B_WIDTH(BW), .OUT_REG(1), .TILE_REG(TREG)) u_mul_bb (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .valid_i(p3_valid_q),
                .a_i(p3_b_q), .b_i(p3_b_q), .valid_o(unused_vbb), .p_o(p4_bb));
            csgrt_mul #(.A_WIDTH(AW), .B_WIDTH(CW), .OUT_REG(1), .TILE_REG(TREG)) u_mul_ac (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .valid_i(p3_valid_q),
                .a_i(p3_a_q), .b_i(p3_c_q), .valid_o(unused_vac), .p_o(p4_ac));
        end else begin : g_p4_shared
            // b*b and a*c on one BW x CW multiplier (AW < BW < CW), the
            // operands sign-extended: each product is exact in BW + CW bits
            // and its low 2BW (AW+CW) bits are the narrow product's
            localparam P4W = BW + CW;
            wire [2*P4W-1:0] p4_p;
            wire [BW-1:0] p4_a_x = {{(BW-AW){p3_a_q[AW-1]}}, p3_a_q};
            wire [CW-1:0] p4_b_x = {{(CW-BW){p3_b_q[BW-1]}}, p3_b_q};
            csgrt_mul_vec #(.A_WIDTH(BW), .B_WIDTH(CW), .N(2), .II(II), .TILE_REG(TREG)) u_mul_p4 (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en), .adv_i(adv), .phase_i(phase),
                .a_i({p4_a_x, p3_b_q}), .b_i({p3_c_q, p4_b_x}), .p_o(p4_p));
            assign p4_bb = p4_p[0 +: 2*BW];
            assign p4_ac = p4_p[P4W +: AW+CW];
            wire unused_p4 = ^{p4_p[P4W-1:2*BW], p4_p[2*P4W-1:P4W+AW+CW]};   // sign copies
        end
    endgenerate
    wire          p4_valid;
    wire [AW-1:0] p4_a;
    wire [BW-1:0] p4_b;
    wire [CW-1:0] p4_c;
    wire [LW-1:0] p4_leaf;
    csgrt_delay #(.WIDTH(AW + BW + CW + LW), .STAGES(MUL_LAT)) u_dly4 (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .valid_i(p3_valid_q),
        .data_i({p3_leaf_q, p3_c_q, p3_b_q, p3_a_q}), .valid_o(p4_valid),
        .data_o({p4_leaf, p4_c, p4_b, p4_a}));

    // ---- P5: discriminant and sign flags -------------------------------------
    wire [DSW-1:0] disc = {{(DSW-2*BW){p4_bb[2*BW-1]}}, p4_bb} - {{(DSW-AW-CW){p4_ac[AW+CW-1]}}, p4_ac};

    // the facts about a, b, c that the final stage needs
    localparam FLW = 6;
    wire [FLW-1:0] flags_d = {disc[DSW-1],                           // 5: disc < 0
                              p4_a[AW-1],                            // 4: a < 0
                              p4_c[CW-1] || (p4_c == {CW{1'b0}}),    // 3: c <= 0
                              p4_b[BW-1],                            // 2: b < 0
                              (p4_b == {BW{1'b0}}),                  // 1: b == 0
                              (p4_a == {AW{1'b0}})};                 // 0: a == 0
    localparam SBW = FLW + AW + BW + CW + LW;   // sideband through the square root

    reg             p5_valid_q;
    reg [2*SQ-1:0]  p5_n_q;
    reg [SBW-1:0]   p5_side_q;
    always @(posedge clk_i) begin
        if (!rst_ni) p5_valid_q <= 1'b0;
        else if (adv) p5_valid_q <= p4_valid;
        if (adv) begin
            p5_n_q    <= disc[2*SQ-1:0];   // disc[DSW-1] is the sign, kept in flags
            p5_side_q <= {flags_d, p4_leaf, p4_c, p4_b, p4_a};
        end
    end

    // ---- P6: s = floor(sqrt(disc)) -------------------------------------------
    wire           p6_valid;
    wire [SQ-1:0]  p6_s;
    wire [SBW-1:0] p6_side;
    // the sidebands' RAM lines end in fabric registers: P7 and P9 compute
    // on them straight away (csgrt_delay_ram OUT_REG)
    csgrt_sqrt_core #(.RESULT_BITS(SQ), .USER_WIDTH(SBW), .USER_OUT_REG(1), .FOLD(II)) u_sqrt (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .run_i(en), .phase_i(phase), .valid_i(p5_valid_q),
        .n_i(p5_n_q), .user_i(p5_side_q),
        .valid_o(p6_valid), .root_o(p6_s), .user_o(p6_side));
    wire [AW-1:0]  p6_a     = p6_side[0 +: AW];
    wire [BW-1:0]  p6_b     = p6_side[AW +: BW];
    wire [CW-1:0]  p6_c     = p6_side[AW+BW +: CW];
    wire           p6_a_zero = p6_side[AW+BW+CW+LW + 0];   // flags[0]
    wire           p6_b_neg  = p6_side[AW+BW+CW+LW + 2];   // flags[2]

    // ---- P7: qq and the divider operands -------------------------------------
    // qq = -(b + s) for b >= 0, s - b for b < 0 (sgn(0) = +1)
    wire [QQW-1:0] b_x  = {{(QQW-BW){p6_b[BW-1]}}, p6_b};
    wire [QQW-1:0] s_x  = {{(QQW-SQ){1'b0}}, p6_s};
    wire [QQW-1:0] qq   = p6_b_neg ? s_x - b_x : {QQW{1'b0}} - (b_x + s_x);
    wire [NUMW-1:0] c_sh  = {{(NUMW-CW-F){p6_c[CW-1]}}, p6_c, {F{1'b0}}};    // c << F
    wire [NUMW-1:0] qq_sh = {{(NUMW-QQW-F){qq[QQW-1]}}, qq, {F{1'b0}}};      // qq << F
    wire [DENW-1:0] a_x   = {{(DENW-AW){p6_a[AW-1]}}, p6_a};
    wire [DENW-1:0] b2_x  = {{(DENW-BW-1){p6_b[BW-1]}}, p6_b, 1'b0};       // 2 b
    // divider 0: t_first = (qq << F) / a, or the linear root -(c << F) / (2 b)
    wire [NUMW-1:0] num0  = p6_a_zero ? {NUMW{1'b0}} - c_sh : qq_sh;
    wire [DENW-1:0] den0  = p6_a_zero ? b2_x : a_x;
    localparam SB7W = SBW + 1;

    reg            p7_valid_q;
    reg [NUMW-1:0] p7_num0_q, p7_num1_q;
    reg [DENW-1:0] p7_den0_q, p7_den1_q;
    reg [SB7W-1:0] p7_side_q;
    always @(posedge clk_i) begin
        if (!rst_ni) p7_valid_q <= 1'b0;
        else if (adv) p7_valid_q <= p6_valid;
        if (adv) begin
            p7_num0_q <= num0;
            p7_den0_q <= den0;
            p7_num1_q <= c_sh;   // t_second = (c << F) / qq
            p7_den1_q <= qq;
            p7_side_q <= {(qq == {QQW{1'b0}}), p6_side};
        end
    end

    // ---- P8: the two divisions ------------------------------------------------
    wire            p8_valid;
    wire [QB-1:0]   q0_mag, q1_mag;
    wire            q0_neg, q0_ovf, q1_neg, q1_ovf;
    wire [SB7W-1:0] p8_side;
    wire            unused_v1, unused_u1;
    csgrt_div_core #(.NUM_WIDTH(NUMW), .DEN_WIDTH(DENW), .QUOT_BITS(QB), .USER_WIDTH(SB7W), .USER_OUT_REG(1), .FOLD(II)) u_div0 (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .run_i(en), .phase_i(phase), .valid_i(p7_valid_q),
        .num_i(p7_num0_q), .den_i(p7_den0_q), .user_i(p7_side_q),
        .valid_o(p8_valid), .quot_o(q0_mag), .neg_o(q0_neg), .ovf_o(q0_ovf), .user_o(p8_side));
    csgrt_div_core #(.NUM_WIDTH(NUMW), .DEN_WIDTH(DENW), .QUOT_BITS(QB), .USER_WIDTH(1), .FOLD(II)) u_div1 (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .run_i(en), .phase_i(phase), .valid_i(p7_valid_q),
        .num_i(p7_num1_q), .den_i(p7_den1_q), .user_i(1'b0),
        .valid_o(unused_v1), .quot_o(q1_mag), .neg_o(q1_neg), .ovf_o(q1_ovf), .user_o(unused_u1));

    // ---- P9: the events' t and range, registered ------------------------------
    // (The quotients' sign and the equal-pair test after it were one path
    // from the dividers' output registers into the skid buffer: the routed
    // effects build's critical path, 11.71 ns, 4.59 of them the route from
    // the dividers to the skid; docs/fpga.md.)
    wire           p8_qq_zero = p8_side[SBW];
    wire o_a_zero   = o_flags[0];
    wire o_b_zero   = o_flags[1];
    wire o_b_neg    = o_flags[2];
    wire o_c_le0    = o_flags[3];
    wire o_a_neg    = o_flags[4];
    wire o_disc_neg = o_flags[5];

    // set_t(): a saturated quotient is NegInf or PosInf by its sign, t = 0
    wire [TW-1:0] q0_x = {1'b0, q0_mag};
    wire [TW-1:0] q1_x = {1'b0, q1_mag};
    wire [TW-1:0] t0_div = q0_ovf ? {TW{1'b0}} : q0_neg ? {TW{1'b0}} - q0_x : q0_x;
    wire [TW-1:0] t1_div = q1_ovf ? {TW{1'b0}} : q1_neg ? {TW{1'b0}} - q1_x : q1_x;
    wire [1:0]    r0_div = q0_ovf ? (q0_neg ? R_NEGINF : R_POSINF) : R_FINITE;
    wire [1:0]    r1_div = q1_ovf ? (q1_neg ? R_NEGINF : R_POSINF) : R_FINITE;
    // qq == 0 (b = s = 0, so c = 0): a double root at 0, second = first
    wire [TW-1:0] t1_q = p8_qq_zero ? t0_div : t1_div;
    wire [1:0]    r1_q = p8_qq_zero ? r0_div : r1_div;
    reg            p9_valid_q;
    reg [TW-1:0]   p9_t0_q, p9_t1_q;
    reg [1:0]      p9_r0_q, p9_r1_q;
    reg [SBW-1:0]  p9_side_q;          // the sideband without qq == 0 (used in P9)
    always @(posedge clk_i) begin
        if (!rst_ni)  p9_valid_q <= 1'b0;
        else if (adv)  p9_valid_q <= p8_valid;
        if (adv) begin
            p9_t0_q   <= t0_div;
            p9_t1_q   <= t1_q;
            p9_r0_q   <= r0_div;
            p9_r1_q   <= r1_q;
            p9_side_q <= p8_side[SBW-1:0];
        end
    end

    // ---- P10: events (combinational into the skid buffer) --------------------
    wire [AW-1:0]  o_a      = p9_side_q[0 +: AW];
    wire [BW-1:0]  o_b      = p9_side_q[AW +: BW];
    wire [CW-1:0]  o_c      = p9_side_q[AW+BW +: CW];
    wire [LW-1:0]  o_leaf   = p9_side_q[AW+BW+CW +: LW];
    wire [FLW-1:0] o_flags  = p9_side_q[AW+BW+CW+LW +: FLW];
    // drop_equal_pair(): two events on the same t cross nothing
    wire          equal_pair = (p9_r0_q == p9_r1_q) && (p9_r0_q != R_FINITE || p9_t0_q == p9_t1_q);

    reg [1:0]    count_d;
    reg          inside_d, enter0_d, enter1_d;
    reg [TW-1:0] t0_d, t1_d;
    reg [1:0]    range0_d, range1_d;
    always @* begin
        // the model's defaults for events it does not set
        count_d  = 2'd0;
        inside_d = 1'b0;
        t0_d     = {TW{1'b0}};
        range0_d = R_FINITE;
        enter0_d = 1'b0;
        t1_d     = {TW{1'b0}};
        range1_d = R_FINITE;
        enter1_d = 1'b0;
        case ({o_a_zero, o_b_zero})
            2'b11: begin
                // Q = c along the whole line
                inside_d = o_c_le0;
            end
            2'b10: begin
                // linear: Q = 2 b t + c, entering where Q decreases
                inside_d = !o_b_neg;
                count_d  = 2'd1;
                t0_d     = p9_t0_q;
                range0_d = p9_r0_q;
                enter0_d = o_b_neg;
            end
            default: begin
                // quadratic: roots only for disc >= 0
                inside_d = o_a_neg;
                if (!o_disc_neg) begin
                    count_d  = equal_pair ? 2'd0 : 2'd2;
                    t0_d     = p9_t0_q;
                    range0_d = p9_r0_q;
                    enter0_d = !o_b_neg;
                    t1_d     = p9_t1_q;
                    range1_d = p9_r1_q;
                    enter1_d = o_b_neg;
                end
            end
        endcase
    end

    // ---- output skid buffer ---------------------------------------------------
    localparam OUTW = LW + 2 + 2 * (TW + 3) + 1 + AW + BW + CW;
    csgrt_skid #(.WIDTH(OUTW)) u_skid (
        .clk_i  (clk_i),
        .rst_ni (rst_ni),
        .valid_i(p9_valid_q && last),
        .ready_o(en),
        .ready_next_o(en_next),
        .data_i ({o_leaf, count_d, t0_d, range0_d, enter0_d, t1_d, range1_d, enter1_d, inside_d,
                  o_a, o_b, o_c}),
        .valid_o(valid_o),
        .ready_i(ready_i),
        .data_o ({leaf_o, count_o, t0_o, range0_o, enter0_o, t1_o, range1_o, enter1_o, inside_o,
                  a_o, b_o, c_o})
    );

    generate
        if (BITS < 12 || BITS > 32 || LEAF_WIDTH < 1 || (II != 1 && II != 3)) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_isect needs 12 <= BITS <= 32, LEAF_WIDTH >= 1, II = 1 or 3");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
