`default_nettype none
// csgrt_mul — registered signed multiplier, p = a * b (full A_WIDTH+B_WIDTH
// bit product, two's complement), meant to map onto ECP5 MULT18X18D blocks
// (yosys mul2dsp splits operands wider than 18 bits over several blocks; the
// input and output registers become the block's REG_INPUT/REG_OUTPUT).
//
// Latency: 2 clocks (input register, output register), counted in enabled
// clocks: every register, valid included, only moves when ce_i is high.
// Handshake: none of its own. valid_i is shifted alongside the operands and
// comes out as valid_o with the product; ce_i is the stall input of the
// enclosing pipeline (low = hold every register).
module csgrt_mul #(
    parameter A_WIDTH = 18,   // width of signed operand a (>= 2)
    parameter B_WIDTH = 18    // width of signed operand b (>= 2)
) (
    input  wire                       clk_i,
    input  wire                       rst_ni,   // synchronous, active low (valid bits only)
    input  wire                       ce_i,     // clock enable / stall (low = hold)
    input  wire                       valid_i,
    input  wire [A_WIDTH-1:0]         a_i,
    input  wire [B_WIDTH-1:0]         b_i,
    output wire                       valid_o,
    output wire [A_WIDTH+B_WIDTH-1:0] p_o
);

    localparam P_WIDTH = A_WIDTH + B_WIDTH;   // exact signed product width

    reg               valid_q, valid_q2;
    reg [A_WIDTH-1:0] a_q;
    reg [B_WIDTH-1:0] b_q;
    reg [P_WIDTH-1:0] p_q;
    wire [P_WIDTH-1:0] p_d;

    // Both operands signed: the product of an A- and a B-bit two's complement
    // number always fits in A+B bits. The operands are extended to the
    // context width P_WIDTH by the language rules (sign extension, both
    // being signed), which is exactly what a signed multiply needs.
    assign p_d = $signed(a_q) * $signed(b_q);

    always @(posedge clk_i) begin
        if (!rst_ni) begin
            valid_q  <= 1'b0;
            valid_q2 <= 1'b0;
        end else if (ce_i) begin
            valid_q  <= valid_i;
            valid_q2 <= valid_q;
        end
        if (ce_i) begin
            a_q <= a_i;
            b_q <= b_i;
            p_q <= p_d;
        end
    end

    assign valid_o = valid_q2;
    assign p_o     = p_q;

    generate
        if (A_WIDTH < 2 || B_WIDTH < 2) begin : g_bad_width
            initial begin
                $display("ERROR %m: csgrt_mul A_WIDTH and B_WIDTH must be >= 2");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
