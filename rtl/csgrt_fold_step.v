`default_nettype none
// csgrt_fold_step — the schedule of one stage of a digit-by-digit pipeline
// (csgrt_sqrt_core, csgrt_div_core): which step the stage takes on this
// clock, on which item, and the operand bits that step brings down.
//
// The operation takes STEPS steps, step j finding result bit STEPS-1-j and
// bringing down the W operand bits of that index (bits[(STEPS-1-j)*W +: W]
// of the item's operand word).
//   FOLD = 1: stage k takes step k, on the previous stage's item, whenever
//     the pipeline moves (ce_i).
//   FOLD = 3 (a pipeline that moves every third running clock, csgrt_beat
//     II = 3): stage k takes steps 3k, 3k+1, 3k+2, one per running clock of
//     a beat: 3k at the beat's advance (phase 2) on the item it takes from
//     the stage before, 3k+1 and 3k+2 at phases 0 and 1 on its own item.
//     A step past the last (STEPS not a multiple of 3) is not taken.
// Combinational but for FOLD = 3's copy of the phase: the caller's stage
// registers load the step's result when step_o is high, computed from the
// previous stage's item when take_prev_o is high and from their own
// otherwise.
// FOLD = 3 keeps a copy of the beat's phase register per stage, one-hot
// (stepped as csgrt_beat steps it: reset to 0, +1 mod 3 on every running
// clock), and steers the stage from it: take_prev_o selects the stage's
// whole remainder and operands (about 100 multiplexers in a 24-bit divider
// stage), and the beat's one phase register with a decode behind it
// steered all stages of every folded core, 1,686 loads in the 24-bit
// intersection unit: the longest path of the netlist (tools/logic_depth.py
// 18.84 ns, 36.82 MHz after placement at c657fc4). The copy is checked
// against phase_i in simulation (csgrt_check_same).
module csgrt_fold_step #(
    parameter FOLD  = 1,   // steps per stage: 1 or 3
    parameter STEPS = 8,   // steps of the whole operation (>= 1)
    parameter STAGE = 0,   // this stage's index, 0 .. ceil(STEPS / FOLD) - 1
    parameter W     = 1    // operand bits each step brings down (>= 1)
) (
    input  wire               clk_i,
    input  wire               rst_ni,       // synchronous, active low (FOLD = 3: the phase copy)
    input  wire               ce_i,         // the pipeline moves (FOLD = 3: the beat's advance)
    input  wire               run_i,        // FOLD = 3: a running clock of the beat
    input  wire [1:0]         phase_i,      // FOLD = 3: its phase (csgrt_beat's phase_o)
    input  wire [STEPS*W-1:0] prev_bits_i,  // the previous stage's item's operand word
    input  wire [STEPS*W-1:0] own_bits_i,   // this stage's item's operand word
    output wire               take_prev_o,  // the step starts from the previous stage's item
    output wire               step_o,       // a step is taken at this clock's edge
    output wire [W-1:0]       bits_o        // the operand bits the step brings down
);
    // the words are read at the steps' indices only
    wire unused_bits = ^{prev_bits_i, own_bits_i};

    generate
        if (FOLD == 1) begin : g_one
            localparam I = STEPS - 1 - STAGE;   // result bit found by this stage
            assign take_prev_o = 1'b1;
            assign step_o      = ce_i;
            assign bits_o      = prev_bits_i[I*W +: W];
            wire unused_fold = ^{clk_i, rst_ni, run_i, phase_i};
        end else begin : g_three
            // result bits I0 (at the advance), I1, I2 (phases 0 and 1);
            // a step past bit 0 (LIVE1/LIVE2 = 0) is not taken
            localparam J0    = FOLD * STAGE;
            localparam LIVE1 = (J0 + 1 < STEPS) ? 1 : 0;
            localparam LIVE2 = (J0 + 2 < STEPS) ? 1 : 0;
            localparam I0    = STEPS - 1 - J0;
            localparam I1    = LIVE1 ? STEPS - 2 - J0 : 0;
            localparam I2    = LIVE2 ? STEPS - 3 - J0 : 0;
            // the stage's own copy of the phase, one-hot (bit k: phase k),
            // so that the selects come straight from flip-flops; (* keep *):
            // the copies of all stages have the same inputs, and yosys would
            // merge them into one register again (opt_merge)
            reg [2:0] ph_oh_q;
            (* keep *) always @(posedge clk_i) begin
                if (!rst_ni) ph_oh_q <= 3'b001;
                else if (run_i) ph_oh_q <= {ph_oh_q[1:0], ph_oh_q[2]};
            end
            csgrt_check_same #(.WIDTH(3), .WHAT("csgrt_fold_step's phase copy")) u_check_phase (
                .clk_i(clk_i), .rst_ni(rst_ni), .copy_i(ph_oh_q), .orig_i(3'b001 << phase_i));
            wire advance = ph_oh_q[2];
            assign take_prev_o = advance;
            assign step_o      = run_i && (advance || (ph_oh_q[1] ? (LIVE2 == 1) : (LIVE1 == 1)));
            assign bits_o      = advance    ? prev_bits_i[I0*W +: W]
                               : ph_oh_q[1] ? own_bits_i[I2*W +: W] : own_bits_i[I1*W +: W];
            wire unused_ce = ce_i;   // the advance is run_i at phase 2
        end

        if ((FOLD != 1 && FOLD != 3) || STEPS < 1 || W < 1 || STAGE * FOLD >= STEPS) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_fold_step needs FOLD 1 or 3, STEPS >= 1, W >= 1, STAGE < ceil(STEPS / FOLD)");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
