// csgrt_unit_latency.vh — csgrt_unit's latency in beats (enabled clocks of
// its beat's advance), the one place that counts it: csgrt_unit carries its
// sideband over exactly this many advances and sizes its shared divider's
// pad with csgrt_unit_div_pad(), and a user whose own RAM delay lines span a
// unit (csgrt_shade's segments A and B) counts the unit's part with
// csgrt_unit_latency(), so none of them can drift apart.
// Included inside a module body (`include "csgrt_unit_latency.vh"):
// constant functions, for localparams.
//
//   II = 1: M 2 + S 1 + Q sqrt_stages + P 1 + D (frac + 2) + O 1
//   II = 3: M 2 + S 1 + Q ceil(sqrt_stages / 3) + P 1
//           + D (dl + pad + 4) / 3 + O 1, where dl = frac + 2 is the shared
//           csgrt_div_core's latency in running clocks and pad (0 to 2)
//           brings dl + pad to 2 mod 3 (csgrt_unit's g_div_shared)

// II = 3: registers after the shared divider, so that its latency (frac + 2
// running clocks) plus the pad is 2 mod 3
function integer csgrt_unit_div_pad(input integer frac);
    begin
        csgrt_unit_div_pad = (5 - ((frac + 2) % 3)) % 3;
    end
endfunction

// II = 3: beats from P to O's input (the shared divider, its pad and the
// gather)
function integer csgrt_unit_div_beats(input integer frac);
    begin
        csgrt_unit_div_beats = (frac + 2 + csgrt_unit_div_pad(frac) + 4) / 3;
    end
endfunction

function integer csgrt_unit_latency(input integer frac, input integer sqrt_stages,
                                    input integer ii);
    begin
        if (ii == 1) csgrt_unit_latency = 2 + 1 + sqrt_stages + 1 + (frac + 2) + 1;
        else         csgrt_unit_latency = 2 + 1 + (sqrt_stages + 2) / 3 + 1 + csgrt_unit_div_beats(frac) + 1;
    end
endfunction
