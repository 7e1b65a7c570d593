// csgrt_unit_latency.vh — csgrt_unit's latency in beats (enabled clocks of
// its beat's advance), the one place that counts it: csgrt_unit carries its
// sideband over exactly this many advances, and a user whose own RAM delay
// lines span a unit (csgrt_shade's segments A and B) counts the unit's part
// with the same function, so the two cannot drift apart.
// Included inside a module body (`include "csgrt_unit_latency.vh"): a
// constant function, for localparams.
//
//   II = 1: M 2 + S 1 + Q sqrt_stages + P 1 + D (frac + 2) + O 1
//   II = 3: M 2 + S 1 + Q ceil(sqrt_stages / 3) + P 1
//           + D (dl + pad + 4) / 3 + O 1, where dl = frac + 2 is the shared
//           csgrt_div_core's latency in running clocks and pad (0 to 2)
//           brings dl + pad to 2 mod 3 (csgrt_unit's g_div_shared)
function integer csgrt_unit_latency(input integer frac, input integer sqrt_stages,
                                    input integer ii);
    integer dl, pad;
    begin
        dl  = frac + 2;
        pad = (5 - (dl % 3)) % 3;
        if (ii == 1) csgrt_unit_latency = 2 + 1 + sqrt_stages + 1 + dl + 1;
        else         csgrt_unit_latency = 2 + 1 + (sqrt_stages + 2) / 3 + 1 + (dl + pad + 4) / 3 + 1;
    end
endfunction
