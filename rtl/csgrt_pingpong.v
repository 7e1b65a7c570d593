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
    // Room after this clock: a pop always leaves some (both slots full
    // means no push, so the pop's slot stays empty), and without one there
    // is room unless both slots are full after the push. Written so that
    // the pop, the consumer's late decision, enters last: through
    // ready_next_o it reaches the producer's beat (csgrt_beat's adv_q), and
    // from the full bits it ran through three more LUT levels into it (the
    // hit preparation's beat behind the ray tree's event choice,
    // tools/logic_depth.py 13.63 ns). The same value as
    // !(full0_d && full1_d) (u_check_room).
    wire room_np = !(((push && !wr_q) || full0_q) && ((push && wr_q) || full1_q));
    wire room_d  = pop || room_np;

    assign ready_o      = ready_q;
    assign ready_next_o = !rst_ni || room_d;   // the synchronous reset empties both
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
            ready_q <= room_d;
            valid_q <= full0_d || full1_d;
        end
        if (!wr_q && !full0_q) slot0_q <= data_i;
        if ( wr_q && !full1_q) slot1_q <= data_i;
    end

    csgrt_check_same #(.WHAT("the room after this clock (room_d)")) u_check_room (
        .clk_i, .rst_ni, .copy_i(room_d), .orig_i(!(full0_d && full1_d)));
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
