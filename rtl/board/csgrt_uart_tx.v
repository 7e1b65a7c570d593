`default_nettype none
// csgrt_uart_tx — 8N1 UART transmitter, DIV clocks per bit. Takes a byte
// on a valid/ready handshake (ready while the line is idle) and sends start
// bit, 8 data bits LSB first, stop bit. The line idles high.
module csgrt_uart_tx #(
    parameter DIV = 868
) (
    input  wire       clk_i,
    input  wire       rst_ni,
    input  wire       valid_i,
    output wire       ready_o,
    input  wire [7:0] data_i,
    output reg        tx_o
);
    localparam CW = $clog2(DIV + 1);
    /* verilator lint_off WIDTH */
    localparam [CW-1:0] BIT_LAST = DIV - 1;
    /* verilator lint_on WIDTH */
    reg [CW-1:0] cnt_q;
    reg [3:0]    left_q;             // bits still to send, 0: idle
    reg [8:0]    sh_q;               // {stop, data} still to send
    // left_q == 0, left_q == 1 and cnt_q == 0 as registers of their own,
    // loaded with the tests of the next values: as compares they were three
    // LUT levels of a six-level path into sh_q (tools/logic_depth.py
    // 11.66 ns, the transmitter's longest); u_check_tests compares them
    reg          idle_q, last_q, cnt_zero_q;
    localparam   BIT_LAST_ZERO = (DIV == 1);
    assign ready_o = idle_q;

    always @(posedge clk_i) begin
        if (!rst_ni) begin
            tx_o       <= 1'b1;
            left_q     <= 4'd0;
            cnt_q      <= {CW{1'b0}};
            idle_q     <= 1'b1;
            last_q     <= 1'b0;
            cnt_zero_q <= 1'b1;
        end else if (idle_q) begin
            if (valid_i) begin
                tx_o       <= 1'b0;               // start bit
                sh_q       <= {1'b1, data_i};
                left_q     <= 4'd10;
                idle_q     <= 1'b0;
                last_q     <= 1'b0;
                cnt_q      <= BIT_LAST;
                cnt_zero_q <= BIT_LAST_ZERO;
            end
        end else if (!cnt_zero_q) begin
            cnt_q      <= cnt_q - 1'b1;
            cnt_zero_q <= cnt_q == {{(CW-1){1'b0}}, 1'b1};
        end else begin
            left_q <= left_q - 4'd1;
            idle_q <= last_q;
            last_q <= left_q == 4'd2;
            if (!last_q) begin
                tx_o       <= sh_q[0];
                sh_q       <= {1'b1, sh_q[8:1]};
                cnt_q      <= BIT_LAST;
                cnt_zero_q <= BIT_LAST_ZERO;
            end
        end
    end
    csgrt_check_same #(.WIDTH(3), .WHAT("the transmitter's tests (idle_q, last_q, cnt_zero_q)")) u_check_tests (
        .clk_i(clk_i), .rst_ni(rst_ni), .copy_i({idle_q, last_q, cnt_zero_q}),
        .orig_i({left_q == 4'd0, left_q == 4'd1, cnt_q == {CW{1'b0}}}));
endmodule
`default_nettype wire
