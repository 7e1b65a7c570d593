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
// II = 3: the core's iteration stages find three quotient bits each, one
// per running clock of a three-clock beat (csgrt_beat, csgrt_div_core
// FOLD = 3); an operand pair is taken at a beat's last clock, one per beat,
// and the result is handed to the skid buffer at one: latency
// 3 (ceil(QUOT_BITS / 3) + 1) + 1 clocks, throughput one result per three
// clocks.
// Handshake: as csgrt_sqrt: valid/ready on both sides; every stage advances
// on the beat's advance (II = 1: the skid buffer's registered ready), and
// ready_o is that advance from a register of its own (csgrt_beat's
// adv_q_o; no combinational path from ready_i).
module csgrt_div #(
    parameter NUM_WIDTH  = 16,   // signed numerator width (> QUOT_BITS)
    parameter DEN_WIDTH  = 8,    // signed denominator width (>= 2)
    parameter QUOT_BITS  = 8,    // quotient magnitude bits = stages (>= 2)
    parameter USER_WIDTH = 1,    // sideband carried alongside (>= 1)
    parameter USER_OUT_REG = 0,  // csgrt_div_core's
    parameter II         = 1     // running clocks per result: 1, or 3 (csgrt_div_core FOLD = 3)
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

    // the beat (II = 1: adv = en, every running clock); ready_o is the
    // advance from a register of its own, as csgrt_isect's
    wire       en_next;   // en after the next rising edge
    wire [1:0] phase;
    wire       last, adv;
    csgrt_beat #(.II(II)) u_beat (.clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en), .ce_next_i(en_next),
                                  .phase_o(phase), .last_o(last), .adv_o(adv), .adv_q_o(ready_o));

    csgrt_div_core #(
        .NUM_WIDTH (NUM_WIDTH),
        .DEN_WIDTH (DEN_WIDTH),
        .QUOT_BITS (QUOT_BITS),
        .USER_WIDTH(USER_WIDTH),
        .USER_OUT_REG(USER_OUT_REG),
        .FOLD      (II)
    ) u_core (
        .clk_i  (clk_i),
        .rst_ni (rst_ni),
        .ce_i   (adv),
        .run_i  (en),
        .phase_i(phase),
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

    csgrt_skid #(
        .WIDTH(QUOT_BITS + 3 + USER_WIDTH)
    ) u_skid (
        .clk_i  (clk_i),
        .rst_ni (rst_ni),
        .valid_i(core_valid && last),
        .ready_o(en),
        .ready_next_o(en_next),
        .data_i ({core_user, core_ovf, core_neg, quot_signed}),
        .valid_o(valid_o),
        .ready_i(ready_i),
        .data_o ({user_o, ovf_o, neg_o, quot_o})
    );

endmodule

`default_nettype wire
