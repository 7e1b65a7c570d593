`default_nettype none
// csgrt_dispatch — turns rays into ray-primitive pairs for NUM_UNITS
// intersection lanes in lock step: rays are gathered into a group (ray n
// goes to lane n mod NUM_UNITS), then each candidate leaf of the group
// (csgrt_candidates) is read once from the scene memory and paired with every
// lane's ray in the same clock. While a group is issued the next one fills,
// so the lanes see one pair per clock. Each accepted ray is also pushed,
// whole, into the ray queue that waits beside the pipeline for its hit.
//
// A group starts when it is full, or early with the frame's last ray, or
// (NUM_UNITS > 1) early whenever the pair issue is free and no ray comes in
// that clock: the ray tree's secondary rays come in bursts, and a group
// must not wait for a ray that only its own results would spawn. Lanes
// without a ray in a group get no pairs. Each group's size goes into the
// group queue (group_*_o, in ray order), from which the merge behind the
// lanes knows how many lanes hold a record of the group: lane k holds the
// group's ray k.
//
// With INFO_W > 0 (secondary rays) every ray comes with an info word for
// its lane's csgrt_event_sort (inherited flags, t limit, look-behind run):
// it is pushed into that lane's info FIFO when the ray is accepted, long
// before the ray's first leaf result reaches the sorter, which pops it.
//
// Latency: a candidate's pairs are valid 1 clock after its memory read.
// Handshake: valid/ready everywhere. The pair registers advance together
// when every lane holding a pair has taken it (a lane that takes its pair
// early sees its valid drop until then); pair_ready_i must come from
// registers (csgrt_isect's ready does), so no combinational path crosses a
// lane.
module csgrt_dispatch #(
    parameter BITS        = 24,
    parameter LEAF_BITS   = 6,
    parameter TREE_HEIGHT = 8,
    parameter NUM_UNITS   = 1,                 // intersection lanes
    parameter RAY_W       = 24 + 6 * BITS,     // {payload, o, d}: o and d in the low 6 BITS
    parameter INFO_W      = 0,                 // info word per ray (0: none)
    parameter INFO_DEPTH  = 16,                // info FIFO entries per lane
    parameter INFO_P      = (INFO_W > 0) ? INFO_W : 1,
    parameter GW          = $clog2(NUM_UNITS + 1)  // group size width
) (
    input  wire                       clk_i,
    input  wire                       rst_ni,
    input  wire [LEAF_BITS:0]         num_leaves_i,
    // rays from the camera: {x[11:0], y[11:0], o[3*BITS], d[3*BITS]}
    input  wire                       ray_valid_i,
    output wire                       ray_ready_o,
    input  wire [RAY_W-1:0]           ray_i,
    input  wire                       ray_last_i,    // the frame's last ray
    input  wire [INFO_P-1:0]          info_i,        // INFO_W > 0: the ray's info word
    // per-lane info streams (INFO_W > 0; else valid is 0)
    output wire [NUM_UNITS-1:0]       info_valid_o,
    input  wire [NUM_UNITS-1:0]       info_ready_i,
    output wire [NUM_UNITS*INFO_P-1:0] info_o,
    // the ray queue (to the shading lookup), in ray order
    output wire                       queue_valid_o,
    input  wire                       queue_ready_i,
    output wire [RAY_W-1:0]           queue_ray_o,
    // the group queue: rays per group, in ray order (NUM_UNITS > 1; with
    // one lane every group is one ray and group_valid_o is 1)
    output wire                       group_valid_o,
    input  wire                       group_ready_i,
    output wire [GW-1:0]              group_size_o,
    // leaf memory read port (registered: data one clock after the address)
    output wire [LEAF_BITS-1:0]       leaf_addr_o,
    input  wire [10*BITS-1:0]         leaf_coef_i,
    input  wire [TREE_HEIGHT-1:0]     leaf_slot_i,
    // pairs to the lanes; coefficients, leaf, slot and last are shared
    output reg  [NUM_UNITS-1:0]       pair_valid_o,
    input  wire [NUM_UNITS-1:0]       pair_ready_i,
    output wire [NUM_UNITS*3*BITS-1:0] pair_o_o,
    output wire [NUM_UNITS*3*BITS-1:0] pair_d_o,
    output wire [10*BITS-1:0]         pair_coef_o,
    output reg  [LEAF_BITS-1:0]       pair_leaf_o,
    output wire [TREE_HEIGHT-1:0]     pair_slot_o,
    output reg                        pair_last_o
);
    localparam OD = 6 * BITS;                   // {o, d} of one ray
    localparam CW = (NUM_UNITS > 1) ? $clog2(NUM_UNITS + 1) : 1;

    // ---- the group being filled
    reg [NUM_UNITS*OD-1:0] fill_od_q;
    reg [CW-1:0]           fill_count_q;
    reg                    fill_done_q;         // full, or holds the frame's last ray
    // ---- the group being issued
    reg [NUM_UNITS*OD-1:0] iss_od_q;
    reg [NUM_UNITS-1:0]    iss_lanes_q;         // lanes with a ray in this group
    // ---- the pair registers
    reg [NUM_UNITS*OD-1:0] pair_od_q;

    wire queue_room;
    wire cand_valid, cand_last, cand_ready;
    wire [LEAF_BITS-1:0] cand_leaf;
    // all lanes holding a pair take it (or none holds one)
    wire advance = &(pair_ready_i | ~pair_valid_o);
    wire take    = advance && cand_valid;          // a candidate moves into the pair registers
    wire accept  = ray_valid_i && ray_ready_o;
    wire group_room;                                // the group queue has room (NUM_UNITS > 1)
    // the filled group starts issuing; with several lanes also a part-filled
    // one when no ray comes in (a full ray queue included)
    wire early   = (NUM_UNITS > 1) && fill_count_q != {CW{1'b0}} && !accept;
    wire launch  = (fill_done_q || early) && cand_ready && group_room;

    wire info_room;   // the accepting lane's info FIFO has room
    assign ray_ready_o = !fill_done_q && queue_room && info_room;

    csgrt_candidates #(.LEAF_BITS(LEAF_BITS)) u_candidates (
        .clk_i, .rst_ni,
        .num_leaves_i,
        .start_i (launch),
        .ready_o (cand_ready),
        .valid_o (cand_valid),
        .next_i  (take),
        .leaf_o  (cand_leaf),
        .last_o  (cand_last)
    );

    // block RAM: a ray is a few hundred bits, and LUTs are what the FPGA lacks
    csgrt_fifo_block #(.WIDTH(RAY_W), .DEPTH(64)) u_ray_queue (
        .clk_i, .rst_ni,
        .valid_i (accept),
        .ready_o (queue_room),
        .data_i  (ray_i),
        .valid_o (queue_valid_o),
        .ready_i (queue_ready_i),
        .data_o  (queue_ray_o)
    );

    generate
        if (NUM_UNITS > 1) begin : g_groups
            csgrt_fifo #(.WIDTH(GW), .DEPTH(64)) u_group_queue (
                .clk_i, .rst_ni,
                .valid_i (launch), .ready_o (group_room), .data_i (fill_count_q[GW-1:0]),
                .valid_o (group_valid_o), .ready_i (group_ready_i), .data_o (group_size_o));
        end else begin : g_one_lane
            assign group_room    = 1'b1;
            assign group_valid_o = 1'b1;
            assign group_size_o  = {{(GW-1){1'b0}}, 1'b1};
            wire unused_group = group_ready_i;
        end
    endgenerate

    // While the pair registers wait, read their own leaf again, so that the
    // memory's output register (the pairs' coefficient field) holds.
    assign leaf_addr_o = advance ? cand_leaf : pair_leaf_o;
    assign pair_coef_o = leaf_coef_i;
    assign pair_slot_o = leaf_slot_i;

    // lanes that hold a ray of the filled group: 0 .. fill_count-1
    wire [NUM_UNITS-1:0] fill_lanes;
    genvar k;
    generate
        if (INFO_W > 0) begin : g_info
            wire [NUM_UNITS-1:0] room, here;
            for (k = 0; k < NUM_UNITS; k = k + 1) begin : g_lane_info
                assign here[k] = (fill_count_q == k);
                // the head in fabric registers: the sorter computes the
                // ray's origin flags from it at once, which started at the
                // block RAM's read port (about 5 ns); the info is read a
                // pipeline's length after it is written, so the extra clock
                // of latency is hidden. A two-word csgrt_pingpong (HEAD_REG
                // 3), so that the pop, which comes with the ray's last leaf
                // at the end of the sorter -> isect -> walker handshake,
                // stops at its pointers instead of running on into the
                // words' enables and the RAM's pointers
                csgrt_fifo_block #(.WIDTH(INFO_W), .DEPTH(INFO_DEPTH), .HEAD_REG(3)) u_info (
                    .clk_i, .rst_ni,
                    .valid_i (accept && here[k]), .ready_o (room[k]), .data_i (info_i),
                    .valid_o (info_valid_o[k]), .ready_i (info_ready_i[k]), .data_o (info_o[k*INFO_W +: INFO_W]));
            end
            assign info_room = |(room & here);
        end else begin : g_no_info
            assign info_room    = 1'b1;
            assign info_valid_o = {NUM_UNITS{1'b0}};
            assign info_o       = {NUM_UNITS*INFO_P{1'b0}};
            wire unused_info = ^{info_i, info_ready_i};
        end
    endgenerate
    generate
        for (k = 0; k < NUM_UNITS; k = k + 1) begin : g_lane
            assign pair_o_o[k*3*BITS +: 3*BITS] = pair_od_q[k*OD + 3*BITS +: 3*BITS];
            assign pair_d_o[k*3*BITS +: 3*BITS] = pair_od_q[k*OD +: 3*BITS];
            assign fill_lanes[k] = (k < fill_count_q);
            // Slot k takes ray_i on every clock that it is the next to fill,
            // accepted or not: it is read (at a launch) only once
            // fill_count_q has passed it, and the accept that passes it
            // takes that clock's ray; a launch reads the old words. So the
            // slot's enable is a decode of fill_count_q instead of the
            // accept handshake (the ray tree's queue valid and this unit's
            // ready: the enables of 144 bits at the end of the 24-bit
            // netlist's fourth-longest path, tools/logic_depth.py 11.28 ns).
            always @(posedge clk_i)
                if (fill_count_q == k) fill_od_q[k*OD +: OD] <= ray_i[OD-1:0];
        end
    endgenerate

    always @(posedge clk_i) begin
        if (!rst_ni) begin
            pair_valid_o <= {NUM_UNITS{1'b0}};
            fill_count_q <= {CW{1'b0}};
            fill_done_q  <= 1'b0;
            iss_lanes_q  <= {NUM_UNITS{1'b0}};
        end else begin
            // a lane that took its pair holds no pair until the others
            // have taken theirs (else it would take the same pair again)
            if (advance) pair_valid_o <= cand_valid ? iss_lanes_q : {NUM_UNITS{1'b0}};
            else         pair_valid_o <= pair_valid_o & ~pair_ready_i;
            if (launch) begin
                iss_od_q     <= fill_od_q;
                iss_lanes_q  <= fill_lanes;
                fill_count_q <= {CW{1'b0}};
                fill_done_q  <= 1'b0;
            end else if (accept) begin
                fill_count_q <= fill_count_q + 1'b1;
                if ({{(32-CW){1'b0}}, fill_count_q} + 32'd1 == NUM_UNITS || ray_last_i) fill_done_q <= 1'b1;
            end
        end
        if (take) begin
            pair_od_q   <= iss_od_q;
            pair_leaf_o <= cand_leaf;
            pair_last_o <= cand_last;
        end
    end
endmodule
`default_nettype wire
