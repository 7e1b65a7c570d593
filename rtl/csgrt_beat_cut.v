`default_nettype none
// csgrt_beat_cut — a register in the middle of a beat-long path of a
// time-shared pipeline (II = 3), which keeps the path's latency.
//
// With II = 3 (csgrt_beat) a stage's inputs are registers loaded at a
// beat's advance, steady for the three running clocks that follow, and the
// stage's result is read only at the next advance: the logic between has a
// whole beat. nextpnr knows no multicycle path and times it as one clock.
// This register, loaded on every clock, splits such logic in two: the part
// before it (d_i) has one clock, the part after it (q_o) the next. At the
// advance q_o holds d_i of the clock before, which is d_i of the same beat,
// since the inputs have not moved since the beat began; so the stage reads
// the same value as without the cut. It needs no enable: while the
// pipeline stalls, d_i holds and q_o follows it a clock later.
// With II = 1 every clock is an advance and q_o = d_i (a wire).
//
// Use it only where d_i depends on the beat-steady registers alone and q_o
// is read only at the advance. A simulation stops if q_o and d_i ever
// differ at an advance where the stage takes q_o (live_i: tie it high
// where every advance does; static configuration read through a cut moves
// while a scene loads, when no item is taken); synthesis builds no check.
//
// Latency: none in beats (q_o is d_i of the same beat). Handshake: none.
module csgrt_beat_cut #(
    parameter WIDTH = 8,   // bits (>= 1)
    parameter II    = 1    // the pipeline's clocks per beat: 1 or 3
) (
    input  wire             clk_i,
    input  wire             rst_ni,   // synchronous, active low (the check only)
    input  wire             adv_i,    // the beat's advance (csgrt_beat's adv_o)
    input  wire             live_i,   // the advance takes q_o (the check only)
    input  wire [WIDTH-1:0] d_i,
    output wire [WIDTH-1:0] q_o
);
    generate
        if (II == 1) begin : g_wire
            assign q_o = d_i;
            wire unused = ^{clk_i, rst_ni, adv_i, live_i};
        end else begin : g_reg
            reg [WIDTH-1:0] q_q;
            always @(posedge clk_i) q_q <= d_i;
            assign q_o = q_q;
            csgrt_check_same #(.WIDTH(WIDTH), .WHAT("a beat cut's register (are d_i's inputs steady for the beat?)")) u_check (
                .clk_i(clk_i), .rst_ni(rst_ni),
                .copy_i(adv_i && live_i ? q_q : {WIDTH{1'b0}}), .orig_i(adv_i && live_i ? d_i : {WIDTH{1'b0}}));
        end
        if (WIDTH < 1 || (II != 1 && II != 3)) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_beat_cut needs WIDTH >= 1, II = 1 or 3");
                $finish;
            end
        end
    endgenerate
endmodule
`default_nettype wire
