`default_nettype none
// csgrt_sqrt — pipelined integer square root with valid/ready:
// root_o = floor(sqrt(n_i)), bit for bit isqrt_bitwise(n, RESULT_BITS) of
// model/fixed.h (csgrt_sqrt_core: one result bit per stage), user_i carried
// alongside unchanged.
//
// Latency: RESULT_BITS + 1 clocks without back-pressure (RESULT_BITS stages
// and the output skid buffer). Throughput: one result per clock.
// II = 3: the core's stages find three result bits each, one per running
// clock of a three-clock beat (csgrt_beat, csgrt_sqrt_core FOLD = 3); a
// radicand is taken at a beat's last clock, one per beat, and the result
// is handed to the skid buffer at one: latency 3 ceil(RESULT_BITS / 3) + 1
// clocks, throughput one result per three clocks.
// Handshake: valid/ready on both sides, a word moves when valid and ready
// are both high at a rising edge. Every stage advances together on the
// beat's advance (csgrt_beat; II = 1: the skid buffer's registered ready);
// ready_o is that advance from a register of its own (csgrt_beat's
// adv_q_o), so it never depends combinationally on ready_i.
// Nothing is lost or duplicated under any pattern of valid_i and ready_i.
module csgrt_sqrt #(
    parameter RESULT_BITS = 8,   // result bits = pipeline stages (>= 2)
    parameter USER_WIDTH  = 1,   // sideband carried alongside (>= 1)
    parameter USER_OUT_REG = 0,  // csgrt_sqrt_core's
    parameter II          = 1    // running clocks per result: 1, or 3 (csgrt_sqrt_core FOLD = 3)
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

    // the beat (II = 1: adv = en, every running clock); ready_o is the
    // advance from a register of its own, as csgrt_isect's
    wire       en_next;   // en after the next rising edge
    wire [1:0] phase;
    wire       last, adv;
    csgrt_beat #(.II(II)) u_beat (.clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en), .ce_next_i(en_next),
                                  .phase_o(phase), .last_o(last), .adv_o(adv), .adv_q_o(ready_o));

    csgrt_sqrt_core #(
        .RESULT_BITS(RESULT_BITS),
        .USER_WIDTH (USER_WIDTH),
        .USER_OUT_REG(USER_OUT_REG),
        .FOLD       (II)
    ) u_core (
        .clk_i  (clk_i),
        .rst_ni (rst_ni),
        .ce_i   (adv),
        .run_i  (en),
        .phase_i(phase),
        .valid_i(valid_i),
        .n_i    (n_i),
        .user_i (user_i),
        .valid_o(core_valid),
        .root_o (core_root),
        .user_o (core_user)
    );

    csgrt_skid #(
        .WIDTH(RESULT_BITS + USER_WIDTH)
    ) u_skid (
        .clk_i  (clk_i),
        .rst_ni (rst_ni),
        .valid_i(core_valid && last),
        .ready_o(en),
        .ready_next_o(en_next),
        .data_i ({core_user, core_root}),
        .valid_o(valid_o),
        .ready_i(ready_i),
        .data_o ({user_o, root_o})
    );

endmodule

`default_nettype wire
