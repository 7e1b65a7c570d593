`default_nettype none
// csgrt_sqrt — pipelined integer square root with valid/ready:
// root_o = floor(sqrt(n_i)), bit for bit isqrt_bitwise(n, RESULT_BITS) of
// model/fixed.h (csgrt_sqrt_core: one result bit per stage), user_i carried
// alongside unchanged.
//
// Latency: RESULT_BITS + 1 clocks without back-pressure (RESULT_BITS stages
// and the output skid buffer). Throughput: one result per clock.
// Handshake: valid/ready on both sides, a word moves when valid and ready
// are both high at a rising edge. Every stage advances together on one
// global enable, the skid buffer's registered ready; ready_o is that enable,
// so it is a register output and never depends combinationally on ready_i.
// Nothing is lost or duplicated under any pattern of valid_i and ready_i.
module csgrt_sqrt #(
    parameter RESULT_BITS = 8,   // result bits = pipeline stages (>= 2)
    parameter USER_WIDTH  = 1,   // sideband carried alongside (>= 1)
    parameter USER_OUT_REG = 0   // csgrt_sqrt_core's
) (
    input  wire                     clk_i,
    input  wire                     rst_ni,    // synchronous, active low
    // input stream
    input  wire                     valid_i,
    output wire                     ready_o,
    input  wire [2*RESULT_BITS-1:0] n_i,       // radicand, unsigned
    input  wire [USER_WIDTH-1:0]    user_i,
    // output stream
    output wire                     valid_o,
    input  wire                     ready_i,
    output wire [RESULT_BITS-1:0]   root_o,
    output wire [USER_WIDTH-1:0]    user_o
);

    wire                   en;          // global stage enable = skid ready
    wire                   core_valid;
    wire [RESULT_BITS-1:0] core_root;
    wire [USER_WIDTH-1:0]  core_user;

    assign ready_o = en;

    csgrt_sqrt_core #(
        .RESULT_BITS(RESULT_BITS),
        .USER_WIDTH (USER_WIDTH),
        .USER_OUT_REG(USER_OUT_REG)
    ) u_core (
        .clk_i  (clk_i),
        .rst_ni (rst_ni),
        .ce_i   (en),
        .valid_i(valid_i),
        .n_i    (n_i),
        .user_i (user_i),
        .valid_o(core_valid),
        .root_o (core_root),
        .user_o (core_user)
    );

    wire unused_en_next;   // no beat here
    csgrt_skid #(
        .WIDTH(RESULT_BITS + USER_WIDTH)
    ) u_skid (
        .clk_i  (clk_i),
        .rst_ni (rst_ni),
        .valid_i(core_valid),
        .ready_o(en),
        .ready_next_o(unused_en_next),
        .data_i ({core_user, core_root}),
        .valid_o(valid_o),
        .ready_i(ready_i),
        .data_o ({user_o, root_o})
    );

endmodule

`default_nettype wire
