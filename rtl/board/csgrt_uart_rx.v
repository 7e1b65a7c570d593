`default_nettype none
// csgrt_uart_rx — 8N1 UART receiver. DIV clocks per bit (DIV >= 4); the
// line is synchronised by two flip-flops, the start bit is confirmed at its
// middle and each bit sampled at its middle. A byte whose stop bit is low
// (framing error) is dropped. One-clock valid pulse per byte, no back-pressure.
module csgrt_uart_rx #(
    parameter DIV = 868              // clocks per bit (clock / baud)
) (
    input  wire       clk_i,
    input  wire       rst_ni,        // synchronous, active low
    input  wire       rx_i,          // the line, idle high
    output reg        valid_o,
    output reg  [7:0] data_o,
    output wire       active_o       // a frame is being received
);
    localparam CW = $clog2(DIV + 1);
    /* verilator lint_off WIDTH */
    localparam [CW-1:0] BIT_LAST = DIV - 1, HALF_LAST = (DIV / 2 > 3) ? DIV / 2 - 3 : 0;   // less the synchroniser's 2 clocks
    /* verilator lint_on WIDTH */
    reg [2:0]    sync_q;             // sync_q[2] is the synchronised line
    reg          busy_q;
    reg [CW-1:0] cnt_q;
    reg [3:0]    bit_q;              // 0 start, 1..8 data, 9 stop
    reg [7:0]    sh_q;
    assign active_o = busy_q;

    always @(posedge clk_i) begin
        sync_q <= {sync_q[1:0], rx_i};
        valid_o <= 1'b0;
        if (!rst_ni) begin
            sync_q <= 3'b111;
            busy_q <= 1'b0;
            cnt_q  <= {CW{1'b0}};
            bit_q  <= 4'd0;
        end else if (!busy_q) begin
            if (!sync_q[2]) begin                 // start edge: wait half a bit
                busy_q <= 1'b1;
                cnt_q  <= HALF_LAST;
                bit_q  <= 4'd0;
            end
        end else if (cnt_q != {CW{1'b0}}) begin
            cnt_q <= cnt_q - 1'b1;
        end else begin                            // the middle of bit bit_q
            cnt_q <= BIT_LAST;
            bit_q <= bit_q + 4'd1;
            if (bit_q == 4'd0) begin
                if (sync_q[2]) busy_q <= 1'b0;    // a glitch, not a start bit
            end else if (bit_q <= 4'd8) begin
                sh_q <= {sync_q[2], sh_q[7:1]};   // LSB first
            end else begin
                busy_q <= 1'b0;
                if (sync_q[2]) begin
                    valid_o <= 1'b1;
                    data_o  <= sh_q;
                end
            end
        end
    end
endmodule
`default_nettype wire
