`default_nettype none
// csgrt_beat_gather — the N (<= 3) results a time-shared unit computed for
// one beat's items, gathered and shown together for a whole beat
// (csgrt_beat's three-clock beat; used by csgrt_mul_vec and csgrt_unit).
//
// The unit (a multiplier, a divider) runs on every running clock; item k of
// a beat enters it at phase k, and d_i shows that item's result a latency
// of 2 mod 3 clocks later, i.e. at phase (k + 2) mod 3 (the caller pads
// the unit's latency to that). Each result is caught in a hold register
// at its phase; the advance of the beat after the last catch (phase 2,
// when hold 0 is about to take the next beat's first result) copies the N
// held results to q_o, which keeps them for the whole following beat.
// Example, latency 2 (csgrt_mul): items x0 x1 x2 enter at phases 0 1 2 of
// beat k; d_i shows x0 at phase 2 of beat k, x1 and x2 at phases 0 and 1
// of beat k+1; q_o holds {x2, x1, x0} for all of beat k+2.
//
// Handshake: none; ce_i low (the pipeline's stall) holds everything.
module csgrt_beat_gather #(
    parameter integer WIDTH = 8,   // result width (>= 1)
    parameter integer N     = 3    // results per beat (1..3)
) (
    input  wire               clk_i,
    input  wire               ce_i,      // the pipeline runs
    input  wire [1:0]         phase_i,   // csgrt_beat's phase
    input  wire [WIDTH-1:0]   d_i,       // the unit's output, item k at phase (k + 2) mod 3
    output wire [N*WIDTH-1:0] q_o        // item k at k*WIDTH
);

    wire [N*WIDTH-1:0] held;
    reg  [N*WIDTH-1:0] q_q;
    genvar k;
    generate
        for (k = 0; k < N; k = k + 1) begin : g_hold
            localparam [1:0] CATCH = (k + 2) % 3;
            reg [WIDTH-1:0] hold_q;
            always @(posedge clk_i)
                if (ce_i && phase_i == CATCH) hold_q <= d_i;
            assign held[k*WIDTH +: WIDTH] = hold_q;
        end
        if (WIDTH < 1 || N < 1 || N > 3) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_beat_gather needs WIDTH >= 1, 1 <= N <= 3");
                $finish;
            end
        end
    endgenerate
    always @(posedge clk_i)
        if (ce_i && phase_i == 2'd2) q_q <= held;
    assign q_o = q_q;

endmodule

`default_nettype wire
