`default_nettype none
// tb_mul — Verilator top for tb_mul.cpp: csgrt_mul at the operand widths
// the design uses and at the edges of the ECP5 tiling (one chunk, an 18-bit
// top chunk, a 1-bit top chunk, three chunks), side by side on one clock
// enable. Built twice: behavioural (build/tb/mul) and with CSGRT_ECP5_DSP
// and the MULT18X18D model (build/tb/mul_ecp5). Instance k's operands are
// a_i/b_i[k*MAXW +: WA(k)/WB(k)], its product p_o[k*2*MAXW +: WA(k)+WB(k)];
// the width table is kWidths in tb_mul.cpp. TILE_REG = 1 (build/tb/mul_ecp5_treg)
// puts a register behind each tile: latency 3.
module tb_mul #(
    parameter N        = 18,   // instances
    parameter MAXW     = 40,   // operand slot width
    parameter TILE_REG = 0     // csgrt_mul's
) (
    input  wire              clk_i,
    input  wire              rst_ni,
    input  wire              ce_i,
    input  wire              valid_i,
    input  wire [N*MAXW-1:0] a_i,
    input  wire [N*MAXW-1:0] b_i,
    output wire [N-1:0]      valid_o,
    output wire [2*N*MAXW-1:0] p_o
);
    function automatic integer width_a(input integer k);
        case (k)
            0: width_a = 18;  1: width_a = 24;  2: width_a = 21;  3: width_a = 17;
            4: width_a = 32;  5: width_a = 19;  6: width_a = 26;  7: width_a = 36;
            8: width_a = 37;  9: width_a = 2;  10: width_a = 29; 11: width_a = 16;
           12: width_a = 12; 13: width_a = 34; 14: width_a = 24; 15: width_a = 27;
           16: width_a = 22; default: width_a = 24;
        endcase
    endfunction
    function automatic integer width_b(input integer k);
        case (k)
            0: width_b = 18;  1: width_b = 24;  2: width_b = 21;  3: width_b = 25;
            4: width_b = 32;  5: width_b = 40;  6: width_b = 24;  7: width_b = 36;
            8: width_b = 5;   9: width_b = 2;  10: width_b = 29; 11: width_b = 19;
           12: width_b = 12; 13: width_b = 34; 14: width_b = 26; 15: width_b = 27;
           16: width_b = 24; default: width_b = 30;
        endcase
    endfunction

    genvar k;
    generate
        for (k = 0; k < N; k = k + 1) begin : g_mul
            localparam WA = width_a(k);
            localparam WB = width_b(k);
            wire [WA+WB-1:0] p;
            csgrt_mul #(.A_WIDTH(WA), .B_WIDTH(WB), .TILE_REG(TILE_REG)) u_mul (
                .clk_i, .rst_ni, .ce_i, .valid_i,
                .a_i (a_i[k*MAXW +: WA]), .b_i (b_i[k*MAXW +: WB]),
                .valid_o (valid_o[k]), .p_o (p));
            assign p_o[k*2*MAXW +: 2*MAXW] = {{(2*MAXW-WA-WB){p[WA+WB-1]}}, p};
        end
    endgenerate
    wire unused_slots = ^{a_i, b_i};   // the slots' bits above each instance's widths
endmodule

`default_nettype wire
