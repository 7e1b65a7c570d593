`default_nettype none
// tb_class_node — Verilator top for tb_class_node.cpp: one csgrt_class_node
// (combinational) at MAT_BITS = 8.
module tb_class_node (
    input  wire [1:0]  op_i,
    input  wire [17:0] l_i,
    input  wire [17:0] r_i,
    output wire [17:0] c_o
);
    csgrt_class_node #(.MAT_BITS(8)) u_node (.op_i(op_i), .l_i(l_i), .r_i(r_i), .c_o(c_o));
endmodule
`default_nettype wire
