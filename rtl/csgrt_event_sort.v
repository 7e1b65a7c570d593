`default_nettype none
// csgrt_event_sort — collects one ray's leaf results (csgrt_isect) and sorts
// the events ahead of the origin; computes the origin flags. Matches the
// primary-ray branch of trace_generic() in model/trace.cpp (with SECONDARY
// = 1 also its secondary-ray branch, see below) and the key of
// event_before() (docs/numerics.md section 4).
//
// Per leaf result (one transaction, valid/ready):
//   origin flag of the slot = inside_i toggled once per event behind
//     (range NegInf, or Finite with t < 0);
//   events ahead (Finite, t >= 0) go into the fill bank, sorted by the key
//     {t, tie}, LB = LEAF_BITS:
//       paper   (ties_regular_i = 0): tie = {0, leaf}
//       regular (ties_regular_i = 1): tie = entering ? {0, ~leaf} : {1, leaf}
//     e.g. LB = 6, t equal: regular orders entering leaf 9 (tie 0_110110)
//     before entering leaf 2 (0_111101) before leaving leaf 2 (1_000010).
//   PosInf events and events past count_i are dropped.
//   Slots not written by any leaf of the ray have flag 0.
//
// Each event is stored with its key already encoded ({t, tie} above, then
// slot and entering): the tie policy enters at the input stage only, and
// the cells' comparators compare stored words without it (it is static
// during a frame; fanned out to every cell's comparator it was the routed
// BITS 20 build's critical path). The leaf is decoded from the tie field
// at the drain bank's head: leaf = ~tie[LB-1:0] for an entering event
// under the regular policy, tie[LB-1:0] otherwise.
//
// Insertion: the fill bank is a sorted array of MAX_EVENTS cells; an input
// stage sorts the leaf's (up to) two ahead events into a pair a < b.
//   INSERTS = 2: every cell compares its word with a and with b (two
//     comparators per cell) and picks its next word from itself, a, its
//     left neighbour, b or the cell two to its left: both events are
//     inserted in one clock.
//   INSERTS = 1: every cell compares its word with a alone and picks
//     itself, a or its left neighbour (one comparator and a 3-way choice
//     per cell: about a third less logic); a leaf with two events ahead
//     stays in the input stage for a second clock, b moved into a's place,
//     and the input is not ready in that clock. The same events in the
//     same order: only the timing differs.
//
// Double buffering: when the fill bank holds a complete ray (its last leaf
// inserted) and the drain bank is free, the fill bank moves to the drain
// bank in one clock, and the next ray's first leaf may go into the emptied
// fill bank in that same clock. The drain bank is a shift register: the
// walker sees the ray (flags, payload, event count) and the smallest event,
// pops events one per clock and releases the ray with ray_done_i (it may do
// so before popping them all). While the fill bank holds a complete ray and
// the drain bank is busy, the input stage fills and then ready_o goes low.
//
// Secondary rays (SECONDARY = 1; with SECONDARY = 0 none of this is built:
// info_ready_o is 0, the info_* inputs and cpos_i are ignored). Every ray,
// primary or secondary, comes with one record on the info stream
// (info_valid_i / info_ready_o, valid/ready). The record is read with each
// leaf result of its ray: ready_o is low while info_valid_i is low (so the
// record must be valid when the ray's first leaf is accepted, else the
// input stalls), and the record is popped with the ray's last leaf:
// info_ready_o = valid_i && ready_o && last_i. Fields:
//   info_secondary_i  0: a primary ray, handled exactly as with
//                     SECONDARY = 0 (the other fields are ignored);
//                     1: a secondary ray (trace_secondary_fx()):
//   info_flags_i      inherited flag per slot: the origin flag of a slot is
//                     info_flags_i[slot] (taken with the slot's leaf result;
//                     a slot without a leaf result is 0 as for primary
//                     rays); events behind the origin are ignored;
//   info_tlimit_i     t limit, unsigned t-ahead format (F+1 bits, the t
//                     of an event ahead): an event ahead is kept only if
//                     info_tlimit_i == 0 (no limit) or t < info_tlimit_i
//                     (a limit of 2 or more is given as 0);
//   info_lb_count_i,  the look-behind run of the parent's hit (csgrt_walker's
//   info_lb_slot_i,   lb_*_o, entry 0 the most recent crossing before the
//   info_lb_entering_i, hit, entry k at [k*TREE_HEIGHT +: TREE_HEIGHT] and
//   info_lb_same_t_i  bit k; count 0..LOOK_BEHIND, entries past it ignored).
// cpos_i (per leaf result): c > 0, the leaf's quadric is positive at the
// ray's origin (csgrt_isect's c_o > 0). Once the ray's last leaf is in, the
// origin flags get the look-behind fix-up (as they pass to the drain
// bank): entry k is undone iff k < count,
// entries 0 .. k-1 are undone, and same_t[k] or the origin does not lie
// beyond its surface, beyond[k] = entering[k] ? !cpos : cpos of the leaf
// result in slot lb_slot[k] (0 if the ray has none); undoing sets
// flag[lb_slot[k]] = !entering[k], the older entry winning when a slot
// appears twice. For a child ray starting at its parent's hit point this
// turns the parent's flags just before the hit crossing (csgrt_walker's
// flags_before_o) into the model's TraceResult::flags_before (near side
// with the look-behind), since c at the child's origin is quadric_at_fx()
// at the hit point.
//
// ev_same_t_o: the head event's t equals the t of the event popped before
// it in the same ray (0 for a ray's first event): a register, set with
// each pop from the head and the next event (head_q, second_q), so the
// walker's tie-group decision (csgrt_walker's `later`) needs no t
// comparator on its way to ev_pop_i.
//
// ev_next_slot_o: the slot of the event after the head (second_q; don't
// care when the head is the ray's last), the head's slot after a pop. The
// walker reads its flag banks there a clock ahead (csgrt_walker's fh_q).
// ev_next_same_t_o: the next event's t equals the head's, ev_same_t_o after
// a pop (the walker's probe_q).
//
// Latency: a leaf result accepted at edge k is in the pre-stage after edge
// k, in the input stage after k+1 and in the fill bank after edge k+2; a
// ray whose last leaf is accepted at edge k is on the drain side
// (ray_valid_o) after edge k+3 if the drain bank is free. The same with
// SECONDARY = 1.
// Throughput: one leaf result (up to two events) per clock with INSERTS =
// 2, no bubble between rays while the walker keeps up; with INSERTS = 1 one
// event per clock (a leaf with two events ahead takes two clocks). ready_o
// is a function of registers only (with SECONDARY = 1: of registers and
// info_valid_i).
module csgrt_event_sort #(
    parameter BITS          = 24,   // coordinate width B; t is F+2 = B-1 bits
    parameter MAX_LEAVES    = 64,   // leaves per ray (events: 2*MAX_LEAVES)
    parameter LEAF_BITS     = 6,    // leaf index width (2^LEAF_BITS >= MAX_LEAVES)
    parameter TREE_HEIGHT   = 8,    // slot index width; 2^TREE_HEIGHT origin flags
    parameter PAYLOAD_WIDTH = 1,    // per-ray sideband (>= 1)
    parameter SECONDARY     = 0,    // 1: info stream, secondary rays (see above)
    parameter LOOK_BEHIND   = 4,    // look-behind entries (kLookBehind), >= 1
    parameter INSERTS       = 1     // events inserted per clock: 1 or 2 (see above)
) (
    input  wire                     clk_i,
    input  wire                     rst_ni,           // synchronous, active low
    input  wire                     ties_regular_i,   // tie policy (static during a ray)
    // leaf results
    input  wire                     valid_i,
    output wire                     ready_o,
    input  wire [TREE_HEIGHT-1:0]   slot_i,
    input  wire [LEAF_BITS-1:0]     leaf_i,
    input  wire [1:0]               count_i,
    input  wire [BITS-2:0]          t0_i,
    input  wire [1:0]               range0_i,
    input  wire                     enter0_i,
    input  wire [BITS-2:0]          t1_i,
    input  wire [1:0]               range1_i,
    input  wire                     enter1_i,
    input  wire                     inside_i,         // inside at t = -infinity
    input  wire                     last_i,           // the ray's last leaf
    input  wire [PAYLOAD_WIDTH-1:0] payload_i,        // taken from the last leaf
    input  wire                     cpos_i,           // c > 0 at the origin (SECONDARY)
    // per-ray info (SECONDARY; one record per ray, popped with its last leaf)
    input  wire                     info_valid_i,
    output wire                     info_ready_o,
    input  wire                     info_secondary_i,
    input  wire [(1<<TREE_HEIGHT)-1:0]          info_flags_i,
    input  wire [BITS-3:0]                      info_tlimit_i,
    input  wire [$clog2(LOOK_BEHIND+1)-1:0]     info_lb_count_i,
    input  wire [LOOK_BEHIND*TREE_HEIGHT-1:0]   info_lb_slot_i,
    input  wire [LOOK_BEHIND-1:0]               info_lb_entering_i,
    input  wire [LOOK_BEHIND-1:0]               info_lb_same_t_i,
    // sorted ray (drain bank)
    output wire                     ray_valid_o,      // a ray is on the drain side
    output wire [(1<<TREE_HEIGHT)-1:0] ray_flags_o,   // origin flag per slot
    output wire [PAYLOAD_WIDTH-1:0] ray_payload_o,
    input  wire                     ray_done_i,       // release the ray (drops unpopped events)
    output wire                     ev_valid_o,       // an event is left
    output wire                     ev_last_o,        // it is the ray's last
    output wire [BITS-2:0]          ev_t_o,
    output wire [LEAF_BITS-1:0]     ev_leaf_o,
    output wire [TREE_HEIGHT-1:0]   ev_slot_o,
    output wire                     ev_entering_o,
    output wire                     ev_same_t_o,      // its t equals the ray's previously popped event's
    output wire [TREE_HEIGHT-1:0]   ev_next_slot_o,   // the next event's slot (the head's after a pop)
    output wire [TREE_HEIGHT-1:0]   ev_slot_tree_o,   // ev_slot_o from a copy of its own, for the walker's class tree
    output wire                     ev_next_same_t_o, // the next event's t equals the head's (same_t_q after a pop)
    input  wire                     ev_pop_i
);

    localparam TW = BITS - 1;                  // t width, F+2
    localparam UW = TW - 1;                    // t of an event ahead (t >= 0)
    localparam LB = LEAF_BITS;
    localparam H  = TREE_HEIGHT;
    localparam NS = 1 << H;
    localparam N  = 2 * MAX_LEAVES;            // MAX_EVENTS
    localparam HH = H / 2;                     // a slot's high half (0 bits when H = 1)
    localparam HL = H - HH;                    // its low half
    localparam NLO = 1 << HL;                  // one-hot codes of the halves (onehot_lo, onehot_hi)
    localparam NHI = 1 << HH;
    localparam NB = $clog2(N + 1);             // event count width
    localparam KW = UW + LB + 1;               // key {t, tie}
    localparam DW = KW + H + 1;                // stored event {key, slot, entering}
    localparam [1:0] R_NEGINF = 2'd0, R_FINITE = 2'd1;

    // the tie field of an event's key under the policy
    function [LB:0] tie_of(input [LB-1:0] leaf, input ent, input reg_ties);
        begin
            if (!reg_ties) tie_of = {1'b0, leaf};
            else if (ent)  tie_of = {1'b0, ~leaf};
            else           tie_of = {1'b1, leaf};
        end
    endfunction
    // the key of a stored event: its top KW bits (the slot is not part of it)
    `define CSGRT_KEY(e) e[DW-1 -: KW]

    // ---- pre-stage: behind / ahead, origin flag, the pair's order --------
    // A leaf result is taken into the pre-stage (p_*) and its tests are
    // worked out there: which events lie ahead, their order (swap), how
    // many the t limit keeps, the slot's origin flag. The input stage
    // (s1_*) then loads the pair already decided, one choice per bit.
    // Computed in the clock that loads s1_a_q, the tests (the count, the
    // ranges, the t compare, then the pair's choice over 2 x DW bits) were
    // the longest paths of aaa564b's 24-bit netlist after the class tree's
    // (tools/logic_depth.py 11.81 ns, 6 LUT levels, count_i -> s1_a_q).
    wire p_fire = valid_i && ready_o;      // a leaf result into the pre-stage
    wire in_fire;                          // the pre-stage's leaf into the input stage
    wire ev0 = count_i != 2'd0;
    wire ev1 = count_i == 2'd2;
    wire keep0, keep1;                     // within the t limit (secondary rays)
    // ahead of the origin (Finite, t >= 0), the t limit aside: the pair is
    // ordered among these, and the limit only counts how many of a, b go
    // in (s1_n_q). The limit keeps an event iff t < limit, so it keeps the
    // smaller t whenever it keeps the larger: of the pair a < b it keeps
    // both, a alone or neither (u_check_keep), and a, b need not wait for
    // the limit's compare, whose limit comes through the info queue's
    // read multiplexer (the whole design's longest path, tools/logic_depth.py)
    wire ahead0  = ev0 && range0_i == R_FINITE && !t0_i[TW-1];
    wire ahead1  = ev1 && range1_i == R_FINITE && !t1_i[TW-1];
    wire behind0 = ev0 && (range0_i == R_NEGINF || (range0_i == R_FINITE && t0_i[TW-1]));
    wire behind1 = ev1 && (range1_i == R_NEGINF || (range1_i == R_FINITE && t1_i[TW-1]));
    wire [DW-1:0] e0 = {t0_i[UW-1:0], tie_of(leaf_i, enter0_i, ties_regular_i), slot_i, enter0_i};
    wire [DW-1:0] e1 = {t1_i[UW-1:0], tie_of(leaf_i, enter1_i, ties_regular_i), slot_i, enter1_i};
    // The pair's order from t alone: a leaf's two events ahead never share
    // a t (csgrt_isect drops such a pair, as the model's drop_equal_pair():
    // two crossings of one surface at one t cross nothing), and both carry
    // the same leaf, so the tie field cannot decide. The full key compare
    // had the tie policy in front of it (the module's longest path out of
    // context); u_check_swap stops a simulation in which the two differ.
    wire          swap = ahead0 && ahead1 && (t1_i[UW-1:0] < t0_i[UW-1:0]);

    reg                     s1_valid_q;
    reg [1:0]               s1_n_q;        // events ahead: 0, 1 (a) or 2 (a < b)
    wire [DW-1:0]           s1_a_q;        // the first group's copy (s1_ag, below)
    reg [DW-1:0]            s1_b_q;
    reg [NLO-1:0]           s1_slo_q;      // the slot's low and high halves, one-hot (onehot_lo, onehot_hi)
    reg [NHI-1:0]           s1_shi_q;
    reg                     s1_flag_q, s1_last_q;
    reg [PAYLOAD_WIDTH-1:0] s1_pay_q;

    // ---- banks ------------------------------------------------------------
    // The banks are cells of one DW-bit word each, not flat N x DW vectors:
    // each cell is a register of its own in g_cell (fill_q, drain_q), seen
    // by its neighbours through the wire arrays fill_w and drain_w, so that
    // the Verilator model writes each cell as a variable of its own (array
    // elements written one per always block each cost a delayed-assignment
    // flag and value per clock).
    wire [DW-1:0]           fill_w [0:N-1];   // sorted, cells 0 .. fcnt-1 valid
    reg [NB-1:0]            fcnt_q;
    reg [N-1:0]             occ_q;         // occ_q[j] = (j < fcnt_q): fcnt_q as a thermometer code
    reg                     full_q;        // fill bank holds a complete ray
    reg [NS-1:0]            fflags_q;
    reg [PAYLOAD_WIDTH-1:0] fpay_q;
    // sorted, cell 0 is the next event; entries N and N+1 are zero (past
    // the last cell: what the shift brings in, and the head's reads at the
    // owed shift's offset below)
    wire [DW-1:0]           drain_w [0:N+1];
    reg [NB-1:0]            dcnt_q;
    reg                     busy_q;        // drain bank holds a ray
    // dcnt_q's two tests as registers of their own, kept with the count:
    // dne_q = busy_q && dcnt_q != 0 (an event is left), dlast_q = dcnt_q == 1.
    // The walker's pop decision reads them, and the pop fans out to every
    // drain cell's enable: a zero test of the count in front of that (two
    // LUT levels) lay on the whole design's longest path (tools/logic_depth.py).
    reg                     dne_q;
    reg                     dlast_q;
    reg [NS-1:0]            dflags_q;
    reg [PAYLOAD_WIDTH-1:0] dpay_q;

    // handover = full_q && !busy_q, as a register of its own (loaded with
    // the next values of both): it selects every cell's next word (about
    // 5,000 loads), a net better started at a flip-flop than behind a LUT
    // (tools/logic_depth.py); a simulation stops if it differs
    reg  handover_q;
    wire handover = handover_q;
    // The cells read the handover from copies, one per group of HC_CELLS
    // cells (hov_q, below), loaded as handover_q is: as one register it
    // had 974 loads at 32 cells (each cell's occupancy, its drain word's
    // enable and choice), its net alone 4.4 ns of tools/logic_depth.py's
    // 11.40 into the fill cells' enables, and a net that spans the whole
    // bank on the die. Groups of 4 cells: with 8, a copy still had 427
    // loads, the first net of an 11.17 ns path on aaa564b's netlist.
    localparam HC_CELLS = 4;
    localparam NHC      = (N + HC_CELLS - 1) / HC_CELLS;
    wire [NHC-1:0] hov;
    // The cells read the event a from copies of s1_a_q too, one per group
    // of AC_CELLS cells (s1_ag, below), loaded as s1_a_q is: each key bit
    // of the one register went to 64 loads (every cell's comparator and
    // next-word choice), the first net of the bank's insertion paths, whose
    // 1,055 endpoints were over 10 ns on aaa564b's netlist (tools/
    // logic_depth.py 10.75 ns: a's key -> a cell's compare -> its enable).
    localparam AC_CELLS = 8;
    localparam NAC      = (N + AC_CELLS - 1) / AC_CELLS;
    wire [DW-1:0] s1_ag [0:NAC-1];
    // The input stage's tests as registers of their own, loaded with the
    // next values of what they test: fb_q = full_q && busy_q (the fill
    // bank holds a ray that cannot hand over), s1_two_q = s1_n_q == 2
    // (meaningful while s1_valid_q). The stage's ready is then one LUT of
    // flip-flops: from the state bits and the count it was two LUT levels
    // in front of the ready's 88 loads and the info queue's pop
    // (tools/logic_depth.py 11.45 ns on 9f2f1a7's netlist, the sorter's
    // s1_n_q -> ready -> the dispatcher's info queue head). Simulation
    // checks compare both with the tests.
    reg  fb_q;
    reg  s1_two_q;
    wire s1_adv   = s1_valid_q && !fb_q;                    // the stage inserts into the fill bank
    // INSERTS = 1, two events ahead: this clock inserts a, b stays (split)
    wire s1_split = (INSERTS == 1) && s1_two_q;
    wire s1_done  = s1_adv && !s1_split;                   // the leaf leaves the stage
    // The stage's ready itself is a register too (in_ready_q, loaded with
    // its next value below): as a LUT of fb_q, s1_two_q and s1_valid_q it
    // still took the info queue's valid as a fifth input, two LUT levels
    // in front of the ready's 88 loads and the info pop (tools/
    // logic_depth.py 11.27 ns on 0adc21f's netlist). A check compares it.
    reg  in_ready_q;
    wire in_ready = in_ready_q;
    wire flag_in;                          // the slot's origin flag

    // the pre-stage's registers: the leaf's two events as they came (the
    // tie field encoded), which of them are a and b, how many go in
    reg                     p_valid_q;
    reg [DW-1:0]            p_e0_q, p_e1_q;
    reg                     p_asel_q;      // a = e1 (else e0)
    reg                     p_bsel_q;      // b = e0 (else e1): the pair swapped
    reg [1:0]               p_n_q;         // events ahead within the limit: 0, 1 or 2 (bit 1: two)
    reg [NLO-1:0]           p_slo_q;
    reg [NHI-1:0]           p_shi_q;
    reg                     p_flag_q, p_last_q;
    reg [PAYLOAD_WIDTH-1:0] p_pay_q;
    assign in_fire = p_valid_q && in_ready;
    // ready_o (below): the pre-stage is empty or its leaf moves on in this
    // clock, a LUT of two registers (with SECONDARY and the info's valid)
    wire p_room = !p_valid_q || in_ready;
    // look-behind fix-up (SECONDARY), applied with the ray's handover: entry
    // e sets the flag of its slot to !fix_ent[e] iff fix_lo's and fix_hi's
    // one-hot halves of entry e both select the slot (see g_sec)
    wire                      fix_en;
    wire [LOOK_BEHIND*NLO-1:0] fix_lo;
    wire [LOOK_BEHIND*NHI-1:0] fix_hi;
    wire [LOOK_BEHIND-1:0]     fix_ent;
    // a slot's low and high halves as one-hot codes (the high half's is 1
    // when HH = 0)
    function [NLO-1:0] onehot_lo(input [H-1:0] slot);
        integer i;
        for (i = 0; i < NLO; i = i + 1) onehot_lo[i] = {{(32-H){1'b0}}, slot} % NLO == i;
    endfunction
    function [NHI-1:0] onehot_hi(input [H-1:0] slot);
        integer i;
        for (i = 0; i < NHI; i = i + 1) onehot_hi[i] = {{(32-H){1'b0}}, slot} / NLO == i;
    endfunction
    // The input stage's slot as a mask of the flags, from its one-hot
    // halves in registers: each flag's write condition is a 2-input AND.
    // Written as fflags_q[s1_slot_q] <= .. (or with the mask decoded from
    // a registered slot: the same), every flag's next value depended on the
    // slot's 7 bits, and yosys/abc mapped that per flag instead of through
    // one shared decoder: about 26 LUT4 per flag at H 7, with wide muxes
    // (PFUMX, L6MUX21). Registered halves: the bank's logic 3,367 -> 1,660
    // LUT4 out of context, with the fix-up below done the same way.
    wire [NS-1:0] s1_sel;
    wire [NS-1:0] base_flags = handover ? {NS{1'b0}} : fflags_q;
    genvar hs;
    generate
        for (hs = 0; hs < NHI; hs = hs + 1) begin : g_sel
            assign s1_sel[hs*NLO +: NLO] = s1_slo_q & {NLO{s1_shi_q[hs]}};
        end
    endgenerate

    // the pre-stage's loads (its declarations are above)
    always @(posedge clk_i) begin
        if (!rst_ni) p_valid_q <= 1'b0;
        else p_valid_q <= p_fire || (p_valid_q && !in_fire);
        if (p_fire) begin
            p_e0_q   <= e0;
            p_e1_q   <= e1;
            p_asel_q <= swap || !ahead0;
            p_bsel_q <= swap;
            p_n_q    <= {1'b0, ahead0 && keep0} + {1'b0, ahead1 && keep1};
            p_slo_q  <= onehot_lo(slot_i);
            p_shi_q  <= onehot_hi(slot_i);
            p_flag_q <= flag_in;
            p_last_q <= last_i;
            p_pay_q  <= payload_i;
        end
    end

    // the input stage's event a (s1_a_q) as copies, one per group of cells
    // (s1_ag), each in an always block of its own under (* keep *): yosys
    // merges flip-flops of the same input otherwise. A split leaf's b moves
    // into a; a leaf into the stage brings its a.
    genvar ag;
    generate
        for (ag = 0; ag < NAC; ag = ag + 1) begin : g_acopy
            reg [DW-1:0] ag_q;
            (* keep *) always @(posedge clk_i) begin
                if (s1_adv && s1_split) ag_q <= s1_b_q;
                if (in_fire)            ag_q <= p_asel_q ? p_e1_q : p_e0_q;
            end
            assign s1_ag[ag] = ag_q;
        end
        for (ag = 1; ag < NAC; ag = ag + 1) begin : g_acheck
            csgrt_check_same #(.WIDTH(DW), .WHAT("s1_ag (the cells' copies of s1_a_q)")) u_check_ag (
                .clk_i, .rst_ni, .copy_i(s1_valid_q ? s1_ag[ag] : {DW{1'b0}}), .orig_i(s1_valid_q ? s1_a_q : {DW{1'b0}}));
        end
    endgenerate
    assign s1_a_q = s1_ag[0];

    // ---- insertion into the fill bank (emptied on a handover) ------------
    // Each cell learns whether it holds an event from its own bit of occ_q
    // (with the handover), not from a compare of its index with the count:
    // that compare, fanned out to every cell, was the sorter's critical path
    // out of context (full_q -> base_cnt -> j < base_cnt -> the cell's
    // next word: 13.05 ns, tools/module_timing.py).
    wire [NB-1:0] base_cnt = handover ? {NB{1'b0}} : fcnt_q;
    wire [N-1:0]  base_occ = handover ? {N{1'b0}} : occ_q;
    wire [N+1:0]  occ_in1  = {1'b0, base_occ, 1'b1};    // one event more (bits N-1:0)
    wire [N+1:0]  occ_in2  = {base_occ, 2'b11};         // two more
    wire [KW-1:0] key_b = `CSGRT_KEY(s1_b_q);
    wire [N-1:0]  lt_a, lt_b;              // cell j holds an event before a / b
                                           // (a missing event counts as +infinity;
                                           // lt_b is unused with INSERTS = 1)
    wire pop;                              // the walker takes the drain bank's cell 0
    genvar j;
    generate
        for (j = 0; j < N; j = j + 1) begin : g_cell
            reg  [DW-1:0] fill_q, drain_q;
            wire [DW-1:0] cur  = fill_q;
            wire          hov_j = hov[j / HC_CELLS];    // handover, from the group's copy
            wire [DW-1:0] a_j   = s1_ag[j / AC_CELLS];  // the event a, from the group's copy
            wire          here = !hov_j && occ_q[j];    // base_occ[j]: j < base_cnt
            wire [KW-1:0] k    = `CSGRT_KEY(cur);
            wire [DW-1:0] ins;                 // the cell's next word
            assign lt_a[j] = here && (s1_n_q == 2'd0 || k < `CSGRT_KEY(a_j));   // no event: a = +inf
            // b: only the two-insertion array compares with it (with one,
            // a split leaf's b is the next clock's a)
            if (INSERTS == 1) begin : g_b_one
                assign lt_b[j] = 1'b1;
            end else begin : g_b_two
                assign lt_b[j] = here && (s1_n_q != 2'd2 || k < key_b);
            end
            if (j == 0) begin : g_first
                assign ins = lt_a[0] ? cur : a_j;
            end else if (INSERTS == 1) begin : g_one
                assign ins = lt_a[j]   ? cur :
                             lt_a[j-1] ? a_j :
                                         fill_w[j-1];
            end else if (j == 1) begin : g_second
                assign ins = lt_a[1] ? cur :
                             lt_a[0] ? a_j :
                             lt_b[0] ? fill_w[0] : s1_b_q;
            end else begin : g_rest
                assign ins = lt_a[j]   ? cur :
                             lt_a[j-1] ? a_j :
                             lt_b[j-1] ? fill_w[j-1] :
                             lt_b[j-2] ? s1_b_q :
                                         fill_w[j-2];
            end
            // the drain bank shifts towards cell 0 a clock after a pop
            // (pop_q, below)
            always @(posedge clk_i) begin
                if (s1_adv) fill_q <= ins;
                if (hov_j) drain_q <= fill_q;
                else if (pop_q) drain_q <= drain_w[j+1];
            end
            assign fill_w[j]  = fill_q;
            assign drain_w[j] = drain_q;
        end
    endgenerate
    assign drain_w[N]     = {DW{1'b0}};
    assign drain_w[N + 1] = {DW{1'b0}};

    // ---- drain bank ----------------------------------------------------------
    // The bank's cells shift a clock after the pop that takes their head
    // (pop_q): their enable is then a function of two registers (pop_q,
    // handover_q) and not of the walker's pop decision, which reached all
    // 128 x DW of them (some 4,600 loads, the end of the longest control
    // path through the walker, tools/logic_depth.py). The ray's events in
    // order are cells pop_q, pop_q + 1, ...; the head and the next event,
    // which the walker reads, are registers of their own (head_q,
    // second_q) loaded from the cells at that offset, so the pop reaches
    // only them. The walker sees the same values in the same clocks as
    // with the cells shifting on the pop itself. A pop and a handover never
    // meet (a pop needs the drain bank busy, a handover needs it free), and
    // a handover drops a shift still owed to the ray before.
    assign pop = ev_pop_i && dne_q;
    reg           pop_q;                   // the cells owe one shift
    reg  [DW-1:0] head_q, second_q;        // the ray's next event and the one after it
    wire [DW-1:0] after_second = pop_q ? drain_w[3] : drain_w[2];   // the event after second_q
    // (* keep *), as on head_slot_q's block below: with the keep on the
    // copy alone, yosys merged head_q's slot bits into the copy (opt_merge)
    (* keep *) always @(posedge clk_i) begin
        pop_q <= pop && rst_ni;
        if (handover) begin
            head_q   <= fill_w[0];
            second_q <= fill_w[1];
        end else if (pop) begin
            head_q   <= second_q;
            second_q <= after_second;
        end
    end
    assign ray_valid_o   = busy_q;
    assign ray_flags_o   = dflags_q;
    assign ray_payload_o = dpay_q;
    assign ev_valid_o    = dne_q;
    assign ev_last_o     = dlast_q;
    wire [DW-1:0] head   = head_q;
    assign ev_t_o        = {1'b0, head[DW-1 -: UW]};
    wire [LB-1:0] head_tie = head[H+1 +: LB];   // the tie field's leaf bits
    wire          unused_head_tie_top = head[H+1+LB];   // the order's, not the leaf's
    assign ev_leaf_o     = (ties_regular_i && head[0]) ? ~head_tie : head_tie;
    assign ev_slot_o     = head[1 +: H];
    assign ev_entering_o = head[0];
    // the head's t against the next cell's: the same-t bit after a pop
    reg  same_t_q;
    wire [DW-1:0] second = second_q;       // its t is compared, its slot read ahead
    wire [DW-UW-H-1:0] unused_second = {second[DW-UW-1:H+1], second[0]};
    wire next_same_t = second[DW-1 -: UW] == head[DW-1 -: UW];
    assign ev_next_slot_o = second[1 +: H];
    // The head's slot once more, from flip-flops of their own loaded as
    // head_q is, for the walker's class tree (its stage-0 reads by slot):
    // on head_q (319 loads) the placer kept the sorter's head far from the
    // tree, and 3599434's routed critical path ran from it across the die
    // (3.82 ns of route) into the tree's stage 0. (* keep *) on the always
    // block: yosys merges flip-flops of the same input otherwise.
    reg  [H-1:0] head_slot_q;
    (* keep *) always @(posedge clk_i) begin
        if (handover)  head_slot_q <= fill_w[0][1 +: H];
        else if (pop)  head_slot_q <= second_q[1 +: H];
    end
    assign ev_slot_tree_o = head_slot_q;
    csgrt_check_same #(.WIDTH(H), .WHAT("head_slot_q (the head's slot for the class tree)")) u_check_head_slot (
        .clk_i, .rst_ni, .copy_i(dne_q ? head_slot_q : {H{1'b0}}), .orig_i(dne_q ? head[1 +: H] : {H{1'b0}}));
    assign ev_next_same_t_o = next_same_t;
    assign ev_same_t_o = same_t_q;

    // ---- secondary rays: info stream, t limit, inherited flags, look-behind
    localparam LBK = LOOK_BEHIND;
    localparam CB  = $clog2(LOOK_BEHIND + 1);
    wire flag_primary = inside_i ^ behind0 ^ behind1;
    genvar k;
    generate
        if (SECONDARY != 0) begin : g_sec
            wire sec = info_secondary_i;
            wire lim = info_tlimit_i != {UW{1'b0}};
            assign ready_o      = p_room && info_valid_i;
            assign info_ready_o = valid_i && ready_o && last_i;   // popped with the last leaf
            assign keep0   = !sec || !lim || t0_i[UW-1:0] < info_tlimit_i;
            assign keep1   = !sec || !lim || t1_i[UW-1:0] < info_tlimit_i;
            assign flag_in = sec ? info_flags_i[slot_i] : flag_primary;

            // cpos of the leaf in each entry's slot, accumulated over the
            // ray's leaves (acc_q: those past the pre-stage so far; one leaf
            // per slot). The pre-stage holds the leaf's own part (p_cpk_q)
            // and the ray's look-behind entries with its last leaf (p_run_q
            // .. p_hi_q), read from the info record as the leaf comes in.
            reg  [LBK-1:0] acc_q;
            wire [LBK-1:0] cp;
            reg  [LBK-1:0] p_cpk_q, p_run_q, p_same_q, p_lbent_q;
            reg  [LBK*NLO-1:0] p_lo_q;
            reg  [LBK*NHI-1:0] p_hi_q;
            wire [LBK-1:0] cpk;                // the leaf's cpos in entry k's slot
            integer pe;
            for (k = 0; k < LBK; k = k + 1) begin : g_lb
                assign cpk[k] = cpos_i && slot_i == info_lb_slot_i[k*H +: H];
                assign cp[k]  = acc_q[k] || p_cpk_q[k];
            end
            always @(posedge clk_i) begin
                if (p_fire) p_cpk_q <= cpk;
                if (p_fire && last_i) begin
                    p_lbent_q <= info_lb_entering_i;
                    p_same_q  <= info_lb_same_t_i;
                    for (pe = 0; pe < LBK; pe = pe + 1) begin
                        p_run_q[pe]             <= sec && {{(32-CB){1'b0}}, info_lb_count_i} > pe;
                        p_lo_q[pe*NLO +: NLO] <= onehot_lo(info_lb_slot_i[pe*H +: H]);
                        p_hi_q[pe*NHI +: NHI] <= onehot_hi(info_lb_slot_i[pe*H +: H]);
                    end
                end
            end

            // The fix-up travels with the ray's last leaf through the input
            // stage, each entry's slot as two one-hot halves: a flag then
            // tests two register bits per entry instead of comparing the
            // entry's 7-bit slot (512 compares at H 7, mapped per flag as
            // the write above). Whether an entry is undone is worked out
            // in the stage, from the leaf's cpos accumulated into a
            // register (s1_cp_q) and the entry's fields: computed at the
            // input, the undone test (the leaf result's cpos, the slot
            // compare, the chain over the entries) lay between the
            // intersection unit's output register and the halves, the
            // routed critical path of b54f788 (docs/fpga.md).
            reg [LBK*NLO-1:0] s1_lo_q;
            reg [LBK*NHI-1:0] s1_hi_q;
            reg [LBK-1:0]     s1_cp_q, s1_run_q, s1_same_q, s1_lbent_q;
            always @(posedge clk_i) begin
                if (in_fire) acc_q <= p_last_q ? {LBK{1'b0}} : cp;
                if (in_fire && p_last_q) begin
                    s1_cp_q    <= cp;
                    s1_lbent_q <= p_lbent_q;
                    s1_same_q  <= p_same_q;
                    s1_run_q   <= p_run_q;
                    s1_lo_q    <= p_lo_q;
                    s1_hi_q    <= p_hi_q;
                end
                if (!rst_ni) acc_q <= {LBK{1'b0}};
            end
            // undone: in the run, and at the hit's t or the origin not
            // beyond the surface (entering: Q > 0, leaving: Q <= 0) ...
            wire [LBK-1:0] s1_uk = s1_run_q & (s1_same_q | ~(s1_lbent_q ^ s1_cp_q));
            wire [LBK-1:0] s1_und;
            for (k = 0; k < LBK; k = k + 1) begin : g_und
                assign s1_und[k] = &s1_uk[k:0];   // ... and every more recent entry too
            end
            // The fix-up is applied to the ray's flags as they pass to the
            // drain bank (its handover), not to the fill bank with the last
            // leaf: the stage's undone test then ends in registers (s2_*,
            // the undone bit folded into the low half), and the flags'
            // write tests two register bits per entry. With the test in
            // front of the fill bank's write, the entries' fields through
            // the test and the older-wins choice to every flag were the
            // sorter's longest path (tools/logic_depth.py 13.60 ns). The
            // handover comes at the earliest the clock after the last
            // leaf leaves the stage, and the next ray's last leaf leaves
            // it at the earliest in that same clock (the fill bank is
            // full until then), so s2_* hold the ray's fix-up until its
            // handover reads them (u_check_fix).
            reg [LBK*NLO-1:0] s2_lo_q;
            reg [LBK*NHI-1:0] s2_hi_q;
            reg [LBK-1:0]     s2_ent_q;
            reg               s2_any_q;       // some entry is undone (entry 0 is)
            integer           e2;
            always @(posedge clk_i) begin
                if (s1_done && s1_last_q) begin
                    for (e2 = 0; e2 < LBK; e2 = e2 + 1)
                        s2_lo_q[e2*NLO +: NLO] <= s1_lo_q[e2*NLO +: NLO] & {NLO{s1_und[e2]}};
                    s2_hi_q  <= s1_hi_q;
                    s2_ent_q <= s1_lbent_q;
                    s2_any_q <= s1_und[0];
                end
                if (!rst_ni) s2_any_q <= 1'b0;
            end
`ifndef SYNTHESIS
            // a ray's fix-up waits in s2_* from its last leaf to its
            // handover; the next ray's last leaf comes no earlier than that
            reg s2_wait_q = 1'b0;
            always @(posedge clk_i)
                if (!rst_ni) s2_wait_q <= 1'b0;
                else if (s1_done && s1_last_q) s2_wait_q <= 1'b1;
                else if (handover) s2_wait_q <= 1'b0;
            csgrt_check_same #(.WHAT("the look-behind fix-up held to the handover (s2_*)")) u_check_fix (
                .clk_i, .rst_ni, .copy_i(1'b0), .orig_i(s1_done && s1_last_q && s2_wait_q && !handover));
`endif
            // (the guard on an undone entry spares Verilator the loop over
            // the slots with every ray: a primary ray undoes nothing)
            assign fix_en  = handover && s2_any_q;
            assign fix_lo  = s2_lo_q;
            assign fix_hi  = s2_hi_q;
            assign fix_ent = s2_ent_q;
        end else begin : g_pri
            assign ready_o      = p_room;
            assign info_ready_o = 1'b0;
            assign keep0   = 1'b1;
            assign keep1   = 1'b1;
            assign flag_in = flag_primary;
            assign fix_en  = 1'b0;
            assign fix_lo  = {LOOK_BEHIND*NLO{1'b0}};
            assign fix_hi  = {LOOK_BEHIND*NHI{1'b0}};
            assign fix_ent = {LOOK_BEHIND{1'b0}};
            wire unused_sec = ^{cpos_i, info_valid_i, info_secondary_i, info_flags_i, info_tlimit_i,
                                info_lb_count_i, info_lb_slot_i, info_lb_entering_i, info_lb_same_t_i};
        end
    endgenerate

    // the fill bank's and the drain bank's next state, and the input
    // stage's (in_ready_q's next value)
    wire full_d = (s1_done && s1_last_q) || (full_q && !handover);
    wire busy_d = handover || (busy_q && !ray_done_i);
    wire s1_valid_d = in_fire || (s1_valid_q && !s1_done);
    wire s1_two_d   = in_fire ? p_n_q[1] : (s1_adv && s1_split) ? 1'b0 : s1_two_q;
    wire fb_d       = full_d && busy_d;
    // in_ready_q's next value, from private copies of the state it reads
    // (rc_*, each loaded as its original, in an always block of its own
    // under (* keep *)). From the originals it shared s1_adv (79 loads) and
    // s1_done && s1_last_q (54 loads) with the fill bank: three nets of
    // high fan-out in a row, tools/logic_depth.py's longest path on
    // 03fd3dc's netlist (11.64 ns: fb_q -> s1_adv -> full_d -> fb_d ->
    // in_ready_q). The same terms written again on the copies have one load
    // each. s1_two_q, s1_last_q and handover_q are read as they are: copies
    // of them have the same next value in the same form, and yosys merges
    // such a pair into one flip-flop whatever the (* keep *) (opt_merge
    // keeps the kept one and moves the other's loads onto it). A check
    // compares the copies with the originals, and u_check_in_ready the
    // ready with its definition.
    reg rc_valid_q, rc_fb_q, rc_full_q, rc_busy_q, rc_ready_q;
    wire rc_fire   = p_valid_q && rc_ready_q;
    wire rc_adv    = rc_valid_q && !rc_fb_q;
    wire rc_done   = rc_adv && !((INSERTS == 1) && s1_two_q);
    wire rc_full_d = (rc_done && s1_last_q) || (rc_full_q && !handover_q);
    wire rc_busy_d = handover_q || (rc_busy_q && !ray_done_i);
    wire rc_valid_d = rc_fire || (rc_valid_q && !rc_done);
    wire rc_two_d  = rc_fire ? p_n_q[1] : s1_two_q && !rc_adv;
    wire in_ready_d = !rst_ni || !rc_valid_d || (!(rc_full_d && rc_busy_d) && !((INSERTS == 1) && rc_two_d));
    // handover_q's and its copies' (hov) next value, full_q && !busy_q after
    // the edge, from the copies too: from full_d and busy_d it took the same
    // three high-fan-out nets (11.84 ns on 7ff7aef's netlist, once the ready
    // no longer did)
    wire handover_d = rst_ni && rc_full_d && !rc_busy_d;
    (* keep *) always @(posedge clk_i) begin
        rc_valid_q <= rst_ni && s1_valid_d;
        rc_fb_q    <= rst_ni && fb_d;
        rc_full_q  <= rst_ni && full_d;
        rc_busy_q  <= rst_ni && busy_d;
        rc_ready_q <= in_ready_d;
    end
    csgrt_check_same #(.WIDTH(5), .WHAT("rc_* (the ready's copies of the input stage's state)")) u_check_rc (
        .clk_i, .rst_ni,
        .copy_i({rc_valid_q, rc_fb_q, rc_full_q, rc_busy_q, rc_ready_q}),
        .orig_i({s1_valid_q, fb_q, full_q, busy_q, in_ready_q}));
    integer fs, fe;
    always @(posedge clk_i) begin
        // input stage
        s1_two_q <= s1_two_d;
        if (s1_adv && s1_split) begin   // a is in; b waits for the next clock (s1_ag: a <= b)
            s1_n_q <= 2'd1;
        end
        if (in_fire) begin
            s1_n_q    <= p_n_q;
            s1_b_q    <= p_bsel_q ? p_e0_q : p_e1_q;
            s1_slo_q  <= p_slo_q;
            s1_shi_q  <= p_shi_q;
            s1_flag_q <= p_flag_q;
            s1_last_q <= p_last_q;
            s1_pay_q  <= p_pay_q;
        end
        // fill bank
        if (handover) begin
            fcnt_q   <= {NB{1'b0}};
            occ_q    <= {N{1'b0}};
            fflags_q <= {NS{1'b0}};
        end
        if (s1_adv) begin
            fcnt_q   <= base_cnt + {{(NB-2){1'b0}}, s1_split ? 2'd1 : s1_n_q};
            // the thermometer code shifts in as many ones as events go in
            // (never more than N: a ray has at most 2 events per leaf)
            if (s1_split || s1_n_q == 2'd1) occ_q <= occ_in1[N-1:0];
            else if (s1_n_q == 2'd2)        occ_q <= occ_in2[N-1:0];
            else                            occ_q <= base_occ;
            fflags_q <= (base_flags & ~s1_sel) | (s1_sel & {NS{s1_flag_q}});
            if (s1_last_q) fpay_q <= s1_pay_q;
        end
        // drain bank
        if (handover) begin
            dcnt_q   <= fcnt_q;
            dlast_q  <= occ_q[0] && !occ_q[1];     // fcnt_q == 1 (occ_q: its thermometer code)
            dflags_q <= fflags_q;
            dpay_q   <= fpay_q;
            same_t_q <= 1'b0;
        end else if (pop) begin
            dcnt_q   <= dcnt_q - 1'b1;
            dlast_q  <= dcnt_q == {{(NB-2){1'b0}}, 2'd2};
            same_t_q <= next_same_t;
        end
        // the look-behind fix-up of a secondary ray, with its handover
        // (fix_en is constant zero when SECONDARY = 0): entry e undoes the
        // crossing in its slot; a later e is an older entry, and the older
        // one wins
        if (fix_en)
            for (fs = 0; fs < NS; fs = fs + 1)
                for (fe = 0; fe < LOOK_BEHIND; fe = fe + 1)
                    if (fix_lo[fe*NLO + fs % NLO] && fix_hi[fe*NHI + fs / NLO]) dflags_q[fs] <= !fix_ent[fe];
        // dne_q follows busy_q and dcnt_q: set by a handover with events,
        // cleared by the ray's release or by popping its last event
        if (handover)        dne_q <= occ_q[0];   // fcnt_q != 0
        else if (ray_done_i) dne_q <= 1'b0;
        else if (pop)        dne_q <= !dlast_q;
        if (!rst_ni) begin
            s1_valid_q <= 1'b0;
            full_q     <= 1'b0;
            busy_q     <= 1'b0;
            fb_q       <= 1'b0;
            dne_q      <= 1'b0;
            fcnt_q     <= {NB{1'b0}};
            occ_q      <= {N{1'b0}};
            fflags_q   <= {NS{1'b0}};
        end else begin
            if (in_fire) s1_valid_q <= 1'b1;
            else if (s1_done) s1_valid_q <= 1'b0;
            full_q <= full_d;
            busy_q <= busy_d;
            fb_q   <= fb_d;
        end
        in_ready_q <= in_ready_d;
        // the next full_q && !busy_q (both as set just above)
        handover_q <= handover_d;
    end
    csgrt_check_same #(.WHAT("handover_q")) u_check_handover (
        .clk_i, .rst_ni, .copy_i(handover_q), .orig_i(full_q && !busy_q));
    // the cells' copies, each in an always block of its own under
    // (* keep *): yosys merges flip-flops of the same input otherwise
    genvar hg;
    generate
        for (hg = 0; hg < NHC; hg = hg + 1) begin : g_hov
            reg hov_q;
            (* keep *) always @(posedge clk_i) hov_q <= handover_d;
            assign hov[hg] = hov_q;
        end
    endgenerate
    csgrt_check_same #(.WIDTH(NHC), .WHAT("hov (the cells' copies of handover_q)")) u_check_hov (
        .clk_i, .rst_ni, .copy_i(hov), .orig_i({NHC{handover_q}}));
    csgrt_check_same #(.WHAT("in_ready_q (the input stage's ready)")) u_check_in_ready (
        .clk_i, .rst_ni, .copy_i(in_ready_q), .orig_i(!s1_valid_q || (!fb_q && !s1_split)));
    csgrt_check_same #(.WIDTH(2), .WHAT("fb_q / s1_two_q (the input stage's tests)")) u_check_stage_tests (
        .clk_i, .rst_ni, .copy_i({fb_q, s1_valid_q && s1_two_q}),
        .orig_i({full_q && busy_q, s1_valid_q && s1_n_q == 2'd2}));

    // the head and the next event equal the cells at the owed shift's
    // offset while the ray has events left
    wire [DW-1:0] cell_head   = pop_q ? drain_w[1] : drain_w[0];
    wire [DW-1:0] cell_second = pop_q ? drain_w[2] : drain_w[1];
    csgrt_check_same #(.WIDTH(2 * DW), .WHAT("head_q / second_q")) u_check_head (
        .clk_i, .rst_ni, .copy_i(dne_q ? {head_q, second_q} : {2 * DW{1'b0}}),
        .orig_i(dne_q ? {cell_head, cell_second} : {2 * DW{1'b0}}));

    // dlast_q is checked while the drain bank holds a ray (the count is
    // stale after a release)
    csgrt_check_same #(.WIDTH(2), .WHAT("dne_q / dlast_q")) u_check_drain (
        .clk_i, .rst_ni, .copy_i({dne_q, dlast_q}),
        .orig_i({busy_q && dcnt_q != {NB{1'b0}}, busy_q ? dcnt_q == {{(NB-1){1'b0}}, 1'b1} : dlast_q}));

    // the pair's order by the whole key, as the cells order events
    csgrt_check_same #(.WHAT("swap (the pair ordered by t alone)")) u_check_swap (
        .clk_i, .rst_ni, .copy_i(p_fire && swap),
        .orig_i(p_fire && ahead0 && ahead1 && (`CSGRT_KEY(e1) < `CSGRT_KEY(e0))));

    // the t limit keeps a whenever it keeps b (s1_n_q counts a first)
    wire keep_a = (swap || !ahead0) ? keep1 : keep0;
    wire keep_b = swap ? keep0 : keep1;
    csgrt_check_same #(.WHAT("the t limit's monotony (keeps b but not a)")) u_check_keep (
        .clk_i, .rst_ni, .copy_i(p_fire && ahead0 && ahead1 && keep_b && !keep_a), .orig_i(1'b0));

    generate
        if (N < 2 || (1 << LB) < MAX_LEAVES || NB < 2 || LOOK_BEHIND < 1 || (INSERTS != 1 && INSERTS != 2)) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_event_sort needs MAX_LEAVES >= 1, 2^LEAF_BITS >= MAX_LEAVES, LOOK_BEHIND >= 1 and INSERTS 1 or 2");
                $finish;
            end
        end
    endgenerate

    wire unused_in = ^{t0_i[TW-1], t1_i[TW-1], lt_b, key_b, occ_in1[N+1:N], occ_in2[N+1:N]};   // lt_b, key_b: unused with INSERTS = 1

`undef CSGRT_KEY

endmodule

`default_nettype wire
