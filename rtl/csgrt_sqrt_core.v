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
// Latency: RESULT_BITS clocks (one register per stage), counted in enabled
// clocks. Handshake: none; a global stage enable ce_i (low = every register
// holds) and a valid bit shifted alongside. csgrt_sqrt adds valid/ready.
module csgrt_sqrt_core #(
    parameter RESULT_BITS = 8,   // result bits = pipeline stages (>= 2)
    parameter USER_WIDTH  = 1,   // sideband carried alongside (>= 1)
    parameter USER_OUT_REG = 0   // 1: the sideband's RAM line ends in a fabric register (csgrt_delay_ram OUT_REG)
) (
    input  wire                     clk_i,
    input  wire                     rst_ni,    // synchronous, active low (valid bits only)
    input  wire                     ce_i,      // stage enable (low = stall)
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

    // Stage k reads the inputs (k = 0) or the registers of stage k-1 and
    // writes its own. Each stage's registers are plain registers of its
    // generate block, seen by the next stage through the wire arrays below,
    // so that the Verilator model writes each as a variable of its own:
    // array elements written one per always block each took a delayed-
    // assignment flag and value per clock (most of the simulation's time).
    reg  [R-1:0]  valid_q;
    wire [RW-1:0] rem_w  [0:R-1];
    wire [R-1:0]  root_w [0:R-1];
    wire [NW-1:0] n_w    [0:R-1];

    always @(posedge clk_i) begin
        if (!rst_ni) begin
            valid_q <= {R{1'b0}};
        end else if (ce_i) begin
            valid_q <= {valid_q[R-2:0], valid_i};
        end
    end

    genvar k;
    generate
        for (k = 0; k < R; k = k + 1) begin : g_stage
            localparam I = R - 1 - k;   // result bit found by this stage
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
            // rem_in < 2^R: its two top bits are always zero
            wire [1:0]    unused_rem_top = rem_in[RW-1:RW-2];
            wire [RW-1:0] rem_sh = {rem_in[RW-3:0], n_in[2*I+1:2*I]};
            wire [RW-1:0] trial  = {root_in, 2'b01};
            wire          take   = (rem_sh >= trial);
            // root_in < 2^k <= 2^(R-1): its top bit is always zero
            wire          unused_root_top = root_in[R-1];

            reg [RW-1:0] rem_q;
            reg [R-1:0]  root_q;
            reg [NW-1:0] n_q;
            always @(posedge clk_i)
                if (ce_i) begin
                    rem_q  <= take ? rem_sh - trial : rem_sh;
                    root_q <= {root_in[R-2:0], take};
                    n_q    <= n_in;
                end
            assign rem_w[k]  = rem_q;
            assign root_w[k] = root_q;
            assign n_w[k]    = n_q;
        end
    endgenerate

    // The sideband rides along R enabled clocks in a RAM delay line (block
    // or LUT RAM on the FPGA) rather than R copies in flip-flops.
    csgrt_delay_ram #(.WIDTH(USER_WIDTH), .STAGES(R), .OUT_REG(USER_OUT_REG)) u_user (
        .clk_i, .rst_ni, .ce_i, .data_i (user_i), .data_o (user_o)
    );

    assign valid_o = valid_q[R-1];
    assign root_o  = root_w[R-1];

    // the last stage's remainder and radicand copy are not needed
    wire unused_last = ^{rem_w[R-1], n_w[R-1]};

    generate
        if (RESULT_BITS < 2 || USER_WIDTH < 1) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_sqrt_core needs RESULT_BITS >= 2, USER_WIDTH >= 1");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
