`default_nettype none
// csgrt_walker — the exact walk of one ray's sorted events (walk() in
// model/trace.cpp, docs/numerics.md section 5): validity check, classify
// with csgrt_class_tree, toggle the flag; the first BORDER x,y with x != y
// is the hit.
//
// Tokens: every event popped from csgrt_event_sort becomes one token issued
// into the classification tree, one per clock; an invalid event (entering
// while IN, leaving while OUT) is issued as a "skip" token (not a candidate,
// flag unchanged), a ray without events as one skip token marked last. So
// each ray's last token carries `last` and results come back in ray order.
// Rays overlap in the tree: two flag banks (ray parity `seq`); the next ray
// is loaded into the other bank as soon as the current one is issued,
// provided no token of the ray before (same bank) is still in flight.
//
// Results at the tree's output, per token of a ray that has no result yet:
//   !skip and BORDER x,y with x != y -> hit record; the ray is done, its
//                                       later tokens are dropped, its
//                                       issuing stops, its events released
//   last                             -> miss record {hit = 0, payload}
// flags_before_o (bit per slot): the flags just before the hit, i.e. the
// ray's flag bank with the toggles of the hit token and of the ray's tokens
// issued after it (still in flight: a shadow of the tree's pipeline) undone.
// On a miss every field but payload_o is zero.
//
// Secondary rays (SECONDARY = 1; with SECONDARY = 0 these outputs are 0 and
// their logic is not built), beside each hit record (on a miss all 0):
//   flags_after_o  the flags just after the hit crossing: flags_before_o
//                  with the hit's slot toggled (the far side, for a
//                  continuation or transmitted ray: TraceResult::flags_after
//                  without look-ahead).
//                  TODO: the refraction look-ahead (TraceOptions::lookahead,
//                  docs/effects.md: behind a transparent hit, cross the
//                  following coincident surfaces too; the hit then reads
//                  BORDER a1,an) is not implemented; flags_after_o and
//                  from_o/to_o ignore it until it is. (Formed from the
//                  output registers; with the look-ahead it must be
//                  carried in the record instead.)
//   lb_count_o     0..LOOK_BEHIND: the look-behind run, the valid (non-skip)
//   lb_slot_o      tokens of the ray issued before the hit token, most
//   lb_entering_o  recent first (TraceResult::near_run): entry k's slot at
//   lb_same_t_o    [k*TREE_HEIGHT +: TREE_HEIGHT], its entering and
//                  "t equals the hit's t" at bit k; entries at and past
//                  lb_count_o are 0. Each token carries in its tag the run
//                  as it stood when the token was issued (a history of the
//                  ray's last LOOK_BEHIND valid tokens, cleared when a ray
//                  is loaded), so tokens issued after the hit (still in the
//                  tree, undone for flags_before_o) are not part of it.
// flags_before_o, lb_*_o and the hit's position make the info record of
// the near-side children (shadow, reflected) for csgrt_event_sort, which
// applies the look-behind fix-up; flags_after_o that of far-side ones.
//
// Latency: a ray loaded at edge k issues its i-th event (i = 0, 1, ..) at
// edge k+1+i (into the tree's first register); the tree's result is there
// after edge k+i+TREE_HEIGHT and the record on valid_o (csgrt_skid) after
// edge k+i+TREE_HEIGHT+1, the same with SECONDARY = 1. Throughput: one
// event per clock; per ray max(1, issued events) + 2 clocks with event_sort
// (release -> next ray loaded), issued events = all of them on a miss, at
// most hit index + TREE_HEIGHT + 1 on a hit; the same with SECONDARY = 1.
// Handshake: valid/ready out through csgrt_skid; when a result is due and
// the skid cannot take it the whole walker (tree included) stalls. No
// combinational path from ready_i to ev_pop_o / ray_done_o.
module csgrt_walker #(
    parameter BITS          = 24,   // coordinate width B; t is B-1 bits
    parameter LEAF_BITS     = 6,    // leaf index width
    parameter TREE_HEIGHT   = 8,    // H: 2^H slots
    parameter MAT_BITS      = 8,    // material index width
    parameter PAYLOAD_WIDTH = 1,    // per-ray sideband (>= 1)
    parameter SECONDARY     = 0,    // 1: flags_after_o and the look-behind run
    parameter LOOK_BEHIND   = 4     // look-behind entries (kLookBehind), >= 1
) (
    input  wire                     clk_i,
    input  wire                     rst_ni,   // synchronous, active low
    // configuration: the scene's tree layout (csgrt_class_tree)
    input  wire [2*(1<<TREE_HEIGHT)-1:0]        node_op_i,
    input  wire [MAT_BITS*(1<<TREE_HEIGHT)-1:0] slot_mat_i,
    input  wire [(1<<TREE_HEIGHT)-1:0]          slot_used_i,
    // sorted ray from csgrt_event_sort
    input  wire                     ray_valid_i,
    input  wire [(1<<TREE_HEIGHT)-1:0] ray_flags_i,
    input  wire [PAYLOAD_WIDTH-1:0] ray_payload_i,
    output wire                     ray_done_o,
    input  wire                     ev_valid_i,
    input  wire                     ev_last_i,
    input  wire [BITS-2:0]          ev_t_i,
    input  wire [LEAF_BITS-1:0]     ev_leaf_i,
    input  wire [TREE_HEIGHT-1:0]   ev_slot_i,
    input  wire                     ev_entering_i,
    output wire                     ev_pop_o,
    // hit records
    output wire                     valid_o,
    input  wire                     ready_i,
    output wire                     hit_o,
    output wire [BITS-2:0]          t_o,
    output wire [LEAF_BITS-1:0]     leaf_o,
    output wire [TREE_HEIGHT-1:0]   slot_o,
    output wire                     entering_o,
    output wire [MAT_BITS-1:0]      from_o,
    output wire [MAT_BITS-1:0]      to_o,
    output wire [(1<<TREE_HEIGHT)-1:0] flags_before_o,
    output wire [PAYLOAD_WIDTH-1:0] payload_o,
    // beside the hit record (SECONDARY)
    output wire [(1<<TREE_HEIGHT)-1:0]          flags_after_o,
    output wire [$clog2(LOOK_BEHIND+1)-1:0]     lb_count_o,
    output wire [LOOK_BEHIND*TREE_HEIGHT-1:0]   lb_slot_o,
    output wire [LOOK_BEHIND-1:0]               lb_entering_o,
    output wire [LOOK_BEHIND-1:0]               lb_same_t_o
);

    localparam TW = BITS - 1;
    localparam LB = LEAF_BITS;
    localparam H  = TREE_HEIGHT;
    localparam NS = 1 << H;
    localparam MB = MAT_BITS;
    localparam CW = 2 * MB + 2;
    localparam LBK = LOOK_BEHIND;
    localparam CB  = $clog2(LOOK_BEHIND + 1);
    // the look-behind run {count, slots, entering, same_t} (SECONDARY)
    localparam RW  = (SECONDARY != 0) ? CB + LBK * (H + 2) : 0;
    // token tag: {run (SECONDARY), seq, skip, last, t, leaf, slot, entering}
    localparam BGW = 3 + TW + LB + H + 1;
    localparam GW  = BGW + RW;
    // record: {run (SECONDARY), hit, t, leaf, slot, entering, from, to, flags_before, payload}
    localparam BOW = 1 + TW + LB + H + 1 + 2 * MB + NS + PAYLOAD_WIDTH;
    localparam OW  = BOW + RW;

    reg                     act_q;           // a ray is being issued
    reg                     seq_q;           // its bank
    reg [1:0]               done_q;          // bank's ray has its result
    reg [NS-1:0]            fl0_q, fl1_q;    // flag banks
    reg [PAYLOAD_WIDTH-1:0] pl0_q, pl1_q;
    // shadow of the tree's pipeline: stage k = 1 .. H at index k-1
    reg [H-1:0]             sh_valid_q, sh_seq_q, sh_skip_q;
    reg [H*H-1:0]           sh_slot_q;

    // ---- tree output and results ------------------------------------------
    wire          tv;
    wire [CW-1:0] tc;
    wire [GW-1:0] tg;
    wire          t_seq  = tg[BGW-1];
    wire          t_skip = tg[BGW-2];
    wire          t_last = tg[BGW-3];
    wire [TW-1:0] t_t    = tg[LB+H+1 +: TW];
    wire [LB-1:0] t_leaf = tg[H+1 +: LB];
    wire [H-1:0]  t_slot = tg[1 +: H];
    wire          t_ent  = tg[0];
    wire [MB-1:0] c_from = tc[MB +: MB];
    wire [MB-1:0] c_to   = tc[0 +: MB];
    wire          live   = tv && !done_q[t_seq];
    wire          res_hit  = live && !t_skip && tc[CW-1 -: 2] == 2'd2 && c_from != c_to;
    wire          res_miss = live && !res_hit && t_last;
    wire          res      = res_hit || res_miss;
    wire          sk_ready;
    wire          ce = !(res && !sk_ready);

    // ---- issue --------------------------------------------------------------
    wire [NS-1:0] fl_cur = seq_q ? fl1_q : fl0_q;
    wire          stop   = done_q[seq_q] || (res_hit && t_seq == seq_q);
    wire          issue  = ce && act_q && !stop;
    wire          skip   = !ev_valid_i || (fl_cur[ev_slot_i] == ev_entering_i);
    wire          last   = !ev_valid_i || ev_last_i;
    wire          in_fl_next;                 // a token of bank !seq_q in flight
    wire          load   = ce && !act_q && ray_valid_i && !in_fl_next;
    assign ev_pop_o   = issue && ev_valid_i;
    assign ray_done_o = ce && act_q && (stop || last);

    wire [BGW-1:0] tag_base = {seq_q, skip, last, ev_t_i, ev_leaf_i, ev_slot_i, ev_entering_i};
    wire [GW-1:0]  tag_in;

    csgrt_class_tree #(.TREE_HEIGHT(H), .MAT_BITS(MB), .TAG_WIDTH(GW)) u_tree (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(ce),
        .node_op_i(node_op_i), .slot_mat_i(slot_mat_i), .slot_used_i(slot_used_i),
        .valid_i(issue), .flags_i(fl_cur), .slot_i(ev_slot_i), .entering_i(ev_entering_i), .tag_i(tag_in),
        .valid_o(tv), .class_o(tc), .tag_o(tg));

    // ---- flags just before the hit --------------------------------------
    reg [NS-1:0] undo;
    reg          busy_other;
    integer k;
    always @* begin
        undo = {NS{1'b0}};
        busy_other = 1'b0;
        for (k = 0; k < H; k = k + 1) begin
            if (sh_valid_q[k] && !sh_skip_q[k] && sh_seq_q[k] == t_seq)
                undo = undo ^ ({{(NS-1){1'b0}}, 1'b1} << sh_slot_q[k*H +: H]);
            if (sh_valid_q[k] && sh_seq_q[k] != seq_q) busy_other = 1'b1;
        end
    end
    assign in_fl_next = busy_other;
    wire [NS-1:0] flags_before = (t_seq ? fl1_q : fl0_q) ^ undo;

    // ---- state ---------------------------------------------------------------
    always @(posedge clk_i) begin
        if (ce) begin
            sh_valid_q <= {sh_valid_q[H-2:0], issue};
            sh_seq_q   <= {sh_seq_q[H-2:0], seq_q};
            sh_skip_q  <= {sh_skip_q[H-2:0], skip};
            sh_slot_q  <= {sh_slot_q[H*(H-1)-1:0], ev_slot_i};
            if (issue && !skip) begin
                if (seq_q) fl1_q[ev_slot_i] <= !fl1_q[ev_slot_i];
                else       fl0_q[ev_slot_i] <= !fl0_q[ev_slot_i];
            end
            if (load) begin
                if (seq_q) begin
                    fl0_q <= ray_flags_i;
                    pl0_q <= ray_payload_i;
                end else begin
                    fl1_q <= ray_flags_i;
                    pl1_q <= ray_payload_i;
                end
            end
        end
        if (!rst_ni) begin
            act_q      <= 1'b0;
            seq_q      <= 1'b0;
            done_q     <= 2'b00;
            sh_valid_q <= {H{1'b0}};
        end else if (ce) begin
            if (load) begin
                act_q          <= 1'b1;
                seq_q          <= !seq_q;
                done_q[!seq_q] <= 1'b0;
            end else if (ray_done_o) begin
                act_q <= 1'b0;
            end
            if (res_hit) done_q[t_seq] <= 1'b1;
        end
    end

    // ---- output ----------------------------------------------------------------
    wire [BOW-1:0] rec_base = res_hit ? {1'b1, t_t, t_leaf, t_slot, t_ent, c_from, c_to, flags_before,
                                         t_seq ? pl1_q : pl0_q}
                                      : {{(BOW-PAYLOAD_WIDTH){1'b0}}, t_seq ? pl1_q : pl0_q};
    wire [OW-1:0]  rec;
    wire [OW-1:0]  rec_o;
    csgrt_skid #(.WIDTH(OW)) u_out (
        .clk_i(clk_i), .rst_ni(rst_ni),
        .valid_i(res), .ready_o(sk_ready), .data_i(rec),
        .valid_o(valid_o), .ready_i(ready_i), .data_o(rec_o));
    assign {hit_o, t_o, leaf_o, slot_o, entering_o, from_o, to_o, flags_before_o, payload_o} = rec_o[BOW-1:0];

    // ---- secondary rays: the look-behind run, flags after the hit ----------
    genvar g;
    generate
        if (SECONDARY != 0) begin : g_sec
            // the ray's last LBK valid tokens, most recent at entry 0
            reg [CB-1:0]     hc_q;             // entries held, 0 .. LBK
            reg [LBK*H-1:0]  hs_q;
            reg [LBK-1:0]    he_q;
            reg [LBK*TW-1:0] ht_q;
            // the run of the token being issued: the history, same_t against its t
            wire [LBK*H-1:0] run_slot;
            wire [LBK-1:0]   run_ent, run_same;
            for (g = 0; g < LBK; g = g + 1) begin : g_run
                wire held = {{(32-CB){1'b0}}, hc_q} > g;
                assign run_slot[g*H +: H] = held ? hs_q[g*H +: H] : {H{1'b0}};
                assign run_ent[g]         = held && he_q[g];
                assign run_same[g]        = held && ht_q[g*TW +: TW] == ev_t_i;
            end
            assign tag_in = {hc_q, run_slot, run_ent, run_same, tag_base};
            integer i;
            always @(posedge clk_i) begin
                if (ce && issue && !skip) begin
                    for (i = LBK - 1; i > 0; i = i - 1) begin
                        hs_q[i*H +: H]   <= hs_q[(i-1)*H +: H];
                        he_q[i]          <= he_q[i-1];
                        ht_q[i*TW +: TW] <= ht_q[(i-1)*TW +: TW];
                    end
                    hs_q[0 +: H]  <= ev_slot_i;
                    he_q[0]       <= ev_entering_i;
                    ht_q[0 +: TW] <= ev_t_i;
                    if ({{(32-CB){1'b0}}, hc_q} != LBK) hc_q <= hc_q + 1'b1;
                end
                if ((ce && load) || !rst_ni) hc_q <= {CB{1'b0}};
            end
            // the hit token's run (misses: 0) rides in the record
            assign rec = {res_hit ? tg[GW-1:BGW] : {RW{1'b0}}, rec_base};
            assign {lb_count_o, lb_slot_o, lb_entering_o, lb_same_t_o} = rec_o[OW-1:BOW];
            assign flags_after_o = flags_before_o ^ ({{(NS-1){1'b0}}, hit_o} << slot_o);
        end else begin : g_pri
            assign tag_in        = tag_base;
            assign rec           = rec_base;
            assign flags_after_o = {NS{1'b0}};
            assign lb_count_o    = {CB{1'b0}};
            assign lb_slot_o     = {(LBK*H){1'b0}};
            assign lb_entering_o = {LBK{1'b0}};
            assign lb_same_t_o   = {LBK{1'b0}};
        end
    endgenerate

    generate
        if (H < 2 || LOOK_BEHIND < 1) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_walker needs TREE_HEIGHT >= 2 and LOOK_BEHIND >= 1");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
