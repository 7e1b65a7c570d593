`default_nettype none
// csgrt_fifo_block — csgrt_fifo with its words in block RAM (ECP5 DP16KD) for
// wide queues that would otherwise spend hundreds of LUT-RAM cells
// (TRELLIS_DPR16X4) and their read multiplexers: csgrt_raytree's ray and
// spawn-request queues, csgrt_hit_prep's record queue, csgrt_spawn's wide
// per-hit queues, csgrt_dispatch's ray and info queues (docs/fpga.md, "LUT
// RAM into block RAM"). LUTs are the device's scarce resource; block RAMs
// are not.
//
// Block RAM reads are synchronous, so the head word lives in an output
// register loaded from the RAM: a word written at a rising edge reaches the
// output register at the next one if the register is free. Compared with
// csgrt_fifo:
//   latency 2 clocks (written at edge e, valid_o after edge e + 1), then one
//   word per clock; capacity DEPTH + 1 (DEPTH in the RAM, 1 in the output
//   register). Same valid/ready handshake; ready_o and valid_o are registers
//   or functions of registers only, and nothing is lost under back-pressure.
// The RAM reads only entries written at an earlier edge and writes only
// entries that are not about to be read (the read pointer trails the write
// pointer and a full RAM takes no write), so a read never meets a write at
// the same address: `no_rw_check` tells yosys not to add collision logic.
module csgrt_fifo_block #(
    parameter WIDTH = 8,    // payload bits
    parameter DEPTH = 16    // RAM entries, a power of two >= 2
) (
    input  wire             clk_i,
    input  wire             rst_ni,    // synchronous, active low
    input  wire             valid_i,
    output wire             ready_o,
    input  wire [WIDTH-1:0] data_i,
    output wire             valid_o,
    input  wire             ready_i,
    output wire [WIDTH-1:0] data_o
);
    localparam AW = $clog2(DEPTH);

    (* ram_style = "block", no_rw_check *)
    reg [WIDTH-1:0] mem_q [0:DEPTH-1];
    reg [AW:0]      wr_q, rd_q;   // one extra bit tells full from empty
    reg [WIDTH-1:0] head_q;       // the oldest word, out of the RAM's read port
    reg             head_valid_q;

    wire ram_empty = (wr_q == rd_q);
    wire ram_full  = (wr_q[AW-1:0] == rd_q[AW-1:0]) && (wr_q[AW] != rd_q[AW]);
    wire write     = valid_i && !ram_full;
    // the head register is free, or its word leaves at this edge
    wire load      = !ram_empty && (!head_valid_q || ready_i);

    assign ready_o = !ram_full;
    assign valid_o = head_valid_q;
    assign data_o  = head_q;

    always @(posedge clk_i) begin
        if (write) mem_q[wr_q[AW-1:0]] <= data_i;
        if (load)  head_q <= mem_q[rd_q[AW-1:0]];
    end

    always @(posedge clk_i) begin
        if (!rst_ni) begin
            wr_q         <= {(AW+1){1'b0}};
            rd_q         <= {(AW+1){1'b0}};
            head_valid_q <= 1'b0;
        end else begin
            if (write) wr_q <= wr_q + 1'b1;
            if (load) begin
                rd_q         <= rd_q + 1'b1;
                head_valid_q <= 1'b1;
            end else if (ready_i) begin
                head_valid_q <= 1'b0;
            end
        end
    end

    initial begin
        if (DEPTH < 2 || (1 << AW) != DEPTH) begin
            $display("%m: DEPTH (%0d) must be a power of two >= 2", DEPTH);
            $finish;
        end
    end
endmodule
`default_nettype wire
