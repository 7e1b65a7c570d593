`default_nettype none
// csgrt_unit — unit vector, bit for bit unit_fx(v, FRAC, SQRT_STAGES) of
// model/render.cpp (docs/numerics.md sections 2 and 6):
//   L   = isqrt(sum v_i^2, SQRT_STAGES) + 1        (isqrt_bitwise, model/fixed.h)
//   u_i = div(v_i << FRAC, L, FRAC + 1)            (sdiv_trunc: truncated toward zero)
// |u_i| < 2^FRAC because L > |v|, so the division never overflows. root_o is
// the square root itself, isqrt(sum v^2) = L - 1 (shadow_ray_fx's distance).
// The caller guarantees sum v^2 < 4^SQRT_STAGES (the model throws otherwise).
// v_i may carry any number of fraction bits: u has FRAC fraction bits.
//
// Pipeline (every register on ce_i, a valid bit alongside):
//   M (2)            v_i^2, three csgrt_mul VW x VW
//   S (1)            sum of squares (exact, then the low 2 SQRT_STAGES bits)
//   Q (SQRT_STAGES)  csgrt_sqrt_core
//   P (1)            L = root + 1, numerators v_i << FRAC
//   D (FRAC+2)       three csgrt_div_core, FRAC+1 quotient bits (root rides along)
//   O (1)            signed quotients
// Latency: SQRT_STAGES + FRAC + 7 clocks, counted in enabled clocks
// (unit_fx(., 15, 17): 39; unit_fx(., F, F+8) of the geometry: 2F+15).
// Throughput: one vector per clock. Handshake: none (the enclosing
// pipeline's global stall ce_i). Multipliers: 3 (VW x VW).
// II = 3 (a time-shared pipeline, csgrt_beat): every register moves on the
// beat's advance (ce_i at phase_i 2), so the latency is counted in beats
// and the throughput is a vector per beat; the three squares share one
// multiplier (csgrt_mul_vec), and the three divisions one csgrt_div_core
// running on every clock, fed axis k at phase k, its quotients gathered
// as csgrt_mul_vec gathers products (csgrt_beat_gather; the divider's
// FRAC+2 clocks padded by 0 to 2 registers to 2 mod 3: D takes
// (FRAC+2+pad+4)/3 beats, 7 for FRAC 15); the square root finds three
// result bits per stage, one per running clock (csgrt_sqrt_core FOLD = 3):
// Q takes ceil(SQRT_STAGES/3) beats (6 for 17 stages). Latency
// ceil(SQRT_STAGES/3) + (FRAC+2+pad+4)/3 + 5 beats (shading: 18).
// Multipliers: 1; dividers: 1.
// Both latencies are csgrt_unit_latency() (csgrt_unit_latency.vh), which
// sizes the sideband's line here and its callers' lines that span a unit.
// The sideband (user_i) waits in one RAM delay line over the whole latency
// (csgrt_delay_ram), not in the stages' registers: the square root carries
// only v, the divisions only the root.
// Users: csgrt_shade_unit (shading, FRAC 15, 17 stages), csgrt_spawn
// (normals and secondary-ray directions, FRAC F, F+8 stages).
module csgrt_unit #(
    parameter VW          = 18,   // signed width of v_i (>= 2)
    parameter FRAC        = 15,   // fraction bits of u (>= 1)
    parameter SQRT_STAGES = 17,   // square-root stages: sum v^2 < 4^SQRT_STAGES (>= 2)
    parameter USER_WIDTH  = 1,    // sideband carried alongside (>= 1)
    parameter II          = 1     // running clocks per beat: 1, or 3 (csgrt_mul_vec)
) (
    input  wire                    clk_i,
    input  wire                    rst_ni,   // synchronous, active low (valid bits only)
    input  wire                    ce_i,     // the pipeline runs (low = stall)
    input  wire                    adv_i,    // the beat's advance: csgrt_beat's adv_o (a register)
    input  wire [1:0]              phase_i,  // csgrt_beat's phase (II = 3; 0 for II = 1)
    input  wire                    valid_i,
    input  wire [3*VW-1:0]         v_i,      // x, y, z (x low), two's complement
    input  wire [USER_WIDTH-1:0]   user_i,
    output wire                    valid_o,
    output wire [3*(FRAC+2)-1:0]   u_o,      // FRAC fraction bits, FRAC+2 bits signed each
    output wire [SQRT_STAGES-1:0]  root_o,   // isqrt(sum v^2), unsigned
    output wire [USER_WIDTH-1:0]   user_o
);

`include "csgrt_unit_latency.vh"
    localparam LATENCY = csgrt_unit_latency(FRAC, SQRT_STAGES, II);   // beats
    localparam SQ   = SQRT_STAGES;
    localparam QB   = FRAC + 1;           // quotient bits
    localparam UOW  = FRAC + 2;           // signed output width
    localparam PW   = 2 * VW;             // square
    localparam SUMW = (PW + 2 > 2 * SQ) ? PW + 2 : 2 * SQ;   // exact sum of three squares
    localparam NUMW = VW + FRAC;          // v << FRAC
    localparam DENW = SQ + 2;             // L <= 2^SQ, signed
    localparam UW   = USER_WIDTH;
    localparam MW   = 3 * VW;             // v, beside the squares and the square root
    localparam RW   = SQ;                 // the root, beside the divisions

    genvar i;

    // every register but the shared multiplier's moves on the beat's advance
    wire adv = adv_i;

    // ---- the sideband: one line over the whole latency ------------------------------
    // OUT_REG: the line ends in a fabric register, as O's registers did
    csgrt_delay_ram #(.WIDTH(UW), .STAGES(LATENCY), .OUT_REG(1)) u_dly_user (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .data_i(user_i), .data_o(user_o));

    // ---- M: squares -----------------------------------------------------------
    wire [3*PW-1:0] sq;
    // At II 3 a square wider than one block (VW > 18: csgrt_mul's tiles)
    // takes the tile register instead of the operand register; either
    // keeps the two beats (csgrt_mul_vec). The tiles' sum is a carry chain
    // after the blocks, and 2af1f56's routed critical path was a block's
    // output here (csgrt_spawn's u_unit_c) -> 4.94 ns of route -> that sum
    // -> the gather's register (docs/fpga-timing.md item 25); the operand
    // side has one LUT of choice between its registers and the block.
    // At II 1 the tile register would cost a clock: none there.
    localparam SQ_TILE_REG = (II == 3 && VW > 18) ? 1 : 0;
    csgrt_mul_vec #(.A_WIDTH(VW), .B_WIDTH(VW), .N(3), .II(II), .TILE_REG(SQ_TILE_REG)) u_sq (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(ce_i), .adv_i(adv_i), .phase_i(phase_i),
        .a_i(v_i), .b_i(v_i), .p_o(sq));
    wire          m_valid;
    wire [MW-1:0] m_side;
    csgrt_delay #(.WIDTH(MW), .STAGES(2)) u_dly_m (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .valid_i(valid_i),
        .data_i(v_i), .valid_o(m_valid), .data_o(m_side));

    // ---- S: sum (< 4^SQ by the caller's bound) ----------------------------------
    // squares are non-negative: zero-extended
    wire [SUMW-1:0] sum = {{(SUMW-PW){1'b0}}, sq[0 +: PW]} + {{(SUMW-PW){1'b0}}, sq[PW +: PW]}
                        + {{(SUMW-PW){1'b0}}, sq[2*PW +: PW]};
    reg            s_valid_q;
    reg [2*SQ-1:0] s_n_q;
    reg [MW-1:0]   s_side_q;
    always @(posedge clk_i) begin
        if (!rst_ni) s_valid_q <= 1'b0;
        else if (adv) s_valid_q <= m_valid;
        if (adv) begin
            s_n_q    <= sum[2*SQ-1:0];
            s_side_q <= m_side;
        end
    end
    generate
        if (SUMW > 2 * SQ) begin : g_sum_top
            // zero by the caller's bound
            wire unused_sum = ^sum[SUMW-1:2*SQ];
        end
    endgenerate

    // ---- Q: square root ---------------------------------------------------------------
    wire          q_valid;
    wire [SQ-1:0] q_root;
    wire [MW-1:0] q_side;
    // II = 3: three result bits per stage, one per running clock (FOLD)
    csgrt_sqrt_core #(.RESULT_BITS(SQ), .USER_WIDTH(MW), .FOLD(II)) u_sqrt (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .run_i(ce_i), .phase_i(phase_i), .valid_i(s_valid_q),
        .n_i(s_n_q), .user_i(s_side_q), .valid_o(q_valid), .root_o(q_root), .user_o(q_side));

    // ---- P: L = root + 1, numerators ------------------------------------------------------
    reg              p_valid_q;
    reg [DENW-1:0]   p_len_q;
    reg [3*NUMW-1:0] p_num_q;
    reg [RW-1:0]    p_root_q;
    always @(posedge clk_i) begin
        if (!rst_ni) p_valid_q <= 1'b0;
        else if (adv) p_valid_q <= q_valid;
        if (adv) begin
            p_len_q  <= {2'b00, q_root} + {{(DENW-1){1'b0}}, 1'b1};
            p_num_q  <= {q_side[2*VW +: VW], {FRAC{1'b0}}, q_side[VW +: VW], {FRAC{1'b0}},
                         q_side[0 +: VW], {FRAC{1'b0}}};
            p_root_q <= q_root;
        end
    end

    // ---- D: divisions --------------------------------------------------------------------
    wire            d_valid;
    wire [3*QB-1:0] d_mag;
    wire [2:0]      d_neg, d_ovf;
    wire [RW-1:0]  d_root;
    generate
        if (II == 3) begin : g_div_shared
            // one divider, axis k at phase k; its output {neg, quot} reaches
            // the end of the pad after DLE = 3m + 2 clocks, so axis k's is
            // caught at phase (k + 2) mod 3 and all three are copied at the
            // next advance (csgrt_mul_vec's scheme, with 3m more clocks)
            localparam PAD = csgrt_unit_div_pad(FRAC);    // csgrt_div_core's latency QB + 1, + PAD = 2 mod 3
            localparam DB  = csgrt_unit_div_beats(FRAC);  // beats from P to O's input
            reg [NUMW-1:0] num_sel;
            always @* begin
                case (phase_i)
                    2'd1:    num_sel = p_num_q[NUMW +: NUMW];
                    2'd2:    num_sel = p_num_q[2*NUMW +: NUMW];
                    default: num_sel = p_num_q[0 +: NUMW];
                endcase
            end
            wire          dq_neg, dq_ovf, unused_dv, unused_du;
            wire [QB-1:0] dq_mag;
            csgrt_div_core #(.NUM_WIDTH(NUMW), .DEN_WIDTH(DENW), .QUOT_BITS(QB), .USER_WIDTH(1)) u_div (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(ce_i), .run_i(1'b0), .phase_i(2'd0), .valid_i(1'b0),
                .num_i(num_sel), .den_i(p_len_q), .user_i(1'b0),
                .valid_o(unused_dv), .quot_o(dq_mag), .neg_o(dq_neg), .ovf_o(dq_ovf), .user_o(unused_du));
            wire unused_dq_ovf = dq_ovf;   // |v_i| < L: never overflows
            // the pad: PAD registers on the running clock
            wire [QB:0] padded;
            if (PAD == 0) begin : g_pad0
                assign padded = {dq_neg, dq_mag};
            end else begin : g_pad
                reg [QB:0] pad_q [0:PAD-1];
                integer pk;
                always @(posedge clk_i)
                    if (ce_i) begin
                        pad_q[0] <= {dq_neg, dq_mag};
                        for (pk = 1; pk < PAD; pk = pk + 1) pad_q[pk] <= pad_q[pk-1];
                    end
                assign padded = pad_q[PAD-1];
            end
            wire [3*(QB+1)-1:0] gathered;
            csgrt_beat_gather #(.WIDTH(QB + 1), .N(3)) u_gather (
                .clk_i(clk_i), .ce_i(ce_i), .adv_i(adv_i), .d_i(padded), .q_o(gathered));
            for (i = 0; i < 3; i = i + 1) begin : g_quot
                assign d_mag[i*QB +: QB] = gathered[i*(QB+1) +: QB];
                assign d_neg[i]          = gathered[i*(QB+1) + QB];
            end
            assign d_ovf = 3'b000;
            // the valid bit and the sideband: DB beats (DB - 1 of them in the
            // ring buffer, the last in d_q's place)
            wire unused_dvld;
            csgrt_delay #(.WIDTH(1), .STAGES(DB)) u_dly_dv (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .valid_i(p_valid_q), .data_i(1'b0),
                .valid_o(d_valid), .data_o(unused_dvld));
            csgrt_delay_ram #(.WIDTH(RW), .STAGES(DB)) u_dly_du (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .data_i(p_root_q), .data_o(d_root));
        end else begin : g_div_parallel
        for (i = 0; i < 3; i = i + 1) begin : g_div
            if (i == 0) begin : g_main
                csgrt_div_core #(.NUM_WIDTH(NUMW), .DEN_WIDTH(DENW), .QUOT_BITS(QB), .USER_WIDTH(RW)) u_div (
                    .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .run_i(1'b0), .phase_i(2'd0), .valid_i(p_valid_q),
                    .num_i(p_num_q[i*NUMW +: NUMW]), .den_i(p_len_q), .user_i(p_root_q),
                    .valid_o(d_valid), .quot_o(d_mag[i*QB +: QB]), .neg_o(d_neg[i]), .ovf_o(d_ovf[i]),
                    .user_o(d_root));
            end else begin : g_other
                wire unused_v, unused_u;
                csgrt_div_core #(.NUM_WIDTH(NUMW), .DEN_WIDTH(DENW), .QUOT_BITS(QB), .USER_WIDTH(1)) u_div (
                    .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .run_i(1'b0), .phase_i(2'd0), .valid_i(p_valid_q),
                    .num_i(p_num_q[i*NUMW +: NUMW]), .den_i(p_len_q), .user_i(1'b0),
                    .valid_o(unused_v), .quot_o(d_mag[i*QB +: QB]), .neg_o(d_neg[i]), .ovf_o(d_ovf[i]),
                    .user_o(unused_u));
            end
        end
        end
    endgenerate
    // |v_i| < L: never overflows
    wire unused_ovf = ^d_ovf;

    // ---- O: signed output -----------------------------------------------------------------
    reg             o_valid_q;
    reg [3*UOW-1:0] o_u_q;
    reg [RW-1:0]   o_root_q;
    integer k;
    always @(posedge clk_i) begin
        if (!rst_ni) o_valid_q <= 1'b0;
        else if (adv) o_valid_q <= d_valid;
        if (adv) begin
            for (k = 0; k < 3; k = k + 1)
                o_u_q[k*UOW +: UOW] <= d_neg[k] ? {UOW{1'b0}} - {1'b0, d_mag[k*QB +: QB]}
                                                : {1'b0, d_mag[k*QB +: QB]};
            o_root_q <= d_root;
        end
    end
    assign valid_o = o_valid_q;
    assign u_o     = o_u_q;
    assign root_o  = o_root_q;

`ifndef SYNTHESIS
    // LATENCY (which times the sideband's line, and the callers' lines that
    // span a unit) is the pipeline's depth: a valid bit shifted LATENCY
    // advances leaves with valid_o, or the simulation stops
    wire lat_valid, unused_lat;
    csgrt_delay #(.WIDTH(1), .STAGES(LATENCY)) u_lat_check_dly (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .valid_i(valid_i), .data_i(1'b0),
        .valid_o(lat_valid), .data_o(unused_lat));
    csgrt_check_same #(.WIDTH(1), .WHAT("csgrt_unit_latency()'s valid bit")) u_lat_check (
        .clk_i(clk_i), .rst_ni(rst_ni), .copy_i(lat_valid), .orig_i(o_valid_q));
`endif

    generate
        if (VW < 2 || FRAC < 1 || SQRT_STAGES < 2 || USER_WIDTH < 1 || (II != 1 && II != 3)) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_unit needs VW >= 2, FRAC >= 1, SQRT_STAGES >= 2, USER_WIDTH >= 1, II = 1 or 3");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
