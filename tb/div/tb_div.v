`default_nettype none
// tb_div — Verilator top for tb_div.cpp: csgrt_div at
//   x: NUM 10, DEN 8, QUOT 5 bits (exhaustive),
//   m: NUM 28, DEN 17, QUOT 10 (csgrt_isect's dividers at BITS = 12),
//   l: NUM 52, DEN 29, QUOT 22 (csgrt_isect's dividers at BITS = 24),
//   x3, l3: x and l with II = 3 (three quotient bits per stage, one per
//   running clock: csgrt_div_core FOLD = 3; 5 and 22 bits leave the last
//   stage one and two steps short),
// one clock each so that only the instance under test is evaluated.
module tb_div (
    input  wire              x_clk_i,
    input  wire              x_rst_ni,
    input  wire              x_valid_i,
    output wire              x_ready_o,
    input  wire [9:0]  x_num_i,
    input  wire [7:0]  x_den_i,
    input  wire [15:0]       x_user_i,
    output wire              x_valid_o,
    input  wire              x_ready_i,
    output wire [5:0]    x_quot_o,
    output wire              x_neg_o,
    output wire              x_ovf_o,
    output wire [15:0]       x_user_o,
    input  wire              m_clk_i,
    input  wire              m_rst_ni,
    input  wire              m_valid_i,
    output wire              m_ready_o,
    input  wire [27:0]  m_num_i,
    input  wire [16:0]  m_den_i,
    input  wire [15:0]       m_user_i,
    output wire              m_valid_o,
    input  wire              m_ready_i,
    output wire [10:0]    m_quot_o,
    output wire              m_neg_o,
    output wire              m_ovf_o,
    output wire [15:0]       m_user_o,
    input  wire              l_clk_i,
    input  wire              l_rst_ni,
    input  wire              l_valid_i,
    output wire              l_ready_o,
    input  wire [51:0]  l_num_i,
    input  wire [28:0]  l_den_i,
    input  wire [15:0]       l_user_i,
    output wire              l_valid_o,
    input  wire              l_ready_i,
    output wire [22:0]    l_quot_o,
    output wire              l_neg_o,
    output wire              l_ovf_o,
    output wire [15:0]       l_user_o,
    input  wire              x3_clk_i,
    input  wire              x3_rst_ni,
    input  wire              x3_valid_i,
    output wire              x3_ready_o,
    input  wire [9:0]  x3_num_i,
    input  wire [7:0]  x3_den_i,
    input  wire [15:0]       x3_user_i,
    output wire              x3_valid_o,
    input  wire              x3_ready_i,
    output wire [5:0]    x3_quot_o,
    output wire              x3_neg_o,
    output wire              x3_ovf_o,
    output wire [15:0]       x3_user_o,
    input  wire              l3_clk_i,
    input  wire              l3_rst_ni,
    input  wire              l3_valid_i,
    output wire              l3_ready_o,
    input  wire [51:0]  l3_num_i,
    input  wire [28:0]  l3_den_i,
    input  wire [15:0]       l3_user_i,
    output wire              l3_valid_o,
    input  wire              l3_ready_i,
    output wire [22:0]    l3_quot_o,
    output wire              l3_neg_o,
    output wire              l3_ovf_o,
    output wire [15:0]       l3_user_o
);

    csgrt_div #(.NUM_WIDTH(10), .DEN_WIDTH(8), .QUOT_BITS(5), .USER_WIDTH(16)) u_x (
        .clk_i(x_clk_i), .rst_ni(x_rst_ni),
        .valid_i(x_valid_i), .ready_o(x_ready_o), .num_i(x_num_i), .den_i(x_den_i), .user_i(x_user_i),
        .valid_o(x_valid_o), .ready_i(x_ready_i), .quot_o(x_quot_o), .neg_o(x_neg_o), .ovf_o(x_ovf_o),
        .user_o(x_user_o));

    csgrt_div #(.NUM_WIDTH(28), .DEN_WIDTH(17), .QUOT_BITS(10), .USER_WIDTH(16)) u_m (
        .clk_i(m_clk_i), .rst_ni(m_rst_ni),
        .valid_i(m_valid_i), .ready_o(m_ready_o), .num_i(m_num_i), .den_i(m_den_i), .user_i(m_user_i),
        .valid_o(m_valid_o), .ready_i(m_ready_i), .quot_o(m_quot_o), .neg_o(m_neg_o), .ovf_o(m_ovf_o),
        .user_o(m_user_o));

    // the long divider's sideband line ends in a fabric register (USER_OUT_REG)
    csgrt_div #(.NUM_WIDTH(52), .DEN_WIDTH(29), .QUOT_BITS(22), .USER_WIDTH(16), .USER_OUT_REG(1)) u_l (
        .clk_i(l_clk_i), .rst_ni(l_rst_ni),
        .valid_i(l_valid_i), .ready_o(l_ready_o), .num_i(l_num_i), .den_i(l_den_i), .user_i(l_user_i),
        .valid_o(l_valid_o), .ready_i(l_ready_i), .quot_o(l_quot_o), .neg_o(l_neg_o), .ovf_o(l_ovf_o),
        .user_o(l_user_o));

    csgrt_div #(.NUM_WIDTH(10), .DEN_WIDTH(8), .QUOT_BITS(5), .USER_WIDTH(16), .II(3)) u_x3 (
        .clk_i(x3_clk_i), .rst_ni(x3_rst_ni),
        .valid_i(x3_valid_i), .ready_o(x3_ready_o), .num_i(x3_num_i), .den_i(x3_den_i), .user_i(x3_user_i),
        .valid_o(x3_valid_o), .ready_i(x3_ready_i), .quot_o(x3_quot_o), .neg_o(x3_neg_o), .ovf_o(x3_ovf_o),
        .user_o(x3_user_o));

    csgrt_div #(.NUM_WIDTH(52), .DEN_WIDTH(29), .QUOT_BITS(22), .USER_WIDTH(16), .USER_OUT_REG(1), .II(3)) u_l3 (
        .clk_i(l3_clk_i), .rst_ni(l3_rst_ni),
        .valid_i(l3_valid_i), .ready_o(l3_ready_o), .num_i(l3_num_i), .den_i(l3_den_i), .user_i(l3_user_i),
        .valid_o(l3_valid_o), .ready_i(l3_ready_i), .quot_o(l3_quot_o), .neg_o(l3_neg_o), .ovf_o(l3_ovf_o),
        .user_o(l3_user_o));
endmodule

`default_nettype wire
