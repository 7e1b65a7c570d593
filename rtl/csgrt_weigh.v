`default_nettype none
// csgrt_weigh — three colour products rounded to 12 fraction bits:
// p_c = rnd(a_c b_c, 12) = (a_c b_c + 2^11) >> 12 for c = r, g, b, the
// `weigh` of the ray tree (model/raytree.cpp, docs/effects.md "Colour").
// Operands are unsigned; the product is exact, so P_WIDTH = A_WIDTH +
// B_WIDTH - 11 always holds the result.
//
// Latency: 2 clocks (csgrt_mul's input and output registers), counted in
// enabled clocks; the rounding adder follows the output register. A user
// word travels alongside. Handshake: none (ce_i is the enclosing
// pipeline's stall). Multipliers: 3.
module csgrt_weigh #(
    parameter A_WIDTH    = 16,   // unsigned operand a
    parameter B_WIDTH    = 16,   // unsigned operand b
    parameter USER_WIDTH = 1,
    parameter P_WIDTH    = A_WIDTH + B_WIDTH - 11
) (
    input  wire                    clk_i,
    input  wire                    rst_ni,   // synchronous, active low (valid bits only)
    input  wire                    ce_i,
    input  wire                    valid_i,
    input  wire [3*A_WIDTH-1:0]    a_i,      // channel c at c*A_WIDTH
    input  wire [3*B_WIDTH-1:0]    b_i,
    input  wire [USER_WIDTH-1:0]   user_i,
    output wire                    valid_o,
    output wire [3*P_WIDTH-1:0]    p_o,
    output wire [USER_WIDTH-1:0]   user_o
);
    localparam MW = A_WIDTH + B_WIDTH + 2;   // signed product of the zero-extended operands

    genvar c;
    generate
        for (c = 0; c < 3; c = c + 1) begin : g_ch
            wire          unused_v;
            wire [MW-1:0] prod;
            csgrt_mul #(.A_WIDTH(A_WIDTH + 1), .B_WIDTH(B_WIDTH + 1)) u_mul (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(ce_i), .valid_i(valid_i),
                .a_i({1'b0, a_i[c*A_WIDTH +: A_WIDTH]}), .b_i({1'b0, b_i[c*B_WIDTH +: B_WIDTH]}),
                .valid_o(unused_v), .p_o(prod));
            // the product is non-negative and below 2^(A+B): the top two bits are 0
            wire [MW-1:0] rounded = prod + {{(MW-12){1'b0}}, 1'b1, 11'd0};
            wire unused_bits = ^{rounded[11:0], rounded[MW-1:12+P_WIDTH]};
            assign p_o[c*P_WIDTH +: P_WIDTH] = rounded[12 +: P_WIDTH];
        end
    endgenerate

    csgrt_delay #(.WIDTH(USER_WIDTH), .STAGES(2)) u_dly (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(ce_i), .valid_i(valid_i),
        .data_i(user_i), .valid_o(valid_o), .data_o(user_o));

    initial begin
        if (P_WIDTH < 1 || P_WIDTH > A_WIDTH + B_WIDTH - 11) begin
            $display("ERROR %m: csgrt_weigh P_WIDTH must be 1 .. A_WIDTH + B_WIDTH - 11");
            $finish;
        end
    end
endmodule
`default_nettype wire
