`default_nettype none
// csgrt_class_tree — the classification tree, one event per clock: the
// classification of an event's point against the whole CSG tree, laid out
// on a complete binary tree of height TREE_HEIGHT (classify_layout() of
// model/tree_layout.cpp).
//
// Configuration (static while events flow; from the scene's TreeLayout):
//   node_op_i    2 bits per heap position i = 1 .. 2^H-1 at [2i +: 2]
//                (root 1, children 2i, 2i+1; position 0 unused), LayoutOp
//                codes 0 PASS, 1 ADD, 2 SUB, 3 AND
//   slot_mat_i   material of slot s at [s*MAT_BITS +: MAT_BITS]; slot s
//                sits under heap position 2^H + s
//   slot_used_i  bit s: a leaf sits in slot s; an empty slot is OUT
// Per event:
//   flags_i      bit s: slot s is IN (the flags BEFORE this event's toggle)
//   slot_i       the event's slot: BORDER 0,m when entering_i, else BORDER m,0
//   tag_i        TAG_WIDTH bits carried alongside unchanged
// Output: class_o {kind, from, to} as csgrt_class_node (kind 0 OUT, 1 IN,
// 2 BORDER), with valid_o and tag_o.
//
// Pipeline: the slot classes (level 0) are built combinationally from the
// inputs and combined by the first node level in the same clock; then one
// registered stage per node level. Latency: TREE_HEIGHT clocks (counted in
// enabled clocks). Throughput: one event per clock.
// Handshake: none inside; ce_i is a global stage enable (low holds every
// stage), the walker issues events and stalls the pipeline as a whole.
module csgrt_class_tree #(
    parameter TREE_HEIGHT = 8,   // H: 2^H leaf slots, H node levels (>= 1)
    parameter MAT_BITS    = 8,   // material index width
    parameter TAG_WIDTH   = 1    // sideband width (>= 1)
) (
    input  wire                             clk_i,
    input  wire                             rst_ni,    // synchronous, active low
    input  wire                             ce_i,      // stage enable (low = stall)
    // configuration
    input  wire [2*(1<<TREE_HEIGHT)-1:0]        node_op_i,
    input  wire [MAT_BITS*(1<<TREE_HEIGHT)-1:0] slot_mat_i,
    input  wire [(1<<TREE_HEIGHT)-1:0]          slot_used_i,
    // event in
    input  wire                             valid_i,
    input  wire [(1<<TREE_HEIGHT)-1:0]      flags_i,
    input  wire [TREE_HEIGHT-1:0]           slot_i,
    input  wire                             entering_i,
    input  wire [TAG_WIDTH-1:0]             tag_i,
    // classification out
    output wire                             valid_o,
    output wire [2*MAT_BITS+1:0]            class_o,
    output wire [TAG_WIDTH-1:0]             tag_o
);

    localparam H  = TREE_HEIGHT;
    localparam NS = 1 << H;          // slots
    localparam MB = MAT_BITS;
    localparam CW = 2 * MB + 2;      // classification width

    // The slot classes and the node classifications are arrays of CW-bit
    // words, not one wide vector: Verilator then reads and writes each node
    // as a word of its own (assembling a 2^H x CW vector from its pieces
    // cost the simulation a quarter of its time at H = 8).

    // level 0: the slot classes
    wire [CW-1:0] leaf_c [0:NS-1];
    genvar s, i;
    generate
        for (s = 0; s < NS; s = s + 1) begin : g_slot
            wire [MB-1:0] m = slot_mat_i[s*MB +: MB];
            wire          hit = (slot_i == s[H-1:0]);
            assign leaf_c[s] =
                hit                          ? (entering_i ? {2'd2, {MB{1'b0}}, m} : {2'd2, m, {MB{1'b0}}}) :
                (slot_used_i[s] && flags_i[s]) ? {2'd1, {MB{1'b0}}, m} :
                                               {CW{1'b0}};
        end
    endgenerate

    // node levels: node i (heap order) holds its classification in its
    // register g_node[i].node_q, seen by its parent as node_w[i]; its
    // children are nodes 2i, 2i+1 or, on the lowest level, the slot classes
    // 2i-NS, 2i+1-NS. (One register per generate block rather than an
    // array written element by element: the Verilator model writes each
    // as a variable of its own, without a delayed-assignment flag.)
    wire [CW-1:0] node_w [1:NS-1];
    wire [CW-1:0] node_d [1:NS-1];
    generate
        for (i = 1; i < NS; i = i + 1) begin : g_node
            wire [CW-1:0] l, r;
            if (2 * i >= NS) begin : g_low
                assign l = leaf_c[2*i-NS];
                assign r = leaf_c[2*i+1-NS];
            end else begin : g_up
                assign l = node_w[2*i];
                assign r = node_w[2*i+1];
            end
            csgrt_class_node #(.MAT_BITS(MB)) u_node (
                .op_i(node_op_i[2*i +: 2]), .l_i(l), .r_i(r), .c_o(node_d[i]));
            reg [CW-1:0] node_q;
            always @(posedge clk_i)
                if (ce_i) node_q <= node_d[i];
            assign node_w[i] = node_q;
        end
        if (H < 1) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_class_tree needs TREE_HEIGHT >= 1");
                $finish;
            end
        end
    endgenerate

    csgrt_delay #(.WIDTH(TAG_WIDTH), .STAGES(H)) u_tag (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(ce_i),
        .valid_i(valid_i), .data_i(tag_i), .valid_o(valid_o), .data_o(tag_o));

    assign class_o = node_w[1];

    wire unused_cfg = ^node_op_i[1:0];

endmodule

`default_nettype wire
