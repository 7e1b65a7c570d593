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
    assign ready_o = (left_q == 4'd0);

    always @(posedge clk_i) begin
        if (!rst_ni) begin
            tx_o   <= 1'b1;
            left_q <= 4'd0;
            cnt_q  <= {CW{1'b0}};
        end else if (left_q == 4'd0) begin
            if (valid_i) begin
                tx_o   <= 1'b0;                   // start bit
                sh_q   <= {1'b1, data_i};
                left_q <= 4'd10;
                cnt_q  <= BIT_LAST;
            end
        end else if (cnt_q != {CW{1'b0}}) begin
            cnt_q <= cnt_q - 1'b1;
        end else begin
            left_q <= left_q - 4'd1;
            if (left_q != 4'd1) begin
                tx_o  <= sh_q[0];
                sh_q  <= {1'b1, sh_q[8:1]};
                cnt_q <= BIT_LAST;
            end
        end
    end
endmodule
`default_nettype wire
