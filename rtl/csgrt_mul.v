`default_nettype none
// csgrt_mul — registered signed multiplier, p = a * b (full A_WIDTH+B_WIDTH
// bit product, two's complement).
//
// Two implementations of the same function and latency:
//  * behavioural (default): input register, `*`, output register. Yosys
//    maps the `*` through mul2dsp onto MULT18X18D blocks but leaves both
//    registers in the fabric (synth_ecp5 absorbs none into the block).
//  * CSGRT_ECP5_DSP (tools/synth.sh and the board bench define it): the
//    product is cut into tiles of 18-bit operand chunks (the top chunk of an
//    operand signed, the others unsigned 18-bit), each tile one MULT18X18D
//    with its input and output registers inside (csgrt_mul_dsp), or, when
//    the tile is small (chunk widths' product <= LUT_TILE_MAX, by default 36,
//    i.e. the 6 x 6 top corner of a 24 x 24 product; tools/synth.sh
//    --lut-tile-max sets it for every instance through the define
//    CSGRT_LUT_TILE_MAX, trading blocks for LUTs), shift-and-add rows in the fabric
//    between the same two registers. p_o is the sum of the shifted tiles: the registered
//    product itself for a one-tile product; for a wider one an adder after
//    the tiles' output registers (the consumer's stage sees that adder).
//    A 24 x 24 product takes 3 blocks (mul2dsp: 4); a 16 x 16 one 1 block
//    and no fabric register at all (mul2dsp: 1 block, 64 FF around it).
//    Simulation uses tb/ecp5/MULT18X18D.v for the block; tb/mul checks both
//    implementations against each other and the exact product.
//
// Latency: 2 clocks (input register, output register), counted in enabled
// clocks: every register, valid included, only moves when ce_i is high.
// OUT_REG = 1 adds a fabric register after the product (after a wide
// product's tile sum): 3 clocks. The consumer's stage then starts at
// flip-flops the placer can put beside its own logic, not at the blocks'
// output registers in the DSP columns (the routed critical path of a build
// was a block's output -> 4.4 ns of route -> the tiles' sum -> the
// consumer's three-product sum, docs/fpga.md).
// TILE_REG = 1 adds a register before the sum instead: behind each tile
// of a wide product (its MULT18X18D's output register, or a fabric
// tile's), so that the route from the block in its DSP column ends at a
// flip-flop the placer can put beside the block, and the tiles' sum starts
// from flip-flops (the routed critical path of the first 24-bit build: a
// P0 tile -> 5.63 ns of route -> the tiles' sum -> OUT_REG's register,
// docs/fpga.md). One clock more; behavioural: a register after the product.
// A one-tile product has no sum, and the register is only a clock of delay.
// Latency: 2 + TILE_REG + OUT_REG clocks.
// Handshake: none of its own. valid_i is shifted alongside the operands and
// comes out as valid_o with the product; ce_i is the stall input of the
// enclosing pipeline (low = hold every register).
`ifndef CSGRT_LUT_TILE_MAX
`define CSGRT_LUT_TILE_MAX 36
`endif
module csgrt_mul #(
    parameter A_WIDTH = 18,   // width of signed operand a (>= 2)
    parameter B_WIDTH = 18,   // width of signed operand b (>= 2)
    // CSGRT_ECP5_DSP: a tile whose chunk widths' product is at most this is
    // built in the fabric (default 36: the 6 x 6 corner of a 24 x 24 product)
    parameter LUT_TILE_MAX = `CSGRT_LUT_TILE_MAX,
    parameter OUT_REG = 0,    // 1: one more register after the product (latency 3)
    parameter TILE_REG = 0    // 1: a register behind each tile, before their sum (one clock more, above)
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

    // valid through the input, output and tile registers (OUT_REG's below)
    localparam VL = 2 + (TILE_REG != 0 ? 1 : 0);
    reg [VL-1:0] valid_q;
    always @(posedge clk_i) begin
        if (!rst_ni)   valid_q <= {VL{1'b0}};
        else if (ce_i) valid_q <= {valid_q[VL-2:0], valid_i};
    end
    wire valid_w = valid_q[VL-1];
    wire [P_WIDTH-1:0] p_w;   // the product after the two registers (the tile registers and the tiles' sum)

`ifndef CSGRT_ECP5_DSP
    // ---- behavioural
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
        if (ce_i) begin
            a_q <= a_i;
            b_q <= b_i;
            p_q <= p_d;
        end
    end
    // TILE_REG: one more register (csgrt_delay of 0 stages is a wire)
    wire unused_tv;
    csgrt_delay #(.WIDTH(P_WIDTH), .STAGES(TILE_REG != 0 ? 1 : 0)) u_tile_reg (
        .clk_i, .rst_ni, .ce_i, .valid_i(1'b0), .data_i(p_q), .valid_o(unused_tv), .data_o(p_w));
`else
    // ---- ECP5: tiles of 18-bit chunks
    // Operand x of width W is sum_k x_k 2^(18k), chunk k < N-1 unsigned 18
    // bits, the top chunk N-1 signed, W - 18(N-1) bits (1..18). A tile
    // (i, j) is a_i b_j shifted by 18(i+j); its exact value fits P_WIDTH
    // sign-extended, and the tiles' sum modulo 2^P_WIDTH is the product.
    localparam NA = (A_WIDTH + 17) / 18;
    localparam NB = (B_WIDTH + 17) / 18;

    wire [NA*NB*P_WIDTH-1:0] tile;   // each tile's value, extended and shifted
    genvar i, j;
    generate
        for (i = 0; i < NA; i = i + 1) begin : g_a
            for (j = 0; j < NB; j = j + 1) begin : g_b
                localparam WA = (i == NA - 1) ? A_WIDTH - 18 * (NA - 1) : 18;
                localparam WB = (j == NB - 1) ? B_WIDTH - 18 * (NB - 1) : 18;
                localparam SA = (i == NA - 1);   // top chunks are signed
                localparam SB = (j == NB - 1);
                localparam SH = 18 * (i + j);
                wire [WA-1:0] a_c = a_i[18*i +: WA];
                wire [WB-1:0] b_c = b_i[18*j +: WB];
                // the chunks as WA+1 / WB+1 bit signed numbers
                wire [WA:0] a_x = {SA ? a_c[WA-1] : 1'b0, a_c};
                wire [WB:0] b_x = {SB ? b_c[WB-1] : 1'b0, b_c};
                wire [WA+WB+1:0] v;              // the tile's exact value, signed
                if (WA * WB <= LUT_TILE_MAX) begin : g_lut
                    // fabric tile, written as shifted rows of the wider
                    // chunk, one per bit of the narrower one, the sign bit's
                    // row subtracted: yosys sees adders, not a `*` it would
                    // put in a block after all
                    localparam VW = WA + WB + 2;
                    localparam WN = (WA < WB) ? WA : WB;   // the narrower chunk
                    localparam WW = WA + WB - WN;          // the wider one
                    reg [WW:0]    w_q;
                    reg [WN:0]    n_q;
                    wire [VW-1:0] w_e = {{(WN+1){w_q[WW]}}, w_q};
                    // the rows summed as two balanced trees (rows 0 .. H-1
                    // and H .. WN, each 3 adders deep for up to 8 rows)
                    // rather than one after the other (WN + 1 deep); the
                    // sign row (WN) is negated in its place. Leaves past
                    // the rows are zero and their adders vanish.
                    localparam NL = 8;             // leaves per half: WN + 1 <= 2 NL (checked here)
                    localparam H  = (WN + 2) / 2;  // rows in the low half
                    if (WN + 1 > 2 * NL) begin : g_bad_tile
                        initial begin
                            $display("ERROR %m: csgrt_mul fabric tiles take at most 15 x 15 bits (LUT_TILE_MAX < 256)");
                            $finish;
                        end
                    end
                    wire [VW-1:0] leaf_lo [0:NL-1];
                    wire [VW-1:0] leaf_hi [0:NL-1];
                    genvar r;
                    for (r = 0; r < NL; r = r + 1) begin : g_leaf
                        // row k: w << k where bit k of n is set; the sign row negated
                        if (r < H) begin : g_lo
                            assign leaf_lo[r] = (w_e << r) & {VW{n_q[r]}};
                        end else begin : g_lo_zero
                            assign leaf_lo[r] = {VW{1'b0}};
                        end
                        if (H + r < WN) begin : g_hi
                            assign leaf_hi[r] = (w_e << (H + r)) & {VW{n_q[H + r]}};
                        end else if (H + r == WN) begin : g_hi_sign
                            assign leaf_hi[r] = {VW{1'b0}} - ((w_e << WN) & {VW{n_q[WN]}});
                        end else begin : g_hi_zero
                            assign leaf_hi[r] = {VW{1'b0}};
                        end
                    end
                    wire [VW-1:0] half_lo = ((leaf_lo[0] + leaf_lo[1]) + (leaf_lo[2] + leaf_lo[3]))
                                          + ((leaf_lo[4] + leaf_lo[5]) + (leaf_lo[6] + leaf_lo[7]));
                    wire [VW-1:0] half_hi = ((leaf_hi[0] + leaf_hi[1]) + (leaf_hi[2] + leaf_hi[3]))
                                          + ((leaf_hi[4] + leaf_hi[5]) + (leaf_hi[6] + leaf_hi[7]));
                    wire [WW:0] w_x;
                    wire [WN:0] n_x;
                    if (WA < WB) begin : g_b_wide
                        assign w_x = b_x;
                        assign n_x = a_x;
                    end else begin : g_a_wide
                        assign w_x = a_x;
                        assign n_x = b_x;
                    end
                    always @(posedge clk_i)
                        if (ce_i) begin
                            w_q <= w_x;
                            n_q <= n_x;
                        end
                    if (TILE_REG != 0) begin : g_halves
                        // the tile register follows: the two halves of the
                        // tree are registered where a block has its output
                        // register, and added on the way into the tile
                        // register (a 6 x 6 tile's whole tree in one clock
                        // was the 24-bit netlist's worst path after the
                        // non-restoring dividers, tools/logic_depth.py
                        // 12.39 ns, 6 LUT levels)
                        reg [VW-1:0] lo_q, hi_q;
                        always @(posedge clk_i)
                            if (ce_i) begin
                                lo_q <= half_lo;
                                hi_q <= half_hi;
                            end
                        assign v = lo_q + hi_q;
                    end else begin : g_whole
                        reg [VW-1:0] p_q;
                        always @(posedge clk_i)
                            if (ce_i) p_q <= half_lo + half_hi;
                        assign v = p_q;
                    end
                end else begin : g_dsp
                    // the chunks extended to the block's 18 bits (a signed
                    // chunk by its sign, an unsigned one is 18 bits already)
                    wire [35:0] a_w = {{(35-WA){a_x[WA]}}, a_x};
                    wire [35:0] b_w = {{(35-WB){b_x[WB]}}, b_x};
                    wire [35:0] p;
                    csgrt_mul_dsp #(.A_SIGNED(SA ? 1 : 0), .B_SIGNED(SB ? 1 : 0)) u_dsp (
                        .clk_i, .ce_i, .a_i (a_w[17:0]), .b_i (b_w[17:0]), .p_o (p));
                    // the 36-bit product, extended as signed when either
                    // operand is (else it is unsigned); WA+WB+2 <= 38 bits
                    wire [37:0] p_x = {{2{(SA || SB) && p[35]}}, p};
                    assign v = p_x[WA+WB+1:0];
                    wire unused_w = ^{a_w[35:18], b_w[35:18]};
                    if (WA + WB + 2 < 38) begin : g_unused_top
                        wire unused_top = ^p_x[37:WA+WB+2];
                    end
                end
                // TILE_REG: the tile's value from a register of its own
                wire [WA+WB+1:0] v_r;
                wire             unused_tv;
                csgrt_delay #(.WIDTH(WA + WB + 2), .STAGES(TILE_REG != 0 ? 1 : 0)) u_tile_reg (
                    .clk_i, .rst_ni, .ce_i, .valid_i(1'b0), .data_i(v), .valid_o(unused_tv), .data_o(v_r));
                // extended to P_WIDTH, shifted into place
                wire [P_WIDTH+WA+WB+1:0] v_x = {{P_WIDTH{v_r[WA+WB+1]}}, v_r};
                assign tile[(i*NB+j)*P_WIDTH +: P_WIDTH] = v_x[P_WIDTH-1:0] << SH;
                wire unused_vx = ^v_x[P_WIDTH+WA+WB+1:P_WIDTH];   // beyond the product's width
            end
        end
    endgenerate

    reg [P_WIDTH-1:0] sum;
    integer t;
    always @* begin
        sum = {P_WIDTH{1'b0}};
        for (t = 0; t < NA * NB; t = t + 1) sum = sum + tile[t*P_WIDTH +: P_WIDTH];
    end
    assign p_w = sum;
`endif

    // OUT_REG: one more register, valid alongside (0 stages: a wire)
    csgrt_delay #(.WIDTH(P_WIDTH), .STAGES(OUT_REG != 0 ? 1 : 0)) u_out_reg (
        .clk_i, .rst_ni, .ce_i, .valid_i(valid_w), .data_i(p_w), .valid_o, .data_o(p_o));

    generate
        if (A_WIDTH < 2 || B_WIDTH < 2 || LUT_TILE_MAX < 0 || OUT_REG < 0 || OUT_REG > 1 || TILE_REG < 0 || TILE_REG > 1) begin : g_bad_width
            initial begin
                $display("ERROR %m: csgrt_mul A_WIDTH and B_WIDTH must be >= 2, LUT_TILE_MAX >= 0, OUT_REG and TILE_REG 0 or 1");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
