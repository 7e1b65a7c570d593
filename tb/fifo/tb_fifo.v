`default_nettype none
// tb_fifo — Verilator top for tb_fifo.cpp: csgrt_fifo (LUT RAM, latency 1)
// and csgrt_fifo_block (block RAM, latency 2; with HEAD_REG 1, 2 and 3, latency
// 3), side by side with their own handshakes, WIDTH bits wide and DEPTH entries deep;
// csgrt_hold, the one-word register slice (latency 1, a word per 2 clocks);
// and the two-word slices csgrt_skid and csgrt_pingpong (latency 1, a word
// per clock), which must behave alike clock for clock.
module tb_fifo #(
    parameter WIDTH = 40,
    parameter DEPTH = 8
) (
    input  wire             clk_i,
    input  wire             rst_ni,
    // csgrt_fifo
    input  wire             lut_valid_i,
    output wire             lut_ready_o,
    input  wire [WIDTH-1:0] lut_data_i,
    output wire             lut_valid_o,
    input  wire             lut_ready_i,
    output wire [WIDTH-1:0] lut_data_o,
    // csgrt_fifo_block
    input  wire             blk_valid_i,
    output wire             blk_ready_o,
    input  wire [WIDTH-1:0] blk_data_i,
    output wire             blk_valid_o,
    input  wire             blk_ready_i,
    output wire [WIDTH-1:0] blk_data_o,
    // csgrt_fifo_block with HEAD_REG = 1
    input  wire             hr1_valid_i,
    output wire             hr1_ready_o,
    input  wire [WIDTH-1:0] hr1_data_i,
    output wire             hr1_valid_o,
    input  wire             hr1_ready_i,
    output wire [WIDTH-1:0] hr1_data_o,
    // csgrt_fifo_block with HEAD_REG = 2
    input  wire             hr2_valid_i,
    output wire             hr2_ready_o,
    input  wire [WIDTH-1:0] hr2_data_i,
    output wire             hr2_valid_o,
    input  wire             hr2_ready_i,
    output wire [WIDTH-1:0] hr2_data_o,
    // csgrt_fifo_block with HEAD_REG = 3
    input  wire             hr3_valid_i,
    output wire             hr3_ready_o,
    input  wire [WIDTH-1:0] hr3_data_i,
    output wire             hr3_valid_o,
    input  wire             hr3_ready_i,
    output wire [WIDTH-1:0] hr3_data_o,
    // csgrt_hold
    input  wire             hold_valid_i,
    output wire             hold_ready_o,
    input  wire [WIDTH-1:0] hold_data_i,
    output wire             hold_valid_o,
    input  wire             hold_ready_i,
    output wire [WIDTH-1:0] hold_data_o,
    // csgrt_skid
    input  wire             skid_valid_i,
    output wire             skid_ready_o,
    output wire             skid_ready_next_o,
    input  wire [WIDTH-1:0] skid_data_i,
    output wire             skid_valid_o,
    input  wire             skid_ready_i,
    output wire [WIDTH-1:0] skid_data_o,
    // csgrt_pingpong
    input  wire             pp_valid_i,
    output wire             pp_ready_o,
    output wire             pp_ready_next_o,
    input  wire [WIDTH-1:0] pp_data_i,
    output wire             pp_valid_o,
    input  wire             pp_ready_i,
    output wire [WIDTH-1:0] pp_data_o
);
    csgrt_fifo #(.WIDTH(WIDTH), .DEPTH(DEPTH)) u_lut (
        .clk_i, .rst_ni, .valid_i(lut_valid_i), .ready_o(lut_ready_o), .data_i(lut_data_i),
        .valid_o(lut_valid_o), .ready_i(lut_ready_i), .data_o(lut_data_o));
    csgrt_fifo_block #(.WIDTH(WIDTH), .DEPTH(DEPTH)) u_blk (
        .clk_i, .rst_ni, .valid_i(blk_valid_i), .ready_o(blk_ready_o), .data_i(blk_data_i),
        .valid_o(blk_valid_o), .ready_i(blk_ready_i), .data_o(blk_data_o));
    csgrt_fifo_block #(.WIDTH(WIDTH), .DEPTH(DEPTH), .HEAD_REG(1)) u_hr1 (
        .clk_i, .rst_ni, .valid_i(hr1_valid_i), .ready_o(hr1_ready_o), .data_i(hr1_data_i),
        .valid_o(hr1_valid_o), .ready_i(hr1_ready_i), .data_o(hr1_data_o));
    csgrt_fifo_block #(.WIDTH(WIDTH), .DEPTH(DEPTH), .HEAD_REG(2)) u_hr2 (
        .clk_i, .rst_ni, .valid_i(hr2_valid_i), .ready_o(hr2_ready_o), .data_i(hr2_data_i),
        .valid_o(hr2_valid_o), .ready_i(hr2_ready_i), .data_o(hr2_data_o));
    csgrt_fifo_block #(.WIDTH(WIDTH), .DEPTH(DEPTH), .HEAD_REG(3)) u_hr3 (
        .clk_i, .rst_ni, .valid_i(hr3_valid_i), .ready_o(hr3_ready_o), .data_i(hr3_data_i),
        .valid_o(hr3_valid_o), .ready_i(hr3_ready_i), .data_o(hr3_data_o));
    csgrt_hold #(.WIDTH(WIDTH)) u_hold (
        .clk_i, .rst_ni, .valid_i(hold_valid_i), .ready_o(hold_ready_o), .data_i(hold_data_i),
        .valid_o(hold_valid_o), .ready_i(hold_ready_i), .data_o(hold_data_o));
    csgrt_skid #(.WIDTH(WIDTH)) u_skid (
        .clk_i, .rst_ni, .valid_i(skid_valid_i), .ready_o(skid_ready_o), .ready_next_o(skid_ready_next_o),
        .data_i(skid_data_i), .valid_o(skid_valid_o), .ready_i(skid_ready_i), .data_o(skid_data_o));
    csgrt_pingpong #(.WIDTH(WIDTH)) u_pp (
        .clk_i, .rst_ni, .valid_i(pp_valid_i), .ready_o(pp_ready_o), .ready_next_o(pp_ready_next_o),
        .data_i(pp_data_i), .valid_o(pp_valid_o), .ready_i(pp_ready_i), .data_o(pp_data_o));
endmodule
`default_nettype wire
