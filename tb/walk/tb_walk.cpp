// tb_walk.cpp — csgrt_walk_unit (csgrt_event_sort + csgrt_walker) against
// trace_primary_fx() (model/trace.cpp).
//
// Scenes: scenes/*.pov and inline coincident-surface scenes (the same box
// twice, a box minus a flush cylinder, touching boxes, a sphere minus
// itself), compiled with tree_height 8 and max_leaves 64. Rays: a grid of
// camera rays, random rays and dyadic axis-aligned rays (exact ties). For
// each ray the per-leaf results of intersect_fx() go in, leaf order = slot
// order = candidate order, slot from cs.layout.leaf_slot, payload = the ray's
// number. Each output record is compared in order with the model: hit, t,
// leaf, slot, entering, from, to, flags_before (mapped through leaf_slot;
// empty slots 0) and payload; nothing may be lost or duplicated. The ray
// that the sorter hands to the walker (origin flags, events popped) is
// observed too: flags must equal the model's origin flags, the popped
// events a prefix of the model's sorted list. Both tie policies, BITS 16
// and 24, random input gaps and output back-pressure; one back-to-back run
// per width measures clocks per ray.
#include "Vtb_walk.h"
#include "compile.h"
#include "parse.h"
#include "render.h"
#include "stream.h"
#include "trace.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace {

using namespace csgrt;
using Top = Vtb_walk;

template <class W>
void put(W& w, int lsb, int width, uint64_t v) {
    if constexpr (std::is_integral<W>::value)
        w = W((uint64_t(w) & ~(tb::mask(width) << lsb)) | ((v & tb::mask(width)) << lsb));
    else
        tb::set_bits(w, lsb, width, v);
}
template <class W>
uint64_t get(const W& w, int lsb, int width) {
    if constexpr (std::is_integral<W>::value)
        return (uint64_t(w) >> lsb) & tb::mask(width);
    else
        return tb::get_bits(w, lsb, width);
}

