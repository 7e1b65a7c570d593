`default_nettype none
// csgrt_beat_gather — the N (<= 3) results a time-shared unit computed for
// one beat's items, gathered and shown together for a whole beat
// (csgrt_beat's three-clock beat; used by csgrt_mul_vec and csgrt_unit).
//
// The unit (a multiplier, a divider) runs on every running clock; item k of
// a beat enters it at phase k, and d_i shows that item's result a latency
// of 2 mod 3 clocks later, i.e. at phase (k + 2) mod 3 (the caller pads
// the unit's latency to that). The advance of the beat after the last
// result (phase 2, when the next beat's first result shows) copies the N
// results to q_o, which keeps them for the whole following beat.
// Example, latency 2 (csgrt_mul): items x0 x1 x2 enter at phases 0 1 2 of
// beat k; d_i shows x0 at phase 2 of beat k, x1 and x2 at phases 0 and 1
// of beat k+1; q_o holds {x2, x1, x0} for all of beat k+2.
//
// Implementation: a shift register of the unit's last three outputs on
// every running clock (item 0 the oldest), copied to q_o on the advance.
// (Before, item k was caught in a hold register at its phase: the same
// values, but on phase decodes ce_i && phase == k, which yosys shares
// between every gather of a pipeline, LUT outputs with 3,000 to 4,000
// clock enables each in tools/logic_depth.py's model; now every enable is
// a register, ce_i or adv_i.)
//
// LAT_MOD3 = 0: the unit's latency is 0 mod 3 instead (csgrt_mul with
// TILE_REG: 3 clocks), item k shows at phase k of the next beat, and the
// advance takes item 2 from d_i itself, items 1 and 0 from one and two
// clocks back: q_o still holds them for the beat after (the same two beats
// from the items' entry).
// LAT_MOD3 = 1: the latency is 1 mod 3 (csgrt_mul_vec's operand register
// before csgrt_mul with TILE_REG: 4 clocks), item k shows at phase k+1 of
// the next beat, item 2 at phase 0 of the beat after that, whose advance
// takes items 2, 1, 0 from two, three and four clocks back: q_o holds them
// a beat later than above (three beats from the items' entry).
//
// Handshake: none; ce_i low (the pipeline's stall) holds everything.
module csgrt_beat_gather #(
    parameter integer WIDTH = 8,   // result width (>= 1)
    parameter integer N     = 3,   // results per beat (1..3)
    parameter integer LAT_MOD3 = 2 // the unit's latency mod 3: 2, 0 or 1 (above)
) (
    input  wire               clk_i,
    input  wire               ce_i,      // the pipeline runs
    input  wire               adv_i,     // the beat's advance (csgrt_beat's adv_o: ce_i at phase 2)
    input  wire [WIDTH-1:0]   d_i,       // the unit's output, item k at phase (k + LAT_MOD3) mod 3
    output wire [N*WIDTH-1:0] q_o        // item k at k*WIDTH
);

    // At the advance (phase 2) item 0 (shown at phase 2 of the beat
    // before) is three clocks back, item 1 (phase 0) two, item 2 (phase 1)
    // one (LAT_MOD3 0: item 2 is d_i, item 1 one clock back, item 0 two;
    // LAT_MOD3 1: item 2 two clocks back, item 1 three, item 0 four).
    // back_q: d_i of the last DEPTH running clocks, one clock back at the
    // bottom; hist puts d_i itself below, so that hist's entry j is d_i of
    // j clocks back: item 2 is NEWEST clocks back, items 1 and 0 one and
    // two more.
    localparam integer DEPTH  = (LAT_MOD3 == 0) ? 2 : (LAT_MOD3 == 1) ? 4 : 3;
    localparam integer NEWEST = DEPTH - 2;
    reg  [DEPTH*WIDTH-1:0] back_q;
    always @(posedge clk_i)
        if (ce_i) back_q <= {back_q[(DEPTH-1)*WIDTH-1:0], d_i};
    wire [(DEPTH+1)*WIDTH-1:0] hist = {back_q, d_i};
    wire [3*WIDTH-1:0] held = {hist[NEWEST*WIDTH +: WIDTH], hist[(NEWEST+1)*WIDTH +: WIDTH],
                               hist[(NEWEST+2)*WIDTH +: WIDTH]};   // item k at k*WIDTH
    generate
        if (NEWEST > 0) begin : g_newer
            wire unused_newer = ^hist[NEWEST*WIDTH-1:0];   // shifted on, not gathered
        end
    endgenerate
    reg  [N*WIDTH-1:0] q_q;
    always @(posedge clk_i)
        if (adv_i) q_q <= held[N*WIDTH-1:0];
    assign q_o = q_q;
    generate
        if (N < 3) begin : g_spare
            wire unused_held = ^held[3*WIDTH-1:N*WIDTH];
        end
        if (WIDTH < 1 || N < 1 || N > 3 || LAT_MOD3 < 0 || LAT_MOD3 > 2) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_beat_gather needs WIDTH >= 1, 1 <= N <= 3, LAT_MOD3 0, 1 or 2");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
