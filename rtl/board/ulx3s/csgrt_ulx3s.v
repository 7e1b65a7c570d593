`default_nettype none
// csgrt_ulx3s — csgrt on the ULX3S (ECP5 LFE5U-85F): the 25 MHz oscillator
// through the ECP5 PLL (EHXPLLL) to the core clock, reset from the PWR
// button (btn[0], low when pressed) and the PLL lock, and the scene in /
// pixels out over the FT231X USB serial port (UART 8N1, UART_DIV core clocks
// per bit; protocol: csgrt_board_ctrl, docs/fpga.md).
//
// tools/synth.sh computes the PLL dividers and UART_DIV for the requested
// clock (make synth FREQ=.. BAUD=..); the defaults are 100 MHz and 3 Mbaud
// (25 MHz / 1 * 4 = 100 MHz, VCO 600 MHz; 100 MHz / 3 Mbaud = 33, 1 %).
// In simulation, tb/board/ehxplll_sim.v stands in for the PLL.
//
// LEDs: 0 PLL locked, 1 loading, 2 rendering, 3 refused image, 7..4 the
// last status code.
module csgrt_ulx3s #(
    parameter BITS          = 24,
    parameter MAX_LEAVES    = 64,
    parameter TREE_HEIGHT   = 8,
    parameter SHADOWS       = 0,          // csgrt_top's effect units (make synth EFFECTS=..)
    parameter REFLECTION    = 0,
    parameter REFRACTION    = 0,
    parameter SPECULAR      = 1,          // phong highlights (make synth SPECULAR=0: none)
    parameter SORT_INSERTS  = 1,          // the event sorter's insertions per clock (synth.sh --sort-inserts)
    parameter SHARE_II      = 3,          // the shading's clocks per item, 3 or 1 (synth.sh --share-ii)
    parameter ISECT_II      = 1,          // clocks per intersection pair, 1 or 3 (synth.sh --isect-ii)
    parameter NUM_UNITS     = 1,          // intersection lanes (synth.sh --units)
    parameter CONTEXTS      = 8,          // pixels in flight in the ray tree (synth.sh --contexts)
    parameter MAX_LIGHTS    = 8,          // point lights a scene may have (synth.sh --max-lights)
    /* verilator lint_off UNUSEDPARAM */
    parameter CLK_HZ        = 100000000,  // core clock the PLL makes (documentation, idle time)
    /* verilator lint_on UNUSEDPARAM */
    parameter PLL_CLKI_DIV  = 1,          // f_out = 25 MHz / CLKI_DIV * CLKFB_DIV
    parameter PLL_CLKFB_DIV = 4,
    parameter PLL_CLKOP_DIV = 6,          // f_vco = f_out * CLKOP_DIV, 400..800 MHz
    parameter PLL_CLKOP_CPHASE = 2,       // as ecppll computes it
    parameter UART_DIV      = 33,         // core clocks per UART bit
    parameter IDLE_CLOCKS   = CLK_HZ / 10,// 100 ms of silence ends a discard or aborts a load
    parameter LUT_FILE      = "rtl/srgb_lut.hex"
) (
    input  wire       clk_25mhz,
    input  wire [6:0] btn,            // btn[0]: PWR, low when pressed (reset)
    input  wire       ftdi_txd,       // FT231X -> FPGA
    output wire       ftdi_rxd,       // FPGA -> FT231X
    output wire [7:0] led,
    output wire       wifi_gpio0      // held high: keeps the ESP32 from taking the board over
);
    // -------------------------------------------------------------- clock
    wire clk, locked;
    wire [5:0] pll_unused;
    (* FREQUENCY_PIN_CLKI = "25" *)
    (* ICP_CURRENT = "12" *) (* LPF_RESISTOR = "8" *) (* MFG_ENABLE_FILTEROPAMP = "1" *) (* MFG_GMCREF_SEL = "2" *)
    EHXPLLL #(
        .PLLRST_ENA ("DISABLED"), .INTFB_WAKE ("DISABLED"), .STDBY_ENABLE ("DISABLED"),
        .DPHASE_SOURCE ("DISABLED"), .OUTDIVIDER_MUXA ("DIVA"), .OUTDIVIDER_MUXB ("DIVB"),
        .OUTDIVIDER_MUXC ("DIVC"), .OUTDIVIDER_MUXD ("DIVD"),
        .CLKI_DIV (PLL_CLKI_DIV), .CLKFB_DIV (PLL_CLKFB_DIV), .FEEDBK_PATH ("CLKOP"),
        .CLKOP_ENABLE ("ENABLED"), .CLKOP_DIV (PLL_CLKOP_DIV),
        .CLKOP_CPHASE (PLL_CLKOP_CPHASE), .CLKOP_FPHASE (0)
    ) u_pll (
        .RST (1'b0), .STDBY (1'b0), .CLKI (clk_25mhz), .CLKOP (clk), .CLKFB (clk),
        .PHASESEL0 (1'b0), .PHASESEL1 (1'b0), .PHASEDIR (1'b1), .PHASESTEP (1'b1),
        .PHASELOADREG (1'b1), .PLLWAKESYNC (1'b0), .ENCLKOP (1'b0), .ENCLKOS (1'b0),
        .ENCLKOS2 (1'b0), .ENCLKOS3 (1'b0), .LOCK (locked),
        .CLKOS (pll_unused[0]), .CLKOS2 (pll_unused[1]), .CLKOS3 (pll_unused[2]),
        .INTLOCK (pll_unused[3]), .REFCLK (pll_unused[4]), .CLKINTFB (pll_unused[5])
    );

    // -------------------------------------------------------------- reset
    // The button and the lock, synchronised; reset held 16 clocks after both
    // are fine. Flip-flops start at 0 on the ECP5 (and in the simulation's
    // reset), so the design starts in reset.
    reg [1:0] rst_sync_q = 2'b00;
    reg [4:0] rst_cnt_q = 5'd0;
    wire      rst_n = rst_cnt_q[4];
    always @(posedge clk) begin
        rst_sync_q <= {rst_sync_q[0], btn[0] & locked};
        if (!rst_sync_q[1]) rst_cnt_q <= 5'd0;
        else if (!rst_cnt_q[4]) rst_cnt_q <= rst_cnt_q + 5'd1;
    end

    // --------------------------------------------------------------- UART
    wire       rx_valid, tx_valid, tx_ready, rx_active;
    wire [7:0] rx_data, tx_data;
    wire [3:0] state, code;

    csgrt_uart_rx #(.DIV(UART_DIV)) u_rx (
        .clk_i (clk), .rst_ni (rst_n), .rx_i (ftdi_txd),
        .valid_o (rx_valid), .data_o (rx_data), .active_o (rx_active)
    );
    csgrt_uart_tx #(.DIV(UART_DIV)) u_tx (
        .clk_i (clk), .rst_ni (rst_n), .valid_i (tx_valid), .ready_o (tx_ready), .data_i (tx_data),
        .tx_o (ftdi_rxd)
    );
    csgrt_board_ctrl #(
        .BITS (BITS), .MAX_LEAVES (MAX_LEAVES), .TREE_HEIGHT (TREE_HEIGHT),
        .SHADOWS (SHADOWS), .REFLECTION (REFLECTION), .REFRACTION (REFRACTION), .SPECULAR (SPECULAR),
        .SORT_INSERTS (SORT_INSERTS), .SHARE_II (SHARE_II), .ISECT_II (ISECT_II), .NUM_UNITS (NUM_UNITS),
        .CONTEXTS (CONTEXTS), .MAX_LIGHTS (MAX_LIGHTS), .IDLE_CLOCKS (IDLE_CLOCKS), .LUT_FILE (LUT_FILE)
    ) u_ctrl (
        .clk_i (clk), .rst_ni (rst_n),
        .rx_valid_i (rx_valid), .rx_data_i (rx_data),
        .tx_valid_o (tx_valid), .tx_ready_i (tx_ready), .tx_data_o (tx_data),
        .state_o (state), .last_code_o (code)
    );

    assign led = {code, (code != 4'd0), (state == 4'd4), (state == 4'd2), locked};
    assign wifi_gpio0 = 1'b1;
    wire unused_ok = &{1'b0, btn[6:1], rx_active, pll_unused};
endmodule
`default_nettype wire
