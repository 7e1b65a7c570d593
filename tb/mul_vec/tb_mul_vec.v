`default_nettype none
// tb_mul_vec — Verilator top for tb_mul_vec.cpp: csgrt_mul_vec time-shared
// (II = 3) with one, two and three products, and unshared (II = 1) with
// three, each on its own csgrt_beat from one clock enable (and its value
// after the next edge, ce_next_i, for the beats' registered advance
// adv_q_o, which must equal adv_o on every clock). Operand slots
// are MAXW bits, products 2 MAXW bits (sign-extended); the widths are
// kInst in tb_mul_vec.cpp. TILE_REG = 1 (build/tb/mul_vec_treg, with the
// MULT18X18D tiles) gives the time-shared instances csgrt_mul's register
// behind each tile: their latency must stay two beats. OP_REG is
// csgrt_mul_vec's register after the operand choice: -1 (build/tb/mul_vec
// and mul_vec_treg) as the RTL's callers leave it, on where it is free (so
// on without TILE_REG, off with it); 1 (mul_vec_oreg, with TILE_REG = 1:
// three beats); 0 (mul_vec_noop: off, two beats).
module tb_mul_vec #(
    parameter MAXW     = 32,
    parameter TILE_REG = 0,
    parameter OP_REG   = -1
) (
    input  wire              clk_i,
    input  wire              rst_ni,
    input  wire              ce_i,
    input  wire              ce_next_i,  // ce_i after the next rising edge
    output wire [1:0]        phase3_o,   // the II = 3 beat
    output wire              adv3_o,
    output wire              adv1_o,     // the II = 1 beat (= ce_i)
    output wire              adv3_q_o,   // the beats' registered advances
    output wire              adv1_q_o,
    input  wire [4*3*MAXW-1:0] a_i,      // instance k, pair j at (3k+j)*MAXW
    input  wire [4*3*MAXW-1:0] b_i,
    output wire [4*3*2*MAXW-1:0] p_o     // instance k, product j at (3k+j)*2*MAXW
);
    wire [1:0] phase1;
    wire       unused_last3, unused_last1;
    csgrt_beat #(.II(3)) u_beat3 (.clk_i, .rst_ni, .ce_i, .ce_next_i, .phase_o(phase3_o), .last_o(unused_last3),
                                  .adv_o(adv3_o), .adv_q_o(adv3_q_o));
    csgrt_beat #(.II(1)) u_beat1 (.clk_i, .rst_ni, .ce_i, .ce_next_i, .phase_o(phase1), .last_o(unused_last1),
                                  .adv_o(adv1_o), .adv_q_o(adv1_q_o));

    // instance k: {A width, B width, N, II}
    function automatic integer wa(input integer k);
        case (k) 0: wa = 24; 1: wa = 17; 2: wa = 18; default: wa = 24; endcase
    endfunction
    function automatic integer wb(input integer k);
        case (k) 0: wb = 21; 1: wb = 18; 2: wb = 18; default: wb = 21; endcase
    endfunction
    function automatic integer nprod(input integer k);
        case (k) 0: nprod = 3; 1: nprod = 2; 2: nprod = 1; default: nprod = 3; endcase
    endfunction

    genvar k, j;
    generate
        for (k = 0; k < 4; k = k + 1) begin : g_inst
            localparam WA = wa(k);
            localparam WB = wb(k);
            localparam NP = nprod(k);
            localparam II = (k == 3) ? 1 : 3;
            wire [NP*WA-1:0]      a;
            wire [NP*WB-1:0]      b;
            wire [NP*(WA+WB)-1:0] p;
            for (j = 0; j < NP; j = j + 1) begin : g_pair
                assign a[j*WA +: WA] = a_i[(3*k+j)*MAXW +: WA];
                assign b[j*WB +: WB] = b_i[(3*k+j)*MAXW +: WB];
                wire [WA+WB-1:0] pj = p[j*(WA+WB) +: WA+WB];
                assign p_o[(3*k+j)*2*MAXW +: 2*MAXW] = {{(2*MAXW-WA-WB){pj[WA+WB-1]}}, pj};
            end
            for (j = NP; j < 3; j = j + 1) begin : g_none
                assign p_o[(3*k+j)*2*MAXW +: 2*MAXW] = {(2*MAXW){1'b0}};
            end
            csgrt_mul_vec #(.A_WIDTH(WA), .B_WIDTH(WB), .N(NP), .II(II), .TILE_REG(II == 3 ? TILE_REG : 0),
                           .OP_REG(II == 3 ? OP_REG : -1)) u_mul (
                .clk_i, .rst_ni, .ce_i, .adv_i((II == 3) ? adv3_o : adv1_o), .phase_i((II == 3) ? phase3_o : phase1),
                .a_i(a), .b_i(b), .p_o(p));
        end
    endgenerate
    wire unused_slots = ^{a_i, b_i};   // the slots' bits above each instance's widths
endmodule

`default_nettype wire
