`default_nettype none
// csgrt_dispatch — turns rays into ray-primitive pairs: for each ray from the
// camera, one pair per candidate leaf (csgrt_candidates), with the leaf's
// coefficients and tree slot read from the scene memory, at one pair per
// clock. Each accepted ray is also pushed, whole, into the ray queue that
// waits beside the pipeline for the ray's hit record.
//
// Latency: a candidate's pair is valid 1 clock after its memory read.
// Handshake: valid/ready everywhere. The pair register advances when it is
// empty or the intersection unit takes it; pair_ready_i must be a register
// output (csgrt_isect's is), so no combinational path crosses the unit.
module csgrt_dispatch #(
    parameter BITS        = 24,
    parameter LEAF_BITS   = 6,
    parameter TREE_HEIGHT = 8,
    parameter RAY_W       = 24 + 6 * BITS     // {x, y, o, d}
) (
    input  wire                    clk_i,
    input  wire                    rst_ni,
    input  wire [LEAF_BITS:0]      num_leaves_i,
    // rays from the camera: {x[11:0], y[11:0], o[3*BITS], d[3*BITS]}
    input  wire                    ray_valid_i,
    output wire                    ray_ready_o,
    input  wire [RAY_W-1:0]        ray_i,
    // the ray queue (to the shading lookup)
    output wire                    queue_valid_o,
    input  wire                    queue_ready_i,
    output wire [RAY_W-1:0]        queue_ray_o,
    // leaf memory read port (registered: data one clock after the address)
    output wire [LEAF_BITS-1:0]    leaf_addr_o,
    input  wire [10*BITS-1:0]      leaf_coef_i,
    input  wire [TREE_HEIGHT-1:0]  leaf_slot_i,
    // pairs to the intersection unit
    output reg                     pair_valid_o,
    input  wire                    pair_ready_i,
    output wire [3*BITS-1:0]       pair_o_o,
    output wire [3*BITS-1:0]       pair_d_o,
    output wire [10*BITS-1:0]      pair_coef_o,
    output reg  [LEAF_BITS-1:0]    pair_leaf_o,
    output wire [TREE_HEIGHT-1:0]  pair_slot_o,
    output reg                     pair_last_o
);
    // ray register: the ray whose candidates are being issued
    reg [6*BITS-1:0] ray_od_q;       // {o, d} of the current ray
    reg [6*BITS-1:0] pair_od_q;      // {o, d} of the pair on the output

    wire advance = !pair_valid_o || pair_ready_i;
    wire cand_valid, cand_last;
    wire [LEAF_BITS-1:0] cand_leaf;
    wire take = advance && cand_valid;   // a candidate moves into the pair register

    // a new ray starts when the candidate list is free and the queue has room
    wire start = ray_valid_i && cand_ready_start && queue_room;
    wire cand_ready_start;
    wire queue_room;
    assign ray_ready_o = cand_ready_start && queue_room;

    csgrt_candidates #(.LEAF_BITS(LEAF_BITS)) u_candidates (
        .clk_i, .rst_ni,
        .num_leaves_i,
        .start_i (start),
        .ready_o (cand_ready_start),
        .valid_o (cand_valid),
        .next_i  (take),
        .leaf_o  (cand_leaf),
        .last_o  (cand_last)
    );

    csgrt_fifo #(.WIDTH(RAY_W), .DEPTH(64)) u_ray_queue (
        .clk_i, .rst_ni,
        .valid_i (start),
        .ready_o (queue_room),
        .data_i  (ray_i),
        .valid_o (queue_valid_o),
        .ready_i (queue_ready_i),
        .data_o  (queue_ray_o)
    );

    // While the pair register waits, read its own leaf again, so that the
    // memory's output register (which is the pair's coefficient field) holds.
    assign leaf_addr_o = advance ? cand_leaf : pair_leaf_o;
    assign pair_coef_o = leaf_coef_i;    // the memory's output register is the pair's
    assign pair_slot_o = leaf_slot_i;
    assign pair_o_o    = pair_od_q[6*BITS-1:3*BITS];
    assign pair_d_o    = pair_od_q[3*BITS-1:0];

    always @(posedge clk_i) begin
        if (!rst_ni) begin
            pair_valid_o <= 1'b0;
        end else if (advance) begin
            pair_valid_o <= cand_valid;
        end
        if (start) ray_od_q <= ray_i[6*BITS-1:0];
        if (take) begin
            pair_od_q   <= ray_od_q;
            pair_leaf_o <= cand_leaf;
            pair_last_o <= cand_last;
        end
    end
endmodule
`default_nettype wire
