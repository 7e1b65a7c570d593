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
// The hit's surface (docs/numerics.md section 5): leaf_o is the first event
// of the hit's tie group (events at the hit's t) that is a border alone from
// the flags before the group, else the hit's own leaf; slot_o and
// entering_o stay the hit crossing's. An event at the same t as the ray's
// previous event gets a probe token first (the flags before the group, no
// toggle, no result of its own); a hit whose group has no such event yet is
// held (pend_q) until the ray's next tokens decide it.
// flags_before_o (bit per slot): the flags just before the hit's tie group
// (docs/effects.md, look-behind: every crossing at the hit's t undone), kept
// at the output as the group's first token passes; a token's flags there:
// the ray's flag bank with the toggles of that token and of the ray's
// tokens issued after it (still in flight: a shadow of the tree's pipeline)
// undone.
// On a miss every field but payload_o is zero.
//
// Secondary rays (SECONDARY = 1; with SECONDARY = 0 these outputs are 0 and
// their logic is not built), beside each hit record (on a miss all 0):
//   flags_after_o  the flags just after the hit crossing (the far side,
//                  for a continuation or transmitted ray:
//                  TraceResult::flags_after), carried in the record:
//                  with LOOK_AHEAD = 0 the flags before the hit token with
//                  its slot toggled; with LOOK_AHEAD = 1 the flags after
//                  the look-ahead run below.
//   lb_count_o     0..LOOK_BEHIND: the look-behind run, the valid (non-skip)
//   lb_slot_o      tokens of the ray issued before the hit's tie group, most
//   lb_entering_o  recent first (TraceResult::near_run): entry k's slot at
//   lb_same_t_o    [k*TREE_HEIGHT +: TREE_HEIGHT], its entering and
//                  "t equals the hit's t" at bit k; entries at and past
//                  lb_count_o are 0. Each token carries in its tag the run
//                  as it stood when the token was issued (a history of the
//                  ray's last LOOK_BEHIND valid tokens, cleared when a ray
//                  is loaded; a later member of a tie group carries the run
//                  as it stood before the group), so tokens issued after
//                  the hit (still in the tree) are not part of it.
// flags_before_o, lb_*_o and the hit's position make the info record of
// the near-side children (shadow, reflected) for csgrt_event_sort, which
// applies the look-behind fix-up; flags_after_o that of far-side ones.
//
// The refraction look-ahead (LOOK_AHEAD = 1, needs SECONDARY = 1;
// TraceOptions::lookahead, algorithm.md section 6, docs/effects.md): after a
// hit BORDER a1,a2 whose far side a2 is transparent (mat_clear_i), the
// following events that lie at the hit's t, or whose surface the hit point
// already lies beyond (never asked for the hit leaf's own events: the hit
// point lies on that surface), are crossed too (validity check, classify, toggle),
// until the far side is opaque; a crossing BORDER x,y (x != y) in the run
// makes the far side y; the hit reads BORDER a1,an and flags_after_o are
// the flags after the run. A run that comes back to a1 is discarded and the
// walk goes on after it. The run's candidates are the tokens issued after
// the hit token: each was classified, in order, against the flags with
// every earlier valid token toggled, which is the model's run; so the
// walker keeps issuing after such a hit and examines the following results
// one per clock. "Beyond" (only for an event at a later t) is asked on the
// query port: q_valid_o/q_ready_i with the hit's t (q_t_o), the event's
// leaf (q_leaf_o) and the ray's payload (q_payload_o, by which the answerer
// knows o and d); the answer a_valid_i/a_ready_o carries a_nonpos_i:
// quadric_at_fx(leaf, hit_point_fx(o, d, t)) <= 0 (csgrt_quadric_at). The
// walker, tree included, stalls until the answer is in: at most one query
// per token, only behind transparent hits. LOOK_AHEAD = 0 builds none of it.
//
// Latency: a ray loaded at edge k issues its i-th event (i = 0, 1, ..) at
// edge k+1+i (into the tree's first register); the tree's result is there
// after edge k+i+TREE_HEIGHT+1 and the record on valid_o (csgrt_skid) after
// edge k+i+TREE_HEIGHT+2, the same with SECONDARY = 1 (counting probe
// tokens as events). Throughput: one token per clock (an event, or the
// probe of an event at its predecessor's t); per ray max(1, issued tokens)
// + 2 clocks with event_sort
// (release -> next ray loaded), issued events = all of them on a miss, at
// most hit index + TREE_HEIGHT + 3 on a hit; the same with SECONDARY = 1.
// Handshake: valid/ready out through csgrt_skid; while the skid holds a
// word (it cannot take another) the whole walker (tree included) stalls. No
// combinational path from ready_i, nor from the tree's output, to ev_pop_o /
// ray_done_o or the walker's clock enable. With LOOK_AHEAD
// a ray in a run keeps issuing (its tokens after the run are dropped) and
// a query stalls the walker until its answer (q_ready_i and a_valid_i reach
// ev_pop_o / ray_done_o combinationally: the answerer must not depend on
// them).
module csgrt_walker #(
    parameter BITS          = 24,   // coordinate width B; t is B-1 bits
    parameter LEAF_BITS     = 6,    // leaf index width
    parameter TREE_HEIGHT   = 8,    // H: 2^H slots
    parameter MAT_BITS      = 8,    // material index width
    parameter PAYLOAD_WIDTH = 1,    // per-ray sideband (>= 1)
    parameter SECONDARY     = 0,    // 1: flags_after_o and the look-behind run
    parameter LOOK_BEHIND   = 4,    // look-behind entries (kLookBehind), >= 1
    parameter LOOK_AHEAD    = 0     // 1: the refraction look-ahead (needs SECONDARY = 1)
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
    input  wire                     ev_same_t_i,   // ev_t_i equals the ray's previous popped event's (csgrt_event_sort)
    input  wire [TREE_HEIGHT-1:0]   ev_next_slot_i,   // the next event's slot, the head's after a pop (csgrt_event_sort)
    input  wire [TREE_HEIGHT-1:0]   ev_slot_tree_i,   // ev_slot_i from a copy of its own, for the class tree
    input  wire                     ev_next_same_t_i, // the next event's t equals the head's (csgrt_event_sort)
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
    output wire [LOOK_BEHIND-1:0]               lb_same_t_o,
    // the look-ahead (LOOK_AHEAD; else q_valid_o and a_ready_o are 0)
    input  wire [(1<<MAT_BITS)-1:0]             mat_clear_i,   // material m transparent (bit 0: air, 1)
    output wire                     q_valid_o,
    input  wire                     q_ready_i,
    output wire [BITS-2:0]          q_t_o,
    output wire [LEAF_BITS-1:0]     q_leaf_o,
    output wire [PAYLOAD_WIDTH-1:0] q_payload_o,
    input  wire                     a_valid_i,
    output wire                     a_ready_o,
    input  wire                     a_nonpos_i
);

    localparam TW = BITS - 1;
    localparam LB = LEAF_BITS;
    localparam H  = TREE_HEIGHT;
    localparam NS = 1 << H;
    localparam TL = H + 1;       // csgrt_class_tree's latency (stage 0, then one per height)
    localparam MB = MAT_BITS;
    localparam CW = 2 * MB + 2;
    localparam LBK = LOOK_BEHIND;
    localparam CB  = $clog2(LOOK_BEHIND + 1);
    // the look-behind run {count, slots, entering, same_t} (SECONDARY)
    localparam RW  = (SECONDARY != 0) ? CB + LBK * (H + 2) : 0;
    // token tag: {run (SECONDARY), seq, skip, last, probe, later, t, leaf,
    // slot, entering}
    localparam BGW = 5 + TW + LB + H + 1;
    localparam GW  = BGW + RW;
    // record: {flags_after (LOOK_AHEAD), run (SECONDARY), hit, t, leaf, slot,
    // entering, from, to, flags_before, payload}
    localparam LA  = (SECONDARY != 0 && LOOK_AHEAD != 0) ? 1 : 0;
    localparam BOW = 1 + TW + LB + H + 1 + 2 * MB + NS + PAYLOAD_WIDTH;
    localparam FA  = (SECONDARY != 0) ? 1 : 0;   // flags_after rides in the record
    localparam OW  = BOW + RW + FA * NS;
    localparam LEAF_POS = PAYLOAD_WIDTH + NS + 2 * MB + 1 + H;   // leaf's place in the record

    reg                     act_q;           // a ray is being issued
    reg                     seq_q;           // its bank
    reg [1:0]               done_q;          // bank's ray has its result
    reg [NS-1:0]            fl0_q, fl1_q;    // flag banks
    reg [PAYLOAD_WIDTH-1:0] pl0_q, pl1_q;
    // shadow of the tree's pipeline: stage k = 0 .. H at index k
    reg [TL-1:0]            sh_valid_q, sh_seq_q, sh_skip_q;
    reg [TL*H-1:0]          sh_slot_q;

    // ---- tree output and results ------------------------------------------
    wire          tv;
    wire [CW-1:0] tc;
    wire [GW-1:0] tg;
    wire          t_seq  = tg[BGW-1];
    wire          t_skip = tg[BGW-2];
    wire          t_last = tg[BGW-3];
    wire          t_probe = tg[BGW-4];
    wire          t_later = tg[BGW-5];
    wire [TW-1:0] t_t    = tg[LB+H+1 +: TW];
    wire [LB-1:0] t_leaf = tg[H+1 +: LB];
    wire [H-1:0]  t_slot = tg[1 +: H];
    wire          t_ent  = tg[0];
    wire [MB-1:0] c_from = tc[MB +: MB];
    wire [MB-1:0] c_to   = tc[0 +: MB];
    // tc is BORDER c_from, c_to with c_from != c_to: the tree's register
    // (decoded here from tc, it was the first two LUT levels of the hit
    // decision into the output skid, the walker's longest path)
    wire          border;
    wire [1:0]    unused_kind = tc[CW-1 -: 2];
    wire          live_tok = tv && !done_q[t_seq];
    reg           pend_q;                     // a hit waits for its surface (below)
    // a token of the walk: not a probe, and no hit of its ray pending
    wire          live   = live_tok && !t_probe && !pend_q;
    wire          res_hit  = live && !t_skip && border;
    wire          res_miss = live && !res_hit && t_last;
    // what the result stage does: res a record goes out, fin_hit it is the
    // ray's hit (the ray is done), la_stall the walker waits for a
    // look-ahead answer. The walk (with the look-ahead when built) proposes
    // a record (w_*); a hit whose surface is not yet decided waits (pend_q).
    wire          res, fin_hit, la_stall;
    wire          w_out, w_hit, w_dec;
    wire [LB-1:0] w_sleaf;
    wire [OW-1:0] w_rec;
    wire          sk_ready;
    wire          sk_ready_next;              // sk_ready after the next edge (csgrt_skid)
    // The clock enable of the walker, its tree and (through ev_pop_o and
    // ray_done_o) the sorter's drain bank: the skid's ready (a register),
    // not whether the tree's output makes a record this clock: that path
    // (tree output -> result -> enable of every cell) was the critical path
    // of the FPGA build. So the walker also pauses while the skid is full
    // and no record is due, only under back-pressure. (With LOOK_AHEAD the
    // wait for an answer, from the tree's output, stalls it too.)
    wire          ce = sk_ready && !la_stall;
    // The issue logic (issue, load, ray_done_o and so ev_pop_o, which fans
    // out to the sorter's 128 drain cells) reads sk_ready again from a
    // register of its own, loaded with the skid's next ready: the skid's
    // register itself enables the tree's and the walker's stages (about
    // 2,300 flip-flops), and the pop decision continued that net
    // (tools/logic_depth.py). A simulation stops if the two differ.
    reg           ctl_ready_q;
    always @(posedge clk_i) ctl_ready_q <= sk_ready_next;
    wire          ce_ctl = ctl_ready_q && !la_stall;   // = ce
    csgrt_check_same #(.WHAT("ctl_ready_q")) u_check_ready (.clk_i, .rst_ni, .copy_i(ctl_ready_q), .orig_i(sk_ready));

    // ---- issue --------------------------------------------------------------
    // The hit's surface (docs/numerics.md section 5): an event at the same t
    // as the ray's previous one is a later member of a tie group; before its
    // own token a probe token goes into the tree with the flags before the
    // group (gfl_q): its classification says whether crossing that event
    // alone from there is a border (the first member's own token says it).
    // A probe toggles nothing and is neither hit nor miss.
    reg           gv_q;                       // the ray has issued an event
    reg  [NS-1:0] gfl_q;                      // flags before the current tie group
    reg           pr_q;                       // the head event's probe is issued (probe_q's reference)
    wire [NS-1:0] fl_cur = seq_q ? fl1_q : fl0_q;
    // the ray has its result: stop issuing. From done_q alone (registered):
    // in the clock its hit comes out of the tree one more token issues,
    // which the tree's output drops (done_q is set by then).
    wire          stop   = done_q[seq_q];
    // walking_q = act_q && !stop as a register of its own, loaded with the
    // next values of act_q, seq_q and done_q (below): issue and so the
    // crossing's bank write (the walker's longest path, tools/
    // logic_depth.py: the sorter's head through the tie-group, probe and
    // issue decisions into the flag banks, 14.6 ns) read one register
    // instead of the state bits and the bank's done flag behind seq_q.
    // A simulation stops if the two differ.
    reg           walking_q;
    wire          issue  = ce_ctl && walking_q;
    // the event sorter compares the head's t with the previously popped
    // event's (registered, ev_same_t_i): no comparator on the pop path
    wire          later  = ev_valid_i && gv_q && ev_same_t_i;
    // probe = later && !pr_q as a register of its own, loaded with its next
    // value: after a pop the new head is a later member when it has the
    // popped one's t (the sorter's ev_next_same_t_i: the two registers it
    // compares; after the ray's last event the ray ends in the same clock
    // and nothing issues before the next load), a probe's issue clears it,
    // and so does a load (a ray's first event is no later member). From
    // the state bits (dne_q, gv_q, same_t_q, pr_q) it was two LUT levels
    // at the start of the bank's write, tools/logic_depth.py's longest
    // path. A simulation check compares the two at every issue, the only
    // clocks it is read in.
    reg           probe_q;
    wire          probe  = probe_q;
    // The token is classified with gfl_q (a probe) or fl_cur. probe comes
    // late (from the sorter's head through the tie-group test), so the
    // flags are read at the event's slot first and probe chooses between
    // the bits, here and in the tree (its alt_i): in front of the 2^H-to-1
    // choices it made the walker's paths into the tree's stage 0 ten LUT
    // levels long (tools/logic_depth.py). The bits at the head's slot and
    // at its sibling (the tree's stage 0) are registers, fh_q and gh_q,
    // read a clock ahead (below): read here from the sorter's head, the
    // flag went on through probe and skip into the pending crossing
    // (g_sec's pv_q), the routed critical path of the 231e4db build.
    reg  [1:0]    fh_q;                       // fl_cur at the head's slot (bit 0) and its sibling (bit 1)
    reg  [1:0]    gh_q;                       // gfl_q at the same two slots
    wire          fl_tok_at = probe ? gh_q[0] : fh_q[0];   // the token's flag of the event's slot
    wire          skip   = !ev_valid_i || (fl_tok_at == ev_entering_i);
    wire          toggle = !skip && !probe;   // the token crosses (flag toggled)
    wire          crossing = issue && !probe && ev_valid_i;   // a walk token of an event
    wire          last   = !probe && (!ev_valid_i || ev_last_i);
    wire          in_fl_next;                 // a token of bank !seq_q in flight
    wire          load   = ce_ctl && !act_q && ray_valid_i && !in_fl_next;
    assign ev_pop_o   = issue && ev_valid_i && !probe;
    assign ray_done_o = ce_ctl && act_q && (stop || last);
    always @(posedge clk_i)
        if (!rst_ni)
            probe_q <= 1'b0;
        else begin   // (load, crossing and issue include ce_ctl: the walker's ce)
            if (load)          probe_q <= 1'b0;
            else if (crossing) probe_q <= ev_next_same_t_i;
            else if (issue)    probe_q <= 1'b0;
        end
    csgrt_check_same #(.WHAT("probe_q")) u_check_probe (
        .clk_i, .rst_ni, .copy_i(issue && probe_q), .orig_i(issue && later && !pr_q));

    // fh_q and gh_q follow the bank and gfl_q at the head's slot (p = 0)
    // and its sibling (p = 1). The head moves only at a pop, which is a
    // crossing (ev_pop_o), to the sorter's next event (ev_next_slot_i);
    // the bank changes only at a crossing (the head's slot becomes
    // entering: the next slot's bit read from the bank before that write
    // takes it when the two are the same slot) or at a load, which gives
    // the new ray's bank ray_flags_i under a head that stays until the
    // ray's first pop (the sorter hands a ray over only while the walker
    // is idle, and a load comes a clock after it at the earliest).
    // gfl_q takes fl_cur on every clock whose head is not a later member
    // (above): at a pop the bank's bit at the next slot before the write,
    // else fh_q. After a load gh_q is stale until the first clock without
    // a later member, as gfl_q is, and the first issue of a ray is not one
    // (gv_q clear). Simulation checks compare both with the reads from the
    // sorter's head at every issue.
    // The head's slot one-hot (hoh_q), for the bank's write: it follows
    // the head as fh_q does, to the next event's slot at a crossing (a pop)
    // and to the new ray's first event at a load. A check compares it with
    // the decode of the head's slot at every crossing, where it is read.
    // Its next value is the decode of a slot chosen by load alone (early),
    // so that the late crossing reaches only the flip-flops' enable; with
    // two decodes under load and crossing yosys made the crossing a
    // synchronous reset, a LUT after the enable's (13.91 ns out of context).
    reg  [NS-1:0] hoh_q;
    wire [H-1:0]  hoh_slot = load ? ev_slot_i : ev_next_slot_i;
    wire [NS-1:0] hoh_d;
    genvar hs;
    generate
        for (hs = 0; hs < NS; hs = hs + 1) begin : g_hoh
            assign hoh_d[hs] = hoh_slot == hs[H-1:0];
        end
    endgenerate
    always @(posedge clk_i)
        if (load || crossing) hoh_q <= hoh_d;
    csgrt_check_same #(.WIDTH(NS), .WHAT("hoh_q (the head's slot one-hot)")) u_check_hoh (
        .clk_i, .rst_ni, .copy_i(crossing ? hoh_q : {NS{1'b0}}),
        .orig_i(crossing ? {{(NS-1){1'b0}}, 1'b1} << ev_slot_i : {NS{1'b0}}));
    genvar p;
    generate
        for (p = 0; p < 2; p = p + 1) begin : g_head_flag
            wire [H-1:0] next_at = ev_next_slot_i ^ p[H-1:0];   // the next head's slot (or sibling)
            wire [H-1:0] head_at = ev_slot_i ^ p[H-1:0];
            wire         cur_next = seq_q ? fl1_q[next_at] : fl0_q[next_at];   // before this clock's write
            always @(posedge clk_i) begin
                if (load)          fh_q[p] <= ray_flags_i[head_at];
                else if (crossing) fh_q[p] <= (next_at == ev_slot_i) ? ev_entering_i : cur_next;
                if (crossing)          gh_q[p] <= later ? gfl_q[next_at] : cur_next;
                else if (ce && !later) gh_q[p] <= fh_q[p];
            end
            csgrt_check_same #(.WIDTH(2), .WHAT("fh_q / gh_q (the flags at the head's slot)")) u_check_head_flag (
                .clk_i, .rst_ni,
                .copy_i(issue && ev_valid_i ? {fh_q[p], probe && gh_q[p]} : 2'b00),
                .orig_i(issue && ev_valid_i ? {fl_cur[head_at], probe && gfl_q[head_at]} : 2'b00));
        end
    endgenerate

    wire [BGW-1:0] tag_base = {seq_q, skip, last, probe, later, ev_t_i, ev_leaf_i, ev_slot_i, ev_entering_i};
    wire [GW-1:0]  tag_in;

    csgrt_class_tree #(.TREE_HEIGHT(H), .MAT_BITS(MB), .TAG_WIDTH(GW)) u_tree (
        .clk_i(clk_i), .rst_ni(rst_ni), .ce_i(ce),
        .node_op_i(node_op_i), .slot_mat_i(slot_mat_i), .slot_used_i(slot_used_i),
        .valid_i(issue), .flags_i(fl_cur), .flags_alt_i(gfl_q), .alt_i(probe), .sib_flag_i(probe ? gh_q[1] : fh_q[1]),
        .slot_i(ev_slot_tree_i), .entering_i(ev_entering_i), .tag_i(tag_in),
        .valid_o(tv), .class_o(tc), .border_o(border), .tag_o(tg));

    // ---- flags just before the hit --------------------------------------
    // The flags before the output token's crossing: its bank without the
    // crossings of the tokens still in the tree (the output token's own
    // among them). Both halves are registers: a lagging copy of the banks
    // (lag0_q, lag1_q) that takes each crossing a clock after the bank, from
    // the shadow's newest entry, so it holds every crossing but that of the
    // token at shadow index 0; and undo_q, the crossings of the tokens that
    // will be at indices 1 .. TL-1 after the next enable (now at 0 .. TL-2)
    // of the bank of the next output token (now at TL-2). Computed at the
    // output from the live bank and the whole shadow, this path (the tree's
    // output seq -> the shadow's compares and slot decodes -> the XOR of
    // TL terms -> the record -> the output skid) was 10 LUT levels
    // (tools/logic_depth.py). A simulation check compares the two.
    reg  [NS-1:0] lag0_q, lag1_q, undo_q;
    reg  [NS-1:0] undo_d;
    reg           busy_other;                 // a token of bank !seq_q in the tree
    reg           busy_same_next, busy_flip_next;
    integer k;
    always @* begin
        undo_d = {NS{1'b0}};
        busy_other = 1'b0;
        busy_same_next = 1'b0;
        busy_flip_next = 1'b0;
        for (k = 0; k < TL; k = k + 1) begin
            if (k < TL - 1 && sh_valid_q[k] && !sh_skip_q[k] && sh_seq_q[k] == sh_seq_q[TL-2])
                undo_d = undo_d ^ ({{(NS-1){1'b0}}, 1'b1} << sh_slot_q[k*H +: H]);
            if (sh_valid_q[k] && sh_seq_q[k] != seq_q) busy_other = 1'b1;
            // the tokens that stay in the tree after the next enable
            // (indices 0 .. TL-2 move to 1 .. TL-1), against seq_q kept
            // or toggled by a load
            if (k < TL - 1 && sh_valid_q[k] && sh_seq_q[k] != seq_q) busy_same_next = 1'b1;
            if (k < TL - 1 && sh_valid_q[k] && sh_seq_q[k] == seq_q) busy_flip_next = 1'b1;
        end
    end
    // busy_other as a register of its own (busy_q), loaded with its next
    // value: at an enable the shadow shifts in the issue's token, of bank
    // seq_q, which is never of the other bank (a load, the only step of
    // seq_q, issues nothing: it needs !act_q); a load toggles seq_q, so the
    // tokens that stay are tested against the toggled bank. From the
    // shadow's compares and OR, load went on into every bank bit's load
    // (the two banks, the lagging copies, the payloads: tools/
    // logic_depth.py 12.58 ns). A simulation stops if the two differ.
    reg busy_q;
    always @(posedge clk_i)
        if (!rst_ni)  busy_q <= 1'b0;
        else if (ce)  busy_q <= load ? busy_flip_next : busy_same_next;
    csgrt_check_same #(.WHAT("busy_q (a token of the other bank in flight)")) u_check_busy (
        .clk_i, .rst_ni, .copy_i(busy_q), .orig_i(busy_other));
    assign in_fl_next = busy_q;
    wire [NS-1:0] sh0_toggle = {{(NS-1){1'b0}}, sh_valid_q[0] && !sh_skip_q[0]} << sh_slot_q[0 +: H];
    always @(posedge clk_i)
        if (ce) begin
            undo_q <= undo_d;
            if (sh_seq_q[0]) lag1_q <= lag1_q ^ sh0_toggle;
            else             lag0_q <= lag0_q ^ sh0_toggle;
            // a load fills the bank with no token in flight (in_fl_next), lagging copy too
            if (load) begin
                if (seq_q) lag0_q <= ray_flags_i;
                else       lag1_q <= ray_flags_i;
            end
        end
    wire [NS-1:0] flags_before = (t_seq ? lag1_q : lag0_q) ^ undo_q;
`ifndef SYNTHESIS
    // the same flags from the live bank and the whole shadow
    reg [NS-1:0] undo_chk;
    always @* begin
        undo_chk = {NS{1'b0}};
        for (k = 0; k < TL; k = k + 1)
            if (sh_valid_q[k] && !sh_skip_q[k] && sh_seq_q[k] == t_seq)
                undo_chk = undo_chk ^ ({{(NS-1){1'b0}}, 1'b1} << sh_slot_q[k*H +: H]);
    end
    // (from the first reset on, as the state starts undefined before it)
    csgrt_check_same #(.WIDTH(NS), .WHAT("flags_before (the lagging banks and undo_q)")) u_check_before (
        .clk_i, .rst_ni, .copy_i(tv ? flags_before : {NS{1'b0}}),
        .orig_i(tv ? (t_seq ? fl1_q : fl0_q) ^ undo_chk : {NS{1'b0}}));
`endif
    // the near side starts before the hit's tie group: the flags before the
    // group's first token, kept as it passes (probes change no flag)
    reg  [NS-1:0] gs_flags_q;
    wire [NS-1:0] flags_near = t_later ? gs_flags_q : flags_before;
    always @(posedge clk_i)
        if (ce && live_tok && !t_probe && !t_later) gs_flags_q <= flags_before;

    // ---- state ---------------------------------------------------------------
    always @(posedge clk_i) begin
        if (ce) begin
            sh_valid_q <= {sh_valid_q[TL-2:0], issue};
            sh_seq_q   <= {sh_seq_q[TL-2:0], seq_q};
            sh_skip_q  <= {sh_skip_q[TL-2:0], !toggle};
            sh_slot_q  <= {sh_slot_q[H*(TL-1)-1:0], ev_slot_i};
            // gfl_q follows the bank on every clock whose head is not a
            // later member of a tie group, so it holds the flags from the
            // clock the group's first member issues until the group ends.
            // (Loaded only at that issue, its enable ran from the sorter's
            // head through the probe and issue decisions: tools/
            // logic_depth.py's longest path.) The clocks between have no
            // other load: within a ray the sorter's head stays valid until
            // its last event, and a ray's first issue has gv_q clear. A
            // simulation check compares it at every probe with a copy
            // loaded only at the first member's issue.
            if (!later) gfl_q <= fl_cur;
        end
        // The writes at an issue, a crossing or a load: these include
        // ce_ctl, which equals ce (u_check_ready) but comes from a
        // register of its own. Nested in `if (ce)` as well, the enables
        // ANDed ce_ctl's crossing with the output skid's ready (ce) again,
        // a fourth LUT level into the flag registers' and banks' enables
        // (tools/logic_depth.py 11.44 ns on 9f2f1a7's netlist). (act_q,
        // seq_q and done_q stay under ce below: taken out as well, done_q's
        // hit term went into its data input, 11.98 ns from pend_q.)
        if (issue && probe) pr_q <= 1'b1;
        if (issue && !probe) begin
            pr_q <= 1'b0;
            if (ev_valid_i) gv_q <= 1'b1;
        end
        // The crossing leaves the flag at the event's side whether it
        // toggles it (the flag was !entering) or is skipped as invalid
        // (it was entering already), so the bank is written with
        // ev_entering_i and its write needs no read of the flag: the
        // 128-to-1 choice of the token's flag stays off the bank's loop
        // (it was the walker's critical path on the FPGA, docs/fpga.md).
        // The write's slot comes one-hot from a register (hoh_q): its
        // decode from the sorter's head (319 loads) was most of the
        // whole design's longest path into the banks
        // (tools/logic_depth.py 12.74 ns).
        if (crossing) begin
            if (seq_q) fl1_q <= (fl1_q & ~hoh_q) | (hoh_q & {NS{ev_entering_i}});
            else       fl0_q <= (fl0_q & ~hoh_q) | (hoh_q & {NS{ev_entering_i}});
        end
        if (load) begin
            gv_q <= 1'b0;
            pr_q <= 1'b0;
            if (seq_q) begin
                fl0_q <= ray_flags_i;
                pl0_q <= ray_payload_i;
            end else begin
                fl1_q <= ray_flags_i;
                pl1_q <= ray_payload_i;
            end
        end
        if (!rst_ni) begin
            act_q      <= 1'b0;
            seq_q      <= 1'b0;
            gv_q       <= 1'b0;
            pr_q       <= 1'b0;
            done_q     <= 2'b00;
            sh_valid_q <= {TL{1'b0}};
        end else if (ce) begin
            if (load) begin
                act_q          <= 1'b1;
                seq_q          <= !seq_q;
                done_q[!seq_q] <= 1'b0;
            end else if (ray_done_o) begin
                act_q <= 1'b0;
            end
            if (fin_hit) done_q[t_seq] <= 1'b1;
        end
    end
    // the next act_q && !done_q[seq_q], from the updates above: a load
    // starts the other bank's ray (its done flag cleared, unless its hit
    // comes out in the same clock), the end of a ray stops it, and a hit
    // of the walking bank's ray stops it
    always @(posedge clk_i)
        if (!rst_ni)
            walking_q <= 1'b0;
        else if (ce) begin
            if (load)            walking_q <= !(fin_hit && t_seq == !seq_q);
            else if (ray_done_o) walking_q <= 1'b0;
            else                 walking_q <= act_q && !stop && !(fin_hit && t_seq == seq_q);
        end
    csgrt_check_same #(.WHAT("walking_q")) u_check_walking (
        .clk_i, .rst_ni, .copy_i(walking_q), .orig_i(act_q && !stop));

`ifndef SYNTHESIS
    // gfl_q as it was: loaded at the issue of a tie group's first member only
    reg [NS-1:0] gfl_ref_q;
    always @(posedge clk_i)
        if (ce && issue && !probe && ev_valid_i && !later) gfl_ref_q <= fl_cur;
    csgrt_check_same #(.WIDTH(NS), .WHAT("gfl_q (the flags before a tie group) at a probe")) u_check_gfl (
        .clk_i, .rst_ni, .copy_i(issue && probe ? gfl_q : {NS{1'b0}}),
        .orig_i(issue && probe ? gfl_ref_q : {NS{1'b0}}));
`endif

    // ---- output ----------------------------------------------------------------
    wire [PAYLOAD_WIDTH-1:0] t_pl = t_seq ? pl1_q : pl0_q;
    // The record's fields (zero in a miss) are chosen by the token's own
    // crossing test, not by res_hit: the two agree on every record that
    // goes out or parks (a hit is a live crossing, a miss a live token
    // that is none), and a record that does neither is never read. With
    // res_hit the choice (~130 loads) hung on the live test behind the
    // tree's output, and through it the output skid's valid and the
    // walker's ready (tools/logic_depth.py's longest path, 13.70 ns; the
    // parked record's choice, below, was the next).
    // The look-ahead keeps res_hit: its run's records are chosen otherwise.
    wire           rec_hit  = (LA != 0) ? res_hit : (!t_skip && border);
    wire [BOW-1:0] rec_base = rec_hit ? {1'b1, t_t, t_leaf, t_slot, t_ent, c_from, c_to, flags_near, t_pl}
                                      : {{(BOW-PAYLOAD_WIDTH){1'b0}}, t_pl};
    wire [OW-1:0]  rec;
    wire [OW-1:0]  rec_o;

    // ---- the hit's surface ---------------------------------------------------
    // The first event of the hit's tie group, in order, that is a border
    // alone from the flags before the group: tracked over the walk's tokens
    // (gf_*: the current group at the output), and after a hit whose group
    // has none yet, over the ray's next tokens (pend_q: the record waits)
    // until one is, or the group ends (a later t, or the ray's last event):
    // then the hit leaf.
    reg          pb_surf_q;                   // the last probe: its event alone is a border
    reg          gf_found_q;                  // the current group has its surface
    reg [LB-1:0] gf_leaf_q;
    wire         tok_surf  = t_later ? pb_surf_q : (!t_skip && border);
    wire         grp_found = (t_later && gf_found_q) || tok_surf;      // with this token
    wire [LB-1:0] grp_leaf = (t_later && gf_found_q) ? gf_leaf_q : t_leaf;
    reg  [OW-1:0] pend_rec_q;
    wire         obs      = live_tok && !t_probe && pend_q;            // a token after a pending hit
    // the token lies at the pending hit's t: the token that parked the hit
    // did, and every observed token since (else the record would have
    // left), so this one does exactly when it lies at its predecessor's t:
    // its `later` bit. (Comparing t with the hit's, BITS-1 bits, was the
    // walker's out-of-context critical path into the output skid's enable.)
    wire         pend_same = t_later;
    wire         pend_surf = obs && pend_same && pb_surf_q;            // same t, after the hit
    wire         p_out    = obs && (pend_surf || !pend_same || t_last);
    // the walk's hit waits (never on the ray's last token: its group ends
    // there, and the next token at the output is another ray's)
    wire         w_park   = w_out && w_hit && !w_dec;
    assign res     = (w_out && !w_park) || p_out;
    assign fin_hit = (w_out && w_hit && !w_park) || p_out;
    // Which record goes out: the parked one while a hit is pending. That
    // is p_out's choice wherever a record goes out: without the
    // look-ahead a pending hit stops the walk (live needs !pend_q, so
    // w_out is 0) and p_out needs pend_q, so pend_q alone selects, a
    // register in place of the token's live test behind the tree's
    // output (the 136-load choice was the walker's longest path after
    // 6e37c85, into the output skid). The look-ahead's run can end while
    // a hit is pending, so it keeps p_out.
    // pend_q itself had 151 loads, through a LUT of 142 more into the
    // record's bits and the walker's done (tools/logic_depth.py 11.00 ns
    // on aaa564b's netlist): the record's choice reads a copy of its own
    // (pend_sel_q, below), as the skid's valid does (pend_res_q).
    wire          pend_sel;
    wire          rec_pend = (LA != 0) ? p_out : pend_sel;
    wire [OW-1:0] rec_out = rec_pend ? pend_rec_q : w_rec;
    wire [LB-1:0] rec_leaf = rec_out[LEAF_POS +: LB];                 // the hit leaf (miss: 0)
    wire [LB-1:0] leaf_out = rec_pend ? (pend_surf ? t_leaf : rec_leaf) : (w_hit ? w_sleaf : rec_leaf);
    assign rec = {rec_out[OW-1:LEAF_POS+LB], leaf_out, rec_out[LEAF_POS-1:0]};
    always @(posedge clk_i) begin
        if (ce) begin
            if (live_tok && t_probe) pb_surf_q <= !t_skip && border;
            if (live_tok && !t_probe) begin
                gf_found_q <= grp_found;
                gf_leaf_q  <= grp_leaf;
            end
            // loaded on every clock without a pending hit: it is read only
            // while one is (p_out), and it holds from the park on. (On
            // w_park, the tree's output through the walk's hit decision,
            // its enable was the walker's longest path out of context.)
            if (!pend_q) pend_rec_q <= w_rec;
        end
    end
    // (* keep *), as on its copy pend_res_q below: yosys merges two
    // flip-flops of the same input into one (opt_merge), and with the
    // keep on the copy alone the copy took pend_q's loads as well
    // pend_q's next value while the walker runs (a park sets it, the
    // parked record's leaving clears it); pend_res_q below loads it too
    wire pend_d = w_park || (pend_q && !p_out);
    (* keep *) always @(posedge clk_i) begin
        if (!rst_ni) pend_q <= 1'b0;
        else if (ce) pend_q <= pend_d;
    end
    reg pend_sel_q;
    (* keep *) always @(posedge clk_i) begin
        if (!rst_ni) pend_sel_q <= 1'b0;
        else if (ce) pend_sel_q <= pend_d;
    end
    assign pend_sel = pend_sel_q;
    csgrt_check_same #(.WHAT("pend_sel_q (pend_q's copy for the record's choice)")) u_check_pend_sel (
        .clk_i, .rst_ni, .copy_i(pend_sel_q), .orig_i(pend_q));
    // a hit parks only without one pending (the walk's records need live,
    // which needs !pend_q), so pend_rec_q above holds the parked one
    csgrt_check_same #(.WHAT("a park while a hit is pending (pend_rec_q)")) u_check_park (
        .clk_i, .rst_ni, .copy_i(1'b0), .orig_i(ce && w_park && pend_q));
    // a record goes out from the park exactly when p_out says so
    csgrt_check_same #(.WHAT("the parked record's choice (rec_pend against p_out)")) u_check_rec_pend (
        .clk_i, .rst_ni, .copy_i(1'b0), .orig_i(ce && res && (rec_pend != p_out)));
    // Without the look-ahead, whether a record goes out in one expression
    // with the pending hit as the last select. From the definitions above
    // (the walk's tokens are live only without a pending hit):
    //   w_out && !w_park = live && (X && grp_found || t_last),
    //   X && grp_found   = X && (!t_later || gf_found_q || pb_surf_q),
    //   p_out            = obs && (pb_surf_q || !t_later || t_last),
    // with X = !t_skip && border, the token's crossing test. Written
    // through res, the skid's valid hung on `live` (130 loads) and then
    // three more LUT levels, and on through the skid's next ready into
    // ctl_ready_q (tools/logic_depth.py 13.42 ns, the walker's longest).
    // It reads pend_q through a copy of its own (pend_res_q): with pend_q
    // itself, abc shared the expression's first level with `live` again
    // (a LUT of 134 loads) and the path stayed as long.
    wire res_skid;
    generate
        if (LA != 0) begin : g_res_la
            assign res_skid = res;
        end else begin : g_res_walk
            reg pend_res_q;
            // (* keep *): the copy has pend_q's input, and yosys would
            // merge the two flip-flops again (opt_merge)
            (* keep *) always @(posedge clk_i) begin
                if (!rst_ni) pend_res_q <= 1'b0;
                else if (ce) pend_res_q <= pend_d;
            end
            csgrt_check_same #(.WHAT("pend_res_q (pend_q's copy)")) u_check_pend_res (
                .clk_i, .rst_ni, .copy_i(pend_res_q), .orig_i(pend_q));
            assign res_skid = live_tok && !t_probe &&
                              (t_last || (pend_res_q ? (pb_surf_q || !t_later)
                                                     : (!t_skip && border && (!t_later || gf_found_q || pb_surf_q))));
        end
    endgenerate
    csgrt_check_same #(.WHAT("the record's valid in one expression (res_skid against res)")) u_check_res (
        .clk_i, .rst_ni, .copy_i(res_skid), .orig_i(res));
    csgrt_skid #(.WIDTH(OW)) u_out (
        .clk_i(clk_i), .rst_ni(rst_ni),
        .valid_i(res_skid), .ready_o(sk_ready), .ready_next_o(sk_ready_next), .data_i(rec),
        .valid_o(valid_o), .ready_i(ready_i), .data_o(rec_o));
    assign {hit_o, t_o, leaf_o, slot_o, entering_o, from_o, to_o, flags_before_o, payload_o} = rec_o[BOW-1:0];

    // ---- secondary rays: the look-behind run, flags after the hit ----------
    genvar g;
    generate
        if (SECONDARY != 0) begin : g_sec
            // the ray's last LBK valid tokens, most recent at entry 0. A
            // token's crossing waits a clock in a pending entry (pv_q)
            // before it is shifted in, so that the history's shift is
            // enabled by a register: whether a token crosses (toggle)
            // comes from the flag at its slot, a 128-to-1 choice, too late
            // in the clock to enable LBK * (H + 1 + TW) flip-flops (the
            // walker's critical path out of context). The history as seen
            // (eff_*) puts the pending entry in front.
            reg [LBK*H-1:0]  hs_q;
            reg [LBK-1:0]    he_q;
            reg [LBK*TW-1:0] ht_q;
            reg              pv_q;             // the last token crossed: ps, pe, pt not yet shifted in
            reg [H-1:0]      ps_q;
            reg              pe_q;
            reg [TW-1:0]     pt_q;
            wire [LBK*H-1:0]  eff_s;
            wire [LBK-1:0]    eff_e;
            wire [LBK*TW-1:0] eff_t;
            // The count as seen (pending entry included) and its thermometer
            // code (held_q[g]: entry g holds a token) are registers of their
            // own, loaded a clock ahead of the history, on the crossing
            // (issue && toggle, pv_q's next value) itself: as the pending
            // count plus pv_q, compared per entry, they were the first three
            // LUT levels of the walker's longest path (pv_q -> the run ->
            // the tree's tag register, tools/logic_depth.py 12.35 ns). A
            // crossing on the clock of a load is discarded, as pv_q's is.
            reg [CB-1:0]      ec_q;            // entries held, 0 .. LBK
            reg [LBK-1:0]     held_q;
            wire [CB-1:0]     eff_c = ec_q;
            always @(posedge clk_i) begin
                if (!rst_ni || (ce && load)) begin
                    ec_q   <= {CB{1'b0}};
                    held_q <= {LBK{1'b0}};
                end else if (ce && issue && toggle) begin
                    if ({{(32-CB){1'b0}}, ec_q} != LBK) ec_q <= ec_q + 1'b1;
                    held_q <= ~(~held_q << 1);   // one more entry held
                end
            end
`ifndef SYNTHESIS
            // the count as it was kept before: the history's count (hc_q)
            // plus the pending entry; the registers above must equal it
            reg [CB-1:0] hc_q;
            always @(posedge clk_i) begin
                if (ce && pv_q) hc_q <= eff_c;
                if ((ce && load) || !rst_ni) hc_q <= {CB{1'b0}};
            end
            wire [CB-1:0] hc_eff = (pv_q && {{(32-CB){1'b0}}, hc_q} != LBK) ? hc_q + 1'b1 : hc_q;
            wire [LBK-1:0] held_ref;
            for (g = 0; g < LBK; g = g + 1) begin : g_held_ref
                assign held_ref[g] = {{(32-CB){1'b0}}, hc_eff} > g;
            end
            csgrt_check_same #(.WIDTH(CB + LBK), .WHAT("the look-behind count and its thermometer code (ec_q, held_q)")) u_check_count (
                .clk_i, .rst_ni, .copy_i({ec_q, held_q}), .orig_i({hc_eff, held_ref}));
`endif
            if (LBK == 1) begin : g_eff_one
                assign eff_s = pv_q ? ps_q : hs_q;
                assign eff_e = pv_q ? pe_q : he_q;
                assign eff_t = pv_q ? pt_q : ht_q;
            end else begin : g_eff
                assign eff_s = pv_q ? {hs_q[0 +: (LBK-1)*H], ps_q} : hs_q;
                assign eff_e = pv_q ? {he_q[0 +: LBK-1], pe_q} : he_q;
                assign eff_t = pv_q ? {ht_q[0 +: (LBK-1)*TW], pt_q} : ht_q;
            end
            // the run of the token being issued: the history, same_t against its t
            wire [LBK*H-1:0] run_slot;
            wire [LBK-1:0]   run_ent, run_same;
            // same_t of the pending entry (same_at[0]) and of history entry
            // g (same_at[g + 1]): entry g as seen is history entry g, or the
            // one before it behind a pending entry, so pv_q chooses between
            // two compares of registers with ev_t_i after them, instead of
            // choosing each compare's TW-bit operand first
            wire [LBK:0] same_at;
            assign same_at[0] = pt_q == ev_t_i;
            for (g = 0; g < LBK; g = g + 1) begin : g_same
                assign same_at[g + 1] = ht_q[g*TW +: TW] == ev_t_i;
            end
            for (g = 0; g < LBK; g = g + 1) begin : g_run
                assign run_slot[g*H +: H] = held_q[g] ? eff_s[g*H +: H] : {H{1'b0}};
                assign run_ent[g]         = held_q[g] && eff_e[g];
                assign run_same[g]        = held_q[g] && (pv_q ? same_at[g] : same_at[g + 1]);
            end
            wire [RW-1:0] run_now = {eff_c, run_slot, run_ent, run_same};
            // a later member of a tie group carries the run as it stood
            // before the group (the crossings of the group are undone
            // whole, by flags_near)
            reg  [RW-1:0] grun_q;
            assign tag_in = {later ? grun_q : run_now, tag_base};
            // loaded on every clock whose head is not a later member of a
            // group, as gfl_q is (above), so its enable is no longer behind
            // the probe and issue decisions; a simulation check compares it
            // at every later member's issue with a copy loaded as before
            always @(posedge clk_i)
                if (ce && !later) grun_q <= run_now;
`ifndef SYNTHESIS
            reg  [RW-1:0] grun_ref_q;
            always @(posedge clk_i)
                if (ce && issue && !probe && !later) grun_ref_q <= run_now;
            csgrt_check_same #(.WIDTH(RW), .WHAT("grun_q (the run before a tie group) at a later member")) u_check_grun (
                .clk_i, .rst_ni, .copy_i(issue && later ? grun_q : {RW{1'b0}}),
                .orig_i(issue && later ? grun_ref_q : {RW{1'b0}}));
`endif
            wire [NS-1:0] slot_bit = {{(NS-1){1'b0}}, 1'b1} << t_slot;
            wire [NS-1:0] fa_hit   = flags_before ^ slot_bit;   // after the hit's own crossing
            always @(posedge clk_i) begin
                if (ce) begin
                    // the pending crossing goes into the history
                    if (pv_q) begin
                        hs_q <= eff_s;
                        he_q <= eff_e;
                        ht_q <= eff_t;
                    end
                    // this clock's token: its fields always (an enable from
                    // registers), whether it crossed as data
                    pv_q <= issue && toggle;
                    if (crossing) begin
                        ps_q <= ev_slot_i;
                        pe_q <= ev_entering_i;
                        pt_q <= ev_t_i;
                    end
                end
                if ((ce && load) || !rst_ni) pv_q <= 1'b0;
            end
            // the hit token's run (misses: 0) rides in the record
            wire [RW-1:0] lb_run = rec_hit ? tg[GW-1:BGW] : {RW{1'b0}};
            if (LA != 0) begin : g_la
                // ---- the look-ahead run ----------------------------------------
                // a run is open; every live token while it is belongs to
                // the run's ray (results come out in ray order)
                reg               la_act_q;
                reg  [TW-1:0]     la_t_q;          // the hit's t
                reg  [MB-1:0]     la_from_q, la_to_q;
                reg  [LB-1:0]     la_leaf_q;
                reg  [H-1:0]      la_slot_q;
                reg               la_ent_q;
                reg  [NS-1:0]     la_fb_q;         // flags_before of the hit
                reg  [PAYLOAD_WIDTH-1:0] la_pl_q;
                reg  [RW-1:0]     la_run_q;        // the hit's look-behind run
                reg               q_sent_q;        // the query for the token at the output is out
                reg               ans_q, beyond_q; // its answer
                // the token at the tree's output, examined by the open run
                wire              run_tok   = la_act_q && live;
                wire              same_t    = t_t == la_t_q;
                // the hit leaf's own later events join only at the same t:
                // the hit point lies on its surface (no query for them)
                wire              own_leaf  = t_leaf == la_leaf_q;
                wire              need_q    = run_tok && !same_t && !own_leaf && !ans_q;
                wire              decided   = run_tok && !need_q;
                wire              member    = same_t || (!own_leaf && beyond_q);
                wire              m_border  = !t_skip && border;
                wire [MB-1:0]     new_to    = (member && m_border) ? c_to : la_to_q;
                wire              end_after = decided && member && (t_last || !mat_clear_i[new_to]);
                wire              end_before= decided && !member;
                wire              run_end   = end_after || end_before;
                wire              cancel    = run_end && new_to == la_from_q;   // back to a1: discarded
                wire              run_out   = run_end && !cancel;
                // the token is walked as usual: no run open, or a run
                // discarded just before it
                wire              normal    = live && (!la_act_q || (end_before && cancel));
                wire              start     = normal && res_hit && mat_clear_i[c_to] && !t_last;
                wire              out_hit   = normal && res_hit && !start;
                wire              out_miss  = (normal && res_miss) || (end_after && cancel && t_last);
                // the hit's surface over the run: its group ends at a later t
                reg               hg_found_q;      // the hit's group has its surface (hg_leaf_q)
                reg  [LB-1:0]     hg_leaf_q;
                wire              x_surf    = run_tok && same_t && pb_surf_q;   // a later member
                wire              found_now = hg_found_q || x_surf;
                wire [LB-1:0]     found_leaf= hg_found_q ? hg_leaf_q : t_leaf;
                wire              run_dec   = !same_t || found_now || t_last;
                assign w_out    = run_out || out_hit || out_miss;
                assign w_hit    = run_out || out_hit;
                assign w_dec    = run_out ? run_dec : (grp_found || t_last);
                assign w_sleaf  = run_out ? (found_now ? found_leaf : la_leaf_q) : grp_leaf;
                assign la_stall = need_q;
                // flags after the run: before the token that ends it, or
                // after the member that ends it
                wire [NS-1:0]     fa_run    = end_after && !t_skip ? flags_before ^ slot_bit : flags_before;
                assign w_rec = run_out ? {fa_run, la_run_q, 1'b1, la_t_q, la_leaf_q, la_slot_q, la_ent_q, la_from_q,
                                          new_to, la_fb_q, la_pl_q}
                                       : {out_hit ? fa_hit : {NS{1'b0}}, lb_run, rec_base};
                assign flags_after_o = rec_o[OW-1 -: NS];
                assign q_valid_o   = need_q && !q_sent_q;
                assign q_t_o       = la_t_q;
                assign q_leaf_o    = t_leaf;
                assign q_payload_o = la_pl_q;
                assign a_ready_o   = q_sent_q;
                always @(posedge clk_i) begin
                    if (!rst_ni) begin
                        la_act_q <= 1'b0;
                        q_sent_q <= 1'b0;
                        ans_q    <= 1'b0;
                    end else begin
                        if (q_valid_o && q_ready_i) q_sent_q <= 1'b1;
                        if (a_valid_i && a_ready_o) begin
                            q_sent_q <= 1'b0;
                            ans_q    <= 1'b1;
                            beyond_q <= t_ent ? a_nonpos_i : !a_nonpos_i;
                        end
                        if (ce) begin
                            ans_q <= 1'b0;
                            if (run_end) la_act_q <= 1'b0;
                            else if (decided) la_to_q <= new_to;
                            if (decided && x_surf && !hg_found_q) begin
                                hg_found_q <= 1'b1;
                                hg_leaf_q  <= t_leaf;
                            end
                            if (start) begin
                                la_act_q  <= 1'b1;
                                la_t_q    <= t_t;
                                la_from_q <= c_from;
                                la_to_q   <= c_to;
                                la_leaf_q <= t_leaf;
                                la_slot_q <= t_slot;
                                la_ent_q  <= t_ent;
                                la_fb_q   <= flags_near;
                                la_pl_q   <= t_pl;
                                la_run_q  <= lb_run;
                                hg_found_q <= grp_found;
                                hg_leaf_q  <= grp_leaf;
                            end
                        end
                    end
                end
            end else begin : g_no_la
                assign w_out    = res_hit || res_miss;
                assign w_hit    = res_hit;
                assign w_dec    = grp_found || t_last;
                assign w_sleaf  = grp_leaf;
                assign la_stall = 1'b0;
                assign w_rec = {rec_hit ? fa_hit : {NS{1'b0}}, lb_run, rec_base};
                assign flags_after_o = rec_o[OW-1 -: NS];
                assign q_valid_o   = 1'b0;
                assign q_t_o       = {TW{1'b0}};
                assign q_leaf_o    = {LB{1'b0}};
                assign q_payload_o = {PAYLOAD_WIDTH{1'b0}};
                assign a_ready_o   = 1'b0;
                wire unused_la = ^{mat_clear_i, q_ready_i, a_valid_i, a_nonpos_i};
            end
            assign {lb_count_o, lb_slot_o, lb_entering_o, lb_same_t_o} = rec_o[BOW +: RW];
        end else begin : g_pri
            assign tag_in        = tag_base;
            assign w_rec         = rec_base;
            assign w_out         = res_hit || res_miss;
            assign w_hit         = res_hit;
            assign w_dec         = grp_found || t_last;
            assign w_sleaf       = grp_leaf;
            assign la_stall      = 1'b0;
            assign q_valid_o     = 1'b0;
            assign q_t_o         = {TW{1'b0}};
            assign q_leaf_o      = {LB{1'b0}};
            assign q_payload_o   = {PAYLOAD_WIDTH{1'b0}};
            assign a_ready_o     = 1'b0;
            wire unused_la = ^{mat_clear_i, q_ready_i, a_valid_i, a_nonpos_i};
            assign flags_after_o = {NS{1'b0}};
            assign lb_count_o    = {CB{1'b0}};
            assign lb_slot_o     = {(LBK*H){1'b0}};
            assign lb_entering_o = {LBK{1'b0}};
            assign lb_same_t_o   = {LBK{1'b0}};
        end
    endgenerate

    generate
        if (H < 2 || LOOK_BEHIND < 1 || (LOOK_AHEAD != 0 && SECONDARY == 0)) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_walker needs TREE_HEIGHT >= 2, LOOK_BEHIND >= 1, SECONDARY = 1 for LOOK_AHEAD");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
