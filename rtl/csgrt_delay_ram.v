`default_nettype none
// csgrt_delay_ram — a data word delayed by STAGES enabled clocks, like a
// STAGES-register shift chain on one stage enable, but kept in a RAM ring
// buffer so that wide side data riding along a long pipeline (the sideband
// of csgrt_sqrt_core / csgrt_div_core) lands in block or LUT RAM instead of
// STAGES * WIDTH flip-flops (docs/fpga.md): ram_style "block" asks yosys for
// DP16KD (512 x 36 each) rather than LUT RAM.
//
// Equivalence with the shift chain: the RAM has STAGES entries and a write
// pointer p that steps (mod STAGES) on every enabled clock. An enabled clock
// writes data_i at p and loads the output register from entry p + 1, the
// oldest entry, written STAGES - 1 enabled clocks earlier; so a word written
// at enabled clock e is in the output register after enabled clock
// e + STAGES - 1, exactly where the STAGES-th register of the chain has it,
// and ce_i low holds everything. Read and write addresses always differ, so
// the RAM's read-during-write behaviour does not matter. No valid bit: the
// caller keeps its valid chain in flip-flops (it needs the reset); the data
// words, like the chain's, are not reset.
//
// OUT_REG = 1 puts a fabric register after the RAM's read register and
// keeps one entry fewer in the ring (STAGES - 1), so the delay is the same:
// the DP16KD's read port takes about 5 ns from clock to output (yosys does
// not use its own output register), which a consumer with logic behind the
// line (csgrt_isect's square root and dividers) pays inside its clock; the
// fabric register's takes 0.5. WIDTH flip-flops more.
//
// Small lines (STAGES < MIN_STAGES or WIDTH * STAGES < MIN_BITS) stay a
// register chain: a RAM's pointer and output register would cost more.
//
// Latency: STAGES enabled clocks. Handshake: none (the enclosing pipeline's
// global stall ce_i).
module csgrt_delay_ram #(
    parameter WIDTH      = 8,    // data width (>= 1)
    parameter STAGES     = 8,    // delay in enabled clocks (>= 1)
    parameter MIN_STAGES = 4,    // below this: a register chain
    parameter MIN_BITS   = 64,   // below WIDTH * STAGES = this: a register chain
    parameter OUT_REG    = 0     // 1: a fabric register after the RAM's (same delay, above)
) (
    input  wire             clk_i,
    input  wire             rst_ni,   // synchronous, active low (the pointer only)
    input  wire             ce_i,     // stage enable (low = hold)
    input  wire [WIDTH-1:0] data_i,
    output wire [WIDTH-1:0] data_o
);
    generate
        if (STAGES >= MIN_STAGES && STAGES >= 3 && WIDTH * STAGES >= MIN_BITS) begin : g_ram
            localparam L  = STAGES - (OUT_REG != 0 ? 1 : 0);   // ring entries (>= 2)
            localparam AW = $clog2(L);
            /* verilator lint_off WIDTH */
            localparam [AW-1:0] LAST = L - 1;
            localparam [AW-1:0] FIRST_RD = 1;   // the read pointer after a reset
            /* verilator lint_on WIDTH */
            // block RAM: nearly all of the ECP5's DP16KD are free while LUTs
            // are the scarce resource, and LUT RAM would spend them
            // no_rw_check: the read and write addresses always differ (rd_q
            // is wr_q + 1 mod L, checked below). With the read pointer a
            // register of its own yosys cannot see that, and emulated
            // read-before-write in the fabric (a register of the written
            // word and a compare per line: +3,005 FF, +1,479 LUT slots at
            // BITS 16 with shadows and reflection, the f8d2add build).
            (* ram_style = "block", no_rw_check *)
            reg  [WIDTH-1:0] mem [0:L-1];
            reg  [AW-1:0]    wr_q;
            // the read pointer (the oldest entry, wr_q + 1 mod L) as a
            // register of its own, stepped beside wr_q: computed from wr_q,
            // its increment and wrap ran into the address pins of block
            // RAMs across the die (the shading's square root's sideband:
            // the critical path of the routed c17b967 build, 11.79 ns)
            reg  [AW-1:0]    rd_q;
            reg  [WIDTH-1:0] out_q;

            always @(posedge clk_i) begin
                if (!rst_ni) begin
                    wr_q <= {AW{1'b0}};
                    rd_q <= FIRST_RD;
                end else if (ce_i) begin
                    wr_q <= rd_q;
                    rd_q <= (rd_q == LAST) ? {AW{1'b0}} : rd_q + 1'b1;
                end
            end
            always @(posedge clk_i) begin
                if (ce_i) begin
                    mem[wr_q] <= data_i;
                    out_q     <= mem[rd_q];
                end
            end
`ifndef SYNTHESIS
            csgrt_check_same #(.WIDTH(AW), .WHAT("rd_q (wr_q + 1 mod the ring)")) u_check_rd (
                .clk_i, .rst_ni, .copy_i(rd_q), .orig_i((wr_q == LAST) ? {AW{1'b0}} : wr_q + 1'b1));
`endif
            if (OUT_REG != 0) begin : g_out_reg
                reg [WIDTH-1:0] out_fab_q;
                always @(posedge clk_i) if (ce_i) out_fab_q <= out_q;
                assign data_o = out_fab_q;
            end else begin : g_out_ram
                assign data_o = out_q;
            end
        end else begin : g_regs
            reg [STAGES*WIDTH-1:0] data_q;
            if (STAGES == 1) begin : g_one
                always @(posedge clk_i) if (ce_i) data_q <= data_i;
            end else begin : g_many
                always @(posedge clk_i) if (ce_i) data_q <= {data_q[(STAGES-1)*WIDTH-1:0], data_i};
            end
            assign data_o = data_q[(STAGES-1)*WIDTH +: WIDTH];
            wire unused_rst = rst_ni;
        end
        if (WIDTH < 1 || STAGES < 1) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_delay_ram needs WIDTH >= 1, STAGES >= 1");
                $finish;
            end
        end
    endgenerate
endmodule

`default_nettype wire
