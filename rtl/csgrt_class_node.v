`default_nettype none
// csgrt_class_node — one node of the classification tree: combines the
// classifications of its left and right child by the node's operator,
// exactly table_add / table_sub / table_and of model/classify.cpp (cells the
// paper marks "cannot occur" give OUT). Purely combinational.
//
// A classification is CW = 2 + 2*MAT_BITS bits {kind, from, to}:
//   kind 2'd0 OUT       {0, 0, 0}
//   kind 2'd1 IN m      {1, 0, m}
//   kind 2'd2 BORDER    {2, from, to}
// e.g. MAT_BITS = 8: IN 3 = 18'h1_00_03, BORDER 0,5 = 18'h2_00_05. Values are
// kept in this normal form (from = 0 for IN, all zero for OUT), as the
// model's Class is, so that classifications compare as plain vectors.
// Operators (LayoutOp of model/tree_layout.h): 2'd0 PASS (the left child),
// 2'd1 ADD (l ++ r, r owns), 2'd2 SUB (l - r), 2'd3 AND (l & r).
module csgrt_class_node #(
    parameter MAT_BITS = 8   // material index width (material 0 is air)
) (
    input  wire [1:0]              op_i,
    input  wire [2*MAT_BITS+1:0]   l_i,   // left child
    input  wire [2*MAT_BITS+1:0]   r_i,   // right child
    output reg  [2*MAT_BITS+1:0]   c_o    // combined
);

    localparam MB = MAT_BITS;
    localparam [1:0] K_OUT = 2'd0, K_IN = 2'd1;
    localparam [1:0] K_BORDER = 2'd2;
    localparam [1:0] OP_PASS = 2'd0, OP_ADD = 2'd1, OP_SUB = 2'd2, OP_AND = 2'd3;
    localparam [2*MB+1:0] C_OUT = {(2*MB+2){1'b0}};
    localparam [MB-1:0] AIR = {MB{1'b0}};

    wire [1:0]    lk = l_i[2*MB+1:2*MB];
    wire [MB-1:0] lt = l_i[MB-1:0];
    wire [1:0]    rk = r_i[2*MB+1:2*MB];
    wire [MB-1:0] rf = r_i[2*MB-1:MB];
    wire [MB-1:0] rt = r_i[MB-1:0];
    // the left child's "from" is never looked at: a BORDER on the left is
    // passed on whole or dropped
    wire [MB-1:0] unused_lf = l_i[2*MB-1:MB];

    always @* begin
        c_o = l_i;
        case (op_i)
            OP_PASS: c_o = l_i;
            OP_ADD: begin
                if (rk == K_IN) c_o = r_i;                         // right operand owns
                else if (rk == K_OUT) c_o = l_i;
                else if (lk == K_OUT) c_o = r_i;                   // r is BORDER c,d
                else if (lk == K_IN) begin
                    if (rf == AIR) c_o = {K_BORDER, lt, rt};       // BORDER l,d
                    else if (rt == AIR) c_o = {K_BORDER, rf, lt};  // BORDER c,l
                    else c_o = r_i;                                // BORDER c,d
                end else c_o = C_OUT;                              // cannot occur
            end
            OP_SUB: begin
                if (rk == K_IN) c_o = C_OUT;
                else if (rk == K_OUT) c_o = l_i;
                else if (lk == K_IN) begin
                    if (rf == AIR) c_o = {K_BORDER, lt, AIR};      // entering the cutter
                    else if (rt == AIR) c_o = {K_BORDER, AIR, lt}; // leaving the cutter
                    else c_o = C_OUT;
                end else c_o = C_OUT;                              // OUT row; BORDER row cannot occur
            end
            OP_AND: begin
                if (lk == K_OUT) c_o = C_OUT;
                else if (rk == K_OUT) c_o = C_OUT;
                else if (rk == K_IN) c_o = l_i;                    // IN l, or BORDER a,b
                else if (lk == K_IN) begin
                    if (rf == AIR) c_o = {K_BORDER, AIR, lt};
                    else if (rt == AIR) c_o = {K_BORDER, lt, AIR};
                    else c_o = l_i;                                // IN l
                end else c_o = C_OUT;                              // cannot occur
            end
            default: c_o = l_i;
        endcase
    end

endmodule

`default_nettype wire
