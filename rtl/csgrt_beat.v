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
module csgrt_beat #(
    parameter II = 1   // running clocks per beat: 1 or 3
) (
    input  wire       clk_i,
    input  wire       rst_ni,    // synchronous, active low: phase 0
    input  wire       ce_i,      // the pipeline runs (low = stall)
    output wire [1:0] phase_o,
    output wire       last_o,
    output wire       adv_o
);

    generate
        if (II == 1) begin : g_every
            wire unused_clk = ^{clk_i, rst_ni};   // no state
            assign phase_o = 2'd0;
            assign last_o  = 1'b1;
            assign adv_o   = ce_i;
        end else begin : g_three
            reg [1:0] phase_q;
            always @(posedge clk_i) begin
                if (!rst_ni) phase_q <= 2'd0;
                else if (ce_i) phase_q <= (phase_q == 2'd2) ? 2'd0 : phase_q + 2'd1;
            end
            assign phase_o = phase_q;
            assign last_o  = (phase_q == 2'd2);
            assign adv_o   = ce_i && last_o;
        end

        if (II != 1 && II != 3) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_beat needs II = 1 or 3");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
