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
    reg [AW:0]      wr_q, rd_q;   // one extra bit tells full from empty

    // Empty and full as registers kept with the pointers (csgrt_fifo_block
    // says why): valid_o and ready_o are flip-flops.
    reg  empty_q, full_q;
    wire write = valid_i && !full_q;
    wire read  = ready_i && !empty_q;
    wire [AW:0] wr_inc = wr_q + 1'b1;
    wire [AW:0] rd_inc = rd_q + 1'b1;

    assign ready_o = !full_q;
    assign valid_o = !empty_q;
    assign data_o  = mem_q[rd_q[AW-1:0]];

    always @(posedge clk_i) begin
        if (!rst_ni) begin
            wr_q    <= {(AW+1){1'b0}};
            rd_q    <= {(AW+1){1'b0}};
            empty_q <= 1'b1;
            full_q  <= 1'b0;
        end else begin
            if (write) begin
                mem_q[wr_q[AW-1:0]] <= data_i;
                wr_q <= wr_inc;
            end
            if (read) rd_q <= rd_inc;
            if (write && !read) begin
                empty_q <= 1'b0;
                full_q  <= wr_inc[AW-1:0] == rd_q[AW-1:0] && wr_inc[AW] != rd_q[AW];
            end else if (read && !write) begin
                empty_q <= rd_inc == wr_q;
                full_q  <= 1'b0;
            end
        end
    end
`ifndef SYNTHESIS
    // checked from the first reset on (registers start undefined before it)
    reg reset_seen_q = 1'b0;
    always @(posedge clk_i) if (!rst_ni) reset_seen_q <= 1'b1;
    always @(posedge clk_i)
        if (rst_ni && reset_seen_q && (empty_q != (wr_q == rd_q) ||
                       full_q != (wr_q[AW-1:0] == rd_q[AW-1:0] && wr_q[AW] != rd_q[AW]))) begin
            $display("ERROR %m: the empty / full registers are out of step with the pointers");
            $fatal;
        end
`endif

    initial begin
        if (DEPTH < 2 || (1 << AW) != DEPTH) begin
            $display("%m: DEPTH (%0d) must be a power of two >= 2", DEPTH);
            $finish;
        end
    end
endmodule
`default_nettype wire
