`default_nettype none
// csgrt_sqrt_core — integer square root root = floor(sqrt(n)), one result
// bit per stage, most significant first: the restoring digit-by-digit method
// of isqrt_bitwise() in model/fixed.h, stage k computing result bit
// RESULT_BITS-1-k. Stage k (bit i = RESULT_BITS-1-k):
//   rem   = (rem << 2) | n[2i+1:2i]      bring down two bits of n
//   trial = (root << 2) | 1              2*root+1 at this scale
//   root  = root << 1; if (rem >= trial) { rem -= trial; root |= 1; }
// Example RESULT_BITS = 2, n = 4'b1010 (10): stage 0: rem = 2, trial = 1,
// rem = 1, root = 1; stage 1: rem = 6, trial = 5, rem = 1, root = 3.
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
    // Remainder width: after j result bits rem <= 2*root < 2^(j+1), so the
    // shifted remainder 4*rem+3 < 2^(R+2) fits in R+2 bits at every stage.
    localparam RW = R + 2;
    localparam NS = (R + FOLD - 1) / FOLD;   // stages

    // Stage k reads the inputs (k = 0) or the registers of stage k-1 and
    // writes its own. Each stage's registers are plain registers of its
    // generate block, seen by the next stage through the wire arrays below,
    // so that the Verilator model writes each as a variable of its own:
    // array elements written one per always block each took a delayed-
    // assignment flag and value per clock (most of the simulation's time).
    reg  [NS-1:0] valid_q;
    wire [RW-1:0] rem_w  [0:NS-1];
    wire [R-1:0]  root_w [0:NS-1];
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
            wire [R-1:0]  root_in;
            wire [NW-1:0] n_in;
            if (k == 0) begin : g_in
                assign rem_in   = {RW{1'b0}};
                assign root_in  = {R{1'b0}};
                assign n_in     = n_i;
            end else begin : g_in
                assign rem_in   = rem_w[k-1];
                assign root_in  = root_w[k-1];
                assign n_in     = n_w[k-1];
            end
            reg [RW-1:0] rem_q;
            reg [R-1:0]  root_q;
            reg [NW-1:0] n_q;
            assign rem_w[k]  = rem_q;
            assign root_w[k] = root_q;
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
            wire [R-1:0]  root_src = take_prev ? root_in : root_q;
            // rem_src < 2^R: its two top bits are always zero
            wire [1:0]    unused_rem_top = rem_src[RW-1:RW-2];
            wire [RW-1:0] rem_sh = {rem_src[RW-3:0], n_bits};
            wire [RW-1:0] trial  = {root_src, 2'b01};
            wire          take   = (rem_sh >= trial);
            // root_src < 2^(R-1) before the last step: its top bit is always zero
            wire          unused_root_top = root_src[R-1];

            always @(posedge clk_i)
                if (step) begin
                    rem_q  <= take ? rem_sh - trial : rem_sh;
                    root_q <= {root_src[R-2:0], take};
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
    assign root_o  = root_w[NS-1];

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
