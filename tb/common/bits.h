// bits.h — bit fields of Verilator wide ports (VlWide, 32-bit words), for
// the benches that pack several operands into one port (tb/mul, tb/mul_vec).
#pragma once

#include <cstdint>

namespace tb {

// bits [lo, lo+w) of `port` set to the low w bits of v (w <= 64)
template <class W>
void put_bits(W& port, int lo, int w, uint64_t v) {
    for (int i = 0; i < w; ++i) {
        const int b = lo + i;
        const uint32_t m = 1u << (b % 32);
        if ((v >> i) & 1) port[b / 32] |= m;
        else port[b / 32] &= ~m;
    }
}

// bits [lo, lo+w) of `port` as a w-bit two's complement number (w <= 127)
template <class W>
__int128 get_signed(const W& port, int lo, int w) {
    __int128 v = 0;
    for (int i = 0; i < w; ++i)
        if ((port[(lo + i) / 32] >> ((lo + i) % 32)) & 1) v |= __int128(1) << i;
    if ((v >> (w - 1)) & 1) v -= __int128(1) << w;   // sign
    return v;
}

}  // namespace tb
