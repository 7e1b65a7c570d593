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
// pipeline's stall). Multipliers: 3; II = 3 (a time-shared pipeline,
// csgrt_beat): 1 serving the three channels in turn (csgrt_mul_vec), the
// latency 2 beats, the user word moving on the beat's advance.
module csgrt_weigh #(
    parameter A_WIDTH    = 16,   // unsigned operand a
    parameter B_WIDTH    = 16,   // unsigned operand b
    parameter USER_WIDTH = 1,
    parameter P_WIDTH    = A_WIDTH + B_WIDTH - 11,
    parameter II         = 1      // running clocks per beat: 1 or 3
) (
    input  wire                    clk_i,
    input  wire                    rst_ni,   // synchronous, active low (valid bits only)
    input  wire                    ce_i,     // the pipeline runs (low = stall)
    input  wire                    adv_i,    // the beat's advance: csgrt_beat's adv_o (a register)
    input  wire [1:0]              phase_i,  // csgrt_beat's phase (II = 3; 0 for II = 1)
    input  wire                    valid_i,
    input  wire [3*A_WIDTH-1:0]    a_i,      // channel c at c*A_WIDTH
    input  wire [3*B_WIDTH-1:0]    b_i,
    input  wire [USER_WIDTH-1:0]   user_i,
    output wire                    valid_o,
    output wire [3*P_WIDTH-1:0]    p_o,
    output wire [USER_WIDTH-1:0]   user_o
);
    localparam MW = A_WIDTH + B_WIDTH + 2;   // signed product of the zero-extended operands

    // the operands zero-extended: signed and non-negative
    wire [3*(A_WIDTH+1)-1:0] a_x;
    wire [3*(B_WIDTH+1)-1:0] b_x;
    wire [3*MW-1:0]          prods;
    csgrt_mul_vec #(.A_WIDTH(A_WIDTH + 1), .B_WIDTH(B_WIDTH + 1), .N(3), .II(II)) u_mul (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(ce_i), .adv_i(adv_i), .phase_i(phase_i), .a_i(a_x), .b_i(b_x), .p_o(prods));
    wire adv = adv_i;   // the beat's advance

    genvar c;
    generate
        for (c = 0; c < 3; c = c + 1) begin : g_ch
            assign a_x[c*(A_WIDTH+1) +: A_WIDTH+1] = {1'b0, a_i[c*A_WIDTH +: A_WIDTH]};
            assign b_x[c*(B_WIDTH+1) +: B_WIDTH+1] = {1'b0, b_i[c*B_WIDTH +: B_WIDTH]};
            wire [MW-1:0] prod = prods[c*MW +: MW];
            // the product is non-negative and below 2^(A+B): the top two bits are 0
            wire [MW-1:0] rounded = prod + {{(MW-12){1'b0}}, 1'b1, 11'd0};
            wire unused_bits = ^{rounded[11:0], rounded[MW-1:12+P_WIDTH]};
            assign p_o[c*P_WIDTH +: P_WIDTH] = rounded[12 +: P_WIDTH];
        end
    endgenerate

    csgrt_delay #(.WIDTH(USER_WIDTH), .STAGES(2)) u_dly (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(adv), .valid_i(valid_i),
        .data_i(user_i), .valid_o(valid_o), .data_o(user_o));

    initial begin
        if (P_WIDTH < 1 || P_WIDTH > A_WIDTH + B_WIDTH - 11) begin
            $display("ERROR %m: csgrt_weigh P_WIDTH must be 1 .. A_WIDTH + B_WIDTH - 11");
            $finish;
        end
    end
endmodule
`default_nettype wire
