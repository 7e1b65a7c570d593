`default_nettype none
// tb_sqrt — Verilator top for tb_sqrt.cpp: csgrt_sqrt at RESULT_BITS 6 and 10
// (exhaustive) and 27 (F+6 of the 24-bit configuration), and with II = 3 at
// 8, 10 (exhaustive) and 27, one clock each so
// that only the instance under test is evaluated.
module tb_sqrt (
    input  wire              r6_clk_i,
    input  wire              r6_rst_ni,
    input  wire              r6_valid_i,
    output wire              r6_ready_o,
    input  wire [11:0]  r6_n_i,
    input  wire [15:0]       r6_user_i,
    output wire              r6_valid_o,
    input  wire              r6_ready_i,
    output wire [5:0]    r6_root_o,
    output wire [15:0]       r6_user_o,
    input  wire              r10_clk_i,
    input  wire              r10_rst_ni,
    input  wire              r10_valid_i,
    output wire              r10_ready_o,
    input  wire [19:0]  r10_n_i,
    input  wire [15:0]       r10_user_i,
    output wire              r10_valid_o,
    input  wire              r10_ready_i,
    output wire [9:0]    r10_root_o,
    output wire [15:0]       r10_user_o,
    input  wire              r27_clk_i,
    input  wire              r27_rst_ni,
    input  wire              r27_valid_i,
    output wire              r27_ready_o,
    input  wire [53:0]  r27_n_i,
    input  wire [15:0]       r27_user_i,
    output wire              r27_valid_o,
    input  wire              r27_ready_i,
    output wire [26:0]    r27_root_o,
    output wire [15:0]       r27_user_o,
    input  wire              f8_clk_i,
    input  wire              f8_rst_ni,
    input  wire              f8_valid_i,
    output wire              f8_ready_o,
    input  wire [15:0]  f8_n_i,
    input  wire [15:0]       f8_user_i,
    output wire              f8_valid_o,
    input  wire              f8_ready_i,
    output wire [7:0]    f8_root_o,
    output wire [15:0]       f8_user_o,
    input  wire              f10_clk_i,
    input  wire              f10_rst_ni,
    input  wire              f10_valid_i,
    output wire              f10_ready_o,
    input  wire [19:0]  f10_n_i,
    input  wire [15:0]       f10_user_i,
    output wire              f10_valid_o,
    input  wire              f10_ready_i,
    output wire [9:0]    f10_root_o,
    output wire [15:0]       f10_user_o,
    input  wire              f27_clk_i,
    input  wire              f27_rst_ni,
    input  wire              f27_valid_i,
    output wire              f27_ready_o,
    input  wire [53:0]  f27_n_i,
    input  wire [15:0]       f27_user_i,
    output wire              f27_valid_o,
    input  wire              f27_ready_i,
    output wire [26:0]    f27_root_o,
    output wire [15:0]       f27_user_o
);

    csgrt_sqrt #(.RESULT_BITS(6), .USER_WIDTH(16)) u_r6 (
        .clk_i(r6_clk_i), .rst_ni(r6_rst_ni),
        .valid_i(r6_valid_i), .ready_o(r6_ready_o), .n_i(r6_n_i), .user_i(r6_user_i),
        .valid_o(r6_valid_o), .ready_i(r6_ready_i), .root_o(r6_root_o), .user_o(r6_user_o));

    csgrt_sqrt #(.RESULT_BITS(10), .USER_WIDTH(16)) u_r10 (
        .clk_i(r10_clk_i), .rst_ni(r10_rst_ni),
        .valid_i(r10_valid_i), .ready_o(r10_ready_o), .n_i(r10_n_i), .user_i(r10_user_i),
        .valid_o(r10_valid_o), .ready_i(r10_ready_i), .root_o(r10_root_o), .user_o(r10_user_o));

    // the 27-stage root's sideband line ends in a fabric register (USER_OUT_REG)
    csgrt_sqrt #(.RESULT_BITS(27), .USER_WIDTH(16), .USER_OUT_REG(1)) u_r27 (
        .clk_i(r27_clk_i), .rst_ni(r27_rst_ni),
        .valid_i(r27_valid_i), .ready_o(r27_ready_o), .n_i(r27_n_i), .user_i(r27_user_i),
        .valid_o(r27_valid_o), .ready_i(r27_ready_i), .root_o(r27_root_o), .user_o(r27_user_o));

    // II = 3 (csgrt_sqrt_core FOLD = 3): 8 and 10 bits leave the last
    // stage one and two steps short, 27 fills it
    csgrt_sqrt #(.RESULT_BITS(8), .USER_WIDTH(16), .II(3)) u_f8 (
        .clk_i(f8_clk_i), .rst_ni(f8_rst_ni),
        .valid_i(f8_valid_i), .ready_o(f8_ready_o), .n_i(f8_n_i), .user_i(f8_user_i),
        .valid_o(f8_valid_o), .ready_i(f8_ready_i), .root_o(f8_root_o), .user_o(f8_user_o));

    csgrt_sqrt #(.RESULT_BITS(10), .USER_WIDTH(16), .II(3)) u_f10 (
        .clk_i(f10_clk_i), .rst_ni(f10_rst_ni),
        .valid_i(f10_valid_i), .ready_o(f10_ready_o), .n_i(f10_n_i), .user_i(f10_user_i),
        .valid_o(f10_valid_o), .ready_i(f10_ready_i), .root_o(f10_root_o), .user_o(f10_user_o));

    csgrt_sqrt #(.RESULT_BITS(27), .USER_WIDTH(16), .USER_OUT_REG(1), .II(3)) u_f27 (
        .clk_i(f27_clk_i), .rst_ni(f27_rst_ni),
        .valid_i(f27_valid_i), .ready_o(f27_ready_o), .n_i(f27_n_i), .user_i(f27_user_i),
        .valid_o(f27_valid_o), .ready_i(f27_ready_i), .root_o(f27_root_o), .user_o(f27_user_o));
endmodule

`default_nettype wire
