`default_nettype none
// csgrt_class_tree — the classification tree, one event per clock: the
// classification of an event's point against the whole CSG tree, laid out
// on a complete binary tree of height TREE_HEIGHT (classify_layout() of
// model/tree_layout.cpp).
//
// Configuration (static while events flow, and for a clock before the first
// event after a change; from the scene's TreeLayout):
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

    // The path's node at one height: the full table (csgrt_class_node) with
    // the sibling IN m or OUT (sin, m; its "from" is air), the path p on
    // the side on_right says, and the air tests of the path's fields given
    // as flags (pfz: p's from is air, ptz: its to is air) instead of made
    // on p's bits: the two 8-bit zero tests on the path register, then the
    // table's choice, were the longest paths of the whole design
    // (tools/logic_depth.py 12.20 ns, 6 LUT levels, g_path[3].path_q ->
    // g_path[4].path_q, on aaa564b's netlist). It returns the node's
    // classification with its own flags {c, fz, tz}, from the flags it was
    // given and mz (m is air): every field of c is a field of p, m or air.
    // The same c as csgrt_class_node (u_check_node compares them).
    // Written as a choice of sources per field (the path's, the sibling's
    // material, air), decided once from the few control bits and applied
    // as one LUT per field bit: as a priority chain over the cases the
    // decision ran on through the bits' multiplexers (10.45 ns out of
    // context against 9.24 with the table's own zero tests).
    localparam [1:0] K_OUT = 2'd0, K_IN = 2'd1, K_BORDER = 2'd2;
    localparam [1:0] F_P = 2'd0, F_M = 2'd1, F_AIR = 2'd2;            // a field's source
    localparam [1:0] KS_P = 2'd0, KS_S = 2'd1, KS_B = 2'd2, KS_OUT = 2'd3;   // the kind's
    function automatic [CW+1:0] path_node(input [1:0] op, input [CW-1:0] p, input pfz, input ptz,
                                          input sin, input [MB-1:0] m, input mz, input on_right);
        reg [1:0]    pk, fs, ts, ks;
        reg [MB-1:0] pf, pt, f, t;
        reg [1:0]    k;
        reg          fz, tz;
        begin
            pk = p[CW-1 -: 2];
            pf = p[MB +: MB];
            pt = p[0 +: MB];
            // the case's sources: the path P (F_P, F_P, KS_P), the sibling S
            // (F_AIR, F_M, KS_S), OUT (F_AIR, F_AIR, KS_OUT), or a BORDER of
            // the sibling's material and a field of the path or air
            {ks, fs, ts} = {KS_P, F_P, F_P};
            if (!on_right) begin                                // node(op, path, sibling)
                case (op)
                    OP_ADD:  if (sin) {ks, fs, ts} = {KS_S, F_AIR, F_M};
                    OP_SUB:  if (sin) {ks, fs, ts} = {KS_OUT, F_AIR, F_AIR};
                    OP_AND:  if (pk == K_OUT || !sin) {ks, fs, ts} = {KS_OUT, F_AIR, F_AIR};
                    default: ;                                  // PASS: the path
                endcase
            end else begin                                      // node(op, sibling, path)
                case (op)
                    OP_ADD:
                        if (pk == K_IN || !sin) ;                                   // r IN owns; OUT ++ r
                        else if (pk == K_OUT)   {ks, fs, ts} = {KS_S, F_AIR, F_M};
                        else if (pfz)           {ks, fs, ts} = {KS_B, F_M, F_P};    // BORDER m,d
                        else if (ptz)           {ks, fs, ts} = {KS_B, F_P, F_M};    // BORDER c,m
                    OP_SUB:
                        if (pk == K_OUT)        {ks, fs, ts} = {KS_S, F_AIR, F_M};
                        else if (pk == K_IN || !sin) {ks, fs, ts} = {KS_OUT, F_AIR, F_AIR};
                        else if (pfz)           {ks, fs, ts} = {KS_B, F_M, F_AIR};
                        else if (ptz)           {ks, fs, ts} = {KS_B, F_AIR, F_M};
                        else                    {ks, fs, ts} = {KS_OUT, F_AIR, F_AIR};
                    OP_AND:
                        if (!sin || pk == K_OUT) {ks, fs, ts} = {KS_OUT, F_AIR, F_AIR};
                        else if (pk == K_IN)     {ks, fs, ts} = {KS_S, F_AIR, F_M};
                        else if (pfz)            {ks, fs, ts} = {KS_B, F_AIR, F_M};
                        else if (ptz)            {ks, fs, ts} = {KS_B, F_M, F_AIR};
                        else                     {ks, fs, ts} = {KS_S, F_AIR, F_M};
                    default:                     {ks, fs, ts} = {KS_S, F_AIR, F_M};   // PASS: the sibling
                endcase
            end
            f  = (fs == F_P) ? pf : (fs == F_M) ? m : {MB{1'b0}};
            t  = (ts == F_P) ? pt : (ts == F_M) ? m : {MB{1'b0}};
            fz = (fs == F_P) ? pfz : (fs == F_M) ? mz : 1'b1;
            tz = (ts == F_P) ? ptz : (ts == F_M) ? mz : 1'b1;
            case (ks)
                KS_P:    k = pk;
                KS_S:    k = {1'b0, sin};
                KS_B:    k = K_BORDER;
                default: k = K_OUT;
            endcase
            path_node = {k, f, t, fz, tz};
        end
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
    // the path's air flags (path_node): the slot's material is air, tested
    // per slot on the configuration into a register of its own (slot_mz_q,
    // loaded on every clock: hence the configuration's clock of notice,
    // above) and read by the slot as slot_m is. Tested on the event's slot
    // (behind slot_m's choice: two LUT levels more), or per slot but
    // without the register (abc merged the tests into the choice), stage 0
    // was the module's longest path (tools/logic_depth.py 10.18 ns out of
    // context, against 9.32 before the flags). A check compares it.
    reg  [NS-1:0] slot_mz_q;
    reg           pfz0_q, ptz0_q;
    integer       sz;
    always @(posedge clk_i)
        for (sz = 0; sz < NS; sz = sz + 1) slot_mz_q[sz] <= slot_mat_i[sz*MB +: MB] == {MB{1'b0}};
    csgrt_check_same #(.WHAT("slot_mz_q (the slot's material is air; the configuration changed under an event?)")) u_check_slot_mz (
        .clk_i, .rst_ni, .copy_i(valid_i && ce_i && slot_mz_q[slot_i]),
        .orig_i(valid_i && ce_i && slot_m == {MB{1'b0}}));
    always @(posedge clk_i)
        if (ce_i) begin
            flags_q <= alt_i ? flags_alt_i : flags_i;
            slot0_q <= slot_i;
            path0_q <= entering_i ? {2'd2, {MB{1'b0}}, slot_m} : {2'd2, slot_m, {MB{1'b0}}};
            pfz0_q  <= entering_i || slot_mz_q[slot_i];
            ptz0_q  <= !entering_i || slot_mz_q[slot_i];
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
    wire          pfz_w  [0:H];      // path_w[j]'s from is air
    wire          ptz_w  [0:H];      // path_w[j]'s to is air
    // stage j holds an event (for the checks only: synthesis drops them,
    // and with them these; the stages run on junk between events)
    reg  [H:0]    chk_vld_q;
    always @(posedge clk_i)
        if (!rst_ni)   chk_vld_q <= {(H + 1){1'b0}};
        else if (ce_i) chk_vld_q <= {chk_vld_q[H-1:0], valid_i};
    wire unused_chk_vld = chk_vld_q[H];   // the root's output (valid_o comes from u_tag)
    assign path_w[0] = path0_q;
    assign slot_w[0] = slot0_q;
    assign pfz_w[0]  = pfz0_q;
    assign ptz_w[0]  = ptz0_q;
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
            // The node on the path by path_node, with the path's air flags;
            // csgrt_class_node's full table for either side, the reference
            // in simulation (synthesis drops it: nothing reads it there)
            wire          sib_mz = sib[MB-1:0] == {MB{1'b0}};
            wire [CW+1:0] cf = path_node(op, path_w[j-1], pfz_w[j-1], ptz_w[j-1], sib[MB], sib[MB-1:0],
                                         sib_mz, on_right);
            wire [CW-1:0] c  = cf[CW+1:2];
`ifndef SYNTHESIS
            // (not built by synthesis: yosys shared the reference's cells
            // with path_node's before dropping them, in the mapped netlist
            // and in its paths)
            wire [CW-1:0] c_sib_right, c_sib_left;
            csgrt_class_node #(.MAT_BITS(MB)) u_node_r (
                .op_i(op), .l_i(path_w[j-1]), .r_i(sib_c), .c_o(c_sib_right));
            csgrt_class_node #(.MAT_BITS(MB)) u_node_l (
                .op_i(op), .l_i(sib_c), .r_i(path_w[j-1]), .c_o(c_sib_left));
            csgrt_check_same #(.WIDTH(CW + 2), .WHAT("path_node (against csgrt_class_node, and its air flags)")) u_check_node (
                .clk_i, .rst_ni, .copy_i(ce_i && chk_vld_q[j-1] ? cf : {(CW + 2){1'b0}}),
                .orig_i(ce_i && chk_vld_q[j-1] ? {on_right ? c_sib_left : c_sib_right,
                                                  c[MB +: MB] == {MB{1'b0}}, c[0 +: MB] == {MB{1'b0}}}
                                               : {(CW + 2){1'b0}}));
`else
            wire unused_sib_c = ^sib_c;
`endif
            reg [CW-1:0] path_q;
            reg [H-1:0]  slot_q;
            reg          pfz_q, ptz_q;
            always @(posedge clk_i)
                if (ce_i) begin
                    path_q <= c;
                    slot_q <= slot_w[j-1];
                    pfz_q  <= cf[1];
                    ptz_q  <= cf[0];
                end
            assign path_w[j] = path_q;
            assign slot_w[j] = slot_q;
            assign pfz_w[j]  = pfz_q;
            assign ptz_w[j]  = ptz_q;
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
                wire          m_nz = !sib_mz;
                wire          m_ne_pt = m != pt;
                wire          pf_ne_m = pf != m;
                wire          pf_z = pfz_w[j-1];   // the path's air flags
                wire          pt_z = ptz_w[j-1];
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
