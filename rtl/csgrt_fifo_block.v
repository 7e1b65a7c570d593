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
// HEAD_REG adds a fabric register after the RAM's read register: the
// DP16KD's read port takes 5.6 ns from clock to output in nextpnr's model
// (without its own output register, which yosys does not infer), more than
// half of a 100 MHz clock before the consumer's logic starts; the fabric
// register's takes 0.5 ns. Latency 3 clocks, capacity DEPTH + 2.
//   HEAD_REG = 1: a word per clock; the RAM's read enable and the head's
//     enable follow ready_i, as in the plain queue. For consumers whose
//     ready is a register or nearly (csgrt_spawn's queues, popped at fixed
//     phases).
//   HEAD_REG = 2: every enable decided by registers: the RAM reads when its
//     read register is empty, the head loads when it is empty, and ready_i
//     only clears head_valid. An enable that waits for the consumer's ready
//     reaches from the consumer's decision across the die to the RAM or to
//     a wide register; the price is one word every 2 clocks at most (the
//     head is refilled the clock after it is taken). For consumers that
//     take a word every 2 clocks or less often and decide late in the clock:
//     csgrt_hit_prep's record queue (a record per hit, II clocks apart,
//     taken by the ray tree's event selection).
//   HEAD_REG = 3: the head in a two-word csgrt_pingpong after the RAM's
//     read register: every enable on the RAM's side decided by registers
//     (the ping-pong's ready_o is one), and still a word per clock; ready_i
//     reaches only the ping-pong's pointers, not the words' enables.
//     Latency 3 clocks, capacity DEPTH + 3. For
//     consumers that take a word per clock and decide late in the clock:
//     csgrt_dispatch's info queues, popped with a ray's last leaf at the
//     end of the handshake chain from the event sorter through the
//     intersection unit and the walker (with HEAD_REG 1 that ready went on
//     through the head's load, the read register's and the RAM's read
//     enable into the pointers: tools/logic_depth.py's longest path);
//     csgrt_raytree's ray FIFO, whose head goes across the die into the
//     dispatcher's ray queue and is taken on the dispatcher's ready.
// The RAM reads only entries written at an earlier edge and writes only
// entries that are not about to be read (the read pointer trails the write
// pointer and a full RAM takes no write), so a read never meets a write at
// the same address: `no_rw_check` tells yosys not to add collision logic.
module csgrt_fifo_block #(
    parameter WIDTH = 8,    // payload bits
    parameter DEPTH = 16,   // RAM entries, a power of two >= 2
    parameter HEAD_REG = 0  // 1, 2, 3: the head word in fabric registers (above)
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
    reg [WIDTH-1:0] rd_data_q;    // the RAM's read register: the oldest word read
    reg             rd_valid_q;

    // pointers, and empty and full as registers (csgrt_fifo_ptrs): ready_o
    // and the read enable start at a flip-flop
    wire [AW-1:0] wr_addr, rd_addr;
    wire          ram_empty, ram_full;
    wire          write = valid_i && !ram_full;
    wire          rd_free;        // the read register is free, or its word moves on at this edge
    wire          load  = !ram_empty && rd_free;
    csgrt_fifo_ptrs #(.AW(AW)) u_ptrs (
        .clk_i, .rst_ni, .write_i(write), .read_i(load),
        .wr_addr_o(wr_addr), .rd_addr_o(rd_addr), .empty_o(ram_empty), .full_o(ram_full));

    assign ready_o = !ram_full;

    always @(posedge clk_i) begin
        if (write) mem_q[wr_addr] <= data_i;
        if (load)  rd_data_q <= mem_q[rd_addr];
    end

    generate
        if (HEAD_REG == 3) begin : g_head_pingpong
            wire head_ready;
            wire unused_ready_next;
            assign rd_free = !rd_valid_q || head_ready;
            csgrt_pingpong #(.WIDTH(WIDTH)) u_head (
                .clk_i, .rst_ni, .valid_i(rd_valid_q), .ready_o(head_ready), .ready_next_o(unused_ready_next),
                .data_i(rd_data_q), .valid_o(valid_o), .ready_i(ready_i), .data_o(data_o));
            always @(posedge clk_i) begin
                if (!rst_ni)         rd_valid_q <= 1'b0;
                else if (load)       rd_valid_q <= 1'b1;
                else if (head_ready) rd_valid_q <= 1'b0;
            end
        end else if (HEAD_REG != 0) begin : g_head_reg
            // the head in the fabric, loaded from the read register when
            // it is free (HEAD_REG 2: when it is empty, so that no enable
            // here depends on ready_i)
            reg [WIDTH-1:0] head_q;
            reg             head_valid_q;
            wire head_load = rd_valid_q && (!head_valid_q || (HEAD_REG == 1 && ready_i));
            assign rd_free = !rd_valid_q || (HEAD_REG == 1 && head_load);
            assign valid_o = head_valid_q;
            assign data_o  = head_q;
            always @(posedge clk_i) if (head_load) head_q <= rd_data_q;
            always @(posedge clk_i) begin
                if (!rst_ni) begin
                    rd_valid_q   <= 1'b0;
                    head_valid_q <= 1'b0;
                end else begin
                    if (load)           rd_valid_q <= 1'b1;
                    else if (head_load) rd_valid_q <= 1'b0;
                    if (head_load)      head_valid_q <= 1'b1;
                    else if (ready_i)   head_valid_q <= 1'b0;
                end
            end
        end else begin : g_head_ram
            // the head is the read register itself
            assign rd_free = !rd_valid_q || ready_i;
            assign valid_o = rd_valid_q;
            assign data_o  = rd_data_q;
            always @(posedge clk_i) begin
                if (!rst_ni)      rd_valid_q <= 1'b0;
                else if (load)    rd_valid_q <= 1'b1;
                else if (ready_i) rd_valid_q <= 1'b0;
            end
        end
    endgenerate

    initial begin
        if (DEPTH < 2 || (1 << AW) != DEPTH || HEAD_REG < 0 || HEAD_REG > 3) begin
            $display("%m: DEPTH (%0d) must be a power of two >= 2, HEAD_REG (%0d) 0 to 3", DEPTH, HEAD_REG);
            $finish;
        end
    end
endmodule
`default_nettype wire
