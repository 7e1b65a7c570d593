`default_nettype none
// csgrt_shade_unit — the shading unit vector, bit for bit unit_fx(v, 15, 17)
// of model/render.cpp: u_i = div(v_i << 15, isqrt(sum v^2, 17) + 1, 16),
// truncated toward zero, |u_i| < 2^15 (17-bit signed output). The caller
// guarantees sum v^2 < 2^34 (the model's bound; it throws otherwise).
//
// A thin wrapper of csgrt_unit (FRAC 15, SQRT_STAGES 17), which has the
// pipeline: M (2) squares, S (1) sum, Q (17) square root, P (1) L = root + 1,
// D (17) divisions, O (1) signed output.
// Latency: 39 clocks, counted in enabled clocks (II = 3: 18 beats of
// three clocks, the squares on one multiplier, the divisions on one
// divider, the square root three result bits per stage: csgrt_unit). Handshake: none (the
// enclosing pipeline's global stall ce_i). Multipliers: 3 (II = 3: 1).
module csgrt_shade_unit #(
    parameter VW         = 18,   // signed width of v_i (<= 18 keeps 18x18 multipliers)
    parameter USER_WIDTH = 1,    // sideband carried alongside (>= 1)
    parameter II         = 1     // running clocks per beat: 1 or 3 (csgrt_unit)
) (
    input  wire                  clk_i,
    input  wire                  rst_ni,   // synchronous, active low (valid bits only)
    input  wire                  ce_i,     // the pipeline runs (low = stall)
    input  wire                  adv_i,    // the beat's advance: csgrt_beat's adv_o
    input  wire [1:0]            phase_i,  // csgrt_beat's phase (II = 3)
    input  wire                  valid_i,
    input  wire [3*VW-1:0]       v_i,      // x, y, z (x low), any common fraction
    input  wire [USER_WIDTH-1:0] user_i,
    output wire                  valid_o,
    output wire [3*17-1:0]       u_o,      // 15 fraction bits, signed
    output wire [USER_WIDTH-1:0] user_o
);

    // the square root (the length before +1) is not needed by shading;
    // synthesis removes its registers
    wire [16:0] unused_root;

    csgrt_unit #(.VW(VW), .FRAC(15), .SQRT_STAGES(17), .USER_WIDTH(USER_WIDTH), .II(II)) u_unit (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(ce_i), .adv_i(adv_i), .phase_i(phase_i), .valid_i(valid_i),
        .v_i(v_i), .user_i(user_i),
        .valid_o(valid_o), .u_o(u_o), .root_o(unused_root), .user_o(user_o));

    generate
        if (VW < 2 || VW > 19 || USER_WIDTH < 1) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_shade_unit needs 2 <= VW <= 19, USER_WIDTH >= 1");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
