`default_nettype none
// csgrt_spawn — the geometry of secondary rays, bit for bit the model's
// functions (model/raytree.cpp, model/trace.cpp, model/render.cpp;
// docs/effects.md): for one hit, its hit point and its child rays, one child
// per output transaction.
//
// ---- Interface ---------------------------------------------------------------
// B = BITS (12..32), F = B-3 fraction bits of points, directions and t,
// FC = B-1 of quadric coefficients (model/fixed.h, struct Formats).
// Input, one transaction per hit (s_valid_i/s_ready_o):
//   s_o_i, s_d_i   3 x B signed, F frac, x low: the ray's origin and unit direction
//   s_t_i          F+2 = B-1 bits signed, F frac: the walker's t (>= 0)
//   s_coef_i       10 x B signed, FC frac: the hit leaf's quadric, CoefIndex
//                  order (model/compile.h) as csgrt_isect takes it (q unused)
//   s_ior_from_i, s_ior_to_i   16 bits unsigned, 12 frac (kColorFrac; air =
//                  1 << 12): ior_of(border.from), ior_of(border.to)
//   s_lights_i     light k wants a shadow ray
//   s_refract_i, s_reflect_i   a transmitted / a reflected child
//   s_continue_i   a shadow ray crossing a transparent surface goes on from
//                  the hit point in the same direction (shadow_fx)
//   s_user_i       sideband, returned with every child
// A request with no child (no flag set) must not be sent; if one is, it is
// consumed and produces nothing. A request must not ask for a kind the
// build does not have (below): s_lights_i must be 0 without SHADOWS,
// s_reflect_i without REFLECTION, s_refract_i without REFRACTION. Such a
// flag is ignored (no child; a request with nothing else produces nothing)
// and stops a simulation ($fatal, outside `SYNTHESIS).
// Static: light_pos_i, light k axis i at (3k+i)*B (csgrt_top's light_pos,
// F frac), read when the hit's shadow children are issued.
// Output, one transaction per child (m_valid_o/m_ready_i), per hit in the
// order: continue, shadow rays for each requested light k ascending, refract
// (or its total-internal-reflection fallback), reflect; m_last_o marks the
// hit's last child. Per child:
//   m_kind_o       KIND_* below
//   m_light_o      SHADOW: the light k; else 0
//   m_o_o          p = hit_point_fx: p_i = o_i + rnd(t d_i, F), 3 x B, F frac
//                  (the low B bits of p when out of range)
//   m_in_range_o   hit_point_fx's return: every p_i in [-4, 4). When 0 the hit
//                  counts as no hit (trace_colour_fx returns the background):
//                  the children still come out (same count, kinds and order),
//                  but their m_d_o (except CONTINUE's), m_dist_o, m_lit_o and
//                  the choice between REFRACT and TIR_REFLECT are meaningless
//   m_d_o          3 x B, F frac: CONTINUE the ray's d unchanged; SHADOW
//                  shadow_ray_fx's direction unit_fx(light - p, F, F+8);
//                  REFRACT refract_fx's direction; TIR_REFLECT and REFLECT
//                  reflect_fx(d, n, F). |m_d_o_i| < 2^F.
//   m_dist_o       SHADOW: shadow_ray_fx's distance isqrt(|light - p|^2), the
//                  t limit of the shadow ray (events at t >= it are not
//                  reached); B+1 = F+4 bits unsigned, F frac: |light_i - p_i|
//                  < 8 (both in [-4, 4)), so the distance is < 8 sqrt(3) < 14
//                  < 2^4. 0 for the other kinds.
//   m_lit_o        SHADOW: n . (light - p) > 0, exact sign (trace_colour_fx),
//                  with n = normal_fx(p, d). A light with m_lit_o = 0 gets no
//                  shadow ray: the consumer treats it as dark. 0 for the other kinds.
//   m_user_o       the hit's s_user_i
//
// ---- Effect units (SHADOWS, REFLECTION, REFRACTION; 1 by default) ----------------
// A build has only the child kinds it is given (csgrt_top passes its own):
//   REFRACTION 0   none of the refraction datapath: no eta division, eta^2,
//                  S1..S6 (cos^2, eta cos, eta2 sin2, k, TIR, isqrt(k << F),
//                  a) or their queues, no Y multipliers and no t sum; the
//                  sequencer waits for the normal's queue instead (latency
//                  F+7 clocks shorter, below); the X multipliers and U2 are
//                  narrower (X's eta factor and U2's |t_i| < 128 are gone:
//                  X (F+2) x (B+1), U2's input B+1 bits); s_ior_*_i unused.
//   REFLECTION 0   and REFRACTION 0: no dn (d . n after the flip, its
//                  rounding and its queue entry), no reflected direction
//                  r = d - rnd(2 dn n, F) and no d in the child pipeline.
//                  With REFRACTION 1 the total-internal-reflection fallback
//                  needs all of that, so only the REFLECT kind goes.
//   SHADOWS 0      no lv = light - p, light selection or lit sum (X then
//                  serves REFLECT/TIR and REFRACT); light_pos_i unused.
// What stays in every build: the front up to the faced normal (H..NDA:
// the hit point, the gradient, unit(g), n . d and the flip, which shadows
// need as much as reflection), the X multipliers and U2, which serve every
// kind (U2's root is also the shadow distance), and the sequencer.
//
// ---- Arithmetic (every rounding; rnd(x, k) = (x + 2^(k-1)) >> k, ties up) ----
//   p_i   = o_i + rnd(t d_i, F)                          hit_point_fx (trace.cpp)
//   g_i   = rnd(sum_j A_ij p_j + (P_i << F), FC)         half_gradient_fx (trace.cpp), |g| < 16
//   n     = unit(g): L = isqrt(sum g^2, F+8) + 1, n_i = div(g_i << F, L, F+1)
//                                                        unit_fx (render.cpp), normal_fx
//   n     = -n if n . d > 0 (exact sign)                 face_against (trace.cpp)
//   dn    = rnd(d . n, F)                                dot_round (render.cpp)
//   eta   = div(ior_from << F, ior_to, F+7) (0 when it overflows), cos = -dn,
//   sin2  = 1 - rnd(cos^2, F), k = 1 - rnd(rnd(eta^2, F) sin2, F); k < 0: TIR,
//   sk    = isqrt(k << F), a = rnd(eta cos, F) - sk,
//   t_i   = rnd(eta d_i, F) + rnd(a n_i, F), unit(t)     refract_fx (raytree.cpp)
//   r_i   = d_i - rnd(2 dn n_i, F) (= rnd(dn n_i, F-1)), unit(r)   reflect_fx (raytree.cpp)
//   lv    = light - p, unit(lv), distance isqrt(|lv|^2)  shadow_ray_fx (raytree.cpp)
//   lit   = n . lv > 0 (exact)                           trace_colour_fx (raytree.cpp)
// unit() is unit_fx(v, F, F+8) (|v_i| < 128 as the model requires: it throws
// otherwise): csgrt_unit for the children, spread over three clocks for the
// normal. isqrt is isqrt_bitwise, div sdiv_trunc (model/fixed.h).
// Widths: p B+1 bits before the range check, g B+2, n F+1, dn/cos/sin2 F+2,
// eta F+8 (F+7 magnitude bits), eta^2 rounded F+15, k F+16, a F+8, lv B+1,
// r B+1, t F+9 summed and F+8 into the unit. Every product is exact
// (csgrt_mul), every sum exact at its width.
//
// ---- Structure ---------------------------------------------------------------
// Front (per hit, free running: it never stalls; a hit is admitted at most
// every third clock, and only while fewer than CTX = 32 hits sit between the
// input and the child sequencer, so no queue below can overflow):
//   H    (3)        the hit held for three clocks; phase j feeds axis j
//   T    (3)        t d_j                      1 multiplier, shared by the 3 axes (tiles registered)
//   P    (1)        p_j = o_j + rnd(t d_j, F), range check
//   G    (2)        A_ij p_j (column j)        3 multipliers, shared by the 3 columns
//   ACC  (1)        g_i accumulated column by column (+ P_i << F, + rounding)
//   N    (2F+20)    n = unit(g), csgrt_unit's stages with one axis per clock:
//                   g_j^2 (3+2+1, 1 multiplier), isqrt (F+8, csgrt_sqrt_core),
//                   L = root + 1 held (3), div(g_j << F, L) (F+2, one
//                   csgrt_div_core), n_j signed (1)
//   FD   (2+1)      n_j d_j as n_j comes out   1 multiplier; accumulate n . d
//   NDA  (1)        face: flip n, d.n when n . d > 0   (d.n: REFLECTION or REFRACTION)
//   NDB  (1)        dn = rnd(d.n, F), cos = -dn   (dn: the same; cos: REFRACTION)
//   --- REFRACTION only, from here to the eta lines ---
//   S1   (2)        cos^2, eta cos             2 multipliers
//   S2   (1)        sin2, rnd(eta cos, F)
//   S3   (2)        eta2 sin2                  1 multiplier
//   S4   (1)        k, TIR, k << F
//   S5   (F+1)      sk = isqrt(k << F)         csgrt_sqrt_core
//   S6   (0)        a = rnd(eta cos, F) - sk   into the last queue
//   eta, beside H..S1: div(ior_from << F, ior_to) (csgrt_div_core, F+8),
//   eta^2 (1 multiplier, 2), rnd (0) into queues.
// Per-hit values wait in small queues instead of riding along the
// pipelines (the wide ones csgrt_fifo_block, in block RAM: its head is
// valid 2 clocks after a push, and every pop or read of these comes at
// least a multiplier's 2 clocks after its push; the narrow refraction ones
// csgrt_fifo, LUT RAM): {d, flags, user}, {d} (for FD), {p, in_range},
// {g} (for the divisions), {eta, eta2}, {eta}, {n, dn}, {rnd(eta cos)},
// {a, TIR} (the last three and the eta ones: REFRACTION; dn: REFLECTION or
// REFRACTION).
// Children (one global enable, the output skid buffer's registered ready):
//   SEQ             the hit register and its pending children, lowest first;
//                   the next hit is loaded as the last child leaves
//   C0   (1)        lv = light_k - p and the hit's n, dn, eta, a, d
//   X/Y  (2)        SHADOW: n_i lv_i; REFLECT, TIR: dn n_i; REFRACT: eta d_i
//                   and a n_i             6 multipliers shared by every kind
//                   (Y: REFRACTION only; II 3: 3 beats, X_BEATS)
//   C3   (1)        lit = sum > 0 (exact); r; t; the unit's input v
//                   (lit: SHADOWS; r: REFLECTION or REFRACTION; t: REFRACTION)
//   U2   (2F+15)    unit(v)                    csgrt_unit #2, 3 multipliers,
//                   shared by every child (its root is the shadow distance)
//   skid (1)        output; p, d, in_range and user from the hit's queue
//                   entry (written at SEQ load, read by the hit's last child)
// Multipliers (REFRACTION 1): 19 csgrt_mul: T 1 ((F+2) x B), G 3 (B x B),
// N 1 ((B+2)^2), FD 1 ((F+1) x B), eta^2 1 ((F+8)^2), S1 2 ((F+2)^2,
// (F+8) x (F+2)), S3 1 ((F+15) x (F+2)), X 3 ((F+8) x (B+1)),
// Y 3 ((F+8) x (F+1)), U2 3 ((F+8)^2). Dividers: 5 csgrt_div_core (eta, N,
// U2 x 3); square roots: 3 csgrt_sqrt_core (N, S5, U2).
// REFRACTION 0 (any SHADOWS, REFLECTION): 12 csgrt_mul: T, G, N, FD as
// above, X 3 ((F+2) x (B+1)), U2 3 ((B+1)^2); 4 csgrt_div_core (N, U2 x 3);
// 2 csgrt_sqrt_core (N, U2).
// Shared: T, G, N and FD serve the three axes in turn (a hit every third
// clock); X, Y and U2 serve every child kind (U2's square root is also the
// shadow distance). II = 3 (csgrt_top's SHARE_II): the children's stages
// move once every three clocks (csgrt_beat) and X, Y and U2's squares
// serve their three axes in turn on one multiplier each (csgrt_mul_vec):
// 6 csgrt_mul fewer (REFRACTION 1; 4 with REFRACTION 0), a child every
// third clock, the children's 2F+19 stages three times as long, but for
// U2's F+8-bit square root, which finds three result bits per stage
// (csgrt_unit: ceil((F+8)/3) stages) and its divisions (on one divider),
// and for X and Y, one stage more (their operands registered before the
// blocks, X_OP_REG).
// yosys 0.23 synth_ecp5 of this module alone, MAX_LIGHTS 8, USER_WIDTH 1,
// BITS 16, (REFLECTION, REFRACTION) with SHADOWS 1:
//   (1, 1): MULT18X18D 39, LUT4 17.7k + CCU2C 3.4k, FF 9.5k, DPR16X4 246, DP16KD 3
//   (1, 0): MULT18X18D 12, LUT4 15.6k + CCU2C 2.5k, FF 7.5k, DPR16X4 188, DP16KD 3
//   (0, 0): MULT18X18D 12, LUT4 15.4k + CCU2C 2.4k, FF 7.3k, DPR16X4 180, DP16KD 3
// (BITS 24, (1, 1), an earlier build: MULT18X18D 76, LUT4 39.7k + CCU2C
// 6.7k, FF 20.3k, DPR16X4 354). These figures predate the wide queues'
// move to block RAM (csgrt_fifo_block, ad33daa), which took most of those
// DPR16X4 into DP16KD. The csgrt_div_cores (N's and U2's three)
// take most of the LUTs in every configuration.
//
// ---- Timing --------------------------------------------------------------------
// Latency (no back-pressure, idle front): 5F+67 clocks from a hit's
// acceptance to its first child (BITS 12: 112, 16: 132, 24: 172, 32: 212);
// without REFRACTION 4F+61 (the sequencer takes the hit from the normal's
// queue, F+6 clocks before S6 would have finished: BITS 12: 97, 16: 113,
// 24: 145, 32: 177; 4F+56 before the queue moved to block RAM, whose head
// comes one clock later, two clocks less before the gradient's products
// and the normal's squares were registered ahead of their sums, gp_q and
// ggp_q, one less before T's tiles were, u_mul_t's TILE_REG, and one
// less before n . d's were, u_mul_nd's). The
// consumer (csgrt_raytree) takes children by valid/ready and m_user_o and
// assumes no latency.
// Throughput: one child per clock while hits are waiting at the sequencer:
// a hit's children leave on consecutive clocks and the next hit's first
// child follows its predecessor's last without a gap. The front accepts a
// hit every third clock at most, and holds each of its 32 credits for 3F+46
// clocks (2F+40 without REFRACTION): back to back, a hit every
// max(3, (3F+46)/32) clocks (BITS 12, 16: 3; 24: 3.4; 32: 4.2; without
// REFRACTION 3 up to BITS 32), so hits with fewer children than that leave
// gaps.
// At most 32 hits wait between sequencer and output (their p, d, user).
// Handshake: valid/ready on both sides. s_ready_o depends only on registers
// (the front's phase and hit count); the child pipeline advances on the
// output skid buffer's registered ready; no combinational path from
// m_ready_i to s_ready_o. Back-pressure stops the children; the front keeps
// running into its queues and stops accepting when 32 hits wait. Nothing is
// lost or duplicated.
module csgrt_spawn #(
    parameter BITS       = 24,   // coordinate width B (12..32)
    parameter MAX_LIGHTS = 8,    // lights (>= 1)
    parameter USER_WIDTH = 1,    // sideband width (>= 1)
    parameter SHADOWS    = 1,    // SHADOW children (s_lights_i); 0: s_lights_i must be 0
    parameter REFLECTION = 1,    // REFLECT children (s_reflect_i); 0: s_reflect_i must be 0
    parameter REFRACTION = 1,    // REFRACT / TIR_REFLECT children (s_refract_i); 0: s_refract_i must be 0
    parameter II         = 1     // the children's clocks per child: 1, or 3 with X, Y and U2's
                                 // three axes on one multiplier each (csgrt_mul_vec)
) (
    input  wire                                   clk_i,
    input  wire                                   rst_ni,      // synchronous, active low
    // static configuration
    input  wire [MAX_LIGHTS*3*BITS-1:0]           light_pos_i, // light k axis i at (3k+i)*BITS
    // input stream: one hit
    input  wire                                   s_valid_i,
    output wire                                   s_ready_o,
    input  wire [3*BITS-1:0]                      s_o_i,
    input  wire [3*BITS-1:0]                      s_d_i,
    input  wire [BITS-2:0]                        s_t_i,
    input  wire [10*BITS-1:0]                     s_coef_i,
    input  wire [15:0]                            s_ior_from_i,
    input  wire [15:0]                            s_ior_to_i,
    input  wire [MAX_LIGHTS-1:0]                  s_lights_i,
    input  wire                                   s_reflect_i,
    input  wire                                   s_refract_i,
    input  wire                                   s_continue_i,
    input  wire [USER_WIDTH-1:0]                  s_user_i,
    // output stream: one child ray
    output wire                                   m_valid_o,
    output wire                                   m_valid_copy_o,   // m_valid_o again, from a flip-flop of its own
    output wire                                   m_valid_rec_o,    // and once more (for the ray tree's record choice)
    input  wire                                   m_ready_i,
    output wire                                   m_last_o,
    output wire [2:0]                             m_kind_o,
    output wire [((MAX_LIGHTS > 1) ? $clog2(MAX_LIGHTS) : 1)-1:0] m_light_o,
    output wire [3*BITS-1:0]                      m_o_o,
    output wire                                   m_in_range_o,
    output wire [3*BITS-1:0]                      m_d_o,
    output wire [BITS:0]                          m_dist_o,
    output wire                                   m_lit_o,
    output wire [USER_WIDTH-1:0]                  m_user_o
);

    // child kinds (m_kind_o)
    localparam [2:0] KIND_CONTINUE    = 3'd0;   // transparent shadow crossing: same d
    localparam [2:0] KIND_SHADOW      = 3'd1;   // towards light m_light_o
    localparam [2:0] KIND_REFRACT     = 3'd2;   // transmitted (Snell)
    localparam [2:0] KIND_TIR_REFLECT = 3'd3;   // transmitted asked, total internal reflection
    localparam [2:0] KIND_REFLECT     = 3'd4;   // mirror reflection

    // ---- formats -------------------------------------------------------------
    localparam B    = BITS;
    localparam F    = B - 3;
    localparam FC   = B - 1;
    localparam TW   = B - 1;          // t
    localparam ML   = MAX_LIGHTS;
    localparam LW   = (ML > 1) ? $clog2(ML) : 1;
    localparam FLW  = ML + 3;         // child flags {reflect, refract, lights, continue}
    localparam UW   = USER_WIDTH;
    // the child kinds this build has (the others are never requested)
    localparam SH   = (SHADOWS != 0);
    localparam RL   = (REFLECTION != 0);
    localparam RF   = (REFRACTION != 0);
    localparam RDN  = RL || RF;       // dn and the reflected direction (REFLECT, TIR_REFLECT)
    localparam [FLW-1:0] FLAG_MASK = {RL ? 1'b1 : 1'b0, RF ? 1'b1 : 1'b0, {ML{SH ? 1'b1 : 1'b0}}, 1'b1};
    localparam SQ   = F + 8;          // geo_sqrt_stages(F)
    localparam UOW  = F + 2;          // csgrt_unit output component
    localparam CTX  = 32;             // queue depth, hits admitted ahead of the sequencer
    localparam CW   = 6;              // counter 0..CTX
    localparam [CW-1:0] CTX_N = CTX;
    localparam PTW  = TW + B;         // t d
    localparam PPW  = B + 1;          // p before the range check, |p| < 6
    localparam GPW  = 2 * B;          // A_ij p_j
    localparam ACCW = 2 * B + 2;      // |sum| < 13 * 2^(F+FC)
    localparam GW   = B + 2;          // g, |g| < 16
    localparam NW   = F + 1;          // n, |n_i| < 2^F
    localparam NDPW = NW + B;         // n_j d_j
    localparam NDSW = NDPW + 2;       // n . d
    localparam DNW  = F + 2;          // dn, cos, sin2: |.| <= 2^F
    localparam EMW  = F + 7;          // eta magnitude (quotient bits)
    localparam ETW  = F + 8;          // eta signed
    localparam E2W  = F + 15;         // rnd(eta^2, F) < 2^(F+14), signed
    localparam KW   = F + 16;         // k in [-2^(F+14), 2^F]
    localparam AW   = F + 8;          // rnd(eta cos, F) < 2^(F+7), a
    localparam SKB  = F + 1;          // isqrt(k << F) stages: k << F <= 2^(2F)
    localparam LVW  = B + 1;          // lv = light - p, r
    localparam XAW  = RF ? F + 8 : DNW;   // X multiplier: n | dn | eta
    localparam XBW  = B + 1;          //               lv | n | d
    localparam XPW  = XAW + XBW;
    localparam XSW  = XPW + 2;
    localparam YAW  = AW;             // Y multiplier: a
    localparam YBW  = NW;             //               n
    localparam YPW  = YAW + YBW;
    localparam TSW  = F + 9;          // t_i = rnd(eta d_i) + rnd(a n_i)
    localparam VW2  = RF ? F + 8 : LVW;   // child unit input: |v_i| < 128 (refract), < 2^(F+3) (lv, r)

    genvar i;
    integer k, kl;

    wire accept;     // a hit enters the front
    wire seq_load;   // a hit leaves the front's queues into the sequencer

    // =========================================================================
    // Front
    // =========================================================================
    // ---- H: the hit, three phases --------------------------------------------
    reg [CW-1:0]  cnt_q;     // hits admitted and not yet loaded by the sequencer
    reg           h_valid_q;
    reg [1:0]     h_ph_q;
    reg [3*B-1:0] h_o_q, h_d_q;
    reg [TW-1:0]  h_t_q;
    reg [9*B-1:0] h_coef_q;   // q is not needed

    // s_ready_o is a register (ready_q), loaded with the test of the next
    // values of the count and the phase: tested on the registers
    // themselves, the phase's ~200 loads and two LUTs went on through
    // accept into the hit queue's pointers and these registers' enables
    // (tools/logic_depth.py). A simulation stops if the two differ.
    reg           ready_q;
    wire          h_valid_d = accept || (h_valid_q && h_ph_q != 2'd2);
    wire [1:0]    h_ph_d    = accept ? 2'd0 : h_valid_q ? h_ph_q + 2'd1 : h_ph_q;
    wire [CW-1:0] cnt_d     = cnt_q + {{(CW-1){1'b0}}, accept} - {{(CW-1){1'b0}}, seq_load};
    assign s_ready_o = ready_q;
    assign accept    = s_valid_i && s_ready_o;
`ifndef SYNTHESIS
    csgrt_check_same #(.WHAT("s_ready_o")) u_check_ready (
        .clk_i(clk_i), .rst_ni(rst_ni), .copy_i(ready_q),
        .orig_i((cnt_q != CTX_N) && (!h_valid_q || h_ph_q == 2'd2)));
`endif
    wire unused_q    = ^s_coef_i[9*B +: B];

    always @(posedge clk_i) begin
        if (!rst_ni) begin
            h_valid_q <= 1'b0;
            h_ph_q    <= 2'd0;
            cnt_q     <= {CW{1'b0}};
            ready_q   <= 1'b1;
        end else begin
            h_valid_q <= h_valid_d;
            h_ph_q    <= h_ph_d;
            cnt_q     <= cnt_d;
            ready_q   <= (cnt_d != CTX_N) && (!h_valid_d || h_ph_d == 2'd2);
        end
        if (accept) begin
            h_o_q    <= s_o_i;
            h_d_q    <= s_d_i;
            h_t_q    <= s_t_i;
            h_coef_q <= s_coef_i[0 +: 9*B];
        end
    end

    // the hit's d, flags and user wait for the sequencer; d also for FD.
    // A kind this build does not have is never requested: its flag is
    // ignored here (and below), and a simulation stops on it.
    localparam QHW = 3 * B + FLW + UW + 2 + FLW;   // + the flags' two tests and lowest flag (below)
    wire [FLW-1:0] s_req   = {s_reflect_i, s_refract_i, s_lights_i, s_continue_i};
    wire [FLW-1:0] s_flags = s_req & FLAG_MASK;
`ifndef SYNTHESIS
    always @(posedge clk_i)
        if (rst_ni && accept && ((s_req & ~FLAG_MASK) != {FLW{1'b0}})) begin
            $display("ERROR %m: a hit requests a child kind this build does not have (s_lights_i %b, s_reflect_i %b, s_refract_i %b; SHADOWS %0d, REFLECTION %0d, REFRACTION %0d)",
                     s_lights_i, s_reflect_i, s_refract_i, SHADOWS, REFLECTION, REFRACTION);
            $fatal;
        end
`endif
    wire [QHW-1:0] qh_data;
    wire           unused_qh_ready, unused_qh_valid;
    // the hit's head in a fabric register (HEAD_REG 1): read long after the
    // push, by the sequencer's load (seq_load, a few LUTs of registers);
    // the block RAM's read port went on into the output queue's write
    // address (qh_any -> qo_push)
    csgrt_fifo_block #(.WIDTH(QHW), .DEPTH(CTX), .HEAD_REG(1)) u_q_hit (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(accept), .ready_o(unused_qh_ready),
        .data_i({lowest(s_flags), at_most_one(s_flags), s_flags != {FLW{1'b0}}, s_user_i, s_flags, s_d_i}),
        .valid_o(unused_qh_valid), .ready_i(seq_load), .data_o(qh_data));
    wire [3*B-1:0] qh_d     = qh_data[0 +: 3*B];
    wire [FLW-1:0] qh_flags = qh_data[3*B +: FLW] & FLAG_MASK;
    wire [UW-1:0]  qh_user  = qh_data[3*B+FLW +: UW];
    // the hit's flags tested before they are queued, so that the tests do
    // not follow the queue's head (before the head register, the block
    // RAM's slow read port: 5.6 ns from the clock in nextpnr's model): a
    // child at all (qh_any), at most one (qh_one, cur_last_q's next value
    // at a load: RAM -> carry chain -> cur_last_q was csgrt_spawn's
    // longest path out of context), and the first child to issue
    // (qh_pick, the lowest flag: pick_q's next value at a load)
    wire           qh_any   = qh_data[3*B+FLW+UW];
    wire           qh_one   = qh_data[3*B+FLW+UW+1];
    wire [FLW-1:0] qh_pick  = qh_data[3*B+FLW+UW+2 +: FLW];

    wire [3*B-1:0] qnd_d;
    wire           qnd_pop;
    wire           unused_qnd_ready, unused_qnd_valid;
    // d waits for the normal (n . d) here. Its head in a fabric register
    // (HEAD_REG 1, as u_q_g's below): the block RAM's read port (5.6 ns
    // from the clock) went on through the axis choice into the n . d
    // multiplier's input register, the longest path out of context once
    // the products were registered before their sums; read long after the
    // push, popped at a fixed phase (a register)
    csgrt_fifo_block #(.WIDTH(3 * B), .DEPTH(CTX), .HEAD_REG(1)) u_q_nd (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(accept), .ready_o(unused_qnd_ready),
        .data_i(s_d_i), .valid_o(unused_qnd_valid), .ready_i(qnd_pop), .data_o(qnd_d));

    // phase j: axis j of t d, column j of the gradient {P_j, A_2j, A_1j, A_0j}
    reg [B-1:0]   h_dj, h_oj;
    reg [4*B-1:0] h_col;
    always @* begin
        case (h_ph_q)
            2'd0: begin
                h_dj  = h_d_q[0 +: B];
                h_oj  = h_o_q[0 +: B];
                h_col = {h_coef_q[6*B +: B], h_coef_q[4*B +: B], h_coef_q[3*B +: B], h_coef_q[0*B +: B]};
            end
            2'd1: begin
                h_dj  = h_d_q[B +: B];
                h_oj  = h_o_q[B +: B];
                h_col = {h_coef_q[7*B +: B], h_coef_q[5*B +: B], h_coef_q[1*B +: B], h_coef_q[3*B +: B]};
            end
            default: begin
                h_dj  = h_d_q[2*B +: B];
                h_oj  = h_o_q[2*B +: B];
                h_col = {h_coef_q[8*B +: B], h_coef_q[2*B +: B], h_coef_q[5*B +: B], h_coef_q[4*B +: B]};
            end
        endcase
    end

    // ---- T: t d_j ------------------------------------------------------------
    wire [PTW-1:0] td_p;
    wire           unused_td_v;
    // TILE_REG: the tiles' values registered before their sum, so that P
    // (the sum, the rounding, o_j + rnd(t d_j) and the range test) starts
    // from flip-flops beside it and not at the MULT18X18D's output across
    // the die (the routed critical path of 18b6b1d's 24-bit build with
    // shadows and reflection, 81.93 MHz: 0.74 ns clock to output, 3.20 ns
    // of route, then those carry chains). T takes csgrt_mul's 2 + TILE_REG
    // clocks.
    localparam T_TILE_REG = 1;
    csgrt_mul #(.A_WIDTH(TW), .B_WIDTH(B), .TILE_REG(T_TILE_REG)) u_mul_t (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(1'b1), .valid_i(h_valid_q),
        .a_i(h_t_q), .b_i(h_dj), .valid_o(unused_td_v), .p_o(td_p));
    localparam TSDW = 2 + B + 4 * B;
    wire            t_valid;
    wire [TSDW-1:0] t_side;
    csgrt_delay #(.WIDTH(TSDW), .STAGES(2 + T_TILE_REG)) u_dly_t (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(1'b1), .valid_i(h_valid_q),
        .data_i({h_col, h_oj, h_ph_q}), .valid_o(t_valid), .data_o(t_side));
    wire [1:0]     t_colj = t_side[1:0];
    wire [B-1:0]   t_oj   = t_side[2 +: B];
    wire [4*B-1:0] t_cc   = t_side[2+B +: 4*B];

    // ---- P: p_j = o_j + rnd(t d_j, F) ----------------------------------------------
    wire [PTW-1:0] td_r = td_p + {{(PTW-F){1'b0}}, 1'b1, {(F-1){1'b0}}};
    wire [PPW-1:0] tdr  = td_r[F +: PPW];              // |rnd(t d)| <= 2^(F+1)
    wire unused_td_r    = ^{td_r[F-1:0], td_r[PTW-1:F+PPW]};
    wire [PPW-1:0] pj   = {t_oj[B-1], t_oj} + tdr;
    wire           inr_j = (pj[B] == pj[B-1]);         // fits B bits: [-4, 4)

    reg           p_valid_q;
    reg [1:0]     p_col_q;
    reg [B-1:0]   p_val_q;
    reg [4*B-1:0] p_cc_q;
    reg [3*B-1:0] p_vec_q;
    reg [2:0]     p_inr_q;
    always @(posedge clk_i) begin
        if (!rst_ni) p_valid_q <= 1'b0;
        else p_valid_q <= t_valid;
        if (t_valid) begin
            p_col_q <= t_colj;
            p_val_q <= pj[B-1:0];
            p_cc_q  <= t_cc;
            case (t_colj)
                2'd0:    begin p_vec_q[0 +: B]   <= pj[B-1:0]; p_inr_q[0] <= inr_j; end
                2'd1:    begin p_vec_q[B +: B]   <= pj[B-1:0]; p_inr_q[1] <= inr_j; end
                default: begin p_vec_q[2*B +: B] <= pj[B-1:0]; p_inr_q[2] <= inr_j; end
            endcase
        end
    end
    // column 2 in P: the whole p is known
    wire           qp_push = p_valid_q && (p_col_q == 2'd2);
    wire [3*B:0]   qp_data;
    wire           unused_qp_ready, qp_valid;
    // the hit's p in a fabric register (HEAD_REG 1), as the hit's head
    // (u_q_hit): the block RAM's read port went straight into u_q_out's
    // write data, another block RAM across the die (9f2f1a7's routed
    // critical path with seed 1: 5.61 ns clock to output, 6.13 ns of
    // route). p is queued several clocks before the normal the sequencer
    // loads with it, so the clock the head register adds is not waited
    // for: a simulation stops if a load finds the queue empty.
    csgrt_fifo_block #(.WIDTH(3 * B + 1), .DEPTH(CTX), .HEAD_REG(1)) u_q_p (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(qp_push), .ready_o(unused_qp_ready),
        .data_i({&p_inr_q, p_vec_q}), .valid_o(qp_valid), .ready_i(seq_load), .data_o(qp_data));
`ifndef SYNTHESIS
    always @(posedge clk_i)
        if (rst_ni && seq_load && !qp_valid) begin
            $display("ERROR %m: the sequencer loads a hit whose p is not yet at the head of u_q_p");
            $fatal;
        end
`else
    wire unused_qp_valid = qp_valid;
`endif
    wire [3*B-1:0] qp_p   = qp_data[0 +: 3*B];
    wire           qp_inr = qp_data[3*B];

    // ---- G: A_ij p_j, column j -------------------------------------------------------
    // The corner tile in a MULT18X18D too (LUT_TILE_MAX 0; at BITS 24 the
    // 6 x 6 corner, 3 blocks more): in the fabric it was a tree of rows from
    // the operand registers (43 loads each) into its tile register,
    // tools/logic_depth.py's sixth-longest path of 18b6b1d's 24-bit netlist
    // (11.45 ns), where a block is a register to a register. TILE_REG 1
    // would split it as well but costs a clock on the hit's way.
    wire [3*GPW-1:0] gp;
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_grad
            wire unused_v;
            csgrt_mul #(.A_WIDTH(B), .B_WIDTH(B), .LUT_TILE_MAX(0)) u_mul (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(1'b1), .valid_i(p_valid_q),
                .a_i(p_cc_q[i*B +: B]), .b_i(p_val_q), .valid_o(unused_v), .p_o(gp[i*GPW +: GPW]));
        end
    endgenerate
    // The products are registered once more before the accumulation: the
    // multiplier's tiles are summed in the fabric after their output
    // registers (csgrt_mul), and that sum went on through the accumulation's
    // adder into acc_q, csgrt_spawn's longest path out of context (a
    // MULT18X18D's output -> two carry chains). The side data waits a clock
    // more with it; the pipeline never stalls (ce 1), so every product
    // meets its column a clock later and the sums are the same.
    reg  [3*GPW-1:0] gp_q;
    always @(posedge clk_i) gp_q <= gp;
    wire           g_valid;
    wire [B+1:0]   g_side;
    csgrt_delay #(.WIDTH(B + 2), .STAGES(3)) u_dly_g (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(1'b1), .valid_i(p_valid_q),
        .data_i({p_cc_q[3*B +: B], p_col_q}), .valid_o(g_valid), .data_o(g_side));
    wire [1:0]   g_col = g_side[1:0];
    wire [B-1:0] g_pc  = g_side[2 +: B];   // P_j

    // ---- ACC: g_i = rnd(sum_j A_ij p_j + (P_i << F), FC) ------------------------------
    reg  [3*ACCW-1:0] acc_q;
    wire [3*ACCW-1:0] acc_d;
    reg               acc_done_q;
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_acc
            wire [GPW-1:0]  prod = gp_q[i*GPW +: GPW];
            wire [ACCW-1:0] base = (g_col == 2'd0) ? {{(ACCW-FC){1'b0}}, 1'b1, {(FC-1){1'b0}}}
                                                   : acc_q[i*ACCW +: ACCW];
            wire [ACCW-1:0] pc   = (g_col == i) ? {{(ACCW-B-F){g_pc[B-1]}}, g_pc, {F{1'b0}}}
                                                : {ACCW{1'b0}};
            assign acc_d[i*ACCW +: ACCW] = base + {{(ACCW-GPW){prod[GPW-1]}}, prod} + pc;
        end
    endgenerate
    always @(posedge clk_i) begin
        if (!rst_ni) acc_done_q <= 1'b0;
        else acc_done_q <= g_valid && (g_col == 2'd2);
        if (g_valid) acc_q <= acc_d;
    end
    wire [3*GW-1:0] g_vec;
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_gvec
            assign g_vec[i*GW +: GW] = acc_q[i*ACCW + FC +: GW];
            // below: the rounded-off bits; above: sign copies (|g| < 16)
            wire unused_acc = ^{acc_q[i*ACCW +: FC], acc_q[i*ACCW + FC + GW +: ACCW - FC - GW]};
        end
    endgenerate

    // ---- N: n = unit(g), one axis per clock (unit_fx(g, F, F+8)) -------------------------
    // csgrt_unit's pipeline with its squares and divisions spread over three
    // clocks (hits are at least three clocks apart): 1 multiplier, 1 divider.
    //   NS  (3+2+1)  g_j^2, summed
    //   NQ  (F+8)    root = isqrt(sum g^2)
    //   NP  (3)      L = root + 1 held, g_j << F from the queue
    //   ND  (F+2)    n_j = div(g_j << F, L, F+1)
    //   NO  (1)      n_j signed
    reg            gh_valid_q;
    reg [1:0]      gh_ph_q;
    reg [3*GW-1:0] gh_g_q;
    always @(posedge clk_i) begin
        if (!rst_ni) begin
            gh_valid_q <= 1'b0;
            gh_ph_q    <= 2'd0;
        end else if (acc_done_q) begin
            gh_valid_q <= 1'b1;
            gh_ph_q    <= 2'd0;
        end else if (gh_valid_q) begin
            gh_ph_q <= gh_ph_q + 2'd1;
            if (gh_ph_q == 2'd2) gh_valid_q <= 1'b0;
        end
        if (acc_done_q) gh_g_q <= g_vec;
    end
    reg [GW-1:0] gh_gj;
    always @* begin
        case (gh_ph_q)
            2'd0:    gh_gj = gh_g_q[0 +: GW];
            2'd1:    gh_gj = gh_g_q[GW +: GW];
            default: gh_gj = gh_g_q[2*GW +: GW];
        endcase
    end
    // g waits for L in a queue. Its head in a fabric register (HEAD_REG 1:
    // the block RAM's read port took 5.6 ns of the path into the divider's
    // first stage, docs/fpga.md); read at the square root's output, long
    // after the push, and popped at a fixed phase (a register)
    wire [3*GW-1:0] qg_g;
    wire            qg_pop;
    wire            qg_valid;
    wire            unused_qg_ready;
    csgrt_fifo_block #(.WIDTH(3 * GW), .DEPTH(CTX), .HEAD_REG(1)) u_q_g (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(acc_done_q), .ready_o(unused_qg_ready),
        .data_i(g_vec), .valid_o(qg_valid), .ready_i(qg_pop), .data_o(qg_g));

    // NS: the sum of squares (< 3 * 16^2 * 2^(2F) < 4^SQ)
    localparam GGW = 2 * GW;
    wire [GGW-1:0] ggp;
    wire           unused_gg_v;
    csgrt_mul #(.A_WIDTH(GW), .B_WIDTH(GW)) u_mul_gg (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(1'b1), .valid_i(gh_valid_q),
        .a_i(gh_gj), .b_i(gh_gj), .valid_o(unused_gg_v), .p_o(ggp));
    // the squares registered before their sum, as the gradient's products
    // (gp_q): the tiles' fabric sum and the sum's adder into gs_q were one
    // clock, csgrt_spawn's longest path out of context after gp_q
    reg  [GGW-1:0] ggp_q;
    always @(posedge clk_i) ggp_q <= ggp;
    wire       gg_valid;
    wire [1:0] gg_col;
    csgrt_delay #(.WIDTH(2), .STAGES(3)) u_dly_gg (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(1'b1), .valid_i(gh_valid_q),
        .data_i(gh_ph_q), .valid_o(gg_valid), .data_o(gg_col));
    reg [2*SQ-1:0] gs_q;
    reg            gs_done_q;
    always @(posedge clk_i) begin
        if (!rst_ni) gs_done_q <= 1'b0;
        else gs_done_q <= gg_valid && (gg_col == 2'd2);
        // a square is not negative: zero-extended
        if (gg_valid)
            gs_q <= ((gg_col == 2'd0) ? {(2*SQ){1'b0}} : gs_q) + {{(2*SQ-GGW){1'b0}}, ggp_q};
    end

    // NQ: root = isqrt(sum g^2)
    wire          nq_valid;
    wire [SQ-1:0] nq_root;
    wire          unused_nq_user;
    csgrt_sqrt_core #(.RESULT_BITS(SQ), .USER_WIDTH(1)) u_sqrt_n (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(1'b1), .run_i(1'b0), .phase_i(2'd0), .valid_i(gs_done_q),
        .n_i(gs_q), .user_i(1'b0), .valid_o(nq_valid), .root_o(nq_root), .user_o(unused_nq_user));

    // NP: L = root + 1 for three clocks; numerator g_j << F
    localparam NLW = SQ + 2;         // L <= 2^SQ, signed
    localparam NNW = GW + F;         // g << F
    reg           lh_valid_q;
    reg [1:0]     lh_ph_q;
    reg [NLW-1:0] lh_len_q;
    always @(posedge clk_i) begin
        if (!rst_ni) begin
            lh_valid_q <= 1'b0;
            lh_ph_q    <= 2'd0;
        end else if (nq_valid) begin
            lh_valid_q <= 1'b1;
            lh_ph_q    <= 2'd0;
        end else if (lh_valid_q) begin
            lh_ph_q <= lh_ph_q + 2'd1;
            if (lh_ph_q == 2'd2) lh_valid_q <= 1'b0;
        end
        if (nq_valid) lh_len_q <= {2'b00, nq_root} + {{(NLW-1){1'b0}}, 1'b1};
    end
    assign qg_pop = lh_valid_q && (lh_ph_q == 2'd2);
`ifndef SYNTHESIS
    // the queue is read at fixed times: a simulation stops if its head is not there
    always @(posedge clk_i)
        if (rst_ni && lh_valid_q && !qg_valid) begin
            $display("ERROR %m: g's queue read before its head is valid");
            $fatal;
        end
`else
    wire unused_qg_valid = qg_valid;
`endif
    reg [GW-1:0] lh_gj;
    always @* begin
        case (lh_ph_q)
            2'd0:    lh_gj = qg_g[0 +: GW];
            2'd1:    lh_gj = qg_g[GW +: GW];
            default: lh_gj = qg_g[2*GW +: GW];
        endcase
    end

    // ND: n_j = div(g_j << F, L, F+1), never overflows (|g_j| < L)
    wire          nd_dvalid, unused_nd_ovf;
    wire [F:0]    nd_mag;
    wire          nd_neg;
    wire [1:0]    nd_dph;
    csgrt_div_core #(.NUM_WIDTH(NNW), .DEN_WIDTH(NLW), .QUOT_BITS(F + 1), .USER_WIDTH(2)) u_div_n (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(1'b1), .run_i(1'b0), .phase_i(2'd0), .valid_i(lh_valid_q),
        .num_i({lh_gj, {F{1'b0}}}), .den_i(lh_len_q), .user_i(lh_ph_q),
        .valid_o(nd_dvalid), .quot_o(nd_mag), .neg_o(nd_neg), .ovf_o(unused_nd_ovf), .user_o(nd_dph));
    // |n_j| < 2^F: the top quotient bit is zero
    wire          unused_nd_top = nd_mag[F];

    // NO: n_j signed
    reg           no_valid_q;
    reg [1:0]     no_ph_q;
    reg [NW-1:0]  no_n_q;
    always @(posedge clk_i) begin
        if (!rst_ni) no_valid_q <= 1'b0;
        else no_valid_q <= nd_dvalid;
        no_ph_q <= nd_dph;
        no_n_q  <= nd_neg ? {NW{1'b0}} - {1'b0, nd_mag[F-1:0]} : {1'b0, nd_mag[F-1:0]};
    end

    // ---- FD: n . d, one axis per clock, as n_j comes out ------------------------------
    // the whole n, kept for the flip: n_0, n_1 collected, n_2 joins them
    reg [2*NW-1:0] nc_n_q;
    reg [3*NW-1:0] nh2_n_q;
    always @(posedge clk_i) begin
        if (no_valid_q && no_ph_q == 2'd0) nc_n_q[0 +: NW]  <= no_n_q;
        if (no_valid_q && no_ph_q == 2'd1) nc_n_q[NW +: NW] <= no_n_q;
        if (no_valid_q && no_ph_q == 2'd2) nh2_n_q <= {no_n_q, nc_n_q};
    end
    assign qnd_pop = no_valid_q && (no_ph_q == 2'd2);
    reg [B-1:0] no_dj;
    always @* begin
        case (no_ph_q)
            2'd0:    no_dj = qnd_d[0 +: B];
            2'd1:    no_dj = qnd_d[B +: B];
            default: no_dj = qnd_d[2*B +: B];
        endcase
    end
    wire [NDPW-1:0] ndp;
    wire            unused_fd_v;
    // TILE_REG: the tiles' values registered before their sum, as T's, so
    // that the sum and nd_acc_q's accumulation start from flip-flops beside
    // them and not at the MULT18X18D's output (88832ca's routed critical
    // path at BITS 24 with shadows and reflection, 77.01 MHz: 7.14 ns of
    // route from the block to the tiles' sum). One clock more.
    localparam ND_TILE_REG = 1;
    csgrt_mul #(.A_WIDTH(NW), .B_WIDTH(B), .TILE_REG(ND_TILE_REG)) u_mul_nd (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(1'b1), .valid_i(no_valid_q),
        .a_i(no_n_q), .b_i(no_dj), .valid_o(unused_fd_v), .p_o(ndp));
    wire       nd_valid;
    wire [1:0] nd_col;
    csgrt_delay #(.WIDTH(2), .STAGES(2 + ND_TILE_REG)) u_dly_nd (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(1'b1), .valid_i(no_valid_q),
        .data_i(no_ph_q), .valid_o(nd_valid), .data_o(nd_col));
    reg [NDSW-1:0] nd_acc_q;
    reg            nd_done_q;
    always @(posedge clk_i) begin
        if (!rst_ni) nd_done_q <= 1'b0;
        else nd_done_q <= nd_valid && (nd_col == 2'd2);
        if (nd_valid)
            nd_acc_q <= ((nd_col == 2'd0) ? {NDSW{1'b0}} : nd_acc_q) + {{(NDSW-NDPW){ndp[NDPW-1]}}, ndp};
    end

    // the whole n, a clock later with n . d (ND_TILE_REG): the next hit's
    // n_2 may replace nh2_n_q three clocks after this one's, the clock
    // NDA now takes it
    wire [3*NW-1:0] nda_n_in;
    wire            unused_nh_v;
    csgrt_delay #(.WIDTH(3 * NW), .STAGES(ND_TILE_REG)) u_dly_nh (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(1'b1), .valid_i(1'b0),
        .data_i(nh2_n_q), .valid_o(unused_nh_v), .data_o(nda_n_in));

    // ---- NDA: face the ray (exact sign of n . d) --------------------------------------------
    wire            flip = !nd_acc_q[NDSW-1] && (nd_acc_q != {NDSW{1'b0}});
    reg             nda_valid_q;
    reg [3*NW-1:0]  nda_n_q;
    always @(posedge clk_i) begin
        if (!rst_ni) nda_valid_q <= 1'b0;
        else nda_valid_q <= nd_done_q;
        for (k = 0; k < 3; k = k + 1)
            nda_n_q[k*NW +: NW] <= flip ? {NW{1'b0}} - nda_n_in[k*NW +: NW] : nda_n_in[k*NW +: NW];
    end

    // ---- NDB: dn = rnd(d . n, F) (REFLECTION or REFRACTION) ----------------------------------
    reg             ndb_valid_q;
    reg [3*NW-1:0]  ndb_n_q;
    always @(posedge clk_i) begin
        if (!rst_ni) ndb_valid_q <= 1'b0;
        else ndb_valid_q <= nda_valid_q;
        ndb_n_q <= nda_n_q;
    end
    wire [DNW-1:0]  dn_d;       // into NDB: rnd(d . n, F) after the flip
    wire [3*NW-1:0] qn_n;       // the faced normal and dn wait for the sequencer
    wire [DNW-1:0]  qn_dn;
    wire            qn_valid;
    generate
        if (RDN) begin : g_dn
            reg [NDSW-1:0]  nda_ndf_q;   // d . n after the flip
            always @(posedge clk_i) nda_ndf_q <= flip ? {NDSW{1'b0}} - nd_acc_q : nd_acc_q;
            wire [NDSW-1:0] ndf_r = nda_ndf_q + {{(NDSW-F){1'b0}}, 1'b1, {(F-1){1'b0}}};
            assign dn_d = ndf_r[F +: DNW];   // |d . n| < 1: |dn| <= 2^F
            wire unused_ndf_r = ^{ndf_r[F-1:0], ndf_r[NDSW-1:F+DNW]};
            reg  [DNW-1:0]  ndb_dn_q;
            always @(posedge clk_i) ndb_dn_q <= dn_d;
            wire [3*NW+DNW-1:0] qn_data;
            wire                unused_qn_ready;
            csgrt_fifo_block #(.WIDTH(3 * NW + DNW), .DEPTH(CTX)) u_q_n (
                .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(ndb_valid_q), .ready_o(unused_qn_ready),
                .data_i({ndb_dn_q, ndb_n_q}), .valid_o(qn_valid), .ready_i(seq_load), .data_o(qn_data));
            assign qn_n  = qn_data[0 +: 3*NW];
            assign qn_dn = qn_data[3*NW +: DNW];
        end else begin : g_no_dn
            // shadows only: the normal alone
            assign dn_d = {DNW{1'b0}};
            wire unused_dn = ^dn_d;
            wire unused_qn_ready;
            csgrt_fifo_block #(.WIDTH(3 * NW), .DEPTH(CTX)) u_q_n (
                .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(ndb_valid_q), .ready_o(unused_qn_ready),
                .data_i(ndb_n_q), .valid_o(qn_valid), .ready_i(seq_load), .data_o(qn_n));
            assign qn_dn = {DNW{1'b0}};
        end
    endgenerate

    // ---- refraction (REFRACTION): eta, eta2, S1..S6 ------------------------------------------
    // Without it none of this exists: eta, a and TIR are 0 and the
    // sequencer waits for the normal's queue instead of the last one here.
    wire           front_valid;   // the front's last queue holds the next hit
    wire [EMW-1:0] qeta_eta;
    wire [AW-1:0]  qf_a;
    wire           qf_tir;
    generate
        if (RF) begin : g_refr
            // ---- eta = div(ior_from << F, ior_to, F+7), eta2 = rnd(eta^2, F) ------------------
            wire           eta_valid, eta_ovf;
            wire [EMW-1:0] eta_mag;
            wire           unused_eta_neg, unused_eta_user;
            csgrt_div_core #(.NUM_WIDTH(17 + F), .DEN_WIDTH(17), .QUOT_BITS(EMW), .USER_WIDTH(1)) u_div_eta (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(1'b1), .run_i(1'b0), .phase_i(2'd0), .valid_i(accept),
                .num_i({1'b0, s_ior_from_i, {F{1'b0}}}), .den_i({1'b0, s_ior_to_i}), .user_i(1'b0),
                .valid_o(eta_valid), .quot_o(eta_mag), .neg_o(unused_eta_neg), .ovf_o(eta_ovf),
                .user_o(unused_eta_user));
            // the model leaves eta at 0 when the quotient overflows (ior_to = 0)
            wire [EMW-1:0] eta = eta_ovf ? {EMW{1'b0}} : eta_mag;
            wire [2*ETW-1:0] e2p;
            wire             unused_e2_v;
            csgrt_mul #(.A_WIDTH(ETW), .B_WIDTH(ETW)) u_mul_e2 (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(1'b1), .valid_i(eta_valid),
                .a_i({1'b0, eta}), .b_i({1'b0, eta}), .valid_o(unused_e2_v), .p_o(e2p));
            wire           e2_valid;
            wire [EMW-1:0] e2_eta;
            csgrt_delay #(.WIDTH(EMW), .STAGES(2)) u_dly_e2 (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(1'b1), .valid_i(eta_valid),
                .data_i(eta), .valid_o(e2_valid), .data_o(e2_eta));
            wire [2*ETW-1:0] e2r  = e2p + {{(2*ETW-F){1'b0}}, 1'b1, {(F-1){1'b0}}};
            wire [E2W-1:0]   eta2 = e2r[F +: E2W];
            wire unused_e2r       = ^{e2r[F-1:0], e2r[2*ETW-1:F+E2W]};
            // {eta2, eta} for S1; eta for the sequencer
            wire [E2W+EMW-1:0] qe_data;
            wire               unused_qe_ready, unused_qe_valid;
            csgrt_fifo #(.WIDTH(E2W + EMW), .DEPTH(CTX)) u_q_e (
                .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(e2_valid), .ready_o(unused_qe_ready),
                .data_i({eta2, e2_eta}), .valid_o(unused_qe_valid), .ready_i(ndb_valid_q), .data_o(qe_data));
            wire [EMW-1:0] qe_eta  = qe_data[0 +: EMW];
            wire [E2W-1:0] qe_eta2 = qe_data[EMW +: E2W];
            wire           unused_qeta_ready, unused_qeta_valid;
            csgrt_fifo #(.WIDTH(EMW), .DEPTH(CTX)) u_q_eta (
                .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(e2_valid), .ready_o(unused_qeta_ready),
                .data_i(e2_eta), .valid_o(unused_qeta_valid), .ready_i(seq_load), .data_o(qeta_eta));

            // ---- NDB': cos = -dn -------------------------------------------------------------
            reg [DNW-1:0] ndb_cos_q;
            always @(posedge clk_i) ndb_cos_q <= {DNW{1'b0}} - dn_d;

            // ---- S1: cos^2, eta cos ------------------------------------------------------------
            localparam C2PW = 2 * DNW;
            localparam ECPW = ETW + DNW;
            wire [C2PW-1:0] c2p;
            wire [ECPW-1:0] ecp;
            wire            unused_c2_v, unused_ec_v;
            csgrt_mul #(.A_WIDTH(DNW), .B_WIDTH(DNW)) u_mul_c2 (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(1'b1), .valid_i(ndb_valid_q),
                .a_i(ndb_cos_q), .b_i(ndb_cos_q), .valid_o(unused_c2_v), .p_o(c2p));
            csgrt_mul #(.A_WIDTH(ETW), .B_WIDTH(DNW)) u_mul_ec (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(1'b1), .valid_i(ndb_valid_q),
                .a_i({1'b0, qe_eta}), .b_i(ndb_cos_q), .valid_o(unused_ec_v), .p_o(ecp));
            wire           s1_valid;
            wire [E2W-1:0] s1_eta2;
            csgrt_delay #(.WIDTH(E2W), .STAGES(2)) u_dly_s1 (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(1'b1), .valid_i(ndb_valid_q),
                .data_i(qe_eta2), .valid_o(s1_valid), .data_o(s1_eta2));

            // ---- S2: sin2 = 1 - rnd(cos^2, F); rnd(eta cos, F) -------------------------------
            wire [C2PW-1:0] c2r  = c2p + {{(C2PW-F){1'b0}}, 1'b1, {(F-1){1'b0}}};
            wire [DNW-1:0]  sin2 = {{(DNW-F-1){1'b0}}, 1'b1, {F{1'b0}}} - c2r[F +: DNW];   // in [0, 2^F]
            wire [ECPW-1:0] ecr  = ecp + {{(ECPW-F){1'b0}}, 1'b1, {(F-1){1'b0}}};
            wire [AW-1:0]   ec   = ecr[F +: AW];
            wire unused_s2       = ^{c2r[F-1:0], c2r[C2PW-1:F+DNW], ecr[F-1:0], ecr[ECPW-1:F+AW]};
            reg             s2_valid_q;
            reg [DNW-1:0]   s2_sin2_q;
            reg [E2W-1:0]   s2_eta2_q;
            always @(posedge clk_i) begin
                if (!rst_ni) s2_valid_q <= 1'b0;
                else s2_valid_q <= s1_valid;
                s2_sin2_q <= sin2;
                s2_eta2_q <= s1_eta2;
            end
            // rnd(eta cos, F) waits for sk
            wire [AW-1:0] qec_ec;
            wire          qec_pop;
            wire          unused_qec_ready, unused_qec_valid;
            csgrt_fifo #(.WIDTH(AW), .DEPTH(CTX)) u_q_ec (
                .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(s1_valid), .ready_o(unused_qec_ready),
                .data_i(ec), .valid_o(unused_qec_valid), .ready_i(qec_pop), .data_o(qec_ec));

            // ---- S3: rnd(eta^2, F) sin2 -------------------------------------------------------
            localparam KPW = E2W + DNW;
            wire [KPW-1:0] kp;
            wire           unused_k_v;
            csgrt_mul #(.A_WIDTH(E2W), .B_WIDTH(DNW)) u_mul_k (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(1'b1), .valid_i(s2_valid_q),
                .a_i(s2_eta2_q), .b_i(s2_sin2_q), .valid_o(unused_k_v), .p_o(kp));
            wire s3_valid;
            wire unused_s3_data;
            csgrt_delay #(.WIDTH(1), .STAGES(2)) u_dly_s3 (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(1'b1), .valid_i(s2_valid_q),
                .data_i(1'b0), .valid_o(s3_valid), .data_o(unused_s3_data));

            // ---- S4: k = 1 - rnd(., F); TIR when k < 0; the radicand k << F --------------------
            wire [KPW-1:0] kr  = kp + {{(KPW-F){1'b0}}, 1'b1, {(F-1){1'b0}}};
            wire [KW-1:0]  kk  = {{(KW-F-1){1'b0}}, 1'b1, {F{1'b0}}} - kr[F +: KW];
            wire unused_kr     = ^{kr[F-1:0], kr[KPW-1:F+KW]};
            wire           tir = kk[KW-1];
            reg            s4_valid_q, s4_tir_q;
            reg [2*SKB-1:0] s4_rad_q;
            always @(posedge clk_i) begin
                if (!rst_ni) s4_valid_q <= 1'b0;
                else s4_valid_q <= s3_valid;
                s4_tir_q <= tir;
                // k >= 0 means k <= 2^F: k << F < 4^(F+1)
                s4_rad_q <= tir ? {(2*SKB){1'b0}} : {1'b0, kk[F:0], {F{1'b0}}};
            end
            wire unused_kk = ^kk[KW-2:F+1];

            // ---- S5: sk = isqrt(k << F) -----------------------------------------------------------
            wire           s5_valid, s5_tir;
            wire [SKB-1:0] s5_sk;
            csgrt_sqrt_core #(.RESULT_BITS(SKB), .USER_WIDTH(1)) u_sqrt_k (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(1'b1), .run_i(1'b0), .phase_i(2'd0), .valid_i(s4_valid_q),
                .n_i(s4_rad_q), .user_i(s4_tir_q), .valid_o(s5_valid), .root_o(s5_sk), .user_o(s5_tir));

            // ---- S6: a = rnd(eta cos, F) - sk ------------------------------------------------------
            assign qec_pop = s5_valid;
            wire [AW-1:0]  a_d = qec_ec - {{(AW-SKB){1'b0}}, s5_sk};
            wire [AW:0]    qf_data;
            wire           unused_qf_ready;
            csgrt_fifo #(.WIDTH(AW + 1), .DEPTH(CTX)) u_q_fin (
                .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(s5_valid), .ready_o(unused_qf_ready),
                .data_i({s5_tir, a_d}), .valid_o(front_valid), .ready_i(seq_load), .data_o(qf_data));
            assign qf_a   = qf_data[0 +: AW];
            assign qf_tir = qf_data[AW];
            wire unused_qn_valid = qn_valid;
        end else begin : g_no_refr
            assign front_valid = qn_valid;
            assign qeta_eta    = {EMW{1'b0}};
            assign qf_a        = {AW{1'b0}};
            assign qf_tir      = 1'b0;
            wire unused_ior = ^{s_ior_from_i, s_ior_to_i};
        end
    endgenerate

    // =========================================================================
    // Children
    // =========================================================================
    wire en_c;   // the child pipeline runs: the output skid buffer's ready
    // its registers move on the beat's advance (every running clock for
    // II = 1, every third for II = 3); the shared multipliers run on every
    // running clock; a child is issued and leaves only at an advance
    wire [1:0] ph_c;
    wire       adv_c;
    wire       last_c;
    wire       en_c_next, adv_c_q;
    csgrt_beat #(.II(II)) u_beat_c (.clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en_c), .ce_next_i(en_c_next),
                                    .phase_o(ph_c), .last_o(last_c), .adv_o(adv_c), .adv_q_o(adv_c_q));
    // The sequencing and the queues' handshakes (issue, seq_load, the pops)
    // read adv_c_q, the advance's own register; adv_c itself enables the
    // stages' few thousand flip-flops (csgrt_beat)

    // ---- SEQ: the current hit and its pending children ------------------------------
    reg             cur_valid_q;
    reg [FLW-1:0]   cur_pend_q;
    reg [3*B-1:0]   cur_d_q, cur_p_q;
    reg [3*NW-1:0]  cur_n_q;
    reg [DNW-1:0]   cur_dn_q;
    reg [EMW-1:0]   cur_eta_q;
    reg [AW-1:0]    cur_a_q;
    reg             cur_tir_q;

    wire [FLW-1:0]  pend  = cur_pend_q & FLAG_MASK;   // the kinds this build has
    wire            issue = adv_c_q && cur_valid_q;
    // the lowest pending kind, the child issued next: a register of its own
    // (pick_q), loaded with the lowest flag of cur_pend_q's next value (at
    // a load, qh_pick from the queue). Computed from cur_pend_q here, its
    // carry chain went on through the light's choice and lv's subtraction
    // into the child's registers: csgrt_spawn's longest path out of
    // context once the queue's tests were off it. A simulation stops if
    // the two differ.
    reg  [FLW-1:0]  pick_q;
    wire [FLW-1:0]  pick  = pick_q;
    wire [FLW-1:0]  rest  = pend & ~pick;
    // last = (rest == 0): at most one child pending. It is a register of its
    // own (cur_last_q), loaded with the test of cur_pend_q's next value:
    // between the pending set and the queues' pops (free -> seq_load, read
    // by some 250 loads) the test's carry chain and zero test were 8 LUT
    // levels (tools/logic_depth.py). A simulation stops if the two differ.
    reg             cur_last_q;
    wire            last  = cur_last_q;
    wire            free  = !cur_valid_q || (issue && last);
    wire            qo_ready;
    assign seq_load = free && front_valid && qo_ready;
    wire            qo_push = seq_load && qh_any;

    reg [2:0]      kind;
    reg [LW-1:0]   light;
    reg [3*B-1:0]  lpos;
    always @* begin
        if (pick[0])                 kind = KIND_CONTINUE;
        else if (RF && pick[ML+1])   kind = cur_tir_q ? KIND_TIR_REFLECT : KIND_REFRACT;
        else if (RL && pick[ML+2])   kind = KIND_REFLECT;
        else                         kind = KIND_SHADOW;
        light = {LW{1'b0}};
        lpos  = {(3*B){1'b0}};
        for (kl = 0; kl < ML; kl = kl + 1)
            if (pick[1+kl]) begin
                light = light | kl[LW-1:0];
                lpos  = lpos | light_pos_i[kl*3*B +: 3*B];
            end
    end
    // lv = light_k - p (SHADOWS)
    wire [3*LVW-1:0] lv;
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_lv
            if (SH) begin : g_sh
                wire [B-1:0] lp = lpos[i*B +: B];
                wire [B-1:0] pp = cur_p_q[i*B +: B];
                assign lv[i*LVW +: LVW] = {lp[B-1], lp} - {pp[B-1], pp};
            end else begin : g_no_sh
                assign lv[i*LVW +: LVW] = {LVW{1'b0}};
            end
        end
        if (!SH) begin : g_no_lights
            wire unused_lights = ^{lpos, light_pos_i, cur_p_q};
        end
    endgenerate

    function automatic [FLW-1:0] lowest(input [FLW-1:0] flags);   // the lowest flag of the kinds this build has
        reg [FLW-1:0] f;
        begin
            f = flags & FLAG_MASK;
            lowest = f & (~f + {{(FLW-1){1'b0}}, 1'b1});
        end
    endfunction
    function automatic at_most_one(input [FLW-1:0] flags);   // of the kinds this build has
        reg [FLW-1:0] f;
        begin
            f = flags & FLAG_MASK;
            at_most_one = (f & (f - {{(FLW-1){1'b0}}, 1'b1})) == {FLW{1'b0}};
        end
    endfunction
    // the pending set's next value without a load (a load takes the queue's tests)
    wire [FLW-1:0] pend_stay = issue ? rest : pend;
    always @(posedge clk_i) cur_last_q <= seq_load ? qh_one : at_most_one(pend_stay);
    always @(posedge clk_i) pick_q <= seq_load ? qh_pick : lowest(pend_stay);
    csgrt_check_same #(.WIDTH(FLW), .WHAT("pick_q")) u_check_pick (
        .clk_i(clk_i), .rst_ni(rst_ni), .copy_i(cur_valid_q ? pick_q : {FLW{1'b0}}),
        .orig_i(cur_valid_q ? lowest(pend) : {FLW{1'b0}}));
    csgrt_check_same #(.WHAT("cur_last_q")) u_check_last (
        .clk_i(clk_i), .rst_ni(rst_ni), .copy_i(cur_valid_q && cur_last_q),
        .orig_i(cur_valid_q && (rest == {FLW{1'b0}})));

    always @(posedge clk_i) begin
        if (!rst_ni) cur_valid_q <= 1'b0;
        else if (seq_load) cur_valid_q <= qh_any;
        else if (issue && last) cur_valid_q <= 1'b0;
        if (seq_load) begin
            cur_pend_q <= qh_flags;
            cur_d_q    <= qh_d;
            cur_p_q    <= qp_p;
            cur_n_q    <= qn_n;
            cur_dn_q   <= qn_dn;
            cur_eta_q  <= qeta_eta;
            cur_a_q    <= qf_a;
            cur_tir_q  <= qf_tir;
        end else if (issue) begin
            cur_pend_q <= rest;
        end
    end

    // ---- C0: one child --------------------------------------------------------------------
    reg             c0_valid_q, c0_last_q;
    reg [2:0]       c0_kind_q;
    reg [LW-1:0]    c0_light_q;
    reg [3*LVW-1:0] c0_lv_q;
    reg [3*B-1:0]   c0_d_q;
    reg [3*NW-1:0]  c0_n_q;
    reg [DNW-1:0]   c0_dn_q;
    reg [EMW-1:0]   c0_eta_q;
    reg [AW-1:0]    c0_a_q;
    always @(posedge clk_i) begin
        if (!rst_ni) c0_valid_q <= 1'b0;
        else if (adv_c) c0_valid_q <= cur_valid_q;
        if (adv_c) begin
            c0_last_q  <= last;
            c0_kind_q  <= kind;
            c0_light_q <= light;
            c0_lv_q    <= lv;
            c0_d_q     <= cur_d_q;
            c0_n_q     <= cur_n_q;
            c0_dn_q    <= cur_dn_q;
            c0_eta_q   <= cur_eta_q;
            c0_a_q     <= cur_a_q;
        end
    end

    // ---- X/Y: the child's products ----------------------------------------------------------
    // X: SHADOW n_i lv_i; REFLECT, TIR_REFLECT dn n_i; REFRACT eta d_i.
    // Y (REFRACTION): a n_i.
    wire [3*XPW-1:0] xp;
    wire [3*YPW-1:0] yp;
    wire [3*LVW-1:0] base;   // SHADOW: lv; else d
    wire [XAW-1:0]   xa_eta; // REFRACT's X factor
    wire [3*XAW-1:0] xa_v;   // X's operands, axis i at i*XAW
    wire [3*XBW-1:0] xb_v;
    localparam X_TILE_REG = (II == 3) ? 1 : 0;
    localparam X_OP_REG   = (II == 3) ? 1 : 0;
    localparam X_BEATS    = (II == 3 && X_OP_REG != 0 && X_TILE_REG != 0) ? 3 : 2;   // csgrt_mul_vec's latency
    generate
        if (RF) begin : g_xa_eta
            assign xa_eta = {1'b0, c0_eta_q};
        end else begin : g_no_xa_eta
            assign xa_eta = {XAW{1'b0}};
            wire unused_eta_a = ^{c0_eta_q, c0_a_q};
        end
        for (i = 0; i < 3; i = i + 1) begin : g_xy
            wire [NW-1:0]  n    = c0_n_q[i*NW +: NW];
            wire [B-1:0]   d    = c0_d_q[i*B +: B];
            wire [LVW-1:0] l    = c0_lv_q[i*LVW +: LVW];
            // sign-extended (XAW >= DNW = NW + 1, XBW = B + 1 > NW)
            wire [XAW-1:0] n_a  = {{(XAW-NW){n[NW-1]}}, n};
            wire [XAW-1:0] dn_a = {{(XAW-DNW+1){c0_dn_q[DNW-1]}}, c0_dn_q[DNW-2:0]};
            wire [XBW-1:0] n_b  = {{(XBW-NW){n[NW-1]}}, n};
            wire [XBW-1:0] d_b  = {d[B-1], d};
            reg  [XAW-1:0] xa;
            reg  [XBW-1:0] xb;
            always @* begin
                if (SH && c0_kind_q == KIND_SHADOW) begin
                    xa = n_a;
                    xb = l;
                end else if (RF && c0_kind_q == KIND_REFRACT) begin
                    xa = xa_eta;
                    xb = d_b;
                end else begin   // REFLECT, TIR_REFLECT (CONTINUE: unused)
                    xa = dn_a;
                    xb = n_b;
                end
            end
            assign xa_v[i*XAW +: XAW] = xa;
            assign xb_v[i*XBW +: XBW] = xb;
            // SHADOW: lv; REFLECT, TIR_REFLECT: d (only lv without them; only d without shadows)
            assign base[i*LVW +: LVW] = (SH && (!RDN || c0_kind_q == KIND_SHADOW)) ? l : d_b;
        end
        // Time-shared (II 3), the tiles are registered before their sum
        // (TILE_REG) at no cost in latency (csgrt_mul_vec: the same two
        // beats): the routed critical path of aaa564b's 24-bit build was
        // this multiplier's MULT18X18D output -> 6.43 ns of route across
        // the die -> the tiles' sum in csgrt_beat_gather (81.33 MHz).
        // With II 1 the register would cost a clock: not set.
        // X_OP_REG (II 3): the phase's pair also registered before the
        // block (csgrt_mul_vec OP_REG): 911d777's routed critical path was
        // this choice (and the kind's before it) -> 5.84 ns of route into
        // the block's input register (80.78 MHz). With the tile registers
        // that makes X and Y three beats (X_BEATS), one beat more for
        // every child.
        csgrt_mul_vec #(.A_WIDTH(XAW), .B_WIDTH(XBW), .N(3), .II(II), .TILE_REG(X_TILE_REG),
                        .OP_REG(X_OP_REG)) u_mul_x (
            .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en_c), .adv_i(adv_c), .phase_i(ph_c), .a_i(xa_v), .b_i(xb_v), .p_o(xp));
        if (RF) begin : g_y
            csgrt_mul_vec #(.A_WIDTH(YAW), .B_WIDTH(YBW), .N(3), .II(II), .TILE_REG(X_TILE_REG),
                            .OP_REG(X_OP_REG)) u_mul_y (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en_c), .adv_i(adv_c), .phase_i(ph_c), .a_i({3{c0_a_q}}), .b_i(c0_n_q),
                .p_o(yp));
        end else begin : g_no_y
            assign yp = {(3*YPW){1'b0}};
        end
    endgenerate
    localparam XSDW = 3 * LVW + 3 + LW + 1;
    wire            x_valid;
    wire [XSDW-1:0] x_side;
    csgrt_delay #(.WIDTH(XSDW), .STAGES(X_BEATS)) u_dly_x (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv_c), .valid_i(c0_valid_q),
        .data_i({c0_last_q, c0_light_q, c0_kind_q, base}), .valid_o(x_valid), .data_o(x_side));
    wire [3*LVW-1:0] x_base  = x_side[0 +: 3*LVW];
    wire [2:0]       x_kind  = x_side[3*LVW +: 3];
    wire [LW-1:0]    x_light = x_side[3*LVW+3 +: LW];
    wire             x_last  = x_side[3*LVW+3+LW];

    // ---- C3: lit, r, t: the unit's input ----------------------------------------------------
    wire             lit;    // n . lv > 0 (SHADOWS)
    generate
        if (SH) begin : g_lit
            wire [XSW-1:0] xs = {{2{xp[XPW-1]}}, xp[0 +: XPW]} + {{2{xp[2*XPW-1]}}, xp[XPW +: XPW]}
                              + {{2{xp[3*XPW-1]}}, xp[2*XPW +: XPW]};
            assign lit = !xs[XSW-1] && (xs != {XSW{1'b0}});
        end else begin : g_no_lit
            assign lit = 1'b0;
        end
    endgenerate
    wire [3*VW2-1:0] v_d;
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_c3
            wire [XPW-1:0] x  = xp[i*XPW +: XPW];
            wire [YPW-1:0] y  = yp[i*YPW +: YPW];
            wire [LVW-1:0] bs = x_base[i*LVW +: LVW];
            // reflect: d - rnd(2 dn n_i, F) = d - rnd(dn n_i, F-1) (REFLECTION or REFRACTION)
            wire [LVW-1:0] refl;
            if (RDN) begin : g_refl
                wire [XPW-1:0] x1r = x + {{(XPW-F+1){1'b0}}, 1'b1, {(F-2){1'b0}}};
                assign refl = bs - x1r[F-1 +: LVW];
                wire unused_refl = ^{x1r[F-2:0], x1r[XPW-1:F-1+LVW]};
            end else begin : g_no_refl
                assign refl = {LVW{1'b0}};
                wire unused_x = ^x;   // shadows only: the sum of X is the lit test
            end
            // refract: rnd(eta d_i, F) + rnd(a n_i, F) (REFRACTION)
            wire [VW2-1:0] refr;
            if (RF) begin : g_refr_t
                wire [XPW-1:0] xr = x + {{(XPW-F){1'b0}}, 1'b1, {(F-1){1'b0}}};
                wire [YPW-1:0] yr = y + {{(YPW-F){1'b0}}, 1'b1, {(F-1){1'b0}}};
                wire [TSW-1:0] t  = xr[F +: TSW] + yr[F +: TSW];
                assign refr = t[VW2-1:0];   // |t_i| < 128 (unit_fx's bound)
                wire unused_refr = ^{xr[F-1:0], xr[XPW-1:F+TSW], yr[F-1:0], t[TSW-1]};
            end else begin : g_no_refr_t
                assign refr = {VW2{1'b0}};
                wire unused_y = ^y;
            end
            // sign-extended (VW2 >= LVW)
            wire [VW2-1:0] bs_v   = {{(VW2-LVW+1){bs[LVW-1]}}, bs[LVW-2:0]};
            wire [VW2-1:0] refl_v = {{(VW2-LVW+1){refl[LVW-1]}}, refl[LVW-2:0]};
            reg [VW2-1:0] v;
            always @* begin
                case (x_kind)
                    KIND_SHADOW:      v = bs_v;
                    KIND_REFRACT:     v = refr;
                    KIND_CONTINUE:    v = {VW2{1'b0}};
                    default:          v = refl_v;
                endcase
            end
            assign v_d[i*VW2 +: VW2] = v;
        end
    endgenerate
    reg             c3_valid_q, c3_last_q, c3_lit_q;
    reg [2:0]       c3_kind_q;
    reg [LW-1:0]    c3_light_q;
    reg [3*VW2-1:0] c3_v_q;
    always @(posedge clk_i) begin
        if (!rst_ni) c3_valid_q <= 1'b0;
        else if (adv_c) c3_valid_q <= x_valid;
        if (adv_c) begin
            c3_v_q     <= v_d;
            c3_kind_q  <= x_kind;
            c3_light_q <= x_light;
            c3_last_q  <= x_last;
            c3_lit_q   <= (x_kind == KIND_SHADOW) && lit;
        end
    end

    // ---- U2: unit(v) ----------------------------------------------------------------------
    localparam U2UW = 3 + LW + 2;
    wire             u2_valid;
    wire [3*UOW-1:0] u2_u;
    wire [SQ-1:0]    u2_root;
    wire [U2UW-1:0]  u2_user;
    csgrt_unit #(.VW(VW2), .FRAC(F), .SQRT_STAGES(SQ), .USER_WIDTH(U2UW), .II(II)) u_unit_c (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en_c), .adv_i(adv_c), .phase_i(ph_c), .valid_i(c3_valid_q),
        .v_i(c3_v_q), .user_i({c3_lit_q, c3_last_q, c3_light_q, c3_kind_q}),
        .valid_o(u2_valid), .u_o(u2_u), .root_o(u2_root), .user_o(u2_user));
    wire [2:0]    o_kind  = u2_user[0 +: 3];
    wire [LW-1:0] o_light = u2_user[3 +: LW];
    wire          o_last  = u2_user[3+LW];
    wire          o_lit   = u2_user[4+LW];

    // ---- the hit's p, d, in_range, user for its children ---------------------------------
    localparam QOW = 6 * B + 1 + UW;
    wire [QOW-1:0] qo_data;
    wire           qo_pop = adv_c_q && u2_valid && o_last;
    wire           unused_qo_valid;
    csgrt_fifo_block #(.WIDTH(QOW), .DEPTH(CTX)) u_q_out (
        .clk_i(clk_i), .rst_ni(rst_ni), .valid_i(qo_push), .ready_o(qo_ready),
        .data_i({qh_user, qp_inr, qh_d, qp_p}), .valid_o(unused_qo_valid), .ready_i(qo_pop), .data_o(qo_data));
    wire [3*B-1:0] qo_p   = qo_data[0 +: 3*B];
    wire [3*B-1:0] qo_d   = qo_data[3*B +: 3*B];
    wire           qo_inr = qo_data[6*B];
    wire [UW-1:0]  qo_user = qo_data[6*B+1 +: UW];

    // ---- output ---------------------------------------------------------------------------
    wire [3*B-1:0] o_dir;
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_dir
            wire [UOW-1:0] u = u2_u[i*UOW +: UOW];
            assign o_dir[i*B +: B] = (o_kind == KIND_CONTINUE) ? qo_d[i*B +: B] : {u[UOW-1], u};
        end
    endgenerate
    // the distance < 14: F+4 bits
    wire [B:0] o_dist = (o_kind == KIND_SHADOW) ? u2_root[B:0] : {(B+1){1'b0}};
    wire unused_root  = ^u2_root[SQ-1:B+1];

    localparam OUTW = 1 + 3 + LW + 3 * B + 1 + 3 * B + (B + 1) + 1 + UW;
    csgrt_skid #(.WIDTH(OUTW)) u_skid (
        .clk_i(clk_i), .rst_ni(rst_ni),
        .valid_i(u2_valid && last_c), .ready_o(en_c), .ready_next_o(en_c_next),
        .data_i({qo_user, o_lit, o_dist, o_dir, qo_inr, qo_p, o_light, o_kind, o_last}),
        .valid_o(m_valid_o), .ready_i(m_ready_i),
        .data_o({m_user_o, m_lit_o, m_dist_o, m_d_o, m_in_range_o, m_o_o, m_light_o, m_kind_o, m_last_o}));
    // The output's valid bit again (m_valid_copy_o), loaded with the skid's
    // next value (its skid register is full exactly while en_c is low): the
    // ray tree decides its event from it, while m_valid_o selects its ~1,000
    // record bits (285 loads, the first net of the whole design's longest
    // path: tools/logic_depth.py 12.85 ns).
    // And a second copy (m_valid_rec_o) for the ray tree's pushed record,
    // whose first choice (a shadow ray from this port or not) took
    // m_valid_o's 408 loads into the ray FIFO's data (tools/logic_depth.py
    // 10.96 ns, 63 endpoints, on aaa564b's netlist). (* keep *) on the
    // always blocks: the two copies have the same input, and with the keep
    // on the regs alone yosys merged them into one flip-flop with both
    // loads (365, the first net of a 13.20 ns path on 997a303's netlist).
    wire valid_next = rst_ni && ((m_ready_i || !m_valid_o) ? (!en_c || (u2_valid && last_c)) : m_valid_o);
    reg  valid_copy_q, valid_rec_q;
    (* keep *) always @(posedge clk_i) valid_copy_q <= valid_next;
    (* keep *) always @(posedge clk_i) valid_rec_q  <= valid_next;
    assign m_valid_copy_o = valid_copy_q;
    assign m_valid_rec_o  = valid_rec_q;
    csgrt_check_same #(.WIDTH(2), .WHAT("m_valid_copy_o / m_valid_rec_o")) u_check_valid_copy (
        .clk_i(clk_i), .rst_ni(rst_ni), .copy_i({valid_copy_q, valid_rec_q}), .orig_i({2{m_valid_o}}));

    generate
        if (BITS < 12 || BITS > 32 || MAX_LIGHTS < 1 || USER_WIDTH < 1) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_spawn needs 12 <= BITS <= 32, MAX_LIGHTS >= 1, USER_WIDTH >= 1");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
