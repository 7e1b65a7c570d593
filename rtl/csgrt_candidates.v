`default_nettype none
// csgrt_candidates — the list of candidate leaves for one ray. Today every
// ray's list is every leaf, 0 .. num_leaves-1, in leaf order; space
// division will replace this module with one that reads a voxel's list from
// memory, without changing the dispatcher or anything behind it.
//
// Handshake: start_i (with ready_o high) begins a ray's list; then leaf_o
// is valid while valid_o is high and advances on next_i. last_o marks the
// list's last entry. Latency: the first entry is valid the clock after
// start_i.
module csgrt_candidates #(
    parameter LEAF_BITS = 6   // leaf index width
) (
    input  wire                 clk_i,
    input  wire                 rst_ni,
    input  wire [LEAF_BITS:0]   num_leaves_i,
    input  wire                 start_i,
    output wire                 ready_o,
    output wire                 valid_o,
    input  wire                 next_i,
    output wire [LEAF_BITS-1:0] leaf_o,
    output wire                 last_o
);
    reg               active_q;
    reg [LEAF_BITS:0] leaf_q;
    // last_o as a register, loaded with the test of the next entry: the
    // test of leaf_q itself (an increment's carry chain and a compare) ran
    // through ready_o into the dispatcher's launch, whose enable reaches
    // the issue registers across the die (the critical path of the routed
    // c715d7c build, 12.07 ns). num_leaves_i is steady while a ray's list
    // is read (it changes only when a scene is loaded).
    reg               last_q;

    assign ready_o = !active_q || (next_i && last_q);
    assign valid_o = active_q;
    assign leaf_o  = leaf_q[LEAF_BITS-1:0];
    assign last_o  = last_q;

    always @(posedge clk_i) begin
        if (!rst_ni) begin
            active_q <= 1'b0;
            leaf_q   <= {(LEAF_BITS+1){1'b0}};
            last_q   <= 1'b0;
        end else if (start_i && ready_o) begin
            active_q <= (num_leaves_i != 0);
            leaf_q   <= {(LEAF_BITS+1){1'b0}};
            last_q   <= (num_leaves_i == {{LEAF_BITS{1'b0}}, 1'b1});
        end else if (next_i && active_q) begin
            if (last_q) active_q <= 1'b0;
            leaf_q <= leaf_q + 1'b1;
            last_q <= (leaf_q + {{(LEAF_BITS-1){1'b0}}, 2'd2} == num_leaves_i);
        end
    end
`ifndef SYNTHESIS
    // the register is the test of the entry it stands beside
    csgrt_check_same #(.WHAT("last_q (leaf_q + 1 == num_leaves_i)")) u_check_last (
        .clk_i, .rst_ni,
        .copy_i(active_q && last_q), .orig_i(active_q && (leaf_q + 1'b1 == num_leaves_i)));
`endif
endmodule
`default_nettype wire
