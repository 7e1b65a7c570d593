`default_nettype none
// csgrt_pingpong — csgrt_skid's contract (two words, latency 1, a word per
// clock, ready_o a register) with the consumer's ready_i reaching only a
// few flip-flops.
//
// csgrt_skid keeps its head in an output register that reloads when the
// consumer takes a word, so ready_i is the enable of every data bit
// (WIDTH loads). Where ready_i is a late decision made far away (the ray
// tree's event choice, docs/fpga.md), that net ran through the
// consumer's priority logic into hundreds of enables. Here the two words
// sit in two slots written alternately; ready_i only moves the read
// pointer and the full bits, and data_o is the slot the read pointer
// names (a 2:1 multiplexer after the registers, its select a register).
// valid_o and ready_o are registers of their own, so the handshake's
// logic does not hang on the read pointer's WIDTH loads.
//
// Each slot loads data_i on every clock it is the write slot and empty:
// its enable is registers only (the word is kept when valid_i and room
// meet; a clock without a word writes nothing anyone reads).
//
// The same handshake as csgrt_skid clock for clock (tb/fifo compares them):
// count = words held, ready_o = count < 2, valid_o = count > 0.
module csgrt_pingpong #(
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
    reg [WIDTH-1:0] slot0_q, slot1_q;
    reg             full0_q, full1_q;   // slot k holds a word
    reg             wr_q, rd_q;         // the slot written next, the slot read next
    reg             ready_q;            // !(full0_q && full1_q), a register of its own
    reg             valid_q;            // full0_q || full1_q, a register of its own: the
                                        // consumer's handshake reads it, not rd_q's
                                        // WIDTH-wide net

    wire push = valid_i && ready_q;
    wire pop  = valid_o && ready_i;
    wire full0_d = (push && !wr_q) || (full0_q && !(pop && !rd_q));
    wire full1_d = (push &&  wr_q) || (full1_q && !(pop &&  rd_q));

    assign ready_o      = ready_q;
    assign ready_next_o = !rst_ni || !(full0_d && full1_d);   // the synchronous reset empties both
    assign valid_o      = valid_q;   // the word at rd_q is the older, or the only one
    assign data_o       = rd_q ? slot1_q : slot0_q;

    always @(posedge clk_i) begin
        if (!rst_ni) begin
            full0_q <= 1'b0;
            full1_q <= 1'b0;
            wr_q    <= 1'b0;
            rd_q    <= 1'b0;
            ready_q <= 1'b1;
            valid_q <= 1'b0;
        end else begin
            full0_q <= full0_d;
            full1_q <= full1_d;
            if (push) wr_q <= !wr_q;
            if (pop)  rd_q <= !rd_q;
            ready_q <= !(full0_d && full1_d);
            valid_q <= full0_d || full1_d;
        end
        if (!wr_q && !full0_q) slot0_q <= data_i;
        if ( wr_q && !full1_q) slot1_q <= data_i;
    end

    generate
        if (WIDTH < 1) begin : g_bad_width
            initial begin
                $display("ERROR %m: csgrt_pingpong WIDTH must be >= 1");
                $finish;
            end
        end
    endgenerate
endmodule
`default_nettype wire
