// stream.h — the reusable harness of csgrt's Verilator testbenches.
//
// Harness<Top> owns the VerilatedContext and the model (no file-scope
// statics). run_stream() pushes n transactions through one valid/ready DUT
// inside that model with random input gaps and random output back-pressure,
// checks every output in order against the reference (so a lost or
// duplicated transaction shows up as a mismatch or a timeout), checks that
// nothing extra comes out afterwards, and measures the latency.
#pragma once

#include <verilated.h>

#include <cstdint>
#include <cstdlib>
#include <functional>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace tb {

template <class Top>
struct Harness {
    std::unique_ptr<VerilatedContext> ctx;
    std::unique_ptr<Top> top;
    Harness() : ctx(new VerilatedContext) {
        ctx->debug(0);
        ctx->randReset(2);   // registers without reset start random
        top.reset(new Top(ctx.get()));
    }
    ~Harness() { top->final(); }
};

// The handshake ports of one DUT instance in the model.
struct StreamPorts {
    uint8_t* clk;
    uint8_t* rst_n;
    uint8_t* valid_i;
    uint8_t* ready_o;
    uint8_t* valid_o;
    uint8_t* ready_i;
};

struct StreamResult {
    uint64_t sent = 0, received = 0, cycles = 0, mismatches = 0, extra = 0;
    int min_latency = 1 << 30, max_latency = 0;
    bool timeout = false;
    std::vector<std::string> messages;   // the first few mismatches
    bool ok() const { return !timeout && mismatches == 0 && extra == 0; }
    std::string summary() const {
        std::ostringstream s;
        s << "sent " << sent << ", received " << received << ", mismatches " << mismatches << ", extra "
          << extra << (timeout ? ", TIMEOUT" : "") << ", " << cycles << " cycles, latency " << min_latency
          << ".." << max_latency;
        for (const std::string& m : messages) s << "\n  " << m;
        return s.str();
    }
};

// Seed: fixed by default, TB_SEED in the environment overrides it.
inline uint64_t seed(uint64_t dflt) {
    const char* e = std::getenv("TB_SEED");
    return e ? std::strtoull(e, nullptr, 0) : dflt;
}

// Scale factor for vector counts: TB_SCALE=0.1 for a quick run.
inline double scale() {
    const char* e = std::getenv("TB_SCALE");
    return e ? std::atof(e) : 1.0;
}

// drive(i) sets the DUT's data inputs for transaction i; check(i) reads its
// data outputs while transaction i is on them and returns "" or a message.
// p_gap: probability that valid_i stays low in a cycle with work to send;
// p_stall: probability that ready_i is low in a cycle.
template <class Top>
StreamResult run_stream(Top* top, const StreamPorts& p, size_t n, const std::function<void(size_t)>& drive,
                        const std::function<std::string(size_t)>& check, double p_gap, double p_stall,
                        uint64_t rng_seed, size_t max_messages = 8) {
    StreamResult r;
    std::mt19937_64 rng(rng_seed);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    auto tick = [&] {
        *p.clk = 1;
        top->eval();
        *p.clk = 0;
        top->eval();
    };
    // reset
    *p.valid_i = 0;
    *p.ready_i = 0;
    *p.clk = 0;
    *p.rst_n = 0;
    top->eval();
    for (int i = 0; i < 4; ++i) tick();
    *p.rst_n = 1;
    top->eval();

    std::vector<uint64_t> accept_cycle(n);
    bool pending = false;   // valid_i is up and must stay up until accepted
    uint64_t idle = 0;
    size_t drain = 0;
    for (uint64_t cyc = 0;; ++cyc) {
        if (r.sent < n && !pending) pending = !(u01(rng) < p_gap);
        *p.valid_i = pending ? 1 : 0;
        if (pending) drive(r.sent);
        const bool draining = r.received == n;
        *p.ready_i = (draining || !(u01(rng) < p_stall)) ? 1 : 0;
        top->eval();
        const bool in_fire = *p.valid_i && *p.ready_o;
        const bool out_fire = *p.valid_o && *p.ready_i;
        bool progress = in_fire;
        if (out_fire) {
            progress = true;
            if (r.received >= n) {
                ++r.extra;
            } else {
                const size_t k = r.received;
                const std::string msg = check(k);
                if (!msg.empty()) {
                    ++r.mismatches;
                    if (r.messages.size() < max_messages) r.messages.push_back("#" + std::to_string(k) + ": " + msg);
                }
                const int lat = int(cyc - accept_cycle[k]);
                if (lat < r.min_latency) r.min_latency = lat;
                if (lat > r.max_latency) r.max_latency = lat;
                ++r.received;
            }
        }
        if (in_fire) {
            accept_cycle[r.sent] = cyc;
            ++r.sent;
            pending = false;
        }
        tick();
        r.cycles = cyc + 1;
        idle = progress ? 0 : idle + 1;
        if (r.received == n && ++drain > 200) break;   // nothing more may come out
        if (idle > 10000) {
            r.timeout = true;
            break;
        }
    }
    *p.valid_i = 0;
    return r;
}

// Helpers for ports wider than 64 bits (VlWide) and narrower ones.
template <class W>
inline void set_bits(W& w, int lsb, int width, uint64_t v) {
    for (int i = 0; i < width; ++i) {
        const int b = lsb + i;
        const uint32_t bit = (i < 64) ? uint32_t((v >> i) & 1) : uint32_t(v >> 63);   // sign-extend
        w[b / 32] = (w[b / 32] & ~(1u << (b % 32))) | (bit << (b % 32));
    }
}
template <class W>
inline uint64_t get_bits(const W& w, int lsb, int width) {
    uint64_t v = 0;
    for (int i = 0; i < width; ++i) {
        const int b = lsb + i;
        v |= uint64_t((w[b / 32] >> (b % 32)) & 1) << i;
    }
    return v;
}
// Sign-extend the low `width` bits of v.
inline int64_t sext(uint64_t v, int width) {
    if (width >= 64) return int64_t(v);
    const uint64_t m = uint64_t(1) << (width - 1);
    v &= (uint64_t(1) << width) - 1;
    return int64_t((v ^ m) - m);
}
inline uint64_t mask(int width) { return width >= 64 ? ~uint64_t(0) : (uint64_t(1) << width) - 1; }

// A signed field of `width` bits at `lsb` of a port, narrow (an integer)
// or wide (VlWide): set from v (two's complement, truncated) and read back
// sign-extended.
template <class W>
inline void set_field(W& w, int lsb, int width, int64_t v) {
    if constexpr (std::is_integral_v<W>) {
        const uint64_t m = mask(width) << lsb;
        w = W((uint64_t(w) & ~m) | ((uint64_t(v) << lsb) & m));
    } else {
        set_bits(w, lsb, width, uint64_t(v));
    }
}
template <class W>
inline int64_t get_field(const W& w, int lsb, int width) {
    if constexpr (std::is_integral_v<W>)
        return sext(uint64_t(w) >> lsb, width);
    else
        return sext(get_bits(w, lsb, width), width);
}

// The repository's root (this file is tb/common/stream.h): the benches
// read scenes and rtl/srgb_lut.hex from there.
inline std::string repo_root() {
    std::string f = __FILE__;
    for (int i = 0; i < 3; ++i) f = f.substr(0, f.find_last_of('/'));
    return f;
}

}  // namespace tb
