`default_nettype none
// csgrt_fifo — synchronous first-in first-out queue with valid/ready on both
// sides, for payloads that travel beside a pipeline (the rays waiting for
// their hit records).
//
// Latency: 1 clock (a word written at a rising edge can be read after it).
// Handshake: a word moves in when valid_i && ready_o, out when valid_o &&
// ready_i, at a rising edge. ready_o = not full, valid_o = not empty: both
// are registers. DEPTH must be a power of two.
module csgrt_fifo #(
    parameter WIDTH = 8,    // payload bits
    parameter DEPTH = 16    // entries, a power of two >= 2
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

    reg [WIDTH-1:0] mem_q [0:DEPTH-1];
    // pointers, and empty and full as registers (csgrt_fifo_ptrs):
    // valid_o and ready_o are flip-flops
    wire [AW-1:0] wr_addr, rd_addr;
    wire          empty, full;
    wire          write = valid_i && !full;
    wire          read  = ready_i && !empty;
    csgrt_fifo_ptrs #(.AW(AW)) u_ptrs (
        .clk_i, .rst_ni, .write_i(write), .read_i(read),
        .wr_addr_o(wr_addr), .rd_addr_o(rd_addr), .empty_o(empty), .full_o(full));

    assign ready_o = !full;
    assign valid_o = !empty;
    assign data_o  = mem_q[rd_addr];

    always @(posedge clk_i)
        if (rst_ni && write) mem_q[wr_addr] <= data_i;

    initial begin
        if (DEPTH < 2 || (1 << AW) != DEPTH) begin
            $display("%m: DEPTH (%0d) must be a power of two >= 2", DEPTH);
            $finish;
        end
    end
endmodule
`default_nettype wire
