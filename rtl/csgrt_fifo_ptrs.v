`default_nettype none
// csgrt_fifo_ptrs — the write and read pointers of a csgrt_fifo /
// csgrt_fifo_block and its empty and full flags, as registers kept with the
// pointers rather than compares of them: the queue's ready_o, valid_o and
// read enable start at a flip-flop, and a producer's decision behind
// ready_o does not begin with a compare of two counters (csgrt_raytree's
// event selection, fanned out to hundreds of registers, did:
// tools/logic_depth.py). The next flag values compare the pointers one step
// ahead, in front of the flag registers only; csgrt_check_same stops a
// simulation if a flag ever differs from the pointers' compare.
//
// write_i / read_i: a word goes in / out at this edge (the caller gates them
// with !full_o / !empty_o). The pointers carry one bit more than the
// address, which tells full from empty.
module csgrt_fifo_ptrs #(
    parameter AW = 4   // address bits: 2^AW entries
) (
    input  wire          clk_i,
    input  wire          rst_ni,    // synchronous, active low
    input  wire          write_i,
    input  wire          read_i,
    output wire [AW-1:0] wr_addr_o,
    output wire [AW-1:0] rd_addr_o,
    output wire          empty_o,
    output wire          full_o
);
    reg  [AW:0] wr_q, rd_q;
    reg         empty_q, full_q;
    wire [AW:0] wr_inc = wr_q + 1'b1;
    wire [AW:0] rd_inc = rd_q + 1'b1;

    always @(posedge clk_i) begin
        if (!rst_ni) begin
            wr_q    <= {(AW+1){1'b0}};
            rd_q    <= {(AW+1){1'b0}};
            empty_q <= 1'b1;
            full_q  <= 1'b0;
        end else begin
            if (write_i) wr_q <= wr_inc;
            if (read_i)  rd_q <= rd_inc;
            // a write alone: not empty, full if it takes the last entry; a
            // read alone: not full, empty if it takes the last word
            if (write_i && !read_i) begin
                empty_q <= 1'b0;
                full_q  <= wr_inc[AW-1:0] == rd_q[AW-1:0] && wr_inc[AW] != rd_q[AW];
            end else if (read_i && !write_i) begin
                empty_q <= rd_inc == wr_q;
                full_q  <= 1'b0;
            end
        end
    end

    assign wr_addr_o = wr_q[AW-1:0];
    assign rd_addr_o = rd_q[AW-1:0];
    assign empty_o   = empty_q;
    assign full_o    = full_q;

    csgrt_check_same #(.WIDTH(2), .WHAT("the empty / full pair")) u_check (
        .clk_i, .rst_ni, .copy_i({empty_q, full_q}),
        .orig_i({wr_q == rd_q, wr_q[AW-1:0] == rd_q[AW-1:0] && wr_q[AW] != rd_q[AW]}));
endmodule
`default_nettype wire
