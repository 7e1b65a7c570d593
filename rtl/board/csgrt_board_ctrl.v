`default_nettype none
// csgrt_board_ctrl — csgrt_top behind a serial line: the host's protocol
// (docs/fpga.md) on byte streams from/to a UART.
//
// Host -> board: a command byte, then (for P and R) the scene image exactly
// as `csgrt compile` writes it (32-bit words, little-endian bytes).
//   'P' (0x50)  load the image and render it, tie policy paper
//   'R' (0x52)  load the image and render it, tie policy regular
//   'I' (0x49)  identify: no image follows
//   anything else in idle is ignored.
// Board -> host:
//   'I':      A5 49 BITS MAX_LEAVES TREE_HEIGHT EFFECTS (bit 0 shadows,
//             bit 1 reflection, bit 2 refraction, bit 3 specular: the
//             effect units the core was built with)
//   P / R:    A5 code; code 0: the image loaded, then W*H pixels as r, g, b
//             bytes in raster order, then the frame's cycle count (start to
//             last pixel, 8 bytes little-endian). code 1..5: the loader
//             refused the image (csgrt_scene_loader's codes), the rest of the
//             image is discarded until the line is idle for IDLE_CLOCKS;
//             code 15: the image stopped arriving (idle for IDLE_CLOCKS
//             before its last word).
// Each P / R command resets the core first, so every frame starts clean.
module csgrt_board_ctrl #(
    parameter BITS         = 24,
    parameter MAX_LEAVES   = 64,
    parameter TREE_HEIGHT  = 8,
    parameter SHADOWS      = 0,          // csgrt_top's effect units (docs/effects.md)
    parameter REFLECTION   = 0,
    parameter REFRACTION   = 0,
    parameter SPECULAR     = 1,
    parameter SORT_INSERTS = 1,          // csgrt_top's event sorter insertions per clock
    parameter SHARE_II     = 3,          // csgrt_top's shading clocks per item (3 or 1)
    parameter ISECT_II     = 1,          // csgrt_top's clocks per intersection pair (1 or 3)
    parameter NUM_UNITS    = 1,          // csgrt_top's intersection lanes
    parameter CONTEXTS     = 8,          // csgrt_top's pixels in flight in the ray tree
    parameter MAX_LIGHTS   = 8,          // csgrt_top's point lights (a scene with more: status 4)
    parameter IDLE_CLOCKS  = 10000000,   // line idle time that ends a discard / aborts a load
    parameter LUT_FILE     = "rtl/srgb_lut.hex"
) (
    input  wire       clk_i,
    input  wire       rst_ni,            // synchronous, active low
    // received bytes
    input  wire       rx_valid_i,
    input  wire [7:0] rx_data_i,
    // bytes to send
    output wire       tx_valid_o,
    input  wire       tx_ready_i,
    output wire [7:0] tx_data_o,
    // status for LEDs
    output wire [3:0] state_o,
    output reg  [3:0] last_code_o
);
    localparam S_IDLE = 4'd0, S_RESET = 4'd1, S_LOAD = 4'd2, S_STATUS = 4'd3, S_RENDER = 4'd4,
               S_TRAILER = 4'd5, S_DRAIN = 4'd6, S_WAIT = 4'd7;
    localparam IW = $clog2(IDLE_CLOCKS + 1);
    /* verilator lint_off WIDTH */
    localparam [IW-1:0] IDLE_MAX = IDLE_CLOCKS;
    localparam [7:0] ID_BITS = BITS, ID_LEAVES = MAX_LEAVES, ID_HEIGHT = TREE_HEIGHT;
    localparam [7:0] ID_EFFECTS = {4'd0, SPECULAR != 0, REFRACTION != 0, REFLECTION != 0, SHADOWS != 0};
    /* verilator lint_on WIDTH */

    reg [3:0]  state_q;
    reg        core_rst_nq;
    reg [2:0]  rst_cnt_q;
    reg        ties_q;
    reg [1:0]  byte_idx_q;
    reg [31:0] word_q;
    reg        word_valid_q;
    reg [IW-1:0] idle_q;
    reg [3:0]  code_q;
    reg [63:0] ob_q;                     // bytes to send, the next in ob_q[7:0]
    reg [3:0]  on_q;                     // how many
    // on_q == 0 as a register of its own, assigned with every assignment
    // to on_q: the test decides the choice of ob_q's next value, the
    // state's steps and tx_valid_o, and from on_q it was the first two
    // of that choice's six LUT levels (tools/logic_depth.py 12.51 ns)
    reg        on_zero_q;
    // The state machine queues a message (up to 8 bytes) in nb_q, and the
    // sender takes it into ob_q once ob_q is empty: ob_q's next value is
    // then a choice of two (nb_q or its own shift) under on_zero_q and
    // nb_full_q, and the state decode stays on nb_q's side. With the
    // state machine writing ob_q itself, on_zero_q ran through the state
    // decode and the core's pixel handshake into the choice of ob_q's
    // next value (tools/logic_depth.py 11.49 ns, 5 LUT levels, on 18b6b1d's
    // 24-bit netlist). The queue adds a clock before each message's first
    // byte and none between its bytes.
    // Only a message's own bytes are written (the bytes above its length
    // are never sent): zeroing them put the state decode into every bit's
    // reset (LSR) logic (tools/logic_depth.py 12.38 ns on 833bdd6).
    reg [63:0] nb_q;                     // the queued message, first byte in nb_q[7:0]
    reg [3:0]  nn_q;                     // its length
    reg        nb_full_q;                // nb_q holds a message not yet in ob_q
    reg        start_q;
    // The core's pixel is taken into a register of its own (pix_q) and sent
    // from there: pix_ready is then a register, not the byte sender's
    // count test, and the core's output handshake no longer runs on into
    // the choice of ob_q's next value (tools/logic_depth.py: on_q -> the
    // core's pixel handshake -> the state decode -> ob_q, 7 LUT levels).
    // The serial line takes 30 bit times per pixel, so the clock this adds
    // per pixel costs nothing.
    reg        pix_full_q;               // pix_q holds a pixel not yet in ob_q
    reg [23:0] pix_q;
    reg        done_seen_q;              // the core's done_o pulse came (the last pixel is taken)
    assign state_o = state_q;

    // ------------------------------------------------------------- the core
    wire        load_ready, loaded, busy, done, pix_valid;
    wire [3:0]  load_error;
    wire [11:0] pix_x, pix_y;
    wire [23:0] pix_rgb;
    wire [63:0] stat_cycles, stat_pairs;
    // pix_ready = S_RENDER && !pix_full_q, as a register of its own set and
    // cleared with the two: as their LUT (the state's four bits and the
    // flag) it began the core's pixel handshake, five LUT levels through
    // the ray tree's retire decision into its pixel registers' enables
    // (tools/logic_depth.py 11.59 ns on c69b81b's netlist). Checked below.
    reg         pix_ready_q;
    wire        pix_ready = pix_ready_q;
    // The received byte a clock later, with its command tests made on the
    // way (rx_i_q: 'I', rx_pr_q: 'P' or 'R'): the 8-bit compares on
    // rx_data_i ran on through the state decode and nb_full_q into nb_q's
    // reset logic (tools/logic_depth.py 12.03 ns, 7 LUT levels, on 911d777's
    // netlist). A byte takes 10 bit times of at least 4 clocks each, so the
    // clock this adds costs nothing.
    reg         rx_v_q, rx_i_q, rx_pr_q;
    reg  [7:0]  rx_d_q;
    always @(posedge clk_i) begin
        rx_v_q  <= rst_ni && rx_valid_i;
        rx_d_q  <= rx_data_i;
        rx_i_q  <= rx_data_i == 8'h49;
        rx_pr_q <= rx_data_i == 8'h50 || rx_data_i == 8'h52;
    end

    csgrt_top #(.BITS(BITS), .MAX_LEAVES(MAX_LEAVES), .TREE_HEIGHT(TREE_HEIGHT), .LUT_FILE(LUT_FILE),
                .SHADOWS(SHADOWS), .REFLECTION(REFLECTION), .REFRACTION(REFRACTION),
                .SPECULAR(SPECULAR), .SORT_INSERTS(SORT_INSERTS), .SHARE_II(SHARE_II), .ISECT_II(ISECT_II),
                .NUM_UNITS(NUM_UNITS), .CONTEXTS(CONTEXTS), .MAX_LIGHTS(MAX_LIGHTS)) u_core (
        .clk_i, .rst_ni (core_rst_nq),
        .load_valid_i (word_valid_q), .load_ready_o (load_ready), .load_word_i (word_q),
        .loaded_o (loaded), .load_error_o (load_error),
        .start_i (start_q), .ties_regular_i (ties_q), .busy_o (busy), .done_o (done),
        .pix_valid_o (pix_valid), .pix_ready_i (pix_ready),
        .pix_x_o (pix_x), .pix_y_o (pix_y), .pix_rgb_o (pix_rgb),
        .stat_cycles_o (stat_cycles), .stat_pairs_o (stat_pairs)
    );

    // --------------------------------------------------------- byte output
    assign tx_valid_o = !on_zero_q;
    assign tx_data_o  = ob_q[7:0];

    always @(posedge clk_i) begin
        start_q <= 1'b0;
        if (!rst_ni) begin
            state_q      <= S_IDLE;
            core_rst_nq  <= 1'b0;
            word_valid_q <= 1'b0;
            on_q         <= 4'd0;
            on_zero_q    <= 1'b1;
            nb_full_q    <= 1'b0;
            pix_full_q   <= 1'b0;
            pix_ready_q  <= 1'b0;
            done_seen_q  <= 1'b0;
            last_code_o  <= 4'd0;
            idle_q       <= {IW{1'b0}};
        end else begin
            // the sender: ob_q shifts out, then takes the queued message
            // (tx_valid_o is !on_zero_q: the two never meet)
            if (tx_valid_o && tx_ready_i) begin
                ob_q <= {ob_q[7:0], ob_q[63:8]};   // (rotated: the bytes past on_q are never sent)
                on_q <= on_q - 4'd1;
                on_zero_q <= on_q == 4'd1;
            end else if (on_zero_q && nb_full_q) begin
                ob_q      <= nb_q;
                on_q      <= nn_q;
                on_zero_q <= 1'b0;
                nb_full_q <= 1'b0;
            end
            if (word_valid_q && load_ready) word_valid_q <= 1'b0;
            idle_q <= rx_v_q ? {IW{1'b0}} : (idle_q == IDLE_MAX ? idle_q : idle_q + 1'b1);

            case (state_q)
            S_IDLE:
                if (rx_v_q) begin
                    if (rx_pr_q) begin
                        ties_q      <= rx_d_q[1];
                        core_rst_nq <= 1'b0;
                        rst_cnt_q   <= 3'd0;
                        byte_idx_q  <= 2'd0;
                        state_q     <= S_RESET;
                    end else if (rx_i_q && !nb_full_q) begin
                        // (an 'I' while the last reply still waits in nb_q
                        // is dropped: a host asks once and reads 6 bytes)
                        nb_q[47:0] <= {ID_EFFECTS, ID_HEIGHT, ID_LEAVES, ID_BITS, 8'h49, 8'hA5};
                        nn_q      <= 4'd6;
                        nb_full_q <= 1'b1;
                    end
                end
            S_RESET: begin                       // a few clocks of core reset
                rst_cnt_q <= rst_cnt_q + 3'd1;
                if (rst_cnt_q == 3'd7) begin
                    core_rst_nq <= 1'b1;
                    state_q     <= S_LOAD;
                end
            end
            S_LOAD: begin
                if (rx_v_q) begin                // assemble little-endian words
                    word_q     <= {rx_d_q, word_q[31:8]};
                    byte_idx_q <= byte_idx_q + 2'd1;
                    if (byte_idx_q == 2'd3) word_valid_q <= 1'b1;
                end
                if (load_error != 4'd0 || loaded) begin
                    code_q  <= load_error;
                    state_q <= S_STATUS;
                end else if (idle_q == IDLE_MAX) begin
                    code_q  <= 4'd15;
                    state_q <= S_STATUS;
                end
            end
            S_STATUS:
                if (!nb_full_q) begin
                    nb_q[15:0]  <= {4'd0, code_q, 8'hA5};
                    nn_q        <= 4'd2;
                    nb_full_q   <= 1'b1;
                    last_code_o <= code_q;
                    if (code_q == 4'd0) begin
                        start_q     <= 1'b1;
                        pix_full_q  <= 1'b0;
                        pix_ready_q <= 1'b1;
                        done_seen_q <= 1'b0;
                        state_q     <= S_RENDER;
                    end else begin
                        state_q <= (code_q == 4'd15) ? S_IDLE : S_DRAIN;
                    end
                end
            S_RENDER: begin
                if (pix_valid && pix_ready) begin
                    pix_full_q  <= 1'b1;
                    pix_ready_q <= 1'b0;
                    pix_q       <= pix_rgb;
                end
                if (done) done_seen_q <= 1'b1;
                if (pix_full_q && !nb_full_q) begin
                    nb_q[23:0]  <= {pix_q[7:0], pix_q[15:8], pix_q[23:16]};
                    nn_q        <= 4'd3;
                    nb_full_q   <= 1'b1;
                    pix_full_q  <= 1'b0;
                    pix_ready_q <= 1'b1;
                end else if (!pix_full_q && done_seen_q) begin
                    // the last pixel is in ob_q (done_o pulses after it is taken)
                    state_q     <= S_TRAILER;
                    pix_ready_q <= 1'b0;
                end
            end
            S_TRAILER:                           // done_o was the clock before: statistics final
                if (!nb_full_q) begin
                    nb_q      <= stat_cycles;
                    nn_q      <= 4'd8;
                    nb_full_q <= 1'b1;
                    state_q   <= S_WAIT;
                end
            S_WAIT:                              // until the trailer's last byte is taken
                if (on_zero_q && !nb_full_q) state_q <= S_IDLE;
            S_DRAIN:                             // discard the rest of a refused image
                if (idle_q == IDLE_MAX) state_q <= S_IDLE;
            default: state_q <= S_IDLE;
            endcase
        end
    end

    csgrt_check_same #(.WHAT("pix_ready_q")) u_check_pix_ready (
        .clk_i, .rst_ni, .copy_i(pix_ready_q), .orig_i((state_q == S_RENDER) && !pix_full_q));
    csgrt_check_same #(.WHAT("on_zero_q")) u_check_on_zero (
        .clk_i, .rst_ni, .copy_i(on_zero_q), .orig_i(on_q == 4'd0));

    wire unused_ok = &{1'b0, busy, stat_pairs, pix_x, pix_y};
endmodule
`default_nettype wire
