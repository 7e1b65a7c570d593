`default_nettype none
// csgrt_mul_vec — N signed products p_k = a_k * b_k (N <= 3) with csgrt_mul's
// registers and latency, on N multipliers (II = 1) or on one multiplier that
// serves the N operand pairs in turn over a beat of three clocks (II = 3;
// csgrt_beat gives the beat).
//
// II = 3: the enclosing pipeline advances once a beat (csgrt_beat's adv, the
// clock of phase 2), so a_i and b_i are steady for a whole beat. Phase k
// feeds pair k to the multiplier (csgrt_mul, which runs on every running
// clock); its product comes out two clocks later: pair 0 at phase 2 of the
// same beat, pair 1 at phase 0 and pair 2 at phase 1 of the next. The next
// beat's advance (adv_i) copies the three to p_o, which then holds them for
// the whole beat after (csgrt_beat_gather, which keeps the multiplier's
// last three outputs).
// Timeline, beat k with pairs x0..x2, beat k+1 with y0..y2 (each column one
// clock):
//   beat         k          | k+1        | k+2
//   phase        0   1   2  | 0   1   2  | 0 1 2
//   mul input    x0  x1  x2 | y0  y1  y2 |
//   mul output   .   .   x0 | x1  x2  y0 |
//   caught at the clock's end:
//                        x0 | x1  x2  y0 |
//   p_o                     |        <-- | x0 x1 x2 (copied at the end of
//                                          beat k+1's phase 2, held a beat)
// So p_o shows the products of the operands of two beats earlier, as
// csgrt_mul's p_o shows those of two enabled clocks earlier: the pipeline
// around it keeps its delay lines (csgrt_delay, two stages on adv).
// II = 1: N csgrt_mul on ce_i (phase_i and adv_i unused).
// TILE_REG = 1: csgrt_mul's register behind each tile of a wide product.
// With II = 3 the product then comes out three clocks after its pair,
// at phase k of the next beat, and the gather takes pair 2's straight from
// the multiplier at the advance (csgrt_beat_gather LAT_MOD3 0): the same
// two beats. With II = 1 it is one enabled clock more.
//
// OP_REG = 1 (II = 3 only): the pair of the phase is chosen into a fabric
// register before csgrt_mul, so that the block's input register is fed by
// a flip-flop and not by the choice's LUTs (and the choice of the caller's
// operands before it) across the route to the block: the routed critical
// path of 911d777's 24-bit build, csgrt_spawn's X product, 2 LUTs then
// 5.84 ns of route into the block (80.78 MHz). One clock more: with
// TILE_REG 0 the product comes out three clocks after its pair (the
// gather's LAT_MOD3 0, two beats still); with TILE_REG 1 four, at phase
// k+1 of the next beat, and the gather takes pair 2's a beat later
// (LAT_MOD3 1): three beats. A caller's delay lines take the same count:
// (II == 3 && OP_REG == 1 && TILE_REG != 0) ? 3 : 2 (OP_REG -1 never adds a beat).
//
// OP_REG = -1 (the default) sets it where it costs no beat: II = 3 and
// TILE_REG 0, so that every time-shared multiplier's block is fed from a
// flip-flop unless its caller chose the tile register instead.
//
// Latency: 2 beats, 3 with II = 3, OP_REG 1 and TILE_REG 1 (II = 1: 2 +
// TILE_REG enabled clocks). Handshake: none (the
// enclosing pipeline's stall ce_i; everything holds while it is low).
// Multipliers: N (II = 1) or 1 (II = 3), each A_WIDTH x B_WIDTH.
module csgrt_mul_vec #(
    parameter A_WIDTH = 18,   // width of each signed operand a_k (>= 2)
    parameter B_WIDTH = 18,   // width of each signed operand b_k (>= 2)
    parameter integer N  = 3, // products (1..3)
    parameter integer II = 1, // 1: one multiplier per product; 3: one shared
    parameter TILE_REG   = 0, // csgrt_mul's: a register behind each tile (above)
    parameter OP_REG     = -1 // II = 3: the chosen pair registered before the multiplier (above);
                              // -1: where it is free, i.e. II = 3 with TILE_REG 0 (two beats either way)
) (
    input  wire                           clk_i,
    input  wire                           rst_ni,    // synchronous, active low
    input  wire                           ce_i,      // the pipeline runs (low = stall)
    input  wire                           adv_i,     // the beat's advance: csgrt_beat's adv_o (II = 3)
    input  wire [1:0]                     phase_i,   // csgrt_beat's phase (II = 3)
    input  wire [N*A_WIDTH-1:0]           a_i,       // pair k at k*A_WIDTH
    input  wire [N*B_WIDTH-1:0]           b_i,
    output wire [N*(A_WIDTH+B_WIDTH)-1:0] p_o        // product k at k*(A_WIDTH+B_WIDTH)
);

    localparam PW = A_WIDTH + B_WIDTH;
    // the operand register: as asked, or (-1) where it is free
    localparam integer OPR = (OP_REG >= 0) ? OP_REG : (II == 3 && TILE_REG == 0) ? 1 : 0;

    // adv_i must be the beat's advance: every time-shared unit passes it
    // down to here (csgrt_weigh, csgrt_unit and the direct users alike),
    // so the one check covers them all
    csgrt_check_same #(.WHAT("adv_i (is it the beat's adv_o?)")) u_check_adv (
        .clk_i, .rst_ni, .copy_i(adv_i), .orig_i(ce_i && (II == 1 || phase_i == 2'd2)));

    genvar k;
    generate
        if (II == 1) begin : g_parallel
            wire unused_phase = ^{phase_i, adv_i};
            for (k = 0; k < N; k = k + 1) begin : g_mul
                wire unused_v;
                csgrt_mul #(.A_WIDTH(A_WIDTH), .B_WIDTH(B_WIDTH), .TILE_REG(TILE_REG)) u_mul (
                    .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(ce_i), .valid_i(1'b0),
                    .a_i(a_i[k*A_WIDTH +: A_WIDTH]), .b_i(b_i[k*B_WIDTH +: B_WIDTH]),
                    .valid_o(unused_v), .p_o(p_o[k*PW +: PW]));
            end
        end else begin : g_shared
            // the pair of this phase (a phase without a pair feeds pair 0:
            // its product is never caught); P1, P2 keep the selects in range
            localparam integer P1 = (N > 1) ? 1 : 0;
            localparam integer P2 = (N > 2) ? 2 : 0;
            reg [A_WIDTH-1:0] a_sel;
            reg [B_WIDTH-1:0] b_sel;
            always @* begin
                a_sel = a_i[0 +: A_WIDTH];
                b_sel = b_i[0 +: B_WIDTH];
                if (N > 1 && phase_i == 2'd1) begin
                    a_sel = a_i[A_WIDTH*P1 +: A_WIDTH];
                    b_sel = b_i[B_WIDTH*P1 +: B_WIDTH];
                end
                if (N > 2 && phase_i == 2'd2) begin
                    a_sel = a_i[A_WIDTH*P2 +: A_WIDTH];
                    b_sel = b_i[B_WIDTH*P2 +: B_WIDTH];
                end
            end
            // OP_REG: the chosen pair from a register (csgrt_delay of 0
            // stages is a wire)
            wire [A_WIDTH-1:0] a_mul;
            wire [B_WIDTH-1:0] b_mul;
            wire               unused_op_v;
            csgrt_delay #(.WIDTH(A_WIDTH + B_WIDTH), .STAGES(OPR)) u_op_reg (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(ce_i), .valid_i(1'b0),
                .data_i({b_sel, a_sel}), .valid_o(unused_op_v), .data_o({b_mul, a_mul}));
            wire [PW-1:0] prod;
            wire          unused_v;
            csgrt_mul #(.A_WIDTH(A_WIDTH), .B_WIDTH(B_WIDTH), .TILE_REG(TILE_REG)) u_mul (
                .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(ce_i), .valid_i(1'b0),
                .a_i(a_mul), .b_i(b_mul), .valid_o(unused_v), .p_o(prod));
            // pair k's product comes out LAT = OP_REG + 2 + TILE_REG clocks
            // after phase k (2, 3 or 4: 2, 0 or 1 mod 3): gathered
            localparam integer LAT = OPR + 2 + (TILE_REG != 0 ? 1 : 0);
            csgrt_beat_gather #(.WIDTH(PW), .N(N), .LAT_MOD3(LAT % 3)) u_gather (
                .clk_i(clk_i), .ce_i(ce_i), .adv_i(adv_i), .d_i(prod), .q_o(p_o));
        end

        if (A_WIDTH < 2 || B_WIDTH < 2 || N < 1 || N > 3 || (II != 1 && II != 3) || OP_REG < -1 || OP_REG > 1
            || (II == 1 && OP_REG == 1)) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_mul_vec needs A_WIDTH, B_WIDTH >= 2, 1 <= N <= 3, II = 1 or 3, OP_REG -1, 0 or 1 (not 1 with II = 1)");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
