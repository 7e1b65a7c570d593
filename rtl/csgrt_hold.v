`default_nettype none
// csgrt_hold — a one-word register slice whose every enable is a register.
//
// The word is taken while the slice is empty (ready_o = !full_q, a
// register) and held until the consumer takes it. Compared with
// csgrt_skid (two words, full rate): the consumer's ready_i reaches one
// flip-flop only (full_q's next value), not the data registers' enables
// nor the producer's ready, so a consumer that decides late in the clock
// and far away (csgrt_raytree's event decode, which takes a new pixel
// last in its priority) pays for one short hop to full_q, which the placer
// can put beside it. The price is the rate: a word every 2 clocks at most
// (the slice is refilled the clock after it is emptied), enough for the
// camera, which hands a ray to the ray tree at most every SHARE_II clocks
// and whose rays each take the tree at least a pixel's worth of events.
//
// Latency: 1 clock. Handshake: valid/ready on both sides; nothing is lost
// under back-pressure.
module csgrt_hold #(
    parameter WIDTH = 8   // payload width in bits (>= 1)
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
    reg             full_q;
    reg [WIDTH-1:0] data_q;
    // ready_o as a register of its own, !full_q loaded with its next value:
    // full_q is the enable of every data bit (WIDTH loads, 697 in the hit
    // record's slice), and the producer's handshake behind ready_o (the
    // shading lookup's read addresses, csgrt_top) started on that net
    // (tools/logic_depth.py 12.90 ns). keep: yosys would otherwise fold the
    // complement back into full_q.
    (* keep *) reg  room_q;
    wire            full_d = rst_ni && (full_q ? !ready_i : valid_i);

    assign ready_o = room_q;
    assign valid_o = full_q;
    assign data_o  = data_q;

    always @(posedge clk_i) begin
        full_q <= full_d;
        room_q <= !full_d;
        // loads on every clock the slice is empty: the enable is full_q
        if (!full_q) data_q <= data_i;
    end
    csgrt_check_same #(.WHAT("room_q")) u_check_room (
        .clk_i, .rst_ni, .copy_i(room_q), .orig_i(!full_q));

    generate
        if (WIDTH < 1) begin : g_bad_width
            initial begin
                $display("ERROR %m: csgrt_hold WIDTH must be >= 1");
                $finish;
            end
        end
    endgenerate
endmodule

`default_nettype wire
