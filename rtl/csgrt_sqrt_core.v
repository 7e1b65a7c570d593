`default_nettype none
// csgrt_sqrt_core — integer square root root = floor(sqrt(n)), one result
// bit per stage, most significant first: the digit-by-digit method
// of isqrt_bitwise() in model/fixed.h, stage k computing result bit
// RESULT_BITS-1-k. Stage k (bit i = RESULT_BITS-1-k):
//   rem   = (rem << 2) | n[2i+1:2i]      bring down two bits of n
//   trial = (root << 2) | 1              2*root+1 at this scale
//   root  = root << 1; if (rem >= trial) { rem -= trial; root |= 1; }
// Example RESULT_BITS = 2, n = 4'b1010 (10): stage 0: rem = 2, trial = 1,
// rem = 1, root = 1; stage 1: rem = 6, trial = 5, rem = 1, root = 3.
//
// The stages find those result bits without restoring (non-restoring
// square root): a stage keeps the trial remainder r' = 4r + bits - (4 root + 1)
// even when it is negative (r' = r - (2 root' + 1) with root' = 2 root, the
// new root), and the next stage adds 4 root' + 3 instead of subtracting
// 4 root' + 1: 4 r' + bits' + 4 root' + 3 = 4 r + bits' - (4 root' + 1),
// the restoring stage's trial. Every trial equals the restoring one, the
// result bit is its sign (1 when >= 0), and the root is the same bit for
// bit. A stage is one adder (its operation chosen by the remainder's sign
// bit, a register) straight into the registers, where the restoring stage
// had a compare, a subtraction and a select whose select drove every
// remainder bit (tools/logic_depth.py on csgrt_isect, BITS 24, II 3: the
// worst path, 10.59 ns, once the dividers went non-restoring).
// The remainder is R+2 bits signed: -(2 root + 1) <= r' <= 2 root.
//
// FOLD = 3 (a pipeline that moves every third running clock, csgrt_beat
// II = 3): each stage finds three result bits, one per running clock of a
// beat, so there are ceil(RESULT_BITS / 3) stages, a third of the registers
// and of the compare-subtract logic. At the beat's advance (ce_i, phase_i =
// 2) a stage takes the previous stage's item and does its first step on it;
// on the beat's other two running clocks (run_i with phase_i 0 and 1) it
// does the next two steps on its own item. Steps past bit 0 (the last stage
// when 3 does not divide RESULT_BITS) leave the item as it is. The steps
// and their order are FOLD = 1's, so the result is the same bit for bit.
//
// Latency: ceil(RESULT_BITS / FOLD) enabled clocks of ce_i (one register per
// stage). Handshake: none; a global stage enable ce_i (low = every register
// holds; FOLD = 3: the beat's advance) and a valid bit shifted alongside.
// csgrt_sqrt adds valid/ready.
module csgrt_sqrt_core #(
    parameter RESULT_BITS = 8,   // result bits = pipeline stages (>= 2)
    parameter USER_WIDTH  = 1,   // sideband carried alongside (>= 1)
    parameter USER_OUT_REG = 0,  // 1: the sideband's RAM line ends in a fabric register (csgrt_delay_ram OUT_REG)
    parameter FOLD        = 1    // result bits per stage: 1, or 3 (one per running clock of a three-clock beat)
) (
    input  wire                     clk_i,
    input  wire                     rst_ni,    // synchronous, active low (valid bits only)
    input  wire                     ce_i,      // stage enable (low = stall; FOLD = 3: the beat's advance)
    input  wire                     run_i,     // FOLD = 3: a running clock of the beat (csgrt_beat's ce_i)
    input  wire [1:0]               phase_i,   // FOLD = 3: its phase (csgrt_beat's phase_o)
    input  wire                     valid_i,
    input  wire [2*RESULT_BITS-1:0] n_i,       // radicand, unsigned
    input  wire [USER_WIDTH-1:0]    user_i,
    output wire                     valid_o,
    output wire [RESULT_BITS-1:0]   root_o,    // floor(sqrt(n_i))
    output wire [USER_WIDTH-1:0]    user_o
);

    localparam R  = RESULT_BITS;
    localparam NW = 2 * R;   // radicand width
    // Remainder width: after j result bits -(2*root+1) <= rem <= 2*root with
    // root < 2^j, so a remainder that a later step reads (j <= R-1) lies in
    // [-(2^R + 1), 2^R]: R+2 bits signed. The shifted remainder 4*rem + bits
    // and the trial take R+4 bits signed; the remainder after the last step
    // is not read (and not kept whole).
    localparam RW = R + 2;
    localparam TW = RW + 2;   // the shifted remainder and the trial
    localparam NS = (R + FOLD - 1) / FOLD;   // stages

    // Stage k reads the inputs (k = 0) or the registers of stage k-1 and
    // writes its own. Each stage's registers are plain registers of its
    // generate block, seen by the next stage through the wire arrays below,
    // so that the Verilator model writes each as a variable of its own:
    // array elements written one per always block each took a delayed-
    // assignment flag and value per clock (most of the simulation's time).
    reg  [NS-1:0] valid_q;
    wire [RW-1:0] rem_w  [0:NS-1];
    // The root is kept inverted (rootn: bit 1 for a result bit 0), so that
    // the trial's sign bit goes straight from the carry chain into its
    // register, without an inverter LUT on the stage's path; root_o
    // inverts it once at the end.
    wire [R-1:0]  rootn_w [0:NS-1];
    wire [NW-1:0] n_w    [0:NS-1];

    always @(posedge clk_i) begin
        if (!rst_ni) begin
            valid_q <= {NS{1'b0}};
        end else if (ce_i) begin
            valid_q <= {valid_q[NS-2:0], valid_i};
        end
    end

    genvar k;
    generate
        for (k = 0; k < NS; k = k + 1) begin : g_stage
            wire [RW-1:0] rem_in;
            wire [R-1:0]  rootn_in;
            wire [NW-1:0] n_in;
            if (k == 0) begin : g_in
                assign rem_in   = {RW{1'b0}};
                assign rootn_in = {R{1'b1}};
                assign n_in     = n_i;
            end else begin : g_in
                assign rem_in   = rem_w[k-1];
                assign rootn_in = rootn_w[k-1];
                assign n_in     = n_w[k-1];
            end
            reg [RW-1:0] rem_q;
            reg [R-1:0]  rootn_q;
            reg [NW-1:0] n_q;
            assign rem_w[k]  = rem_q;
            assign rootn_w[k] = rootn_q;
            assign n_w[k]    = n_q;

            // the step's operands: the previous stage's item (FOLD = 1, and
            // the beat's advance with FOLD = 3) or this stage's own, and the
            // two radicand bits of the result bit found
            wire          take_prev;   // this clock's step starts from the previous stage's item
            wire          step;        // this clock takes a step
            wire [1:0]    n_bits;
            csgrt_fold_step #(.FOLD(FOLD), .STEPS(R), .STAGE(k), .W(2)) u_sched (
                .clk_i(clk_i), .rst_ni(rst_ni),
                .ce_i(ce_i), .run_i(run_i), .phase_i(phase_i), .prev_bits_i(n_in), .own_bits_i(n_q),
                .take_prev_o(take_prev), .step_o(step), .bits_o(n_bits));
            wire [RW-1:0] rem_src  = take_prev ? rem_in  : rem_q;
            wire [R-1:0]  rootn_src = take_prev ? rootn_in : rootn_q;
            wire          rem_neg  = rem_src[RW-1];
            wire [TW-1:0] rem_sh   = {rem_src, n_bits};
            // one adder: rem_sh - (4 root + 1) (remainder >= 0) or
            // rem_sh + (4 root + 3) (negative), the subtraction's +1 entering
            // as a low bit: ({rem_sh, 1} + {~x, 1}) >> 1 = rem_sh - x, and
            // ({rem_sh, 1} + {x, 0}) >> 1 = rem_sh + x
            wire [TW-1:0] op       = rem_neg ? {2'b00, ~rootn_src, 2'b11} : {2'b11, rootn_src, 2'b10};
            wire [TW:0]   sum      = {rem_sh, 1'b1} + {op, !rem_neg};
            wire [TW-1:0] trial    = sum[TW:1];
            // bits RW-1 .. TW-2 repeat the sign for every remainder a later
            // step reads; sum's low bit is the operation's, not the trial's
            wire          unused_trial = ^{trial[TW-2:RW-1], sum[0]};

            always @(posedge clk_i)
                if (step) begin
                    rem_q  <= {trial[TW-1], trial[RW-2:0]};
                    rootn_q <= {rootn_src[R-2:0], trial[TW-1]};   // the trial's sign: 1 for result bit 0
                    if (take_prev) n_q <= n_in;
                end
        end
    endgenerate

    // The sideband rides along NS enabled clocks in a RAM delay line (block
    // or LUT RAM on the FPGA) rather than NS copies in flip-flops.
    csgrt_delay_ram #(.WIDTH(USER_WIDTH), .STAGES(NS), .OUT_REG(USER_OUT_REG)) u_user (
        .clk_i, .rst_ni, .ce_i, .data_i (user_i), .data_o (user_o)
    );

    assign valid_o = valid_q[NS-1];
    assign root_o  = ~rootn_w[NS-1];

    // the last stage's remainder and radicand copy are not needed
    wire unused_last = ^{rem_w[NS-1], n_w[NS-1]};

    generate
        if (RESULT_BITS < 2 || USER_WIDTH < 1 || (FOLD != 1 && FOLD != 3) || NS < 2) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_sqrt_core needs RESULT_BITS >= 2 (>= 4 with FOLD 3), USER_WIDTH >= 1, FOLD 1 or 3");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
