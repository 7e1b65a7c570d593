`default_nettype none
// csgrt_quadric_at — the value of one quadric at the hit point of a ray,
// bit for bit beyond_fx's arithmetic (model/trace.cpp):
//   p_i = o_i + rnd(t d_i, F)                      hit_point_fx (no range check)
//   w_i = rnd(sum_j A_ij p_j + (P_i << F), FC)     half_gradient_fx
//   q   = rnd(sum_i p_i (w_i + rnd(P_i, FC-F)), F) + rnd(Q, FC-F)   quadric_at_fx
// with rnd(x, k) = (x + 2^(k-1)) >> k (round half up, arithmetic shift).
// It is the geometric test of the refraction look-ahead (algorithm.md
// section 6): "the hit point already lies beyond the next surface" is
// q <= 0 for an entering event and q > 0 for a leaving one. The test is rare
// (only after a transparent hit, only for events at a later t), so the unit
// is small rather than fast: one multiplier, one evaluation at a time.
//
// Formats (model/fixed.h, struct Formats), B = BITS, F = B-3, FC = B-1:
//   s_o_i, s_d_i  3 x B signed, F frac, x in the low bits
//   s_t_i         B-1 bits signed, F frac (the walker's t)
//   s_coef_i      10 x B signed, FC frac, CoefIndex order (A00 A11 A22 A01
//                 A02 A12 P0 P1 P2 Q), coefficient k at [k*B +: B]
//   m_q_o         QW = B+8 bits signed, F frac
// Widths (every product and sum exact): |o| < 4, |t| < 2, |d| <= 1 give
// |p| < 6 (PW = B+1 bits, F frac); |A_ij|, |P_i|, |Q| < 1 give |w_i| < 20
// (WW = B+4 bits), |q| < 3 * 6 * 20 + 1 < 2^9 (QW). Products: one csgrt_mul
// (B+4) x (B+1), 2B+5 bits; the sums are kept at that width.
//
// Schedule, one product issued per clock (step = clocks after acceptance;
// a product issued at step s is read at step s+2, csgrt_mul's latency):
//   steps 0..2    t d_i                 -> p_i at steps 2..4
//   steps 5..13   A_ij p_j, row major   -> w_i at steps 9, 12, 15
//   steps 14..16  p_i w_i               -> q at step 18
// Latency: 20 clocks from acceptance to m_valid_o (II 20 without
// back-pressure). Handshake: valid/ready; s_ready_o is high only while the
// unit is idle (a register: no combinational path from m_ready_i); the
// result is held until taken. s_user_i rides along.
module csgrt_quadric_at #(
    parameter BITS       = 24,   // B (12..32)
    parameter USER_WIDTH = 1     // sideband width (>= 1)
) (
    input  wire                  clk_i,
    input  wire                  rst_ni,     // synchronous, active low
    input  wire                  s_valid_i,
    output wire                  s_ready_o,
    input  wire [3*BITS-1:0]     s_o_i,
    input  wire [3*BITS-1:0]     s_d_i,
    input  wire [BITS-2:0]       s_t_i,
    input  wire [10*BITS-1:0]    s_coef_i,
    input  wire [USER_WIDTH-1:0] s_user_i,
    output wire                  m_valid_o,
    input  wire                  m_ready_i,
    output wire [BITS+7:0]       m_q_o,
    output wire [USER_WIDTH-1:0] m_user_o
);

    localparam B   = BITS;
    localparam F   = B - 3;
    localparam FC  = B - 1;
    localparam PW  = B + 1;          // hit point
    localparam WW  = B + 4;          // w_i + rnd(P_i, FC-F)
    localparam MAW = B + 4;          // multiplier operand a: t, A_ij or w_i
    localparam MBW = B + 1;          // multiplier operand b: d_i or p_j
    localparam SW  = MAW + MBW;      // products and sums (2B+5)
    localparam QW  = B + 8;
    localparam LAST_STEP = 18;       // q is written at this step
    localparam [SW-1:0] RND_F  = {{(SW-F){1'b0}}, 1'b1, {(F-1){1'b0}}};     // 2^(F-1)
    localparam [SW-1:0] RND_FC = {{(SW-FC){1'b0}}, 1'b1, {(FC-1){1'b0}}};   // 2^(FC-1)

    // ---- the request, held while the unit works ------------------------------
    reg [3*B-1:0]        o_q, d_q;
    reg [B-2:0]          t_q;
    reg [10*B-1:0]       coef_q;
    reg [USER_WIDTH-1:0] user_q;
    reg                  busy_q, done_q;
    reg [4:0]            step_q;

    assign s_ready_o = !busy_q && !done_q;
    wire accept = s_valid_i && s_ready_o;

    always @(posedge clk_i) begin
        if (!rst_ni) begin
            busy_q <= 1'b0;
            done_q <= 1'b0;
            step_q <= 5'd0;
        end else begin
            if (accept) begin
                busy_q <= 1'b1;
                step_q <= 5'd0;
            end else if (busy_q) begin
                step_q <= step_q + 5'd1;
                if (step_q == LAST_STEP) begin
                    busy_q <= 1'b0;
                    done_q <= 1'b1;
                end
            end
            if (m_valid_o && m_ready_i) done_q <= 1'b0;
        end
        if (accept) begin
            o_q    <= s_o_i;
            d_q    <= s_d_i;
            t_q    <= s_t_i;
            coef_q <= s_coef_i;
            user_q <= s_user_i;
        end
    end

    // ---- operands by step --------------------------------------------------
    reg [3*PW-1:0] p_q;    // hit point, written at steps 2..4
    reg [3*WW-1:0] w_q;    // w_i + rnd(P_i, FC-F), written at steps 9, 12, 15

    // A(i,j) -> coefficient index: diagonal i, (0,1) 3, (0,2) 4, (1,2) 5.
    function automatic [3:0] a_index(input [1:0] i, input [1:0] j);
        if (i == j) a_index = {2'b00, i};
        else if (i + j == 2'd1) a_index = 4'd3;
        else if (i + j == 2'd2) a_index = 4'd4;
        else a_index = 4'd5;
    endfunction

    // the row and column of the product A_ij p_j issued at step s (5..13)
    function automatic [3:0] row_col(input [4:0] s);
        case (s)
            5'd5:  row_col = {2'd0, 2'd0};
            5'd6:  row_col = {2'd0, 2'd1};
            5'd7:  row_col = {2'd0, 2'd2};
            5'd8:  row_col = {2'd1, 2'd0};
            5'd9:  row_col = {2'd1, 2'd1};
            5'd10: row_col = {2'd1, 2'd2};
            5'd11: row_col = {2'd2, 2'd0};
            5'd12: row_col = {2'd2, 2'd1};
            default: row_col = {2'd2, 2'd2};
        endcase
    endfunction

    reg [MAW-1:0] mul_a;
    reg [MBW-1:0] mul_b;
    reg           mul_issue;
    reg [1:0]     row_i, col_j;
    always @* begin
        mul_a = {MAW{1'b0}};
        mul_b = {MBW{1'b0}};
        mul_issue = busy_q;
        row_i = 2'd0;
        col_j = 2'd0;
        if (step_q <= 5'd2) begin                              // t d_i
            col_j = step_q[1:0];
            mul_a = {{(MAW-B+1){t_q[B-2]}}, t_q};
            mul_b = {{(MBW-B){d_q[col_j*B+B-1]}}, d_q[col_j*B +: B]};
        end else if (step_q >= 5'd5 && step_q <= 5'd13) begin  // A_ij p_j
            {row_i, col_j} = row_col(step_q);
            mul_a = {{(MAW-B){coef_q[a_index(row_i, col_j)*B+B-1]}}, coef_q[a_index(row_i, col_j)*B +: B]};
            mul_b = p_q[col_j*PW +: PW];
        end else if (step_q >= 5'd14 && step_q <= 5'd16) begin // p_i w_i
            row_i = step_q[1:0] - 2'd2;                        // 14, 15, 16 -> 0, 1, 2
            mul_a = w_q[row_i*WW +: WW];
            mul_b = p_q[row_i*PW +: PW];
        end else begin
            mul_issue = 1'b0;
        end
    end

    wire          unused_mul_valid;
    wire [SW-1:0] prod;
    csgrt_mul #(.A_WIDTH(MAW), .B_WIDTH(MBW)) u_mul (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(1'b1), .valid_i(mul_issue),
        .a_i(mul_a), .b_i(mul_b), .valid_o(unused_mul_valid), .p_o(prod));

    // ---- results by step (the product issued at step s arrives at s+2) -------
    // the coefficient P_i << F and rnd(P_i, FC-F), rnd(Q, FC-F), sign-extended
    function automatic [SW-1:0] coef_ext(input [B-1:0] k);
        coef_ext = {{(SW-B){k[B-1]}}, k};
    endfunction
    wire [4:0]    res_step = step_q - 5'd2;          // the step the arriving product was issued at
    wire [3:0]    res_rc   = row_col(res_step);
    wire [1:0]    res_row  = res_rc[3:2];
    wire [1:0]    res_col  = res_rc[1:0];
    wire [3:0]    p_index  = {2'b00, res_row} + 4'd6;   // P_i: coefficient 6 + i
    wire [SW-1:0] p_coef   = coef_ext(coef_q[p_index * B +: B]);
    wire [SW-1:0] q_coef   = coef_ext(coef_q[9 * B +: B]);

    reg  [SW-1:0] acc_q;       // the row sum, then the final sum
    wire [SW-1:0] acc_in   = (res_col == 2'd0) ? (prod + (p_coef << F)) : (acc_q + prod);
    wire [SW-1:0] w_sum    = $signed(acc_in + RND_FC) >>> FC;
    wire [SW-1:0] p_rnd    = $signed(p_coef + {{(SW-2){1'b0}}, 2'd2}) >>> (FC - F);   // FC - F = 2
    wire [SW-1:0] w_full   = w_sum + p_rnd;
    wire [SW-1:0] pt_rnd   = $signed(prod + RND_F) >>> F;
    wire [SW-1:0] pt_sum   = coef_ext(o_q[res_step[1:0]*B +: B]) + pt_rnd;
    wire [SW-1:0] sc_sum   = acc_q + prod;
    wire [SW-1:0] q_rnd    = $signed(q_coef + {{(SW-2){1'b0}}, 2'd2}) >>> (FC - F);
    wire [SW-1:0] q_full   = ($signed(sc_sum + RND_F) >>> F) + q_rnd;

    // the bits past each result's documented width are its sign extension
    wire unused_hi = ^{w_full[SW-1:WW], pt_sum[SW-1:PW], q_full[SW-1:QW]};

    reg [QW-1:0] q_q;
    always @(posedge clk_i) begin
        if (busy_q) begin
            if (step_q >= 5'd2 && step_q <= 5'd4)              // p_i = o_i + rnd(t d_i, F)
                p_q[res_step[1:0]*PW +: PW] <= pt_sum[PW-1:0];
            if (step_q >= 5'd7 && step_q <= 5'd15) begin       // the rows of A p + P << F
                acc_q <= acc_in;
                if (res_col == 2'd2) w_q[res_row*WW +: WW] <= w_full[WW-1:0];
            end
            if (step_q == 5'd16) acc_q <= prod;                // p_0 w_0
            if (step_q == 5'd17) acc_q <= sc_sum;              // + p_1 w_1
            if (step_q == LAST_STEP) q_q <= q_full[QW-1:0];    // + p_2 w_2, rounded, + rnd(Q)
        end
    end

    assign m_valid_o = done_q;
    assign m_q_o     = q_q;
    assign m_user_o  = user_q;

    generate
        if (BITS < 12 || BITS > 32 || USER_WIDTH < 1) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_quadric_at needs BITS in 12..32, USER_WIDTH >= 1");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
