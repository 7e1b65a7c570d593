`default_nettype none
// csgrt_div_core — signed division truncating toward zero with the quotient
// magnitude limited to QUOT_BITS bits, bit for bit sdiv_trunc() of
// model/fixed.h: |q| = udiv_bitwise(|n|, |d|, QUOT_BITS) (restoring, one
// quotient bit per stage, most significant first) unless div_overflows(),
// i.e. (|n| >> QUOT_BITS) >= |d|, which raises ovf_o (the caller saturates;
// quot_o is then meaningless). d = 0 always reports overflow. neg_o is
// (n < 0) != (d < 0), the sign of the quotient and of a saturated result.
//
// Stage 0 (input register): |n|, |d|, neg, ovf, rem = (|n| >> QUOT_BITS).
// Stage 1+k (quotient bit i = QUOT_BITS-1-k):
//   rem = (rem << 1) | |n|[i];  q = q << 1;  if (rem >= |d|) { rem -= |d|; q |= 1; }
// (the restoring form, which defines the bits; the stages below run it
// non-restoring: same quotient)
// Example NUM_WIDTH = 4, DEN_WIDTH = 3, QUOT_BITS = 2, n = -7, d = 3:
// |n| = 0111, rem = 01, bit 1: rem = 3 >= 3 -> 0, q = 1; bit 0: rem = 1, q = 10;
// quot_o = 2, neg_o = 1 (the result is -2).
//
// The stages compute that restoring recurrence's quotient bits without
// restoring (non-restoring division): a stage keeps the trial remainder
// r' = 2r + bit - |d| even when it is negative, and the next stage adds
// |d| back instead of subtracting it: 2r' + bit + |d| = 2(2r + bit) + bit' - |d|,
// the restoring stage's trial. So every trial equals the restoring one, the
// quotient bit is its sign (1 when >= 0) and the quotient is the same bit
// for bit; the remainder, which would need a correction, is not an output.
// A stage is then one adder (add or subtract by the remainder's sign bit,
// a register) straight into the registers, where the restoring stage had a
// compare, a subtraction and a select after them whose select drove every
// remainder bit (tools/logic_depth.py: csgrt_isect's divider stage, 9 LUT
// levels, 13.60 ns, the worst path of the 24-bit netlist at dd70611).
// The remainder is DW+1 bits signed: -|d| <= r' < |d|.
//
// FOLD = 3 (a pipeline that moves every third running clock, csgrt_beat
// II = 3): each iteration stage finds three quotient bits, one per running
// clock of a beat, as csgrt_sqrt_core's FOLD = 3 does (the same steps in the
// same order: the same result bit for bit), in ceil(QUOT_BITS / 3) stages.
//
// Latency: ceil(QUOT_BITS / FOLD) + 1 clocks, counted in enabled clocks of
// ce_i. Handshake: none; a global stage enable ce_i (low = hold; FOLD = 3:
// the beat's advance) and a valid bit shifted alongside. csgrt_div adds the
// sign and valid/ready.
module csgrt_div_core #(
    parameter NUM_WIDTH  = 16,   // signed numerator width (> QUOT_BITS)
    parameter DEN_WIDTH  = 8,    // signed denominator width (>= 2)
    parameter QUOT_BITS  = 8,    // quotient magnitude bits = iteration stages (>= 2)
    parameter USER_WIDTH = 1,    // sideband carried alongside (>= 1)
    parameter USER_OUT_REG = 0,  // 1: the sideband's RAM line ends in a fabric register (csgrt_delay_ram OUT_REG)
    parameter FOLD       = 1     // quotient bits per stage: 1, or 3 (one per running clock of a three-clock beat)
) (
    input  wire                  clk_i,
    input  wire                  rst_ni,   // synchronous, active low (valid bits only)
    input  wire                  ce_i,     // stage enable (low = stall; FOLD = 3: the beat's advance)
    input  wire                  run_i,    // FOLD = 3: a running clock of the beat (csgrt_beat's ce_i)
    input  wire [1:0]            phase_i,  // FOLD = 3: its phase (csgrt_beat's phase_o)
    input  wire                  valid_i,
    input  wire [NUM_WIDTH-1:0]  num_i,    // two's complement
    input  wire [DEN_WIDTH-1:0]  den_i,    // two's complement
    input  wire [USER_WIDTH-1:0] user_i,
    output wire                  valid_o,
    output wire [QUOT_BITS-1:0]  quot_o,   // |n| / |d| rounded down (valid when !ovf_o)
    output wire                  neg_o,    // (n < 0) != (d < 0)
    output wire                  ovf_o,    // |n / d| >= 2^QUOT_BITS (or d = 0)
    output wire [USER_WIDTH-1:0] user_o
);

    localparam NW = NUM_WIDTH;
    localparam DW = DEN_WIDTH;
    localparam QB = QUOT_BITS;
    localparam UW = USER_WIDTH;
    localparam XW = NW + DW;   // width holding both magnitudes for the compare

    // ---- stage 0: magnitudes, sign, overflow check ------------------------
    wire [NW-1:0] un = num_i[NW-1] ? (~num_i + {{(NW-1){1'b0}}, 1'b1}) : num_i;
    wire [DW-1:0] ud = den_i[DW-1] ? (~den_i + {{(DW-1){1'b0}}, 1'b1}) : den_i;
    wire [XW-1:0] un_x = {{DW{1'b0}}, un};
    wire [XW-1:0] ud_x = {{NW{1'b0}}, ud};
    wire [XW-1:0] hi_x = un_x >> QB;   // the bits above the quotient window
    // hi >= |d| as the sign of an explicit subtraction: a carry chain
    // (written as a compare, the LUT mapping gave a 5-level tree behind the
    // magnitudes' chains, csgrt_isect's worst path once its stages were
    // non-restoring, tools/logic_depth.py 9.77 ns)
    wire [XW:0]   hi_minus_d = {1'b0, hi_x} - {1'b0, ud_x};
    wire          ovf0 = !hi_minus_d[XW];
    wire [XW-1:0] unused_hi_minus_d = hi_minus_d[XW-1:0];
    // without overflow hi_x < |d| < 2^DW: the bits above DW are only looked
    // at by the overflow check
    wire [XW-DW-1:0] unused_hi = hi_x[XW-1:DW];

    reg          s0_valid_q;
    reg [DW-1:0] s0_rem_q, s0_ud_q;
    reg [QB-1:0] s0_lo_q;
    reg          s0_neg_q, s0_ovf_q;

    always @(posedge clk_i) begin
        if (!rst_ni) begin
            s0_valid_q <= 1'b0;
        end else if (ce_i) begin
            s0_valid_q <= valid_i;
        end
        if (ce_i) begin
            s0_rem_q  <= hi_x[DW-1:0];
            s0_ud_q   <= ud;
            s0_lo_q   <= un[QB-1:0];
            s0_neg_q  <= num_i[NW-1] ^ den_i[DW-1];
            s0_ovf_q  <= ovf0;
        end
    end

    // ---- stages 1..NS: one quotient bit each (FOLD = 3: three) -------------
    // Side information (|d|, the low numerator bits, neg, ovf) rides along
    // in one flat word per stage. The sideband user_i, needed only at the
    // end, takes a RAM delay line of the same NS + 1 enabled clocks (block
    // or LUT RAM on the FPGA rather than NS + 1 copies in flip-flops).
    localparam SW = DW + QB + 2;        // side word width
    localparam NS = (QB + FOLD - 1) / FOLD;   // iteration stages

    // Each stage's registers are plain registers of its generate block, seen
    // by the next stage through the wire arrays below (csgrt_sqrt_core says
    // why: the Verilator model writes them as variables of their own).
    reg  [NS-1:0] valid_q;
    wire [DW:0]   rem_w  [0:NS-1];   // signed: -|d| <= rem < |d|
    // The quotient is kept inverted (quotn: bit 1 for a quotient bit 0), so
    // that the trial's sign bit goes straight from the carry chain into its
    // register, without an inverter LUT; quot_o inverts it at the end.
    wire [QB-1:0] quotn_w [0:NS-1];
    wire [SW-1:0] side_w [0:NS-1];

    wire [SW-1:0] side0 = {s0_ovf_q, s0_neg_q, s0_lo_q, s0_ud_q};

    always @(posedge clk_i) begin
        if (!rst_ni) begin
            valid_q <= {NS{1'b0}};
        end else if (ce_i) begin
            valid_q <= {valid_q[NS-2:0], s0_valid_q};
        end
    end

    genvar k;
    generate
        for (k = 0; k < NS; k = k + 1) begin : g_stage
            wire [DW:0]   rem_in;
            wire [QB-1:0] quotn_in;
            wire [SW-1:0] side_in;
            if (k == 0) begin : g_first
                assign rem_in  = {1'b0, s0_rem_q};
                assign quotn_in = {QB{1'b1}};
                assign side_in = side0;
            end else begin : g_next
                assign rem_in  = rem_w[k-1];
                assign quotn_in = quotn_w[k-1];
                assign side_in = side_w[k-1];
            end
            reg [DW:0]   rem_q;
            reg [QB-1:0] quotn_q;
            reg [SW-1:0] side_q;
            assign rem_w[k]  = rem_q;
            assign quotn_w[k] = quotn_q;
            assign side_w[k] = side_q;

            // the step's operands: the previous stage's item (FOLD = 1, and
            // the beat's advance with FOLD = 3) or this stage's own, and the
            // numerator bit brought down
            wire take_prev;   // this clock's step starts from the previous stage's item
            wire step;        // this clock takes a step
            wire lo_bit;
            csgrt_fold_step #(.FOLD(FOLD), .STEPS(QB), .STAGE(k), .W(1)) u_sched (
                .clk_i(clk_i), .rst_ni(rst_ni),
                .ce_i(ce_i), .run_i(run_i), .phase_i(phase_i),
                .prev_bits_i(side_in[DW +: QB]), .own_bits_i(side_q[DW +: QB]),
                .take_prev_o(take_prev), .step_o(step), .bits_o(lo_bit));
            wire [DW:0]   rem_src   = take_prev ? rem_in  : rem_q;
            wire [QB-1:0] quotn_src = take_prev ? quotn_in : quotn_q;
            wire [DW-1:0] ud_src    = take_prev ? side_in[DW-1:0] : side_q[DW-1:0];
            wire          rem_neg  = rem_src[DW];
            wire [DW+1:0] rem_sh   = {rem_src, lo_bit};
            // one adder: rem_sh - |d| (remainder >= 0) or rem_sh + |d|
            // (negative), the subtraction's +1 entering as a low bit:
            // ({rem_sh, 1} + {~|d|, 1}) >> 1 = rem_sh - |d|, and
            // ({rem_sh, 1} + {|d|, 0}) >> 1 = rem_sh + |d|
            wire [DW+1:0] d_op     = rem_neg ? {2'b00, ud_src} : ~{2'b00, ud_src};
            wire [DW+2:0] sum      = {rem_sh, 1'b1} + {d_op, !rem_neg};
            wire [DW+1:0] trial    = sum[DW+2:1];
            // -|d| <= trial < |d|: bit DW+1 repeats bit DW; sum's low bit is 1 or 0 by the
            // operation, not part of the trial
            wire          unused_trial = ^{trial[DW], sum[0]};
            wire [DW:0]   rem_nx   = {trial[DW+1], trial[DW-1:0]};
            // the quotient's top bit is still 0 (quotn's 1) before the last step
            wire          unused_quot_top = quotn_src[QB-1];

            always @(posedge clk_i)
                if (step) begin
                    rem_q   <= rem_nx;
                    quotn_q <= {quotn_src[QB-2:0], trial[DW+1]};   // the trial's sign: 1 for quotient bit 0
                    if (take_prev) side_q <= side_in;
                end
        end
    endgenerate

    wire [SW-1:0] side_last = side_w[NS-1];
    assign valid_o = valid_q[NS-1];
    assign quot_o  = ~quotn_w[NS-1];
    assign neg_o   = side_last[DW+QB];
    assign ovf_o   = side_last[DW+QB+1];

    csgrt_delay_ram #(.WIDTH(UW), .STAGES(NS + 1), .OUT_REG(USER_OUT_REG)) u_user (
        .clk_i, .rst_ni, .ce_i, .data_i (user_i), .data_o (user_o)
    );

    // the last stage's remainder, |d| and numerator bits are not needed
    wire unused_last = ^{rem_w[NS-1], side_last[DW+QB-1:0]};

    generate
        if (NUM_WIDTH <= QUOT_BITS || DEN_WIDTH < 2 || QUOT_BITS < 2 || USER_WIDTH < 1
            || (FOLD != 1 && FOLD != 3) || NS < 2) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_div_core needs NUM_WIDTH > QUOT_BITS >= 2 (>= 4 with FOLD 3), DEN_WIDTH >= 2, USER_WIDTH >= 1, FOLD 1 or 3");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
