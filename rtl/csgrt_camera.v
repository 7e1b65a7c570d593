`default_nettype none
// csgrt_camera — primary ray generator, bit for bit camera_ray_fx() of
// model/render.cpp (docs/numerics.md section 2): one ray per pixel in raster
// order (x fastest, row 0 first) after a start pulse.
//
// Per pixel, with B = BITS, F = B-3, CF = F+12 (cam_frac):
//   v_i  = base_i + x dx_i + y dy_i        exact, CF fraction bits, |v_i| < 8
//   vr_i = rnd(v_i, 8)                     F+4 fraction bits, VW = F+8 bits signed
//   L    = isqrt(sum vr_i^2, F+8) + 1      sum < 2^(2F+16)
//   d_i  = div(vr_i << F, L, F+1)          truncated, never overflows, |d_i| < 2^F
// v is formed incrementally (v += dx along a row, row start += dy), exact in
// CW = F+16 bits modulo 2^CW: only the low CW bits of base/dx/dy matter,
// because every v fits CW bits signed (|v| < 8).
//
// d is unit_fx(vr, F, F+8): csgrt_unit computes it.
//
// Pipeline (one global enable, the output skid buffer's registered ready):
//   G   (1)    generator register: x, y, v, last
//   R   (1)    vr = rnd(v, 8)
//   U   (2F+15) csgrt_unit (VW = F+8, FRAC F, F+8 square-root stages): the
//              squares, their sum, the square root, L = root + 1, the
//              divisions vr << F / L, the signed quotients
//   skid(1)    csgrt_skid
// Latency from a generated ray to its output: 2F+18 clocks (BITS 12: 36,
// 24: 60); the first ray appears 2F+19 clocks after start. Throughput: one
// ray per clock. Multipliers: 3 (VW x VW, VW = F+8 = B+5).
// II = 3 (csgrt_top's SHARE_II; csgrt_beat): a ray every third clock, every
// register moving on the beat's advance, csgrt_unit's squares on one
// multiplier, its divisions on one divider and its square root three
// result bits per stage (ceil((F+8)/3) stages); the rays still leave in
// raster order (the intersection unit takes a ray per candidate leaf and
// clock, so the camera only limits scenes with fewer than three leaves).
// Handshake: m_valid_o/m_ready_i; a ray moves when both are high at a
// rising edge. Back-pressure stalls the whole pipeline and the generator.
// done_o pulses for one clock after the frame's last ray has been accepted;
// busy_o is high from start until then. A start while busy restarts the
// frame (rays already in the pipeline still come out).
// Config (base/dx/dy/origin/width/height) is sampled at start (dx, dy,
// origin, width, height are kept for the frame). width/height are 12 bits:
// 1..4095, and 0 stands for 4096 (the counters wrap).
module csgrt_camera #(
    parameter BITS = 24,  // coordinate width B (12..32)
    parameter II   = 1    // clocks per ray: 1, or 3 (time-shared, a third of the multipliers and dividers)
) (
    input  wire             clk_i,
    input  wire             rst_ni,     // synchronous, active low
    // configuration (CameraInfo of model/compile.h)
    input  wire [3*BITS-1:0] origin_i,  // x, y, z, F fraction bits (x in the low bits)
    input  wire [3*64-1:0]  base_i,     // F+12 fraction bits, two's complement
    input  wire [3*64-1:0]  dx_i,
    input  wire [3*64-1:0]  dy_i,
    input  wire [11:0]      width_i,
    input  wire [11:0]      height_i,
    input  wire             start_i,    // one-clock pulse: begin a frame
    output wire             busy_o,
    output reg              done_o,     // one-clock pulse: last ray accepted
    // ray stream
    output wire             m_valid_o,
    input  wire             m_ready_i,
    output wire [11:0]      m_x_o,
    output wire [11:0]      m_y_o,
    output wire [3*BITS-1:0] m_o_o,     // origin, F fraction bits
    output wire [3*BITS-1:0] m_d_o,     // unit direction, F fraction bits
    output wire             m_last_o    // the frame's last ray
);

    localparam B   = BITS;
    localparam F   = B - 3;
    localparam CW  = F + 16;      // v: CF = F+12 fraction bits, |v| < 8
    localparam VW  = F + 8;       // vr: F+4 fraction bits, |vr| < 8
    localparam SQ  = F + 8;       // square-root stages: sum vr^2 < 2^(2F+16)
    localparam UOW = F + 2;       // csgrt_unit's output component, F fraction bits, signed

    wire       en;    // the pipeline runs: the output skid's ready
    wire [1:0] ph;
    wire       adv;   // the beat's advance: every register moves on it
    wire       last;  // the beat's last clock: an item leaves for the output skid only then
    wire       en_next, adv_q;
    csgrt_beat #(.II(II)) u_beat (.clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en), .ce_next_i(en_next), .phase_o(ph),
                                  .last_o(last), .adv_o(adv), .adv_q_o(adv_q));

    // ---- generator -----------------------------------------------------------
    reg [3*CW-1:0] dx_q, dy_q;   // component k at k*CW
    reg [3*CW-1:0] row_q;        // base + y dy
    reg [3*CW-1:0] v_q;          // base + x dx + y dy
    reg [3*B-1:0] origin_q;
    reg [11:0]    wm1_q, hm1_q;  // width-1, height-1 (mod 4096)
    reg [11:0]    x_q, y_q;
    reg           active_q;      // rays left to generate
    reg           busy_q;

    // x_q == wm1_q and y_q == hm1_q as registers of their own, loaded with
    // the tests of the counters' next values: the row's end selects every
    // sum's next value (row_q, v_q: ~100 loads), and a 12-bit compare in
    // front of that select was the camera's longest path
    // (tools/logic_depth.py 12.88 ns)
    reg  x_end_q, y_end_q;
    wire gen_last = x_end_q && y_end_q;
    // the generator steps on the advance's own register (adv_q, equal to
    // adv): adv enables every register of the pipeline (~3,300 loads), and
    // the generator's counters and sums read it again through their own
    // logic (tools/logic_depth.py)
    wire gen_fire = adv_q && active_q;

    // G: the generator's output register
    reg          g_valid_q, g_last_q;
    reg [11:0]   g_x_q, g_y_q;
    reg [3*CW-1:0] g_v_q;

    integer k;
    always @(posedge clk_i) begin
        if (!rst_ni) begin
            active_q  <= 1'b0;
            g_valid_q <= 1'b0;
        end else begin
            if (start_i) active_q <= 1'b1;
            else if (gen_fire && gen_last) active_q <= 1'b0;
            if (adv) g_valid_q <= active_q && !start_i;
        end
        if (start_i) begin
            for (k = 0; k < 3; k = k + 1) begin
                dx_q[k*CW +: CW]  <= dx_i[k*64 +: CW];
                dy_q[k*CW +: CW]  <= dy_i[k*64 +: CW];
                row_q[k*CW +: CW] <= base_i[k*64 +: CW];
                v_q[k*CW +: CW]   <= base_i[k*64 +: CW];
            end
            origin_q <= origin_i;
            wm1_q    <= width_i - 12'd1;
            hm1_q    <= height_i - 12'd1;
            x_q      <= 12'd0;
            y_q      <= 12'd0;
            x_end_q  <= width_i - 12'd1 == 12'd0;
            y_end_q  <= height_i - 12'd1 == 12'd0;
        end else if (gen_fire) begin
            if (x_end_q) begin
                x_q <= 12'd0;
                y_q <= y_q + 12'd1;
                x_end_q <= wm1_q == 12'd0;
                y_end_q <= y_q + 12'd1 == hm1_q;
                for (k = 0; k < 3; k = k + 1) begin
                    row_q[k*CW +: CW] <= row_q[k*CW +: CW] + dy_q[k*CW +: CW];
                    v_q[k*CW +: CW]   <= row_q[k*CW +: CW] + dy_q[k*CW +: CW];
                end
            end else begin
                x_q <= x_q + 12'd1;
                x_end_q <= x_q + 12'd1 == wm1_q;
                for (k = 0; k < 3; k = k + 1) v_q[k*CW +: CW] <= v_q[k*CW +: CW] + dx_q[k*CW +: CW];
            end
        end
        if (adv) begin
            g_x_q    <= x_q;
            g_y_q    <= y_q;
            g_v_q    <= v_q;
            g_last_q <= gen_last;
        end
    end

    // ---- R: vr = rnd(v, 8) ---------------------------------------------------
    wire [3*VW-1:0] vr_d;
    genvar i;
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_round
            wire [CW-1:0] v   = g_v_q[i*CW +: CW];
            wire [CW-1:0] vrf = v + {{(CW-8){1'b0}}, 8'h80};
            wire          unused_lsb = ^vrf[7:0];
            assign vr_d[i*VW +: VW] = vrf[CW-1:8];
        end
    endgenerate

    localparam SIDEW = 24 + 1;   // x, y, last
    reg             r_valid_q;
    reg [3*VW-1:0]  r_vr_q;
    reg [SIDEW-1:0] r_side_q;
    always @(posedge clk_i) begin
        if (!rst_ni) r_valid_q <= 1'b0;
        else if (adv) r_valid_q <= g_valid_q;
        if (adv) begin
            r_vr_q   <= vr_d;
            r_side_q <= {g_last_q, g_y_q, g_x_q};
        end
    end

    // ---- U: d = unit_fx(vr, F, F+8) ------------------------------------------------
    wire             u_valid;
    wire [3*UOW-1:0] u_d;
    wire [SQ-1:0]    unused_root;
    wire [SIDEW-1:0] d_side;
    csgrt_unit #(.VW(VW), .FRAC(F), .SQRT_STAGES(SQ), .USER_WIDTH(SIDEW), .II(II)) u_unit (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(en), .adv_i(adv), .phase_i(ph), .valid_i(r_valid_q),
        .v_i(r_vr_q), .user_i(r_side_q),
        .valid_o(u_valid), .u_o(u_d), .root_o(unused_root), .user_o(d_side));

    wire [3*B-1:0] dir;
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_dir
            wire [UOW-1:0] u = u_d[i*UOW +: UOW];
            assign dir[i*B +: B] = {u[UOW-1], u};   // B = F+3 = UOW+1
        end
    endgenerate

    // ---- output skid buffer --------------------------------------------------------
    localparam OUTW = SIDEW + 3 * B + 3 * B;
    wire             out_last;
    csgrt_skid #(.WIDTH(OUTW)) u_skid (
        .clk_i(clk_i), .rst_ni(rst_ni),
        .valid_i(u_valid && last), .ready_o(en), .ready_next_o(en_next),
        .data_i({d_side, origin_q, dir}),
        .valid_o(m_valid_o), .ready_i(m_ready_i),
        .data_o({out_last, m_y_o, m_x_o, m_o_o, m_d_o}));
    assign m_last_o = out_last;

    // ---- busy / done ---------------------------------------------------------------
    wire out_fire_last = m_valid_o && m_ready_i && out_last;
    always @(posedge clk_i) begin
        if (!rst_ni) begin
            busy_q <= 1'b0;
            done_o <= 1'b0;
        end else begin
            done_o <= out_fire_last && !start_i;
            if (start_i) busy_q <= 1'b1;
            else if (out_fire_last) busy_q <= 1'b0;
        end
    end
    assign busy_o = busy_q;

    // the end tests against the counters, while rays are left to generate
    csgrt_check_same #(.WIDTH(2), .WHAT("x_end_q / y_end_q")) u_check_end (
        .clk_i, .rst_ni, .copy_i(active_q ? {x_end_q, y_end_q} : 2'd0),
        .orig_i(active_q ? {x_q == wm1_q, y_q == hm1_q} : 2'd0));

    // only the low CW bits of the camera words matter (|v| < 8)
    wire unused_cfg = ^{base_i, dx_i, dy_i};

    generate
        if (BITS < 12 || BITS > 32) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_camera needs 12 <= BITS <= 32");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
