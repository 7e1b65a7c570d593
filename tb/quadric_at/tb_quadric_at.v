`default_nettype none
// tb_quadric_at — Verilator top for tb_quadric_at.cpp: csgrt_quadric_at
// (USER_WIDTH 16) at BITS 12, 16, 24 and 32, one clock each so that only the
// instance under test is evaluated.
module tb_quadric_at (
    input  wire              b12_clk_i,
    input  wire              b12_rst_ni,
    input  wire              b12_valid_i,
    output wire              b12_ready_o,
    input  wire [35:0]  b12_o_i,
    input  wire [35:0]  b12_d_i,
    input  wire [10:0]  b12_t_i,
    input  wire [119:0] b12_coef_i,
    input  wire [15:0]       b12_user_i,
    output wire              b12_valid_o,
    input  wire              b12_ready_i,
    output wire [19:0]  b12_q_o,
    output wire [15:0]       b12_user_o,
    input  wire              b16_clk_i,
    input  wire              b16_rst_ni,
    input  wire              b16_valid_i,
    output wire              b16_ready_o,
    input  wire [47:0]  b16_o_i,
    input  wire [47:0]  b16_d_i,
    input  wire [14:0]  b16_t_i,
    input  wire [159:0] b16_coef_i,
    input  wire [15:0]       b16_user_i,
    output wire              b16_valid_o,
    input  wire              b16_ready_i,
    output wire [23:0]  b16_q_o,
    output wire [15:0]       b16_user_o,
    input  wire              b24_clk_i,
    input  wire              b24_rst_ni,
    input  wire              b24_valid_i,
    output wire              b24_ready_o,
    input  wire [71:0]  b24_o_i,
    input  wire [71:0]  b24_d_i,
    input  wire [22:0]  b24_t_i,
    input  wire [239:0] b24_coef_i,
    input  wire [15:0]       b24_user_i,
    output wire              b24_valid_o,
    input  wire              b24_ready_i,
    output wire [31:0]  b24_q_o,
    output wire [15:0]       b24_user_o,
    input  wire              b32_clk_i,
    input  wire              b32_rst_ni,
    input  wire              b32_valid_i,
    output wire              b32_ready_o,
    input  wire [95:0]  b32_o_i,
    input  wire [95:0]  b32_d_i,
    input  wire [30:0]  b32_t_i,
    input  wire [319:0] b32_coef_i,
    input  wire [15:0]       b32_user_i,
    output wire              b32_valid_o,
    input  wire              b32_ready_i,
    output wire [39:0]  b32_q_o,
    output wire [15:0]       b32_user_o
);

    csgrt_quadric_at #(.BITS(12), .USER_WIDTH(16)) u_b12 (
        .clk_i(b12_clk_i), .rst_ni(b12_rst_ni),
        .s_valid_i(b12_valid_i), .s_ready_o(b12_ready_o), .s_o_i(b12_o_i), .s_d_i(b12_d_i), .s_t_i(b12_t_i),
        .s_coef_i(b12_coef_i), .s_user_i(b12_user_i),
        .m_valid_o(b12_valid_o), .m_ready_i(b12_ready_i), .m_q_o(b12_q_o), .m_user_o(b12_user_o));

    csgrt_quadric_at #(.BITS(16), .USER_WIDTH(16)) u_b16 (
        .clk_i(b16_clk_i), .rst_ni(b16_rst_ni),
        .s_valid_i(b16_valid_i), .s_ready_o(b16_ready_o), .s_o_i(b16_o_i), .s_d_i(b16_d_i), .s_t_i(b16_t_i),
        .s_coef_i(b16_coef_i), .s_user_i(b16_user_i),
        .m_valid_o(b16_valid_o), .m_ready_i(b16_ready_i), .m_q_o(b16_q_o), .m_user_o(b16_user_o));

    csgrt_quadric_at #(.BITS(24), .USER_WIDTH(16)) u_b24 (
        .clk_i(b24_clk_i), .rst_ni(b24_rst_ni),
        .s_valid_i(b24_valid_i), .s_ready_o(b24_ready_o), .s_o_i(b24_o_i), .s_d_i(b24_d_i), .s_t_i(b24_t_i),
        .s_coef_i(b24_coef_i), .s_user_i(b24_user_i),
        .m_valid_o(b24_valid_o), .m_ready_i(b24_ready_i), .m_q_o(b24_q_o), .m_user_o(b24_user_o));

    csgrt_quadric_at #(.BITS(32), .USER_WIDTH(16)) u_b32 (
        .clk_i(b32_clk_i), .rst_ni(b32_rst_ni),
        .s_valid_i(b32_valid_i), .s_ready_o(b32_ready_o), .s_o_i(b32_o_i), .s_d_i(b32_d_i), .s_t_i(b32_t_i),
        .s_coef_i(b32_coef_i), .s_user_i(b32_user_i),
        .m_valid_o(b32_valid_o), .m_ready_i(b32_ready_i), .m_q_o(b32_q_o), .m_user_o(b32_user_o));

endmodule

`default_nettype wire
