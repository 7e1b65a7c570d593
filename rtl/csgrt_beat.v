`default_nettype none
// csgrt_beat — the beat of a time-shared pipeline: with II = 3 the pipeline
// moves once every three running clocks and its multipliers serve three
// operand pairs in turn (csgrt_mul_vec); II = 1 is the ordinary pipeline.
//
// phase_o counts the running clocks of a beat, 0, 1, 2 (II = 3; always 0
// for II = 1), and only moves when ce_i is high; last_o marks the beat's
// last clock (phase 2; always for II = 1), the only one at which an item
// may leave for a skid buffer; adv_o = ce_i && last_o is the beat's last
// running clock, the one at which the pipeline's registers take their next
// values (II = 1: every running clock, adv_o = ce_i).
// Example, II = 3, ce_i high throughout: phase_o 0 1 2 0 1 2 ...,
// adv_o 0 0 1 0 0 1 ...; with ce_i low in the third clock the phase holds
// at 2 and adv_o waits for ce_i.
//
// adv_q_o is adv_o again, from a register of its own: adv_o is the enable
// of thousands of flip-flops (every register of the pipeline), so its net
// is slow, and a handshake that reads it (the unit's s_ready_o) continued
// that net into the next module (tools/logic_depth.py). The register is
// loaded with adv_o's next value, from ce_next_i (the enable's value after
// the next rising edge: csgrt_skid's ready_next_o); a simulation stops if
// it ever differs from ce_i && last_o. With II = 3 adv_o is a register
// too, a second one loaded the same way (so that the handshake's reads
// stay off the pipeline's enable net); with II = 1 adv_o is ce_i, itself a
// register (the skid's ready).
module csgrt_beat #(
    parameter II = 1   // running clocks per beat: 1 or 3
) (
    input  wire       clk_i,
    input  wire       rst_ni,    // synchronous, active low: phase 0
    input  wire       ce_i,      // the pipeline runs (low = stall)
    input  wire       ce_next_i, // ce_i after the next rising edge (for adv_q_o)
    output wire [1:0] phase_o,
    output wire       last_o,
    output wire       adv_o,
    output wire       adv_q_o    // adv_o, from a register (above)
);
    reg adv_q;
    assign adv_q_o = adv_q;

    generate
        if (II == 1) begin : g_every
            assign phase_o = 2'd0;
            assign last_o  = 1'b1;
            assign adv_o   = ce_i;
            // ce_next_i already says what a reset makes of the enable
            always @(posedge clk_i) adv_q <= ce_next_i;
        end else begin : g_three
            reg [1:0] phase_q;
            always @(posedge clk_i) begin
                if (!rst_ni) phase_q <= 2'd0;
                else if (ce_i) phase_q <= (phase_q == 2'd2) ? 2'd0 : phase_q + 2'd1;
            end
            assign phase_o = phase_q;
            // last_o from a register of its own (last_q, loaded with the
            // test of the phase's next value, which adv_d shares): the
            // phase steers every shared multiplier's operands (260 loads
            // in csgrt_hit_prep), and the handshake's push (valid && last)
            // read it through that net, on its way into the output buffer's
            // ready and this beat's adv_q (tools/logic_depth.py's second
            // path on 03fd3dc's netlist, 11.54 ns). (* keep *): see below.
            reg  last_q;
            wire last_d = rst_ni && (ce_i ? phase_q == 2'd1 : phase_q == 2'd2);
            (* keep *) always @(posedge clk_i) last_q <= last_d;
            assign last_o  = last_q;
            csgrt_check_same #(.WHAT("last_o (csgrt_beat's last_q)")) u_check_last (
                .clk_i, .rst_ni, .copy_i(last_q), .orig_i(phase_q == 2'd2));
            // adv's next value: the phase after the edge is 2 (a reset makes
            // it 0, a running clock moves 1 to 2, a stalled one keeps 2)
            wire adv_d = ce_next_i && last_d;
            // adv_o from a register too (adv_en_q): ce_i && last_o is a LUT
            // behind the phase register, which also steers every shared
            // multiplier's operands, and every register of the pipeline
            // hangs on adv_o (10,000 loads in csgrt_shade's B stages,
            // tools/logic_depth.py). (* keep *): the two flip-flops have the
            // same input, and yosys would merge them again (opt_merge).
            reg  adv_en_q;
            assign adv_o = adv_en_q;
            (* keep *) always @(posedge clk_i) adv_q    <= adv_d;
            (* keep *) always @(posedge clk_i) adv_en_q <= adv_d;
            csgrt_check_same #(.WHAT("adv_o")) u_check_en (
                .clk_i, .rst_ni, .copy_i(adv_en_q), .orig_i(ce_i && last_o));
        end

        csgrt_check_same #(.WHAT("adv_q_o (is ce_next_i the enable's next value?)")) u_check (
            .clk_i, .rst_ni, .copy_i(adv_q), .orig_i(ce_i && last_o));
        if (II != 1 && II != 3) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_beat needs II = 1 or 3");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
