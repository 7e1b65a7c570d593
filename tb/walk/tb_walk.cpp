// tb_walk.cpp — csgrt_walk_unit (csgrt_event_sort + csgrt_walker) against
// trace_primary_fx() (model/trace.cpp): Walk.* with SECONDARY = 0 (as in
// csgrt_top), WalkSecondary.* with SECONDARY = 1 against
// trace_primary_fx() and trace_secondary_fx() on child rays (see the
// section "Secondary rays" below), and WalkLookAhead.* with LOOK_AHEAD = 1
// against the same with the refraction look-ahead (TraceOptions::lookahead;
// the section "The refraction look-ahead").
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
#include "raytree.h"
#include "render.h"
#include "stream.h"
#include "trace.h"

#include <gtest/gtest.h>

#include <algorithm>
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

#define WALK_MEMBERS(X, B)                                                                                    \
    static constexpr int kBits = B;                                                                           \
    Top* t;                                                                                                   \
    tb::StreamPorts ports() {                                                                                 \
        return {&t->X##_clk_i, &t->X##_rst_ni, &t->X##_valid_i,                                               \
                &t->X##_ready_o, &t->X##_valid_o, &t->X##_ready_i};                                           \
    }                                                                                                         \
    template <class F> void cfg(F f) {                                                                        \
        f(t->X##_ties_regular_i, t->X##_node_op_i, t->X##_slot_mat_i, t->X##_slot_used_i);                    \
    }                                                                                                         \
    void drive(int slot, int leaf, const LeafEvents<i64>& le, bool last, uint32_t pay) {                      \
        const int TW = B - 1;                                                                                 \
        t->X##_slot_i = uint8_t(slot);                                                                        \
        t->X##_leaf_i = uint8_t(leaf);                                                                        \
        t->X##_count_i = uint8_t(le.count);                                                                   \
        t->X##_t0_i = uint32_t(uint64_t(le.ev[0].t) & tb::mask(TW));                                          \
        t->X##_range0_i = uint8_t(le.ev[0].range);                                                            \
        t->X##_enter0_i = le.ev[0].entering;                                                                  \
        t->X##_t1_i = uint32_t(uint64_t(le.ev[1].t) & tb::mask(TW));                                          \
        t->X##_range1_i = uint8_t(le.ev[1].range);                                                            \
        t->X##_enter1_i = le.ev[1].entering;                                                                  \
        t->X##_inside_i = le.inside_at_minus_inf;                                                             \
        t->X##_last_i = last;                                                                                 \
        t->X##_payload_i = pay;                                                                               \
    }                                                                                                         \
    Rec read() {                                                                                              \
        Rec r;                                                                                                \
        r.hit = t->X##_hit_o;                                                                                 \
        r.t = tb::sext(t->X##_t_o, B - 1);                                                                    \
        r.leaf = t->X##_leaf_o;                                                                               \
        r.slot = t->X##_slot_o;                                                                               \
        r.entering = t->X##_entering_o;                                                                       \
        r.from = t->X##_from_o;                                                                               \
        r.to = t->X##_to_o;                                                                                   \
        r.payload = t->X##_payload_o;                                                                         \
        for (int s = 0; s < 256; ++s) r.flags[s] = uint8_t(get(t->X##_flags_before_o, s, 1));                 \
        return r;                                                                                             \
    }                                                                                                         \
    bool mon_load() { return t->X##_mon_load_o; }                                                             \
    std::vector<uint8_t> mon_flags() {                                                                        \
        std::vector<uint8_t> f(256);                                                                          \
        for (int s = 0; s < 256; ++s) f[s] = uint8_t(get(t->X##_mon_flags_o, s, 1));                          \
        return f;                                                                                             \
    }                                                                                                         \
    bool mon_pop() { return t->X##_mon_pop_o; }                                                               \
    Ev mon_ev() {                                                                                             \
        return {tb::sext(t->X##_mon_t_o, B - 1), int(t->X##_mon_leaf_o),                                      \
                int(t->X##_mon_slot_o), bool(t->X##_mon_ent_o)};                                              \
    }

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
struct P16 { WALK_MEMBERS(b16, 16) };
struct P24 { WALK_MEMBERS(b24, 24) };

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
    // six boxes in a row with one top plane: a ray onto the last top crosses
    // five coincident tops first (more than LOOK_BEHIND; the near side
    // undoes the whole tie group)
    {"coplanar_tops",
     "union { box { <-1.5,-0.5,-0.5>, <-1,0.5,0.5> pigment { color rgb <1,0,0> } }\n"
     "        box { <-1,-0.5,-0.5>, <-0.5,0.5,0.5> pigment { color rgb <0,1,0> } }\n"
     "        box { <-0.5,-0.5,-0.5>, <0,0.5,0.5> pigment { color rgb <0,0,1> } }\n"
     "        box { <0,-0.5,-0.5>, <0.5,0.5,0.5> pigment { color rgb <1,1,0> } }\n"
     "        box { <0.5,-0.5,-0.5>, <1,0.5,0.5> pigment { color rgb <0,1,1> } }\n"
     "        box { <1,-0.5,-0.5>, <1.5,0.5,0.5> pigment { color rgb <1,0,1> } } }\n"},
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
    // shared faces: tie groups on every pixel, edges where the hit reports
    // another surface than its crossing's
    for (const char* f : {"fig06_add_shared", "fig07_sub_shared"})
        v.push_back({f, compile(parse_scene_file(std::string("scenes/paper/") + f + ".pov"), bits)});
    for (auto& s : kInline) {
        const std::string text = std::string("camera { location <0.7, 2.3, -5> look_at <0, 0, 0> }\n"
                                             "light_source { <-4, 6, -5> color rgb <1, 1, 1> }\n") + s[1];
        v.push_back({s[0], compile(parse_scene_string(text, std::string(s[0]) + ".pov"), bits)});
    }
    return v;
}

// The model's trace options: WalkLookAhead.* turns the refraction
// look-ahead on (TraceOptions::lookahead), everything else runs without.
bool g_lookahead = false;
TraceOptions model_options() {
    TraceOptions o;
    o.lookahead = g_lookahead;
    return o;
}

std::vector<RayCase> make_rays(const CompiledScene& cs, TiePolicy ties, int grid_x, int grid_y, int n_random,
                               uint64_t seed, bool tie_scan = false) {
    std::vector<RayCase> out;
    const Formats& fmt = cs.fmt;
    auto add = [&](const RayFx& r) {
        RayCase c;
        c.ray = r;
        try {
            for (const LeafInfo& l : cs.leaves) c.le.push_back(intersect_fx(fmt, l.coef, r));
            c.want = trace_primary_fx(cs, r, ties, true, model_options());
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
    // With tie_scan, tie groups (docs/numerics.md section 5, the hit's surface): camera
    // rays of a 640x480 view whose hit reports another surface than its
    // crossing's leaf (rare: an edge at this width's resolution), all of
    // them, and a sample of hits tied with other events (probes, hits held
    // for their group).
    if (!tie_scan) return out;
    CompiledScene fine = cs;
    fine.width = 640, fine.height = 480;
    std::vector<RayFx> tied;
    for (int y = 0; y < fine.height; ++y)
        for (int x = 0; x < fine.width; ++x) {
            const RayFx r = camera_ray_fx(fine, x, y);
            TraceResult<i64> tr;
            try {
                tr = trace_primary_fx(cs, r, ties, false, model_options());
            } catch (const std::logic_error&) {
                continue;
            }
            if (!tr.hit) continue;
            if (tr.leaf != tr.cross_leaf) {
                add(r);
            } else if (tied.size() < 4096 && rng() % 16 == 0) {
                const TraceResult<i64> d = trace_primary_fx(cs, r, ties, true, model_options());
                if (std::count_if(d.events.begin(), d.events.end(), [&](const Event<i64>& e) { return e.t == d.t; }) > 1)
                    tied.push_back(r);
            }
        }
    for (int k = 0; k < n_random / 4 && !tied.empty(); ++k) add(tied[rng() % tied.size()]);
    return out;
}

// Scenes with shared faces, whose rays make_rays() scans for tie groups.
bool tie_scene(const std::string& name) {
    return name.rfind("fig", 0) == 0 || name.find("touching") != std::string::npos ||
           name.find("twice") != std::string::npos || name.find("coplanar") != std::string::npos;
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
    uint64_t surface = 0;   // hits whose reported surface is not the crossing's leaf (a tie group)
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
                    field("slot", o.slot, cs.layout.leaf_slot[c.want.cross_leaf]);
                    field("entering", o.entering, c.want.entering);
                    field("from", o.from, c.want.border.from);
                    field("to", o.to, c.want.border.to);
                    // The flags just before the hit's tie group: the
                    // origin flags with every valid event at an earlier t
                    // applied. (The model's near side also undoes crossings
                    // before the group whose surface the hit point does not
                    // lie beyond, its look-behind; the RTL gains that with
                    // secondary rays, so it is not compared here.)
                    std::vector<uint8_t> before = c.want.origin_flags;
                    for (const auto& e : c.want.events) {
                        if (e.t == c.want.t) break;
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
    for (const RayCase& c : rays) {
        st.hits += c.want.hit, st.events += c.want.events.size();
        st.surface += c.want.hit && c.want.leaf != c.want.cross_leaf;
    }
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
    uint64_t surface = 0;
    for (TiePolicy ties : {TiePolicy::Paper, TiePolicy::Regular}) {
        RunStats st;
        for (const Scenario& sc : scs) {
            const auto rays = make_rays(sc.cs, ties, scaled(16), scaled(12), scaled(160), seed++, tie_scene(sc.name));
            run<P>(sc, ties, rays, 0.2, 0.3, seed++, st);
        }
        surface += st.surface;
        std::printf("walk BITS=%d %s: %llu hits report another surface than their crossing's leaf (tie groups)\n",
                    P::kBits, ties == TiePolicy::Paper ? "paper" : "regular", (unsigned long long)st.surface);
        std::printf("walk BITS=%d %s: %llu rays (%llu hits) in %zu scenes, %llu leaf results, %llu events ahead "
                    "(%llu popped), %llu cycles\n",
                    P::kBits, ties == TiePolicy::Paper ? "paper" : "regular", (unsigned long long)st.rays,
                    (unsigned long long)st.hits, scs.size(), (unsigned long long)st.leaves,
                    (unsigned long long)st.events, (unsigned long long)st.popped, (unsigned long long)st.cycles);
    }
    // the scanned rays must exercise the hit's surface rule (probes, a held
    // hit); at 24 bits the shared-face scenes have no such edge in 640x480
    if (P::kBits <= 16) EXPECT_GT(surface, 0u) << "no ray whose hit reports another surface than its crossing's";
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

// ---------------------------------------------------------------------------
// Secondary rays: the SECONDARY = 1 build (s16, s24).
//
// One stream mixes primary rays and child rays in random order, each with
// its info record (info stream with its own random gaps). Primary rays
// carry random garbage in every other info field (it must be ignored);
// they are compared with trace_primary_fx() as above plus flags_after and
// the look-behind run (TraceResult::flags_after, near_run). Child rays are
// built with the model's functions from each primary hit p (hit_point_fx):
//   reflected  d = reflect_fx(d, normal_fx(..)), near side: info flags =
//              the parent's flags_hit_near, run = its near_run;
//   shadow     shadow_ray_fx() towards each light, near side, t limit =
//              the light's distance (0 when it is 2 or more: no limit);
//   far side   the parent's direction, flags_after, no run, no limit;
//   random run the reflected ray with flags_hit_near and a random run on
//              the hit's and the run's leaves (repeated slots: the order of
//              the fix-up's writes), flags = that run applied as specified,
//              mostly a t limit equal to (or 1 ulp past) an event's t;
// and compared with trace_secondary_fx(cs, child, parent.flags_before (the
// random run: its own fix-up) or flags_after, ties, true, {t_limit}): hit,
// t, leaf, slot, entering, from, to, flags_before (= the model's
// flags_hit_near), flags_after, the run; on a miss all of those must be 0.
// The origin flags the sorter hands to the walker must equal the model's
// (the look-behind fix-up), the popped events a prefix of the model's (the
// t limit). Unused slots and run entries past the count carry random
// garbage too. Primary rays include rays along the boundaries between
// leaves (edge_rays), where the look-behind is decided by c, not by equal t.

struct SecCase {
    int kind = 0;   // 0 primary, 1 reflected, 2 shadow, 3 far side, 4 reflected with a random run
    RayFx ray;
    std::vector<LeafEvents<i64>> le;
    TraceResult<i64> want;
    // the info record
    bool secondary = false;
    std::vector<uint8_t> info_flags = std::vector<uint8_t>(256);
    uint64_t tlimit = 0;
    int lb_count = 0;
    int lb_slot[4] = {}, lb_ent[4] = {}, lb_same[4] = {};
    // the look-behind by the model's rule: entries undone, those of them
    // decided by c (same_t = 0), whether the flags change
    int undone = 0, undone_by_c = 0;
    bool fixup_changes = false;
    bool undone_twice = false;   // two undone entries of one slot whose order matters
    bool limit_on_event = false; // the t limit equals the t of an event ahead
};
const char* const kKind[] = {"primary", "reflected", "shadow", "far side", "random run"};

struct SecRec {
    Rec base;
    std::vector<uint8_t> after = std::vector<uint8_t>(256);
    int lb_count = 0;
    int lb_slot[4] = {}, lb_ent[4] = {}, lb_same[4] = {};
};

#define SEC_MEMBERS(X, B)                                                                                     \
    uint8_t* info_valid() { return &t->X##_info_valid_i; }                                                   \
    bool info_ready() { return t->X##_info_ready_o; }                                                         \
    void cpos(bool c) { t->X##_cpos_i = c; }                                                                  \
    void info(const SecCase& c) {                                                                             \
        t->X##_info_secondary_i = c.secondary;                                                                \
        for (int s = 0; s < 256; ++s) put(t->X##_info_flags_i, s, 1, c.info_flags[s]);                       \
        put(t->X##_info_tlimit_i, 0, B - 2, c.tlimit);                                                        \
        t->X##_info_lb_count_i = uint8_t(c.lb_count);                                                         \
        uint32_t sl = 0, en = 0, sa = 0;                                                                      \
        for (int k = 0; k < 4; ++k)                                                                           \
            sl |= uint32_t(c.lb_slot[k]) << (8 * k), en |= uint32_t(c.lb_ent[k]) << k,                        \
                sa |= uint32_t(c.lb_same[k]) << k;                                                            \
        t->X##_info_lb_slot_i = sl;                                                                           \
        t->X##_info_lb_entering_i = uint8_t(en);                                                              \
        t->X##_info_lb_same_t_i = uint8_t(sa);                                                                \
    }                                                                                                         \
    SecRec read_sec() {                                                                                       \
        SecRec r;                                                                                             \
        r.base = read();                                                                                      \
        for (int s = 0; s < 256; ++s) r.after[s] = uint8_t(get(t->X##_flags_after_o, s, 1));                  \
        r.lb_count = t->X##_lb_count_o;                                                                       \
        for (int k = 0; k < 4; ++k) {                                                                         \
            r.lb_slot[k] = int((t->X##_lb_slot_o >> (8 * k)) & 0xff);                                         \
            r.lb_ent[k] = (t->X##_lb_entering_o >> k) & 1;                                                    \
            r.lb_same[k] = (t->X##_lb_same_t_o >> k) & 1;                                                     \
        }                                                                                                     \
        return r;                                                                                             \
    }

// the look-ahead's configuration and query port (l16, l24)
#define LA_MEMBERS(X, B)                                                                                      \
    static constexpr bool kLA = true;                                                                         \
    void mat_clear(const CompiledScene& cs) {                                                                 \
        for (int m = 0; m < 256; ++m) put(t->X##_mat_clear_i, m, 1, m < int(cs.materials.size()) && is_transparent(cs, m)); \
    }                                                                                                         \
    bool q_valid() { return t->X##_q_valid_o; }                                                               \
    uint8_t* q_ready() { return &t->X##_q_ready_i; }                                                          \
    i64 q_t() { return tb::sext(t->X##_q_t_o, B - 1); }                                                       \
    int q_leaf() { return int(t->X##_q_leaf_o); }                                                             \
    uint32_t q_payload() { return t->X##_q_payload_o; }                                                       \
    uint8_t* a_valid() { return &t->X##_a_valid_i; }                                                          \
    bool a_ready() { return t->X##_a_ready_o; }                                                               \
    uint8_t* a_nonpos() { return &t->X##_a_nonpos_i; }

struct S16 { static constexpr bool kLA = false; WALK_MEMBERS(s16, 16) SEC_MEMBERS(s16, 16) };
struct S24 { static constexpr bool kLA = false; WALK_MEMBERS(s24, 24) SEC_MEMBERS(s24, 24) };
struct L16 { WALK_MEMBERS(l16, 16) SEC_MEMBERS(l16, 16) LA_MEMBERS(l16, 16) };
struct L24 { WALK_MEMBERS(l24, 24) SEC_MEMBERS(l24, 24) LA_MEMBERS(l24, 24) };

std::vector<Scenario> sec_scenarios(int bits) {
    std::vector<Scenario> v = scenarios(bits);
    for (const char* f : {"fig08_reflect", "fig14_self_add"})   // scenarios() has Fig. 6 and 7
        v.push_back({f, compile(parse_scene_file(std::string("scenes/paper/") + f + ".pov"), bits)});
    return v;
}

std::vector<uint8_t> to_slots(const CompiledScene& cs, const std::vector<uint8_t>& by_leaf) {
    std::vector<uint8_t> v(256, 0);
    for (size_t l = 0; l < cs.leaves.size(); ++l) v[cs.layout.leaf_slot[l]] = by_leaf[l];
    return v;
}

// Rays along the boundary between two leaves' visible regions (box edges,
// silhouettes): bisection between two camera rays that hit different leaves
// (or hit and miss) down to adjacent quantised directions; both end rays
// are kept. There the hit's crossing and the one just before it lie within
// an ulp or two of each other, where the look-behind decides by the sign
// of c rather than by equal t.
std::vector<RayCase> edge_rays(const CompiledScene& cs, TiePolicy ties, int n_pairs, std::mt19937_64& rng) {
    std::vector<RayCase> out;
    const int F = cs.fmt.frac;
    auto leaf_of = [&](const RayFx& r) {
        try {
            const TraceResult<i64> tr = trace_primary_fx(cs, r, ties, false, model_options());
            return tr.hit ? tr.leaf : -1;
        } catch (const std::logic_error&) {
            return -2;
        }
    };
    for (int k = 0, tries = 0; k < n_pairs && tries < 20 * n_pairs; ++tries) {
        const RayFx r0 = camera_ray_fx(cs, int(rng() % cs.width), int(rng() % cs.height));
        const RayFx r1 = camera_ray_fx(cs, int(rng() % cs.width), int(rng() % cs.height));
        const int l0 = leaf_of(r0);
        if (l0 == -2 || l0 == leaf_of(r1)) continue;
        ++k;
        RayFx ra = r0, rb = r1;
        double lo = 0.0, hi = 1.0;
        for (int it = 0; it < 64 && ra.d != rb.d; ++it) {
            const double m = 0.5 * (lo + hi);
            double v[3], len = 0.0;
            for (int i = 0; i < 3; ++i) v[i] = (1.0 - m) * double(r0.d[i]) + m * double(r1.d[i]), len += v[i] * v[i];
            len = std::sqrt(len);
            RayFx rm = r0;
            for (int i = 0; i < 3; ++i) rm.d[i] = i64(std::llround(v[i] / len * double((i64(1) << F) - 1)));
            if (leaf_of(rm) == l0) lo = m, ra = rm;
            else hi = m, rb = rm;
        }
        for (const RayFx& r : {ra, rb}) {
            RayCase c;
            c.ray = r;
            try {
                for (const LeafInfo& l : cs.leaves) c.le.push_back(intersect_fx(cs.fmt, l.coef, r));
                c.want = trace_primary_fx(cs, r, ties, true, model_options());
            } catch (const std::logic_error&) {
                continue;
            }
            out.push_back(std::move(c));
        }
    }
    return out;
}

std::vector<SecCase> make_sec_cases(const CompiledScene& cs, TiePolicy ties, int grid_x, int grid_y, int n_random,
                                    int n_edge, uint64_t seed, bool children, bool tie_scan = false) {
    std::mt19937_64 rng(seed);
    const int F = cs.fmt.frac;
    const int n = int(cs.leaves.size());
    auto garbage = [&](SecCase& c) {
        for (int s = 0; s < 256; ++s) c.info_flags[s] = uint8_t(rng() & 1);
        c.tlimit = rng() & tb::mask(F + 1);
        c.lb_count = int(rng() % 8);
        for (int k = 0; k < 4; ++k)
            c.lb_slot[k] = int(rng() & 0xff), c.lb_ent[k] = int(rng() & 1), c.lb_same[k] = int(rng() & 1);
    };
    std::vector<SecCase> out;
    std::vector<RayCase> prim = make_rays(cs, ties, grid_x, grid_y, n_random, seed, tie_scan);
    for (RayCase& c : edge_rays(cs, ties, n_edge, rng)) prim.push_back(std::move(c));
    for (const RayCase& rc : prim) {
        SecCase c;
        garbage(c);   // a primary ray ignores all of it
        c.ray = rc.ray;
        c.le = rc.le;
        c.want = rc.want;
        out.push_back(std::move(c));
    }
    for (const RayCase& rc : prim) {
        const TraceResult<i64>& pt = rc.want;
        std::array<i64, 3> p;
        if (!children || !pt.hit || !hit_point_fx(cs.fmt, rc.ray, pt.t, p)) continue;
        const std::array<i64, 3> nrm = normal_fx(cs, pt.leaf, p, rc.ray.d);
        // kind 1, 2: near side with the parent's run; 3: far side; 4: near
        // side with a random run (entries on the hit's and the run's leaves,
        // slots repeated, random senses and same-t bits)
        auto add = [&](int kind, const std::array<i64, 3>& d, i64 t_limit) {   // t_limit: 0 none
            SecCase c;
            garbage(c);   // unused slots and run entries past the count stay random
            c.kind = kind;
            c.secondary = true;
            c.ray.o = p;
            c.ray.d = d;
            TraceOptions opt = model_options();
            opt.t_limit_fx = t_limit;
            c.tlimit = t_limit < (i64(1) << (F + 1)) ? uint64_t(t_limit) : 0;
            const bool near = kind != 3;
            const std::vector<uint8_t>& in = near ? pt.flags_hit_near : pt.flags_after;
            try {
                for (const LeafInfo& l : cs.leaves) c.le.push_back(intersect_fx(cs.fmt, l.coef, c.ray));
            } catch (const std::logic_error&) {
                return;   // outside the model's bounds
            }
            std::vector<Event<i64>> run;
            std::vector<bool> same;
            if (kind == 4) {
                // a t limit on one of the ray's events ahead, or just past it
                std::vector<i64> ts;
                for (const LeafEvents<i64>& le : c.le)
                    for (int e = 0; e < le.count; ++e)
                        if (le.ev[e].range == TRange::Finite && le.ev[e].t > 0) ts.push_back(le.ev[e].t);
                if (!ts.empty() && rng() % 4) {
                    t_limit = ts[rng() % ts.size()] + i64(rng() % 3 == 0);
                    c.limit_on_event = std::count(ts.begin(), ts.end(), t_limit) > 0;
                }
                opt.t_limit_fx = t_limit;
                c.tlimit = t_limit < (i64(1) << (F + 1)) ? uint64_t(t_limit) : 0;
                std::vector<int> pool{pt.leaf, int(rng() % n)};
                for (const Event<i64>& b : pt.near_run) pool.push_back(b.leaf);
                const int two[2] = {pool[rng() % pool.size()], pool[rng() % pool.size()]};
                for (int k = int(rng() % 5); k > 0; --k) {
                    Event<i64> b;
                    b.leaf = uint16_t(two[rng() % 2]);
                    b.entering = rng() & 1;
                    run.push_back(b);
                    same.push_back(rng() % 3 == 0);
                }
            } else if (near) {
                run = pt.near_run;
                for (const Event<i64>& b : run) same.push_back(b.t == pt.t);
            }
            // the look-behind fix-up as specified: entry k undone iff the
            // more recent ones are and (same t or the origin is not beyond
            // its surface, by the sign of c); later (older) writes win
            for (int l = 0; l < n; ++l) c.info_flags[cs.layout.leaf_slot[l]] = in[l];
            c.lb_count = int(run.size());
            std::vector<uint8_t> fixed = in;
            std::vector<int> undone_slots;
            bool undo = true;
            for (int k = 0; k < c.lb_count; ++k) {
                const Event<i64>& b = run[k];
                c.lb_slot[k] = cs.layout.leaf_slot[b.leaf];
                c.lb_ent[k] = b.entering;
                c.lb_same[k] = same[k];
                const bool cpos = c.le[b.leaf].c > 0;
                const bool beyond = b.entering ? !cpos : cpos;
                undo = undo && (same[k] || !beyond);
                if (undo) {
                    if (std::count(undone_slots.begin(), undone_slots.end(), c.lb_slot[k]) &&
                        fixed[b.leaf] != uint8_t(!b.entering))
                        c.undone_twice = true;   // the order of the writes matters
                    undone_slots.push_back(c.lb_slot[k]);
                    fixed[b.leaf] = !b.entering;
                    ++c.undone;
                    c.undone_by_c += !same[k];
                }
            }
            // what the RTL rests on: the sign of c at the child's origin
            // decides as quadric_at_fx() at the parent's hit point
            if ((kind == 1 || kind == 2) && fixed != pt.flags_before)
                ADD_FAILURE() << "look-behind from the child's c differs from the model's flags_before";
            c.fixup_changes = fixed != in;
            try {
                // the model's flags: parent.flags_before (near side), flags_after
                // (far side), or the random run's fix-up
                c.want = trace_secondary_fx(cs, c.ray, (kind == 1 || kind == 2) ? pt.flags_before : fixed, ties,
                                            true, opt);
            } catch (const std::logic_error&) {
                return;
            }
            out.push_back(std::move(c));
        };
        add(1, reflect_fx(rc.ray.d, nrm, F), 0);
        for (const LightInfo& li : cs.lights) {
            std::array<i64, 3> lv;
            for (int i = 0; i < 3; ++i) lv[i] = li.pos_fx[i] - p[i];
            if (lv[0] == 0 && lv[1] == 0 && lv[2] == 0) continue;
            i64 dist = 0;
            const RayFx sr = shadow_ray_fx(F, p, lv, dist);
            add(2, sr.d, dist);
        }
        add(3, rc.ray.d, 0);
        add(4, reflect_fx(rc.ray.d, nrm, F), 0);
    }
    if (children) std::shuffle(out.begin(), out.end(), rng);
    return out;
}

struct SecStats {
    // undo*: the parent's own runs (kinds 1, 2); random: kind 4
    uint64_t rays[5] = {}, hits[5] = {}, undo = 0, undo_by_c = 0, undo_changes = 0, limited = 0;
    uint64_t random_undo = 0, random_twice = 0, limit_on_event = 0;
    uint64_t cycles = 0, leaves = 0, events = 0, popped = 0, info_stalls = 0;
    uint64_t queries = 0, beyond = 0;   // look-ahead queries answered, of them "beyond"
};

template <class S>
void run_sec(const Scenario& sc, TiePolicy ties, const std::vector<SecCase>& rays, double p_gap, double p_stall,
             double p_info_gap, uint64_t seed, SecStats& st) {
    const CompiledScene& cs = sc.cs;
    const int n = int(cs.leaves.size());
    const std::string tag = sc.name + " SECONDARY BITS=" + std::to_string(S::kBits) +
                            (ties == TiePolicy::Paper ? " paper" : " regular");
    tb::Harness<Top> h;
    S p{h.top.get()};
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
    // the look-ahead's answerer: a query is taken (after random waits),
    // answered by the model's beyond test (quadric_at_fx at hit_point_fx
    // of the ray the payload names) after a random delay, held until taken
    bool q_busy = false, a_on = false, a_nonpos = false;
    int a_delay = 0;
    if constexpr (S::kLA) {
        p.mat_clear(cs);
        *p.q_ready() = 0;
        *p.a_valid() = 0;
    }
    *sp.valid_i = 0;
    *sp.ready_i = 0;
    *p.info_valid() = 0;
    *sp.rst_n = 0;
    for (int i = 0; i < 4; ++i) tick();
    *sp.rst_n = 1;

    const size_t total_in = rays.size() * size_t(n);
    size_t sent = 0, received = 0, extra = 0, mismatches = 0, info_idx = 0, proto = 0;
    std::vector<std::vector<uint8_t>> mon_flags;
    std::vector<std::vector<Ev>> mon_events;
    std::vector<std::string> msgs;
    bool pending = false, info_on = false;
    uint64_t idle = 0, cyc = 0, drain = 0;
    bool timeout = false;
    for (;; ++cyc) {
        if (sent < total_in && !pending) pending = !(u01(rng) < p_gap);
        if (info_idx < rays.size() && !info_on && !(u01(rng) < p_info_gap)) {
            info_on = true;
            p.info(rays[info_idx]);
        }
        *p.info_valid() = info_on;
        *sp.valid_i = pending;
        if (pending) {
            const size_t r = sent / n;
            const int l = int(sent % n);
            p.drive(cs.layout.leaf_slot[l], l, rays[r].le[l], l == n - 1, uint32_t(r));
            p.cpos(rays[r].le[l].c > 0);
        }
        *sp.ready_i = !(u01(rng) < p_stall);
        if constexpr (S::kLA) {
            *p.q_ready() = !q_busy && !(u01(rng) < p_stall);
            *p.a_valid() = a_on;
            *p.a_nonpos() = a_nonpos;
        }
        h.top->eval();
        const bool in_fire = *sp.valid_i && *sp.ready_o;
        const bool out_fire = *sp.valid_o && *sp.ready_i;
        const bool info_fire = info_on && p.info_ready();
        if constexpr (S::kLA) {
            if (a_on && p.a_ready()) {
                a_on = false;
                q_busy = false;
            }
            if (q_busy && !a_on && --a_delay <= 0) a_on = true;
            if (p.q_valid() && *p.q_ready()) {
                const uint32_t r = p.q_payload();
                std::array<i64, 3> hp{};
                if (r < rays.size()) {
                    hit_point_fx(cs.fmt, rays[r].ray, p.q_t(), hp);
                    const int leaf = p.q_leaf();
                    a_nonpos = leaf < n && quadric_at_fx(cs.fmt, cs.leaves[leaf].coef, hp) <= 0;
                } else {
                    ADD_FAILURE() << tag << ": a look-ahead query for ray " << r;
                }
                q_busy = true;
                a_delay = int(rng() % 4 == 0 ? rng() % 24 : 0);
                ++st.queries;
                st.beyond += a_nonpos;   // counted by sign; "beyond" depends on the event's sense
            }
        }
        // the info handshake: a leaf goes in only with its ray's record, the
        // record is popped exactly with the ray's last leaf
        const bool last_fire = in_fire && int(sent % n) == n - 1;
        if ((in_fire && !(info_on && sent / n == info_idx)) || info_fire != last_fire) {
            if (++proto <= 3)
                ADD_FAILURE() << tag << ": info handshake, cycle " << cyc << ": leaf " << sent << " in_fire "
                              << in_fire << " info_valid " << info_on << " info_ready " << p.info_ready()
                              << " record " << info_idx;
        }
        if (pending && !info_on) st.info_stalls += !*sp.ready_o;
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
                const SecCase& c = rays[received];
                const SecRec o = p.read_sec();
                std::ostringstream m;
                auto field = [&](const char* name, i64 dut, i64 model) {
                    if (dut != model) m << " " << name << ": DUT " << dut << " model " << model << ";";
                };
                auto slots = [&](const char* name, const std::vector<uint8_t>& dut, const std::vector<uint8_t>& want) {
                    for (int s = 0; s < 256; ++s)
                        if (dut[s] != want[s]) {
                            m << " " << name << " slot " << s << ": DUT " << int(dut[s]) << " model " << int(want[s])
                              << ";";
                            break;
                        }
                };
                const std::vector<uint8_t> zero(256, 0);
                field("payload", o.base.payload, uint32_t(received));
                field("hit", o.base.hit, c.want.hit);
                if (c.want.hit && o.base.hit) {
                    field("t", o.base.t, c.want.t);
                    field("leaf", o.base.leaf, c.want.leaf);
                    field("slot", o.base.slot, cs.layout.leaf_slot[c.want.cross_leaf]);
                    field("entering", o.base.entering, c.want.entering);
                    field("from", o.base.from, c.want.border.from);
                    field("to", o.base.to, c.want.border.to);
                    slots("flags_before", o.base.flags, to_slots(cs, c.want.flags_hit_near));
                    slots("flags_after", o.after, to_slots(cs, c.want.flags_after));
                    const int cnt = int(c.want.near_run.size());
                    field("lb_count", o.lb_count, cnt);
                    for (int k = 0; k < 4; ++k) {
                        const bool in = k < cnt;
                        const Event<i64>* b = in ? &c.want.near_run[k] : nullptr;
                        field(("lb_slot[" + std::to_string(k) + "]").c_str(), o.lb_slot[k],
                              in ? cs.layout.leaf_slot[b->leaf] : 0);
                        field(("lb_entering[" + std::to_string(k) + "]").c_str(), o.lb_ent[k], in ? b->entering : 0);
                        field(("lb_same_t[" + std::to_string(k) + "]").c_str(), o.lb_same[k],
                              in ? b->t == c.want.t : 0);
                    }
                } else if (!o.base.hit) {
                    // a miss: every field but the payload is 0
                    field("t", o.base.t, 0);
                    slots("flags_before", o.base.flags, zero);
                    slots("flags_after", o.after, zero);
                    field("lb_count", o.lb_count, 0);
                    for (int k = 0; k < 4; ++k) field("lb entry", o.lb_slot[k] | o.lb_ent[k] | o.lb_same[k], 0);
                }
                if (!m.str().empty()) {
                    ++mismatches;
                    if (msgs.size() < 5) {
                        RayCase rc{c.ray, c.le, c.want};
                        msgs.push_back("ray " + std::to_string(received) + " (" + kKind[c.kind] + ", look-behind " +
                                       std::to_string(c.undone) + " of " + std::to_string(c.lb_count) + "):" +
                                       m.str() + "\n    " +
                                       describe(cs, rc, received < mon_flags.size() ? &mon_flags[received] : nullptr,
                                                received < mon_events.size() ? &mon_events[received] : nullptr));
                    }
                }
                ++received;
            }
        }
        if (in_fire) {
            ++sent;
            pending = false;
        }
        if (info_fire) {
            ++info_idx;
            info_on = false;
        }
        tick();
        idle = (in_fire || out_fire) ? 0 : idle + 1;
        if (received == rays.size() && ++drain > 100) break;
        if (idle > 5000) {
            timeout = true;
            break;
        }
    }
    // the sorted rays handed to the walker: origin flags (inherited, with
    // the look-behind fix-up) and the events ahead within the t limit
    size_t sort_bad = 0;
    if (mon_flags.size() != rays.size()) {
        ADD_FAILURE() << tag << ": " << mon_flags.size() << " rays loaded by the walker, " << rays.size() << " sent";
    } else {
        for (size_t r = 0; r < rays.size(); ++r) {
            const SecCase& c = rays[r];
            bool ok = mon_flags[r] == to_slots(cs, c.want.origin_flags);
            const auto& ev = mon_events[r];
            ok = ok && ev.size() <= c.want.events.size();
            for (size_t k = 0; ok && k < ev.size(); ++k) {
                const auto& w = c.want.events[k];
                ok = ev[k].t == w.t && ev[k].leaf == w.leaf && ev[k].entering == w.entering &&
                     ev[k].slot == cs.layout.leaf_slot[w.leaf];
            }
            if (ok && !c.want.hit) ok = ev.size() == c.want.events.size();
            if (!ok && ++sort_bad <= 3) {
                RayCase rc{c.ray, c.le, c.want};
                ADD_FAILURE() << tag << ": sorted ray " << r << " (" << kKind[c.kind] << ", look-behind " << c.undone
                              << " of " << c.lb_count << ") differs\n    " << describe(cs, rc, &mon_flags[r], &ev);
            }
            st.popped += ev.size();
        }
    }
    uint64_t undo_here = 0, undo_c_here = 0;
    for (const SecCase& c : rays) {
        undo_here += c.undone > 0;
        undo_c_here += c.undone_by_c > 0;
        ++st.rays[c.kind];
        st.hits[c.kind] += c.want.hit;
        const bool own = c.kind == 1 || c.kind == 2;
        st.undo += own && c.undone > 0;
        st.undo_by_c += own && c.undone_by_c > 0;
        st.undo_changes += own && c.fixup_changes;
        st.random_undo += c.kind == 4 && c.undone > 0;
        st.random_twice += c.kind == 4 && c.undone_twice;
        st.limit_on_event += c.limit_on_event;
        st.limited += c.kind == 2 && c.tlimit != 0;
        st.events += c.want.events.size();
    }
    st.cycles += cyc;
    st.leaves += total_in;
    std::ostringstream sum;
    sum << tag << ": " << rays.size() << " rays (" << n << " leaves), received " << received << ", mismatches "
        << mismatches << ", extra " << extra << ", sorted-ray mismatches " << sort_bad << ", info handshake errors "
        << proto << (timeout ? ", TIMEOUT" : "") << ", " << cyc << " cycles, look-behind undo in " << undo_here
        << " rays (by c: " << undo_c_here << ")";
    for (const std::string& m : msgs) sum << "\n  " << m;
    EXPECT_TRUE(!timeout && mismatches == 0 && extra == 0 && received == rays.size()) << sum.str();
    if (std::getenv("TB_VERBOSE")) std::printf("%s\n", sum.str().c_str());
}

template <class S>
void run_sec_all(uint64_t seed) {
    const std::vector<Scenario> scs = sec_scenarios(S::kBits);
    uint64_t undo_total = 0, undo_by_c_total = 0, twice_total = 0, limit_total = 0, big_groups = 0;
    for (TiePolicy ties : {TiePolicy::Paper, TiePolicy::Regular}) {
        SecStats st;
        for (const Scenario& sc : scs) {
            const auto rays = make_sec_cases(sc.cs, ties, scaled(12), scaled(9), scaled(80), scaled(24), seed++, true,
                                             tie_scene(sc.name));
            run_sec<S>(sc, ties, rays, 0.2, 0.3, 0.3, seed++, st);
            // hits with more events of their tie group before them than the
            // look-behind's entries (the near side undoes the group whole)
            for (const SecCase& c : rays) {
                if (c.kind != 0 || !c.want.hit) continue;
                int before = 0;
                for (const Event<i64>& e : c.want.events) {
                    if (e.t == c.want.t && e.leaf == c.want.cross_leaf && e.entering == c.want.entering) break;
                    before += e.t == c.want.t;
                }
                big_groups += before > kLookBehind;
            }
        }
        std::printf("walk SECONDARY BITS=%d %s, %zu scenes: primary %llu (%llu hits), reflected %llu (%llu), "
                    "shadow %llu (%llu; %llu with a t limit), far side %llu (%llu), random run %llu (%llu); "
                    "reflected and shadow rays with a non-empty look-behind undo %llu (decided by c, not same "
                    "t: %llu; flags changed: %llu); random runs with an undo %llu (a slot undone twice, order "
                    "matters: %llu; a t limit on an event: %llu); %llu leaf results, %llu events ahead (%llu "
                    "popped), %llu cycles (%llu leaf stalls on the info stream)\n",
                    S::kBits, ties == TiePolicy::Paper ? "paper" : "regular", scs.size(),
                    (unsigned long long)st.rays[0], (unsigned long long)st.hits[0], (unsigned long long)st.rays[1],
                    (unsigned long long)st.hits[1], (unsigned long long)st.rays[2], (unsigned long long)st.hits[2],
                    (unsigned long long)st.limited, (unsigned long long)st.rays[3], (unsigned long long)st.hits[3],
                    (unsigned long long)st.rays[4], (unsigned long long)st.hits[4], (unsigned long long)st.undo,
                    (unsigned long long)st.undo_by_c, (unsigned long long)st.undo_changes,
                    (unsigned long long)st.random_undo, (unsigned long long)st.random_twice,
                    (unsigned long long)st.limit_on_event,
                    (unsigned long long)st.leaves,
                    (unsigned long long)st.events, (unsigned long long)st.popped, (unsigned long long)st.cycles,
                    (unsigned long long)st.info_stalls);
        undo_total += st.undo;
        undo_by_c_total += st.undo_by_c;
        twice_total += st.random_twice;
        limit_total += st.limit_on_event;
    }
    // the look-behind must actually fire, also where c decides and where
    // the order of the writes matters, or the test proves nothing
    EXPECT_GT(undo_total, 0u);
    EXPECT_GT(undo_by_c_total, 0u);
    EXPECT_GT(twice_total, 0u);
    EXPECT_GT(limit_total, 0u);
    std::printf("walk SECONDARY BITS=%d: %llu primary hits with more than %d events of their tie group before them\n",
                S::kBits, (unsigned long long)big_groups, kLookBehind);
    EXPECT_GT(big_groups, 0u);
}

TEST(WalkSecondary, Bits16) { run_sec_all<S16>(tb::seed(1610)); }
TEST(WalkSecondary, Bits24) { run_sec_all<S24>(tb::seed(2410)); }

// ---------------------------------------------------------------------------
// The refraction look-ahead: the LOOK_AHEAD = 1 build (l16, l24) against the
// model with TraceOptions::lookahead, on transparent scenes with coincident
// surfaces (and an opaque one: nothing may change there), primary rays and
// all their children as in WalkSecondary; the bench answers the walker's
// "beyond" queries with the model's own test.

const char* kGlassInline[][2] = {
    {"glass_box_twice",
     "union { box { <-1,-1,-1>, <1,1,1> pigment { color rgbf <1,0.5,0.5,0.8> } interior { ior 1.5 } }\n"
     "        box { <-1,-1,-1>, <1,1,1> pigment { color rgbf <0.5,1,0.5,0.7> } interior { ior 1.3 } } }\n"},
    {"glass_lamina",
     "difference { sphere { <0,0,0>, 1 pigment { color rgbf <1,1,1,0.9> } interior { ior 1.4 } }\n"
     "             sphere { <0,0,0>, 1 pigment { color rgbf <1,1,1,0.9> } interior { ior 1.4 } } }\n"},
    {"touching_glass_boxes",
     "union { box { <-1,-1,-1>, <0,1,1> pigment { color rgbf <1,0.6,0.6,0.8> } interior { ior 1.5 } }\n"
     "        box { <0,-1,-1>, <1,1,1> pigment { color rgbf <0.6,0.6,1,0.6> } interior { ior 1.2 } }\n"
     "        box { <-0.5,-1,-0.5>, <0.5,0,0.5> pigment { color rgb <1,1,0> } } }\n"},
    {"glass_minus_flush_cylinder",
     "difference { box { <-1,-1,-1>, <1,1,1> pigment { color rgbf <0.7,0.7,1,0.8> } interior { ior 1.5 } }\n"
     "             cylinder { <0,-1,0>, <0,1,0>, 0.5 pigment { color rgbf <1,1,1,0.5> } interior { ior 1.1 } } }\n"},
};

std::vector<Scenario> la_scenarios(int bits) {
    std::vector<Scenario> v;
    for (const char* f : {"glass", "nested_glass", "default"})
        v.push_back({f, compile(parse_scene_file(std::string("scenes/") + f + ".pov"), bits)});
    for (const char* f : {"fig13_coincident_transparent", "fig16_transparency"})
        v.push_back({f, compile(parse_scene_file(std::string("scenes/paper/") + f + ".pov"), bits)});
    for (auto& s : kGlassInline) {
        const std::string text = std::string("camera { location <0.7, 2.3, -5> look_at <0, 0, 0> }\n"
                                             "light_source { <-4, 6, -5> color rgb <1, 1, 1> }\n") + s[1];
        v.push_back({s[0], compile(parse_scene_string(text, std::string(s[0]) + ".pov"), bits)});
    }
    return v;
}

// What the look-ahead changed, by the model: hits whose BORDER to or far-side
// flags differ from the crossing alone, and rays whose hit it discarded or
// moved.
struct LaEffect {
    uint64_t moved_to = 0, moved_flags = 0, hit_changed = 0;
};
LaEffect la_effect(const CompiledScene& cs, TiePolicy ties, const std::vector<SecCase>& rays) {
    LaEffect e;
    for (const SecCase& c : rays) {
        if (c.kind != 0) continue;
        const TraceResult<i64>& a = c.want;
        const TraceResult<i64> b = trace_primary_fx(cs, c.ray, ties, true);   // no look-ahead
        if (a.hit != b.hit || (a.hit && (a.t != b.t || a.leaf != b.leaf))) {
            ++e.hit_changed;
            continue;
        }
        if (!a.hit) continue;
        e.moved_to += a.border.to != b.border.to;
        e.moved_flags += a.flags_after != b.flags_after;
    }
    return e;
}

template <class S>
void run_la_all(uint64_t seed) {
    g_lookahead = true;
    const std::vector<Scenario> scs = la_scenarios(S::kBits);
    LaEffect total;
    uint64_t queries = 0, beyond = 0;
    for (TiePolicy ties : {TiePolicy::Paper, TiePolicy::Regular}) {
        for (const Scenario& sc : scs) {
            const auto rays = make_sec_cases(sc.cs, ties, scaled(12), scaled(9), scaled(80), scaled(24), seed++, true,
                                             tie_scene(sc.name));
            SecStats st;
            run_sec<S>(sc, ties, rays, 0.2, 0.3, 0.3, seed++, st);
            const LaEffect e = la_effect(sc.cs, ties, rays);
            total.moved_to += e.moved_to;
            total.moved_flags += e.moved_flags;
            total.hit_changed += e.hit_changed;
            queries += st.queries;
            beyond += st.beyond;
            uint64_t surface = 0;
            for (const SecCase& c : rays) surface += c.kind == 0 && c.want.hit && c.want.leaf != c.want.cross_leaf;
            if (surface)
                std::printf("walk LOOK_AHEAD BITS=%d %s %s: %llu hits report another surface than their crossing's\n",
                            S::kBits, sc.name.c_str(), ties == TiePolicy::Paper ? "paper" : "regular",
                            (unsigned long long)surface);
            std::printf("walk LOOK_AHEAD BITS=%d %s %s: %zu rays; the look-ahead moved BORDER to on %llu primary "
                        "hits, the far-side flags on %llu, the hit itself on %llu; %llu queries (%llu with q <= 0)\n",
                        S::kBits, sc.name.c_str(), ties == TiePolicy::Paper ? "paper" : "regular", rays.size(),
                        (unsigned long long)e.moved_to, (unsigned long long)e.moved_flags,
                        (unsigned long long)e.hit_changed, (unsigned long long)st.queries,
                        (unsigned long long)st.beyond);
        }
    }
    g_lookahead = false;
    // the look-ahead must have done something, or the test proves nothing
    EXPECT_GT(total.moved_to, 0u);
    EXPECT_GT(total.moved_flags, 0u);
    EXPECT_GT(queries, 0u);
}

TEST(WalkLookAhead, Bits16) { run_la_all<L16>(tb::seed(1620)); }
TEST(WalkLookAhead, Bits24) { run_la_all<L24>(tb::seed(2420)); }

// Back to back with the info stream always valid: primary rays as in
// Walk.BackToBack (clocks per ray must match SECONDARY = 0), then with
// their children mixed in.
TEST(WalkSecondary, BackToBack) {
    const std::vector<Scenario> scs = scenarios(24);
    for (const Scenario& sc : scs) {
        if (sc.name != "default" && sc.name != "csg_mix") continue;
        for (bool children : {false, true}) {
            const auto rays = make_sec_cases(sc.cs, TiePolicy::Paper, 16, 12, 0, 0, 1, children);
            SecStats st;
            run_sec<S24>(sc, TiePolicy::Paper, rays, 0.0, 0.0, 0.0, 5, st);
            const uint64_t nr = st.rays[0] + st.rays[1] + st.rays[2] + st.rays[3] + st.rays[4];
            std::printf("walk SECONDARY BITS=24 %s back to back, %s: %llu rays, %d leaves, %.1f events ahead per "
                        "ray, %.1f popped, %.2f clocks per ray (%.2f per leaf)\n",
                        sc.name.c_str(), children ? "primary and child rays" : "primary rays",
                        (unsigned long long)nr, int(sc.cs.leaves.size()), double(st.events) / nr,
                        double(st.popped) / nr, double(st.cycles) / nr, double(st.cycles) / st.leaves);
        }
    }
}

}  // namespace
