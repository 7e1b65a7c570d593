`default_nettype none
// EHXPLLL — behavioural stand-in for the ECP5 PLL in the Verilator board
// bench: CLKOP is CLKI (the bench clocks the core directly; the clock
// frequency only matters to the UART divider, a parameter of the top), LOCK
// rises after 8 input clocks. Never synthesised (yosys has the real cell).
/* verilator lint_off UNUSEDPARAM */
module EHXPLLL #(
    parameter CLKI_DIV = 1, parameter CLKFB_DIV = 1, parameter CLKOP_DIV = 8,
    parameter CLKOP_CPHASE = 0, parameter CLKOP_FPHASE = 0,
    parameter FEEDBK_PATH = "CLKOP", parameter CLKOP_ENABLE = "ENABLED",
    parameter PLLRST_ENA = "DISABLED", parameter INTFB_WAKE = "DISABLED",
    parameter STDBY_ENABLE = "DISABLED", parameter DPHASE_SOURCE = "DISABLED",
    parameter OUTDIVIDER_MUXA = "DIVA", parameter OUTDIVIDER_MUXB = "DIVB",
    parameter OUTDIVIDER_MUXC = "DIVC", parameter OUTDIVIDER_MUXD = "DIVD"
) (
    input  wire CLKI, CLKFB, RST, STDBY, PHASESEL0, PHASESEL1, PHASEDIR, PHASESTEP,
    input  wire PHASELOADREG, PLLWAKESYNC, ENCLKOP, ENCLKOS, ENCLKOS2, ENCLKOS3,
    output wire CLKOP, CLKOS, CLKOS2, CLKOS3, LOCK, INTLOCK, REFCLK, CLKINTFB
);
    reg [3:0] cnt_q = 4'd0;
    always @(posedge CLKI) if (!cnt_q[3]) cnt_q <= cnt_q + 4'd1;
    assign CLKOP = CLKI;
    assign {CLKOS, CLKOS2, CLKOS3, REFCLK, CLKINTFB} = {5{CLKI}};
    assign LOCK = cnt_q[3];
    assign INTLOCK = cnt_q[3];
    wire unused_ok = &{1'b0, CLKFB, RST, STDBY, PHASESEL0, PHASESEL1, PHASEDIR, PHASESTEP, PHASELOADREG,
                       PLLWAKESYNC, ENCLKOP, ENCLKOS, ENCLKOS2, ENCLKOS3};
endmodule
`default_nettype wire