#define WALK_PORTS(B)                                                                                 \
    struct P##B {                                                                                     \
        static constexpr int kBits = B;                                                               \
        Top* t;                                                                                       \
        tb::StreamPorts ports() {                                                                     \
            return {&t->b##B##_clk_i, &t->b##B##_rst_ni, &t->b##B##_valid_i,                          \
                    &t->b##B##_ready_o, &t->b##B##_valid_o, &t->b##B##_ready_i};                      \
        }                                                                                             \
        template <class F> void cfg(F f) {                                                            \
            f(t->b##B##_ties_regular_i, t->b##B##_node_op_i, t->b##B##_slot_mat_i, t->b##B##_slot_used_i); \
        }                                                                                             \
        void drive(int slot, int leaf, const LeafEvents<i64>& le, bool last, uint32_t pay) {          \
            const int TW = B - 1;                                                                     \
            t->b##B##_slot_i = uint8_t(slot);                                                         \
            t->b##B##_leaf_i = uint8_t(leaf);                                                         \
            t->b##B##_count_i = uint8_t(le.count);                                                    \
            t->b##B##_t0_i = uint32_t(uint64_t(le.ev[0].t) & tb::mask(TW));                           \
            t->b##B##_range0_i = uint8_t(le.ev[0].range);                                             \
            t->b##B##_enter0_i = le.ev[0].entering;                                                   \
            t->b##B##_t1_i = uint32_t(uint64_t(le.ev[1].t) & tb::mask(TW));                           \
            t->b##B##_range1_i = uint8_t(le.ev[1].range);                                             \
            t->b##B##_enter1_i = le.ev[1].entering;                                                   \
            t->b##B##_inside_i = le.inside_at_minus_inf;                                              \
            t->b##B##_last_i = last;                                                                  \
            t->b##B##_payload_i = pay;                                                                \
        }                                                                                             \
        Rec read() {                                                                                  \
            Rec r;                                                                                    \
            r.hit = t->b##B##_hit_o;                                                                  \
            r.t = tb::sext(t->b##B##_t_o, B - 1);                                                     \
            r.leaf = t->b##B##_leaf_o;                                                                \
            r.slot = t->b##B##_slot_o;                                                                \
            r.entering = t->b##B##_entering_o;                                                        \
            r.from = t->b##B##_from_o;                                                                \
            r.to = t->b##B##_to_o;                                                                    \
            r.payload = t->b##B##_payload_o;                                                          \
            for (int s = 0; s < 256; ++s) r.flags[s] = uint8_t(get(t->b##B##_flags_before_o, s, 1)); \
            return r;                                                                                 \
        }                                                                                             \
        bool mon_load() { return t->b##B##_mon_load_o; }                                              \
        std::vector<uint8_t> mon_flags() {                                                            \
            std::vector<uint8_t> f(256);                                                              \
            for (int s = 0; s < 256; ++s) f[s] = uint8_t(get(t->b##B##_mon_flags_o, s, 1));           \
            return f;                                                                                 \
        }                                                                                             \
        bool mon_pop() { return t->b##B##_mon_pop_o; }                                                \
        Ev mon_ev() {                                                                                 \
            return {tb::sext(t->b##B##_mon_t_o, B - 1), int(t->b##B##_mon_leaf_o),                    \
                    int(t->b##B##_mon_slot_o), bool(t->b##B##_mon_ent_o)};                            \
        }                                                                                             \
    };

struct Rec {
    bool hit = false;
    i64 t = 0;
    int leaf = 0, slot = 0;
    bool entering = false;
    int from = 0, to = 0;
    uint32_t payload = 0;
    std::vector<uint8_t> flags = std::vector<uint8_t>(256);
};
struct Ev {
    i64 t;
    int leaf, slot;
    bool entering;
};
WALK_PORTS(16)
WALK_PORTS(24)

struct RayCase {
    RayFx ray;
    std::vector<LeafEvents<i64>> le;
    TraceResult<i64> want;
};

struct Scenario {
    std::string name;
    CompiledScene cs;
};

const char* kInline[][2] = {
    {"same_box_twice",
     "union { box { <-1,-1,-1>, <1,1,1> pigment { color rgb <1,0,0> } }\n"
     "        box { <-1,-1,-1>, <1,1,1> pigment { color rgb <0,1,0> } } }\n"},
    {"box_minus_flush_cylinder",
     "difference { box { <-1,-1,-1>, <1,1,1> pigment { color rgb <1,0,0> } }\n"
     "             cylinder { <0,-1,0>, <0,1,0>, 0.5 pigment { color rgb <0,1,0> } } }\n"},
    {"touching_boxes",
     "union { box { <-1,-1,-1>, <0,1,1> pigment { color rgb <1,0,0> } }\n"
     "        box { <0,-1,-1>, <1,1,1> pigment { color rgb <0,0,1> } } }\n"},
    {"sphere_minus_itself_and_flush_box",
     "union { difference { sphere { <-1.5,0,0>, 1 pigment { color rgb <1,0,0> } }\n"
     "                     sphere { <-1.5,0,0>, 1 pigment { color rgb <0,1,0> } } }\n"
     "        difference { box { <0,-1,-1>, <2,1,1> pigment { color rgb <1,1,0> } }\n"
     "                     box { <0.5,-1,-0.5>, <1.5,1,0.5> pigment { color rgb <0,1,1> } }\n"
     "                     box { <0,-1,-1>, <2,0,1> pigment { color rgb <0,1,1> } } } }\n"},
};

CompiledScene compile(const Scene& s, int bits) {
    CompileOptions o;
    o.bits = bits;
    o.tree_height = kRtlTreeHeight;
    o.max_leaves = kRtlMaxLeaves;
    return compile_scene(s, o);
}

std::vector<Scenario> scenarios(int bits) {
    std::vector<Scenario> v;
    for (const char* f : {"default", "basic", "csg_mix", "quadrics", "rotated"})
        v.push_back({f, compile(parse_scene_file(std::string("scenes/") + f + ".pov"), bits)});
    for (auto& s : kInline) {
        const std::string text = std::string("camera { location <0.7, 2.3, -5> look_at <0, 0, 0> }\n"
                                             "light_source { <-4, 6, -5> color rgb <1, 1, 1> }\n") + s[1];
        v.push_back({s[0], compile(parse_scene_string(text, std::string(s[0]) + ".pov"), bits)});
    }
    return v;
}

std::vector<RayCase> make_rays(const CompiledScene& cs, TiePolicy ties, int grid_x, int grid_y, int n_random,
                               uint64_t seed) {
    std::vector<RayCase> out;
    const Formats& fmt = cs.fmt;
    auto add = [&](const RayFx& r) {
        RayCase c;
        c.ray = r;
        try {
            for (const LeafInfo& l : cs.leaves) c.le.push_back(intersect_fx(fmt, l.coef, r));
            c.want = trace_primary_fx(cs, r, ties, true);
        } catch (const std::logic_error&) {
            return;   // outside the model's bounds
        }
        out.push_back(std::move(c));
    };
    for (int j = 0; j < grid_y; ++j)
        for (int i = 0; i < grid_x; ++i)
            add(camera_ray_fx(cs, (2 * i + 1) * cs.width / (2 * grid_x), (2 * j + 1) * cs.height / (2 * grid_y)));
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g(0.0, 1.0);
    auto q = [&](double x) { return i64(std::llround(std::ldexp(x, fmt.frac))); };
    for (int k = 0; k < n_random; ++k) {
        RayFx r;
        if (k % 2) {
            // dyadic origin, axis-aligned direction: exact coincidences
            for (i64& x : r.o) x = i64(int(rng() % 17) - 8) << (fmt.frac - 3);
            r.d = {0, 0, 0};
            r.d[rng() % 3] = (rng() & 1) ? fmt.one() : -fmt.one();
        } else {
            double v[3], n = 0;
            for (double& x : v) x = g(rng), n += x * x;
            n = std::sqrt(n);
            for (int i = 0; i < 3; ++i) {
                r.o[i] = q(std::uniform_real_distribution<double>(-1.5, 1.5)(rng));
                r.d[i] = q(v[i] / n * 0.999999);
            }
        }
        add(r);
    }
    return out;
}

std::string describe(const CompiledScene& cs, const RayCase& c, const std::vector<uint8_t>* rtl_flags,
                     const std::vector<Ev>* rtl_events) {
    std::ostringstream s;
    s << "ray o {" << c.ray.o[0] << " " << c.ray.o[1] << " " << c.ray.o[2] << "} d {" << c.ray.d[0] << " "
      << c.ray.d[1] << " " << c.ray.d[2] << "}\n    model origin flags (by leaf): ";
    for (uint8_t f : c.want.origin_flags) s << int(f);
    if (rtl_flags) {
        s << "\n    RTL   origin flags (by leaf): ";
        for (size_t l = 0; l < cs.leaves.size(); ++l) s << int((*rtl_flags)[cs.layout.leaf_slot[l]]);
    }
    s << "\n    model events (t leaf E/L):";
    for (const auto& e : c.want.events) s << " " << e.t << ":" << e.leaf << (e.entering ? "E" : "L");
    if (rtl_events) {
        s << "\n    RTL   events popped:     ";
        for (const auto& e : *rtl_events) s << " " << e.t << ":" << e.leaf << (e.entering ? "E" : "L");
    }
    s << "\n    model: " << (c.want.hit ? "hit t " + std::to_string(c.want.t) + " leaf " + std::to_string(c.want.leaf) +
                                           (c.want.entering ? " entering " : " leaving ") + c.want.border.str()
                                     : std::string("miss"));
    return s.str();
}

struct RunStats {
    uint64_t rays = 0, hits = 0, events = 0, popped = 0, cycles = 0, leaves = 0;
};

template <class P>
void run(const Scenario& sc, TiePolicy ties, const std::vector<RayCase>& rays, double p_gap, double p_stall,
         uint64_t seed, RunStats& st) {
    const CompiledScene& cs = sc.cs;
    const int n = int(cs.leaves.size());
    const std::string tag = sc.name + " BITS=" + std::to_string(P::kBits) +
                            (ties == TiePolicy::Paper ? " paper" : " regular");
    tb::Harness<Top> h;
    P p{h.top.get()};
    const tb::StreamPorts sp = p.ports();
    p.cfg([&](auto& tr, auto& ops, auto& mat, auto& used) {
        tr = ties == TiePolicy::Regular;
        for (int i = 0; i < 256; ++i) put(ops, 2 * i, 2, uint64_t(cs.layout.node_op[i]));
        for (int s = 0; s < 256; ++s) put(mat, 8 * s, 8, 0xa5), put(used, s, 1, 0);
        for (int l = 0; l < n; ++l) {
            put(mat, 8 * cs.layout.leaf_slot[l], 8, cs.leaf_material[l]);
            put(used, cs.layout.leaf_slot[l], 1, 1);
        }
    });
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    auto tick = [&] {
        *sp.clk = 1;
        h.top->eval();
        *sp.clk = 0;
        h.top->eval();
    };
    *sp.valid_i = 0;
    *sp.ready_i = 0;
    *sp.rst_n = 0;
    for (int i = 0; i < 4; ++i) tick();
    *sp.rst_n = 1;

    const size_t total_in = rays.size() * size_t(n);
    size_t sent = 0, received = 0, extra = 0, mismatches = 0;
    std::vector<std::vector<uint8_t>> mon_flags;
    std::vector<std::vector<Ev>> mon_events;
    std::vector<std::string> msgs;
    bool pending = false;
    uint64_t idle = 0, cyc = 0, drain = 0;
    bool timeout = false;
    for (;; ++cyc) {
        if (sent < total_in && !pending) pending = !(u01(rng) < p_gap);
        *sp.valid_i = pending;
        if (pending) {
            const size_t r = sent / n;
            const int l = int(sent % n);
            p.drive(cs.layout.leaf_slot[l], l, rays[r].le[l], l == n - 1, uint32_t(r));
        }
        *sp.ready_i = !(u01(rng) < p_stall);
        h.top->eval();
        const bool in_fire = *sp.valid_i && *sp.ready_o;
        const bool out_fire = *sp.valid_o && *sp.ready_i;
        if (p.mon_load()) {
            mon_flags.push_back(p.mon_flags());
            mon_events.emplace_back();
        }
        if (p.mon_pop()) {
            if (mon_events.empty()) ADD_FAILURE() << tag << ": pop before any ray was loaded";
            else mon_events.back().push_back(p.mon_ev());
        }
        if (out_fire) {
            if (received >= rays.size()) {
                ++extra;
            } else {
                const RayCase& c = rays[received];
                const Rec o = p.read();
                std::ostringstream m;
                auto field = [&](const char* name, i64 dut, i64 model) {
                    if (dut != model) m << " " << name << ": DUT " << dut << " model " << model << ";";
                };
                field("payload", o.payload, uint32_t(received));
                field("hit", o.hit, c.want.hit);
                if (c.want.hit && o.hit) {
                    field("t", o.t, c.want.t);
                    field("leaf", o.leaf, c.want.leaf);
                    field("slot", o.slot, cs.layout.leaf_slot[c.want.leaf]);
                    field("entering", o.entering, c.want.entering);
                    field("from", o.from, c.want.border.from);
                    field("to", o.to, c.want.border.to);
                    // The flags just before the hit's own crossing: the
                    // origin flags with every valid event before it applied.
                    // (The model's near side also undoes the crossings that
                    // share the hit point, its look-behind; the RTL gains
                    // that with secondary rays, so it is not compared here.)
                    std::vector<uint8_t> before = c.want.origin_flags;
                    for (const auto& e : c.want.events) {
                        if (e.t == c.want.t && e.leaf == c.want.leaf && e.entering == c.want.entering) break;
                        if (bool(before[e.leaf]) != e.entering) before[e.leaf] = e.entering;
                    }
                    std::vector<uint8_t> want_slots(256, 0);
                    for (int l = 0; l < n; ++l) want_slots[cs.layout.leaf_slot[l]] = before[l];
                    for (int s = 0; s < 256; ++s)
                        if (o.flags[s] != want_slots[s]) {
                            m << " flags_before slot " << s << ": DUT " << int(o.flags[s]) << " model "
                              << int(want_slots[s]) << ";";
                            break;
                        }
                }
                if (!m.str().empty()) {
                    ++mismatches;
                    if (msgs.size() < 5)
                        msgs.push_back("ray " + std::to_string(received) + ":" + m.str() + "\n    " +
                                       describe(cs, c, received < mon_flags.size() ? &mon_flags[received] : nullptr,
                                                received < mon_events.size() ? &mon_events[received] : nullptr));
                }
                ++received;
            }
        }
        if (in_fire) {
            ++sent;
            pending = false;
        }
        tick();
        idle = (in_fire || out_fire) ? 0 : idle + 1;
        if (received == rays.size() && ++drain > 100) break;
        if (idle > 5000) {
            timeout = true;
            break;
        }
    }
    // the sorted rays handed to the walker
    size_t sort_bad = 0;
    if (mon_flags.size() != rays.size()) {
        ADD_FAILURE() << tag << ": " << mon_flags.size() << " rays loaded by the walker, " << rays.size() << " sent";
    } else {
        for (size_t r = 0; r < rays.size(); ++r) {
            const RayCase& c = rays[r];
            bool ok = true;
            for (int s = 0; s < 256; ++s) ok = ok && (mon_flags[r][s] == 0 || std::count(cs.layout.leaf_slot.begin(), cs.layout.leaf_slot.end(), s));
            for (int l = 0; l < n; ++l) ok = ok && mon_flags[r][cs.layout.leaf_slot[l]] == c.want.origin_flags[l];
            const auto& ev = mon_events[r];
            ok = ok && ev.size() <= c.want.events.size();
            for (size_t k = 0; ok && k < ev.size(); ++k) {
                const auto& w = c.want.events[k];
                ok = ev[k].t == w.t && ev[k].leaf == w.leaf && ev[k].entering == w.entering &&
                     ev[k].slot == cs.layout.leaf_slot[w.leaf];
            }
            // on a miss every event is popped
            if (ok && !c.want.hit) ok = ev.size() == c.want.events.size();
            if (!ok && ++sort_bad <= 3)
                ADD_FAILURE() << tag << ": sorted ray " << r << " differs\n    " << describe(cs, c, &mon_flags[r], &ev);
            st.popped += ev.size();
        }
    }
    for (const RayCase& c : rays) st.hits += c.want.hit, st.events += c.want.events.size();
    st.rays += rays.size();
    st.cycles += cyc;
    st.leaves += total_in;
    std::ostringstream sum;
    sum << tag << ": " << rays.size() << " rays (" << n << " leaves), received " << received << ", mismatches "
        << mismatches << ", extra " << extra << ", sorted-ray mismatches " << sort_bad << (timeout ? ", TIMEOUT" : "")
        << ", " << cyc << " cycles";
    for (const std::string& m : msgs) sum << "\n  " << m;
    EXPECT_TRUE(!timeout && mismatches == 0 && extra == 0 && received == rays.size()) << sum.str();
    if (std::getenv("TB_VERBOSE")) std::printf("%s\n", sum.str().c_str());
}

int scaled(int x) { return std::max(4, int(x * tb::scale())); }

template <class P>
void run_all(uint64_t seed) {
    const std::vector<Scenario> scs = scenarios(P::kBits);
    for (TiePolicy ties : {TiePolicy::Paper, TiePolicy::Regular}) {
        RunStats st;
        for (const Scenario& sc : scs) {
            const auto rays = make_rays(sc.cs, ties, scaled(16), scaled(12), scaled(160), seed++);
            run<P>(sc, ties, rays, 0.2, 0.3, seed++, st);
        }
        std::printf("walk BITS=%d %s: %llu rays (%llu hits) in %zu scenes, %llu leaf results, %llu events ahead "
                    "(%llu popped), %llu cycles\n",
                    P::kBits, ties == TiePolicy::Paper ? "paper" : "regular", (unsigned long long)st.rays,
                    (unsigned long long)st.hits, scs.size(), (unsigned long long)st.leaves,
                    (unsigned long long)st.events, (unsigned long long)st.popped, (unsigned long long)st.cycles);
    }
}

TEST(Walk, Bits16) { run_all<P16>(tb::seed(1600)); }
TEST(Walk, Bits24) { run_all<P24>(tb::seed(2400)); }

// Back to back (no gaps, no back-pressure): clocks per ray.
template <class P>
void throughput() {
    const std::vector<Scenario> scs = scenarios(P::kBits);
    for (const Scenario& sc : scs) {
        if (sc.name != "default" && sc.name != "csg_mix") continue;
        const auto rays = make_rays(sc.cs, TiePolicy::Paper, 16, 12, 0, 1);
        RunStats st;
        run<P>(sc, TiePolicy::Paper, rays, 0.0, 0.0, 5, st);
        std::printf("walk BITS=%d %s back to back: %llu rays, %d leaves, %.1f events ahead per ray, %.1f popped, "
                    "%.2f clocks per ray (%.2f per leaf)\n",
                    P::kBits, sc.name.c_str(), (unsigned long long)st.rays, int(sc.cs.leaves.size()),
                    double(st.events) / st.rays, double(st.popped) / st.rays, double(st.cycles) / st.rays,
                    double(st.cycles) / st.leaves);
    }
}
TEST(Walk, BackToBack) { throughput<P24>(); }

}  // namespace
