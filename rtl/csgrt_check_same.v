`default_nettype none
// csgrt_check_same — a simulation check that a register kept as a copy of
// another signal equals it on every clock, from the first reset on (the
// registers start undefined before it). Units keep such copies to take a
// decision off a net of thousands of loads, or a compare off a path
// (csgrt_beat's adv_q_o, csgrt_fifo_ptrs' flags, docs/fpga-timing.md "Whole-design
// paths"); the copy is loaded with the original's next value, and this
// check stops the simulation if that ever goes wrong. Synthesis builds
// nothing (SYNTHESIS is defined by yosys and tools/synth.sh).
module csgrt_check_same #(
    parameter WIDTH = 1,
    parameter WHAT  = "copy"   // named in the message
) (
    input  wire             clk_i,
    input  wire             rst_ni,    // synchronous, active low
    input  wire [WIDTH-1:0] copy_i,
    input  wire [WIDTH-1:0] orig_i
);
`ifndef SYNTHESIS
    reg reset_seen_q = 1'b0;
    always @(posedge clk_i) if (!rst_ni) reset_seen_q <= 1'b1;
    always @(posedge clk_i)
        if (rst_ni && reset_seen_q && copy_i != orig_i) begin
            $display("ERROR %m: %0s differs from what it copies", WHAT);
            $fatal;
        end
`else
    wire unused = ^{clk_i, rst_ni, copy_i, orig_i};
`endif
endmodule
`default_nettype wire
