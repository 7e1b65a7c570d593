`default_nettype none
// csgrt_align — re-align a signed fixed-point value from FROM to TO fraction
// bits, bit for bit align() of model/render.cpp: rnd(v, FROM-TO) (add
// 2^(FROM-TO-1), shift right arithmetically: round half up) when dropping
// bits, an exact left shift when adding them. The result is sign-extended or
// truncated to OUT_W bits; the caller guarantees that it fits.
// Example IN_W = 8, FROM = 4, TO = 2: v = 8'b0000_0110 (0.375) ->
// (6 + 2) >> 2 = 2 (0.5 at 2 fraction bits).
// Combinational; no handshake.
module csgrt_align #(
    parameter IN_W  = 16,   // input width, signed (>= 2)
    parameter OUT_W = 16,   // output width, signed (>= 2)
    parameter FROM  = 8,    // input fraction bits
    parameter TO    = 8     // output fraction bits
) (
    input  wire [IN_W-1:0]  v_i,
    output wire [OUT_W-1:0] v_o
);

    // the aligned value at its natural width AW
    localparam S  = (FROM > TO) ? FROM - TO : TO - FROM;
    localparam AW = (FROM > TO) ? IN_W + 1 - S : IN_W + S;

    wire [AW-1:0] a;
    generate
        if (FROM > TO) begin : g_round
            wire [IN_W:0] sum = {v_i[IN_W-1], v_i} + {{(IN_W+1-S){1'b0}}, 1'b1, {(S-1){1'b0}}};
            wire unused_lsb = ^sum[S-1:0];
            assign a = sum[IN_W:S];
        end else if (FROM == TO) begin : g_same
            assign a = v_i;
        end else begin : g_shift
            assign a = {v_i, {S{1'b0}}};
        end
        if (OUT_W >= AW) begin : g_extend
            if (OUT_W > AW) begin : g_sext
                assign v_o = {{(OUT_W-AW){a[AW-1]}}, a};
            end else begin : g_eq
                assign v_o = a;
            end
        end else begin : g_trunc
            wire unused_top = ^a[AW-1:OUT_W];
            assign v_o = a[OUT_W-1:0];
        end
        if (IN_W < 2 || OUT_W < 2 || (FROM > TO && S >= IN_W)) begin : g_bad_param
            initial begin
                $display("ERROR %m: csgrt_align needs IN_W, OUT_W >= 2 and FROM - TO < IN_W");
                $finish;
            end
        end
    endgenerate

endmodule

`default_nettype wire
