`default_nettype none
// csgrt_delay — a valid bit and a data word delayed by STAGES registers, all
// moving on one stage enable; keeps side data in step with a csgrt_mul.
//
// Latency: STAGES clocks, counted in enabled clocks (STAGES = 0: a wire).
// Handshake: none; ce_i low holds every register (the enclosing pipeline's
// global stall).
module csgrt_delay #(
    parameter WIDTH  = 8,   // data width (>= 1)
    parameter STAGES = 2    // number of registers (>= 0)
) (
    input  wire             clk_i,
    input  wire             rst_ni,   // synchronous, active low (valid bits only)
    input  wire             ce_i,     // stage enable (low = stall)
    input  wire             valid_i,
    input  wire [WIDTH-1:0] data_i,
    output wire             valid_o,
    output wire [WIDTH-1:0] data_o
);

    genvar k;
    generate
        if (STAGES == 0) begin : g_wire
            // no register: a time-shared pipeline's optional input stage
            // (II = 1 needs none, II = 3 one)
            wire unused_clk = ^{clk_i, rst_ni, ce_i};
            assign valid_o = valid_i;
            assign data_o  = data_i;
        end else begin : g_regs
            // one word per stage, each the register of its generate block, seen by
            // the next stage through data_w (not a flat STAGES x WIDTH vector, which
            // the Verilator model would shift as a whole every clock, nor an array
            // written element by element, which costs it a delayed-assignment flag
            // and value per element and clock)
            reg [STAGES-1:0] valid_q;
            wire [WIDTH-1:0] data_w [0:STAGES-1];
            if (STAGES == 1) begin : g_one
                always @(posedge clk_i) begin
                    if (!rst_ni) valid_q <= 1'b0;
                    else if (ce_i) valid_q <= valid_i;
                end
            end else begin : g_many
                always @(posedge clk_i) begin
                    if (!rst_ni) valid_q <= {STAGES{1'b0}};
                    else if (ce_i) valid_q <= {valid_q[STAGES-2:0], valid_i};
                end
            end
            for (k = 0; k < STAGES; k = k + 1) begin : g_stage
                reg [WIDTH-1:0] data_q;
                if (k == 0) begin : g_first
                    always @(posedge clk_i) if (ce_i) data_q <= data_i;
                end else begin : g_next
                    always @(posedge clk_i) if (ce_i) data_q <= data_w[k-1];
                end
                assign data_w[k] = data_q;
            end
            assign valid_o = valid_q[STAGES-1];
            assign data_o  = data_w[STAGES-1];
        end
        if (WIDTH < 1 || STAGES < 0) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_delay needs WIDTH >= 1, STAGES >= 0");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
