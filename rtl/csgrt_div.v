`default_nettype none
// csgrt_div — pipelined signed division with valid/ready, bit for bit
// sdiv_trunc() / div_overflows() of model/fixed.h: quot_o = n / d rounded
// toward zero when |n / d| < 2^QUOT_BITS; otherwise ovf_o = 1 and quot_o = 0,
// and neg_o = (n < 0) != (d < 0) tells the saturation's sign (NegInf when
// set). d = 0 reports overflow. user_i is carried alongside unchanged.
//
// Latency: QUOT_BITS + 2 clocks without back-pressure (input stage,
// QUOT_BITS quotient stages, the output skid buffer; the final negation is
// combinational into the skid buffer). Throughput: one result per clock.
// Handshake: as csgrt_sqrt: valid/ready on both sides; every stage advances
// on one global enable, the skid buffer's registered ready, which is also
// ready_o (a register output, no combinational path from ready_i).
module csgrt_div #(
    parameter NUM_WIDTH  = 16,   // signed numerator width (> QUOT_BITS)
    parameter DEN_WIDTH  = 8,    // signed denominator width (>= 2)
    parameter QUOT_BITS  = 8,    // quotient magnitude bits = stages (>= 2)
    parameter USER_WIDTH = 1,    // sideband carried alongside (>= 1)
    parameter USER_OUT_REG = 0   // csgrt_div_core's
) (
    input  wire                  clk_i,
    input  wire                  rst_ni,   // synchronous, active low
    // input stream
    input  wire                  valid_i,
    output wire                  ready_o,
    input  wire [NUM_WIDTH-1:0]  num_i,    // two's complement
    input  wire [DEN_WIDTH-1:0]  den_i,    // two's complement
    input  wire [USER_WIDTH-1:0] user_i,
    // output stream
    output wire                  valid_o,
    input  wire                  ready_i,
    output wire [QUOT_BITS:0]    quot_o,   // two's complement, 0 when ovf_o
    output wire                  neg_o,
    output wire                  ovf_o,
    output wire [USER_WIDTH-1:0] user_o
);

    wire                  en;   // global stage enable = skid ready
    wire                  core_valid, core_neg, core_ovf;
    wire [QUOT_BITS-1:0]  core_quot;
    wire [USER_WIDTH-1:0] core_user;
    wire [QUOT_BITS:0]    quot_mag = {1'b0, core_quot};
    wire [QUOT_BITS:0]    quot_signed = core_ovf ? {(QUOT_BITS+1){1'b0}}
                                      : core_neg ? ~quot_mag + {{QUOT_BITS{1'b0}}, 1'b1}
                                      : quot_mag;

    assign ready_o = en;

    csgrt_div_core #(
        .NUM_WIDTH (NUM_WIDTH),
        .DEN_WIDTH (DEN_WIDTH),
        .QUOT_BITS (QUOT_BITS),
        .USER_WIDTH(USER_WIDTH),
        .USER_OUT_REG(USER_OUT_REG)
    ) u_core (
        .clk_i  (clk_i),
        .rst_ni (rst_ni),
        .ce_i   (en),
        .valid_i(valid_i),
        .num_i  (num_i),
        .den_i  (den_i),
        .user_i (user_i),
        .valid_o(core_valid),
        .quot_o (core_quot),
        .neg_o  (core_neg),
        .ovf_o  (core_ovf),
        .user_o (core_user)
    );

    wire unused_en_next;   // no beat here
    csgrt_skid #(
        .WIDTH(QUOT_BITS + 3 + USER_WIDTH)
    ) u_skid (
        .clk_i  (clk_i),
        .rst_ni (rst_ni),
        .valid_i(core_valid),
        .ready_o(en),
        .ready_next_o(unused_en_next),
        .data_i ({core_user, core_ovf, core_neg, quot_signed}),
        .valid_o(valid_o),
        .ready_i(ready_i),
        .data_o ({user_o, ovf_o, neg_o, quot_o})
    );

endmodule

`default_nettype wire
