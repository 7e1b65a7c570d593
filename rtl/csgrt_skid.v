`default_nettype none
// csgrt_skid — two-entry skid buffer closing every csgrt pipeline.
//
// Latency: 1 clock (data_i accepted at a rising edge is on data_o after it).
// Handshake: valid/ready on both sides; a word moves when valid and ready are
// both high at a rising edge. ready_o is a register (it is low exactly while
// the skid register holds a word), so it never depends combinationally on
// ready_i: upstream pipelines use ready_o as their global stage enable
// without a combinational path from the far side. Full throughput: one word
// per clock while ready_i stays high.
//
//   out register empty or freed  -> take the skid word if any, else data_i
//   out register stalled         -> catch data_i in the skid register
module csgrt_skid #(
    parameter WIDTH = 8   // payload width in bits (>= 1)
) (
    input  wire             clk_i,
    input  wire             rst_ni,    // synchronous, active low
    // upstream
    input  wire             valid_i,
    output wire             ready_o,
    output wire             ready_next_o,   // ready_o after the next rising edge (csgrt_beat's ce_next_i)
    input  wire [WIDTH-1:0] data_i,
    // downstream
    output wire             valid_o,
    input  wire             ready_i,
    output wire [WIDTH-1:0] data_o
);

    reg             out_valid_q, out_valid_d;
    reg [WIDTH-1:0] out_data_q, out_data_d;
    reg             skid_valid_q, skid_valid_d;
    reg [WIDTH-1:0] skid_data_q, skid_data_d;

    assign ready_o = !skid_valid_q;
    assign ready_next_o = !rst_ni || !skid_valid_d;   // the synchronous reset empties the skid
    assign valid_o = out_valid_q;
    assign data_o  = out_data_q;

    always @* begin
        out_valid_d  = out_valid_q;
        out_data_d   = out_data_q;
        skid_valid_d = skid_valid_q;
        // The skid register takes data_i on every clock it is empty: it is
        // read only while it holds a word, and the clock that catches one
        // takes data_i. Its enable is then the register skid_valid_q, not
        // valid_i and the output's stall (valid_i is often the end of the
        // unit's longest decision: csgrt_walker's hit record, for one).
        skid_data_d  = skid_valid_q ? skid_data_q : data_i;
        if (ready_i || !out_valid_q) begin
            // output register free (or being read): refill it, skid first
            if (skid_valid_q) begin
                out_valid_d  = 1'b1;
                out_data_d   = skid_data_q;
                skid_valid_d = 1'b0;
            end else begin
                out_valid_d = valid_i;
                out_data_d  = data_i;
            end
        end else if (valid_i && !skid_valid_q) begin
            // output stalled: catch the word in flight (skid_data_d above)
            skid_valid_d = 1'b1;
        end
    end

    always @(posedge clk_i) begin
        if (!rst_ni) begin
            out_valid_q  <= 1'b0;
            skid_valid_q <= 1'b0;
        end else begin
            out_valid_q  <= out_valid_d;
            skid_valid_q <= skid_valid_d;
        end
        out_data_q  <= out_data_d;
        skid_data_q <= skid_data_d;
    end

    generate
        if (WIDTH < 1) begin : g_bad_width
            initial begin
                $display("ERROR %m: csgrt_skid WIDTH must be >= 1");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
