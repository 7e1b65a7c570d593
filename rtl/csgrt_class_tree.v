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
//   flags_i      bit s: slot s is IN (the flags BEFORE this event's toggle);
//   flags_alt_i  the event's flags instead when alt_i is high. (The walker's
//   alt_i        probe tokens take the flags before their tie group, and
//                that choice comes late in the walker's clock: made here
//                after the reads by slot it is one LUT level at their end,
//                not one in front of a 2^H-to-1 choice.)
//   sib_flag_i   the flag of the slot's sibling (slot_i ^ 1) in those flags,
//                read by the caller (csgrt_walker: a register read a clock
//                ahead, not a 2^H-to-1 choice behind the event's slot)
//   slot_i       the event's slot: BORDER 0,m when entering_i, else BORDER m,0
//   tag_i        TAG_WIDTH bits carried alongside unchanged
// Output: class_o {kind, from, to} as csgrt_class_node (kind 0 OUT, 1 IN,
// 2 BORDER), with valid_o and tag_o; border_o = a crossing of a surface,
// BORDER from, to with from != to, decoded in the root's stage (a
// register: the decode at the output was the first two LUT levels of
// csgrt_walker's hit decision, its longest path out of context).
//
// Evaluated along one path: an event makes one slot BORDER, so only the H
// nodes between that slot and the root can see a BORDER; every other
// subtree is IN m or OUT (1 + MAT_BITS bits, a two-way choice per node,
// instead of the full table on 2 + 2*MAT_BITS bits). The full
// table (csgrt_class_node) runs only on the path, once per height, with the
// path's sibling picked from that height's IN/OUT values by the slot's bits.
// The same classification bit for bit as every node evaluated by the full
// table (tb/class_tree), at about a third of the logic.
//
// Pipeline: stage 0 registers the event's reads by its slot: the flags,
// the path's BORDER (the slot's material), the sibling slot's IN/OUT value
// and height 1's operator (each a 2^H-to-1 choice by slot_i); then one
// registered stage per height. (Without stage 0 the slot reads and the
// first node were one clock: 12 LUT levels, the out-of-context critical
// path of this module and of csgrt_walker, tools/module_timing.py.)
// Likewise each stage j-1 picks the path's sibling and operator for
// stage j: the sibling node's next value (the input of its io_q register,
// chosen by the slot's bits) goes into a register of its own beside io_q,
// so that stage j is the full table alone. (With the choice among
// height j-1's 2^(H-j+1) registers in stage j itself, stage 2 was 10 to
// 11 LUT levels, the longest path of the whole design by
// tools/logic_depth.py.)
// Latency: TREE_HEIGHT + 1 clocks (counted in enabled clocks).
// Throughput: one event per clock.
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
    input  wire [(1<<TREE_HEIGHT)-1:0]      flags_alt_i,   // the event's flags when alt_i
    input  wire                             alt_i,
    input  wire                             sib_flag_i,    // (alt_i ? flags_alt_i : flags_i)[slot_i ^ 1]
    input  wire [TREE_HEIGHT-1:0]           slot_i,
    input  wire                             entering_i,
    input  wire [TAG_WIDTH-1:0]             tag_i,
    // classification out
    output wire                             valid_o,
    output wire [2*MAT_BITS+1:0]            class_o,
    output wire                             border_o,   // class_o is BORDER from, to with from != to
    output wire [TAG_WIDTH-1:0]             tag_o
);

    localparam H  = TREE_HEIGHT;
    localparam NS = 1 << H;          // slots
    localparam MB = MAT_BITS;
    localparam CW = 2 * MB + 2;      // classification width
    localparam IW = 1 + MB;          // IN/OUT value {in, material} (material 0 when OUT)
    localparam [1:0] OP_ADD = 2'd1, OP_SUB = 2'd2, OP_AND = 2'd3;

    // A subtree that does not hold the event's slot sees no BORDER: its
    // classification is IN m or OUT, and a node of two such children gives
    // IN or OUT again (the rows and columns of table_add / table_sub /
    // table_and without BORDER; csgrt_class_node gives the same on them):
    //   ADD  r IN ? r : l        SUB  r IN ? OUT : l
    //   AND  r IN ? l : OUT      PASS l
    function automatic [IW-1:0] inout_combine(input [1:0] op, input [IW-1:0] l, input [IW-1:0] r);
        case (op)
            OP_ADD:  inout_combine = r[MB] ? r : l;
            OP_SUB:  inout_combine = r[MB] ? {IW{1'b0}} : l;
            OP_AND:  inout_combine = r[MB] ? l : {IW{1'b0}};
            default: inout_combine = l;
        endcase
    endfunction

    // The IN/OUT values of every slot and node below the root, in heap order
    // (arrays of IW-bit words: Verilator reads and writes each as a word of
    // its own): slot s at NS + s, from the flags (combinational); node i at
    // height j (H - floor(log2 i)) a register holding the event of j clocks
    // ago, computed from its children's values of the clock before. The
    // value of the node or slot that holds the event's slot is computed too
    // but never read: the path below replaces it.
    // ---- stage 0: the event's reads by its slot, registered --------------
    wire [H-1:0]  sib_slot = slot_i ^ {{(H-1){1'b0}}, 1'b1};
    wire [MB-1:0] slot_m   = slot_mat_i[slot_i*MB +: MB];
    // the sibling's flag comes from the caller (csgrt_walker reads it a
    // clock ahead, from registers); a simulation check compares it with
    // the read here
    csgrt_check_same #(.WHAT("sib_flag_i (the sibling slot's flag)")) u_check_sib (
        .clk_i, .rst_ni, .copy_i(valid_i && ce_i && sib_flag_i),
        .orig_i(valid_i && ce_i && (alt_i ? flags_alt_i[sib_slot] : flags_i[sib_slot])));
    // The sibling slot's {used, material} and its flag are registered
    // apart; stage 1 makes its IN/OUT value of them (IN m when used and
    // IN). As one value here, the flag read (the slowest of stage 0's
    // reads: the event's slot from the sorter, the walker's flag banks)
    // went on through an AND into the register's reset pin, yosys's way
    // to zero it: the walker's longest path out of context (77.63 MHz).
    wire [IW-1:0] sib_in   = {slot_used_i[sib_slot], slot_mat_i[sib_slot*MB +: MB]};
    wire [1:0]    op1_in;                  // height 1's operator on the path
    reg  [NS-1:0] flags_q;
    reg  [H-1:0]  slot0_q;
    reg  [CW-1:0] path0_q;
    reg  [IW-1:0] sib0_q;                  // the sibling slot's {used, material}
    reg           sib_in0_q;               // ... and its flag
    reg  [1:0]    op1_q;
    always @(posedge clk_i)
        if (ce_i) begin
            flags_q <= alt_i ? flags_alt_i : flags_i;
            slot0_q <= slot_i;
            path0_q <= entering_i ? {2'd2, {MB{1'b0}}, slot_m} : {2'd2, slot_m, {MB{1'b0}}};
            sib0_q  <= sib_in;
            sib_in0_q <= sib_flag_i;
            op1_q   <= op1_in;
        end

    wire [IW-1:0] io_w [2:2*NS-1];
    wire [IW-1:0] io_d [2:NS+1];     // node i's next value: the input of its io_q (2 .. NS-1)
    genvar s, i, j, k;
    generate
        if (H == 1) begin : g_op1_root
            assign op1_in = node_op_i[3:2];
        end else begin : g_op1
            wire [1:0] ops1 [0:(NS>>1)-1];
            for (k = 0; k < (NS >> 1); k = k + 1) begin : g_op
                assign ops1[k] = node_op_i[2*((NS >> 1) + k) +: 2];
            end
            assign op1_in = ops1[slot_i[H-1:1]];
        end
        for (s = 0; s < NS; s = s + 1) begin : g_slot
            assign io_w[NS + s] = (slot_used_i[s] && flags_q[s]) ? {1'b1, slot_mat_i[s*MB +: MB]} : {IW{1'b0}};
        end
        for (i = 2; i < NS; i = i + 1) begin : g_node
            // (One register per generate block rather than an array written
            // element by element: the Verilator model writes each as a
            // variable of its own, without a delayed-assignment flag.)
            reg [IW-1:0] io_q;
            assign io_d[i] = inout_combine(node_op_i[2*i +: 2], io_w[2*i], io_w[2*i+1]);
            always @(posedge clk_i)
                if (ce_i) io_q <= io_d[i];
            assign io_w[i] = io_q;
        end
    endgenerate

    // The path from the event's slot to the root: the slot is BORDER 0,m
    // (entering) or BORDER m,0; the path node at height j (1 .. H) combines
    // the path's classification at height j-1 with its sibling's IN/OUT
    // value (the node or slot at heap position ((NS + slot) >> (j-1)) ^ 1),
    // on the side the slot's bit j-1 says, by the full table
    // (csgrt_class_node), and registers it with the slot index: stage j of
    // the pipeline, as the node levels of the whole tree were.
    wire [CW-1:0] path_w [0:H];      // the path's classification at height j (stage j)
    wire [H-1:0]  slot_w [0:H];      // the event's slot at stage j
    assign path_w[0] = path0_q;
    assign slot_w[0] = slot0_q;
    generate
        for (j = 1; j <= H; j = j + 1) begin : g_path
            localparam NL = NS >> (j - 1);             // slots or nodes at height j-1
            wire [H-j:0]  pos     = slot_w[j-1][H-1:j-1];  // the path's place on height j-1
            wire [IW-1:0] sib;
            if (j == 1) begin : g_sib_slot
                // a slot, read in stage 0: IN m if used and IN, else OUT
                assign sib = (sib_in0_q && sib0_q[MB]) ? sib0_q : {IW{1'b0}};
                if (H > 1) begin : g_pos_up
                    wire unused_pos = ^pos[H-j:1];   // only pos[0] (the side) is read here
                end
            end else begin : g_sib_node
                // chosen in stage j-1 from height j-1's next values (io_d)
                // by the slot's bits above j-1 (stage j-1's slot_w[j-2]),
                // registered with the same enable as those nodes' io_q: the
                // sibling's io_q, read a clock early. The field stride is IW
                // rounded up to a power of two: indexing IW-bit fields
                // (IW = 9) made yosys compute the bit offset pos * IW with
                // adders in front of the multiplexer; a power-of-two stride
                // is a plain multiplexer tree
                localparam PW = 1 << $clog2(IW);
                wire [NL*PW-1:0] level_d;
                for (k = 0; k < NL; k = k + 1) begin : g_level
                    assign level_d[k*PW +: PW] = {{(PW-IW){1'b0}}, io_d[NL + k]};
                end
                localparam [H-j:0] SIBLING = 1;        // the sibling's place: pos ^ 1
                wire [H-j:0] pos_early = slot_w[j-2][H-1:j-1];
                wire [H-j:0] sib_pos   = pos_early ^ SIBLING;
                reg  [IW-1:0] sib_q;
                always @(posedge clk_i)
                    if (ce_i) sib_q <= level_d[sib_pos*PW +: IW];
                assign sib = sib_q;
                if (j < H) begin : g_pos_up
                    wire unused_pos = ^pos[H-j:1];   // only pos[0] (the side) is read here
                end
            end
            wire [CW-1:0] sib_c   = {1'b0, sib[MB], {MB{1'b0}}, sib[MB-1:0]};   // IN m or OUT
            wire          on_right = pos[0];
            wire [1:0]    op;
            if (j == 1) begin : g_first
                assign op = op1_q;             // read in stage 0
            end else if (j == H) begin : g_root
                assign op = node_op_i[3:2];
            end else begin : g_inner
                // the operators of height j as an array, indexed by the
                // slot's bits above j; chosen in stage j-1 (slot_w[j-2])
                wire [1:0] ops [0:(NS>>j)-1];
                for (k = 0; k < (NS >> j); k = k + 1) begin : g_op
                    assign ops[k] = node_op_i[2*((NS >> j) + k) +: 2];
                end
                reg [1:0] op_q;
                always @(posedge clk_i)
                    if (ce_i) op_q <= ops[slot_w[j-2][H-1:j]];
                assign op = op_q;
            end
            // The node for either side of the path, and the side's choice
            // after them: with the choice in front, the slot's bit (about 60
            // loads) ran through the operands' multiplexers into the whole
            // table (tools/logic_depth.py: 7 LUT levels from slot_w into
            // path_q). A sibling is IN m or OUT (its "from" field is zero),
            // so each node, with one operand of that form, maps to less than
            // the full table.
            wire [CW-1:0] c_sib_right, c_sib_left;
            csgrt_class_node #(.MAT_BITS(MB)) u_node_r (
                .op_i(op), .l_i(path_w[j-1]), .r_i(sib_c), .c_o(c_sib_right));
            csgrt_class_node #(.MAT_BITS(MB)) u_node_l (
                .op_i(op), .l_i(sib_c), .r_i(path_w[j-1]), .c_o(c_sib_left));
            wire [CW-1:0] c = on_right ? c_sib_left : c_sib_right;
            reg [CW-1:0] path_q;
            reg [H-1:0]  slot_q;
            always @(posedge clk_i)
                if (ce_i) begin
                    path_q <= c;
                    slot_q <= slot_w[j-1];
                end
            assign path_w[j] = path_q;
            assign slot_w[j] = slot_q;
            if (j == H) begin : g_border
                // border_o a clock early: whether the root's classification
                // c is BORDER from, to with from != to, derived from the
                // node table (csgrt_class_node) case by case with the
                // sibling IN m or OUT, so that the material compares run
                // beside the table's choice instead of after it (decoding
                // c, they came after the node and the side's choice:
                // tools/logic_depth.py 12.68 ns, the whole design's longest
                // path). u_check_border compares it with the decode of c.
                wire [1:0]    pk = path_w[j-1][CW-1 -: 2];
                wire [MB-1:0] pf = path_w[j-1][MB +: MB];
                wire [MB-1:0] pt = path_w[j-1][0 +: MB];
                wire [MB-1:0] m  = sib[MB-1:0];
                wire          sin = sib[MB];                    // the sibling is IN m (else OUT)
                wire          p_io = pk == 2'd0 || pk == 2'd1;  // the path is OUT or IN
                wire          pb = pk == 2'd2 && pf != pt;      // the path itself is a crossing
                wire          m_nz = m != {MB{1'b0}};
                wire          m_ne_pt = m != pt;
                wire          pf_ne_m = pf != m;
                wire          pf_z = pf == {MB{1'b0}};
                wire          pt_z = pt == {MB{1'b0}};
                reg           b_right, b_left;                  // path on the left / on the right
                always @* begin
                    // node(op, path, sib): c is the path or not a crossing
                    case (op)
                        2'd0:    b_right = pb;                  // PASS
                        2'd3:    b_right = pb && sin;           // AND: path & IN, else OUT
                        default: b_right = pb && !sin;          // ADD, SUB: IN owns / cuts
                    endcase
                    // node(op, sib, path)
                    case (op)
                        2'd1:    b_left = !sin ? pb :           // ADD: OUT ++ path
                                          p_io ? 1'b0 :         // path IN owns; sib ++ OUT
                                          pf_z ? m_ne_pt :      // BORDER m,d
                                          pt_z ? pf_ne_m : pb;  // BORDER c,m; else the path
                        2'd2:    b_left = sin && !p_io && (pf_z || pt_z) && m_nz;   // SUB: m,0 / 0,m
                        2'd3:    b_left = sin && !p_io && (pf_z || pt_z) && m_nz;   // AND: 0,m / m,0
                        default: b_left = 1'b0;                 // PASS: the sibling
                    endcase
                end
                reg border_q;
                always @(posedge clk_i)
                    if (ce_i) border_q <= on_right ? b_left : b_right;
                assign border_o = border_q;
            end
        end
        if (H < 1) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_class_tree needs TREE_HEIGHT >= 1");
                $finish;
            end
        end
    endgenerate

    csgrt_delay #(.WIDTH(TAG_WIDTH), .STAGES(H + 1)) u_tag (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(ce_i),
        .valid_i(valid_i), .data_i(tag_i), .valid_o(valid_o), .data_o(tag_o));

    assign class_o = path_w[H];
    // border_o is the decode of class_o, made a clock early: checked
    wire [CW-1:0] class_out = path_w[H];
    csgrt_check_same #(.WHAT("border_o")) u_check_border (
        .clk_i(clk_i), .rst_ni(rst_ni), .copy_i(border_o),
        .orig_i(class_out[CW-1 -: 2] == 2'd2 && class_out[MB +: MB] != class_out[0 +: MB]));

    // position 0 of the heap is unused; the slot index's last stage is not
    // read; heap positions 2 and 3 (the root's children: slots when H = 1,
    // else nodes whose io_q is read by nobody, their siblings being chosen
    // from io_d a clock early) and io_d's spare entries NS, NS+1 (so that
    // the array is not empty when H = 1)
    wire unused_cfg = ^{node_op_i[1:0], slot_w[H], io_w[2], io_w[3], io_d[NS], io_d[NS+1]};
    assign io_d[NS]   = {IW{1'b0}};
    assign io_d[NS+1] = {IW{1'b0}};

endmodule

`default_nettype wire
