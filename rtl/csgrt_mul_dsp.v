`default_nettype none
// csgrt_mul_dsp — one ECP5 MULT18X18D with its input and output registers
// (REG_INPUTA/B_CLK = REG_OUTPUT_CLK = CLK0, all on CE0): p = a * b, 18 x 18
// -> 36 bits, each operand signed or unsigned by parameter. It is one tile
// of csgrt_mul's ECP5 mapping (CSGRT_ECP5_DSP); nextpnr times it as
// MULT18X18D_REGS_ALL, so the multiplier array sits between two registers
// inside the block and the fabric sees a register on either side.
//
// Latency: 2 clocks (input register, output register), counted in enabled
// clocks (ce_i low holds both). No reset: the registers hold data only
// (GSR disabled, RST0 tied low), as csgrt_mul's data registers.
// p_o: a signed operand is two's complement, an unsigned one plain binary;
// the 36-bit product is two's complement when either operand is signed,
// plain binary when both are unsigned (it always fits 36 bits).
// Simulation: tb/ecp5/MULT18X18D.v models the primitive for Verilator.
module csgrt_mul_dsp #(
    parameter A_SIGNED = 1,   // 1: a_i is two's complement, 0: unsigned
    parameter B_SIGNED = 1
) (
    input  wire        clk_i,
    input  wire        ce_i,    // clock enable / stall (low = hold)
    input  wire [17:0] a_i,
    input  wire [17:0] b_i,
    output wire [35:0] p_o
);

    localparam [0:0] SA = (A_SIGNED != 0) ? 1'b1 : 1'b0;
    localparam [0:0] SB = (B_SIGNED != 0) ? 1'b1 : 1'b0;

    MULT18X18D #(
        .REG_INPUTA_CLK ("CLK0"), .REG_INPUTA_CE ("CE0"), .REG_INPUTA_RST ("RST0"),
        .REG_INPUTB_CLK ("CLK0"), .REG_INPUTB_CE ("CE0"), .REG_INPUTB_RST ("RST0"),
        .REG_OUTPUT_CLK ("CLK0"), .REG_OUTPUT_CE ("CE0"), .REG_OUTPUT_RST ("RST0"),
        // SOURCEB_MODE: B_SHIFT (the primitive's default) takes the B
        // input while SOURCEB = 0. "B_INPUT" is no mode of the block:
        // yosys and nextpnr passed it through and ecppack crashed on it
        // (no bitstream of a tiled build until this was found).
        .GSR ("DISABLED"), .RESETMODE ("SYNC"), .SOURCEB_MODE ("B_SHIFT")
    ) u_mult (
        .A0 (a_i[0]),  .A1 (a_i[1]),  .A2 (a_i[2]),  .A3 (a_i[3]),  .A4 (a_i[4]),  .A5 (a_i[5]),
        .A6 (a_i[6]),  .A7 (a_i[7]),  .A8 (a_i[8]),  .A9 (a_i[9]),  .A10(a_i[10]), .A11(a_i[11]),
        .A12(a_i[12]), .A13(a_i[13]), .A14(a_i[14]), .A15(a_i[15]), .A16(a_i[16]), .A17(a_i[17]),
        .B0 (b_i[0]),  .B1 (b_i[1]),  .B2 (b_i[2]),  .B3 (b_i[3]),  .B4 (b_i[4]),  .B5 (b_i[5]),
        .B6 (b_i[6]),  .B7 (b_i[7]),  .B8 (b_i[8]),  .B9 (b_i[9]),  .B10(b_i[10]), .B11(b_i[11]),
        .B12(b_i[12]), .B13(b_i[13]), .B14(b_i[14]), .B15(b_i[15]), .B16(b_i[16]), .B17(b_i[17]),
        .SIGNEDA (SA), .SIGNEDB (SB), .SOURCEA (1'b0), .SOURCEB (1'b0),
        .CLK0 (clk_i), .CE0 (ce_i), .RST0 (1'b0),
`ifndef SYNTHESIS
        // For the FPGA these inputs stay unconnected (nextpnr ties them
        // off): tied to a constant each would be a net to route into the
        // DSP tile (70 per block, and the router failed on them at BITS 16)
        // and would take the tile's shared clock, enable and reset ports.
        // The C input feeds only the ALU cascade, the shift inputs are
        // not selected (SOURCEA/B = 0), the other clocks, enables and
        // resets are not used by any register (all are on CLK0/CE0/RST0).
        .C0 (1'b0), .C1 (1'b0), .C2 (1'b0), .C3 (1'b0), .C4 (1'b0), .C5 (1'b0),
        .C6 (1'b0), .C7 (1'b0), .C8 (1'b0), .C9 (1'b0), .C10(1'b0), .C11(1'b0),
        .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
        .CLK1 (1'b0), .CLK2 (1'b0), .CLK3 (1'b0),
        .CE1 (1'b0),  .CE2 (1'b0),  .CE3 (1'b0),
        .RST1 (1'b0), .RST2 (1'b0), .RST3 (1'b0),
        .SRIA0 (1'b0), .SRIA1 (1'b0), .SRIA2 (1'b0), .SRIA3 (1'b0), .SRIA4 (1'b0), .SRIA5 (1'b0),
        .SRIA6 (1'b0), .SRIA7 (1'b0), .SRIA8 (1'b0), .SRIA9 (1'b0), .SRIA10(1'b0), .SRIA11(1'b0),
        .SRIA12(1'b0), .SRIA13(1'b0), .SRIA14(1'b0), .SRIA15(1'b0), .SRIA16(1'b0), .SRIA17(1'b0),
        .SRIB0 (1'b0), .SRIB1 (1'b0), .SRIB2 (1'b0), .SRIB3 (1'b0), .SRIB4 (1'b0), .SRIB5 (1'b0),
        .SRIB6 (1'b0), .SRIB7 (1'b0), .SRIB8 (1'b0), .SRIB9 (1'b0), .SRIB10(1'b0), .SRIB11(1'b0),
        .SRIB12(1'b0), .SRIB13(1'b0), .SRIB14(1'b0), .SRIB15(1'b0), .SRIB16(1'b0), .SRIB17(1'b0),
`endif
        .P0 (p_o[0]),  .P1 (p_o[1]),  .P2 (p_o[2]),  .P3 (p_o[3]),  .P4 (p_o[4]),  .P5 (p_o[5]),
        .P6 (p_o[6]),  .P7 (p_o[7]),  .P8 (p_o[8]),  .P9 (p_o[9]),  .P10(p_o[10]), .P11(p_o[11]),
        .P12(p_o[12]), .P13(p_o[13]), .P14(p_o[14]), .P15(p_o[15]), .P16(p_o[16]), .P17(p_o[17]),
        .P18(p_o[18]), .P19(p_o[19]), .P20(p_o[20]), .P21(p_o[21]), .P22(p_o[22]), .P23(p_o[23]),
        .P24(p_o[24]), .P25(p_o[25]), .P26(p_o[26]), .P27(p_o[27]), .P28(p_o[28]), .P29(p_o[29]),
        .P30(p_o[30]), .P31(p_o[31]), .P32(p_o[32]), .P33(p_o[33]), .P34(p_o[34]), .P35(p_o[35]),
        /* verilator lint_off PINCONNECTEMPTY */
        // cascade and pass-through outputs: not used
        .SROA0 (), .SROA1 (), .SROA2 (), .SROA3 (), .SROA4 (), .SROA5 (),
        .SROA6 (), .SROA7 (), .SROA8 (), .SROA9 (), .SROA10(), .SROA11(),
        .SROA12(), .SROA13(), .SROA14(), .SROA15(), .SROA16(), .SROA17(),
        .SROB0 (), .SROB1 (), .SROB2 (), .SROB3 (), .SROB4 (), .SROB5 (),
        .SROB6 (), .SROB7 (), .SROB8 (), .SROB9 (), .SROB10(), .SROB11(),
        .SROB12(), .SROB13(), .SROB14(), .SROB15(), .SROB16(), .SROB17(),
        .ROA0 (), .ROA1 (), .ROA2 (), .ROA3 (), .ROA4 (), .ROA5 (),
        .ROA6 (), .ROA7 (), .ROA8 (), .ROA9 (), .ROA10(), .ROA11(),
        .ROA12(), .ROA13(), .ROA14(), .ROA15(), .ROA16(), .ROA17(),
        .ROB0 (), .ROB1 (), .ROB2 (), .ROB3 (), .ROB4 (), .ROB5 (),
        .ROB6 (), .ROB7 (), .ROB8 (), .ROB9 (), .ROB10(), .ROB11(),
        .ROB12(), .ROB13(), .ROB14(), .ROB15(), .ROB16(), .ROB17(),
        .ROC0 (), .ROC1 (), .ROC2 (), .ROC3 (), .ROC4 (), .ROC5 (),
        .ROC6 (), .ROC7 (), .ROC8 (), .ROC9 (), .ROC10(), .ROC11(),
        .ROC12(), .ROC13(), .ROC14(), .ROC15(), .ROC16(), .ROC17(),
        .SIGNEDP ()
        /* verilator lint_on PINCONNECTEMPTY */
    );

endmodule

`default_nettype wire
