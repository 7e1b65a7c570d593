// csgrt_mul_tiles.vh — how many MULT18X18D operand chunks csgrt_mul cuts a
// signed operand into (CSGRT_ECP5_DSP: chunks of 18 bits, the top one
// signed), the one place that counts them: csgrt_mul sizes its tile grid
// with csgrt_mul_chunks(), and a user that registers a product's tiles only
// when there is a sum after them (csgrt_isect's TREG, csgrt_unit's
// SQ_TILE_REG) asks csgrt_mul_chunks(width) > 1, so the three cannot drift
// apart. Included inside a module body (`include "csgrt_mul_tiles.vh"):
// constant functions, for localparams.

// chunks of an operand `width` bits wide: one up to 18 bits (a product of
// two such operands is one block, no tiles' sum), more above
function integer csgrt_mul_chunks(input integer width);
    begin
        csgrt_mul_chunks = (width + 17) / 18;
    end
endfunction
