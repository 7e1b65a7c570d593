// cull_test.cpp — bounding-box culling changes nothing (model/cull.h,
// docs/numerics.md section 9):
//   - every scene of scenes/ and scenes/paper/ renders to the same pixels,
//     hit leaves and materials with culling on and off, at 12, 16, 24 and 32
//     bits under both tie policies;
//   - the TraceResult (hit, t, leaf, sense, BORDER, flags before, after and
//     at the hit) of sampled primary rays and of the secondary rays the
//     renderer would cast from them (shadow rays and their crossings,
//     reflected and transmitted rays, a few generations deep) is the same;
//   - the certificate itself: on a ray whose segment misses a node's box,
//     the full trace classifies that subtree OUT at every one of its events;
//   - the pieces: the box test against an exact rational reference,
//     quadric_at_fast against quadric_at_fx, ClassTree::update against
//     reset;
//   - and that the comparison does fail when the boxes are wrong.
#include "classify.h"
#include "compile.h"
#include "cull.h"
#include "parse.h"
#include "raytree.h"
#include "render.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <random>
#include <sstream>

using namespace csgrt;

namespace {

std::vector<std::string> all_scenes() {
    std::vector<std::string> out;
    for (const char* dir : {"scenes", "scenes/paper"})
        for (const auto& e : std::filesystem::directory_iterator(dir))
            if (e.path().extension() == ".pov") out.push_back(e.path().string());
    std::sort(out.begin(), out.end());
    return out;
}

bool is_big(const std::string& path) { return path.find("fig17") != std::string::npos; }

// Compiles a scene at a test size; false when it does not fit the width.
bool compile_at(const std::string& path, int bits, bool cull, CompiledScene& cs) {
    CompileOptions o;
    o.bits = bits;
    o.width = is_big(path) ? 32 : 80;
    o.height = is_big(path) ? 24 : 60;
    o.max_leaves = 16384;
    o.cull = cull;
    try {
        cs = compile_scene(parse_scene_file(path), o);
        return true;
    } catch (const SceneError&) {
        return false;
    }
}

const char* tie_name(TiePolicy t) { return t == TiePolicy::Paper ? "paper" : "regular"; }

// The fields of a TraceResult a culled trace must reproduce.
std::string differs(const TraceResult<i64>& a, const TraceResult<i64>& b) {
    std::ostringstream s;
    if (a.hit != b.hit) s << " hit " << a.hit << "/" << b.hit;
    if (a.t != b.t) s << " t " << a.t << "/" << b.t;
    if (a.leaf != b.leaf) s << " leaf " << a.leaf << "/" << b.leaf;
    if (a.entering != b.entering) s << " entering";
    if (a.border != b.border) s << " border " << a.border.str() << "/" << b.border.str();
    auto flags = [&](const char* name, const std::vector<uint8_t>& x, const std::vector<uint8_t>& y) {
        if (x == y) return;
        s << " " << name;
        if (x.size() != y.size()) {
            s << " sizes " << x.size() << "/" << y.size();
            return;
        }
        for (size_t l = 0; l < x.size(); ++l)
            if (x[l] != y[l]) s << " [" << l << "]" << int(x[l]) << "/" << int(y[l]);
    };
    flags("flags_before", a.flags_before, b.flags_before);
    flags("flags_after", a.flags_after, b.flags_after);
    flags("flags_hit_near", a.flags_hit_near, b.flags_hit_near);
    return s.str();
}

// Traces a ray with culling on and off, compares, and returns the full
// trace's result. `what` names the ray for the failure message.
struct Comparer {
    const CompiledScene& cs;
    TiePolicy ties;
    int rays = 0, mismatches = 0;
    std::string first;

    TraceResult<i64> trace(const RayFx& ray, const std::vector<uint8_t>* flags, TraceOptions opt,
                           const std::string& what) {
        TraceResult<i64> full, culled;
        opt.cull = false;
        try {
            full = flags ? trace_secondary_fx(cs, ray, *flags, ties, false, opt) : trace_primary_fx(cs, ray, ties, false, opt);
        } catch (const std::logic_error&) {
            return full;   // outside the model's bounds: no ray to compare
        }
        opt.cull = true;
        culled = flags ? trace_secondary_fx(cs, ray, *flags, ties, false, opt) : trace_primary_fx(cs, ray, ties, false, opt);
        ++rays;
        const std::string d = differs(culled, full);
        if (!d.empty() && mismatches++ == 0) first = what + ":" + d;
        return full;
    }

    // A ray and the secondary rays the renderer casts from its hit, down to
    // `depth` generations (raytree.cpp's choices: shadow rays with the near
    // side's flags and their crossings with the far side's, the reflected
    // ray with the near side's, the transmitted ray with the far side's or,
    // on total internal reflection, the near side's).
    void tree(const RayFx& ray, const std::vector<uint8_t>* flags, int depth, const EffectSet& fx,
              const std::string& what) {
        const int F = cs.fmt.frac;
        TraceOptions topt;
        topt.lookahead = fx.refraction;
        const TraceResult<i64> tr = trace(ray, flags, topt, what);
        std::array<i64, 3> p;
        if (!tr.hit || !hit_point_fx(cs.fmt, ray, tr.t, p)) return;
        const std::array<i64, 3> n = normal_fx(cs, tr.leaf, p, ray.d);
        for (size_t k = 0; k < cs.lights.size(); ++k) {
            std::array<i64, 3> lv;
            i128 nl = 0;
            for (int i = 0; i < 3; ++i) lv[i] = cs.lights[k].pos_fx[i] - p[i], nl += i128(n[i]) * lv[i];
            if (nl <= 0) continue;
            TraceOptions so;
            so.lookahead = fx.refraction;
            RayFx s = shadow_ray_fx(F, p, lv, so.t_limit_fx);
            std::vector<uint8_t> sf = tr.flags_before;
            for (int crossing = 0; crossing < 16; ++crossing) {
                const TraceResult<i64> st = trace(s, &sf, so, what + " shadow" + std::to_string(crossing));
                if (!st.hit) break;
                std::array<i64, 3> q;
                if (!hit_point_fx(cs.fmt, s, st.t, q)) break;
                s.o = q;
                sf = st.flags_after;
                so.t_limit_fx -= st.t;
                if (so.t_limit_fx <= 0) break;
            }
        }
        if (depth <= 1) return;
        const int mat = tr.border.to ? tr.border.to : tr.border.from;
        const MaterialInfo& m = cs.materials[mat];
        RayFx child;
        child.o = p;
        child.d = reflect_fx(ray.d, n, F);
        tree(child, &tr.flags_before, depth - 1, fx, what + " refl");
        if (m.filter > 0 || is_transparent(cs, tr.border.to)) {
            const std::vector<uint8_t>* cf = &tr.flags_after;
            if (!refract_fx(ray.d, n, ior_of(cs, tr.border.from), ior_of(cs, tr.border.to), F, child.d)) {
                child.d = reflect_fx(ray.d, n, F);
                cf = &tr.flags_before;
            }
            tree(child, cf, depth - 1, fx, what + " refr");
        }
    }
};

bool frames_equal(const Frame& a, const Frame& b) {
    return a.rgb == b.rgb && a.hit_leaf == b.hit_leaf && a.material == b.material;
}

int count_diff(const Frame& a, const Frame& b) {
    int n = 0;
    for (size_t i = 0; i < a.hit_leaf.size(); ++i)
        n += a.rgb_differs(b, i) || a.hit_leaf[i] != b.hit_leaf[i] || a.material[i] != b.material[i];
    return n;
}

}  // namespace

// Every scene, every width, both tie policies: the same frame bit for bit.
TEST(Cull, EveryScenePixelIdenticalWithAndWithoutCulling) {
    reset_cull_stats();
    int configs = 0, skipped = 0;
    for (const std::string& path : all_scenes())
        for (int bits : {12, 16, 24, 32}) {
            CompiledScene on, off;
            if (!compile_at(path, bits, true, on)) {   // too fine for the width (the compiler says so)
                ++skipped;
                continue;
            }
            ASSERT_TRUE(compile_at(path, bits, false, off));
            ASSERT_FALSE(on.cull.empty()) << path;
            ASSERT_TRUE(off.cull.empty()) << path;
            for (TiePolicy ties : {TiePolicy::Paper, TiePolicy::Regular}) {
                RenderOptions ro;
                ro.ties = ties;
                const Frame a = render(on, ro), b = render(off, ro);
                EXPECT_TRUE(frames_equal(a, b)) << path << " bits " << bits << " ties " << tie_name(ties) << ": "
                                                << count_diff(a, b) << " pixels differ";
                ++configs;
            }
        }
    const CullStats st = cull_stats();
    std::printf("culling: %d configurations (%d scene/width pairs refused by the compiler), %llu traces, "
                "%.1f%% of leaves skipped, %llu traced again with some culled leaves, %llu without culling\n",
                configs, skipped, (unsigned long long)st.rays, 100.0 * double(st.culled_leaves) / double(st.leaves),
                (unsigned long long)st.retraces, (unsigned long long)st.fallbacks);
    EXPECT_GE(configs, 140);
    EXPECT_GT(st.culled_leaves, st.leaves / 4);   // the culling did run
    EXPECT_GT(st.retraces, 0u);                    // and so did its second pass
}

// Primary rays and the secondary rays cast from them: the same TraceResult.
TEST(Cull, TraceResultsIdenticalOnPrimaryAndSecondaryRays) {
    int total = 0, configs = 0;
    for (const std::string& path : all_scenes())
        for (int bits : {12, 16, 24, 32}) {
            CompiledScene cs;
            if (!compile_at(path, bits, true, cs)) continue;
            const EffectSet fx = scene_effects(cs);
            for (TiePolicy ties : {TiePolicy::Paper, TiePolicy::Regular}) {
                Comparer cmp{cs, ties, 0, 0, {}};
                const int step = is_big(path) ? 3 : 5;
                for (int y = step / 2; y < cs.height; y += step)
                    for (int x = (y / step) % step; x < cs.width; x += step)
                        cmp.tree(camera_ray_fx(cs, x, y), nullptr, 3, fx,
                                 "pixel " + std::to_string(x) + "," + std::to_string(y));
                EXPECT_EQ(cmp.mismatches, 0) << path << " bits " << bits << " ties " << tie_name(ties) << ": "
                                             << cmp.mismatches << " of " << cmp.rays << " rays, first " << cmp.first;
                total += cmp.rays;
                ++configs;
            }
        }
    std::printf("culling: %d rays compared over %d configurations\n", total, configs);
    EXPECT_GT(total, 100000);
}

// The certificate (docs/numerics.md section 9.2): when a ray's segment misses a
// node's box, the full trace classifies that subtree OUT at every event of
// its leaves and keeps it OUT between events. Checked on the full trace's
// own events and flags, subtree by subtree, for primary rays and for
// secondary rays whose inherited IN certificate leaves are IN by their own
// quadric at the origin (the condition select_culled() checks).
TEST(Cull, MissedBoxMeansOutAlongTheRay) {
    int checked = 0;
    for (const std::string& path : all_scenes()) {
        if (is_big(path)) continue;
        for (int bits : {12, 24, 32}) {
            CompiledScene cs;
            if (!compile_at(path, bits, true, cs)) continue;
            const CullBounds& cb = cs.cull;
            // the subtree of each node as a program over the same leaves: the
            // post-order program's subtrees, numbered in preorder as the
            // compiler numbers the culling nodes
            std::vector<std::vector<Instr>> sub;
            {
                std::vector<int> first(cs.program.size()), left(cs.program.size(), -1), right(cs.program.size(), -1),
                    st;
                for (size_t k = 0; k < cs.program.size(); ++k) {
                    if (cs.program[k].op == Op::LEAF) {
                        first[k] = int(k);
                    } else {
                        right[k] = st.back(), st.pop_back();
                        left[k] = st.back(), st.pop_back();
                        first[k] = first[left[k]];
                    }
                    st.push_back(int(k));
                }
                std::function<void(int)> pre = [&](int k) {
                    sub.emplace_back(cs.program.begin() + first[k], cs.program.begin() + k + 1);
                    if (left[k] >= 0) pre(left[k]), pre(right[k]);
                };
                pre(st.back());
            }
            ASSERT_EQ(sub.size(), cb.nodes.size());
            for (size_t i = 0; i < sub.size(); ++i) {
                if (cb.nodes[i].leaf < 0) continue;
                ASSERT_EQ(sub[i].size(), 1u);
                ASSERT_EQ(sub[i][0].arg, cb.nodes[i].leaf);
            }
            std::mt19937_64 rng(bits * 7919 + path.size());
            for (int k = 0; k < 60; ++k) {
                const RayFx prim = camera_ray_fx(cs, int(rng() % cs.width), int(rng() % cs.height));
                // a primary ray, and a secondary ray from its hit (near side)
                TraceResult<i64> pt;
                try {
                    pt = trace_primary_fx(cs, prim, TiePolicy::Paper, true);
                } catch (const std::logic_error&) {
                    continue;
                }
                std::vector<std::pair<RayFx, std::vector<uint8_t>>> rays{{prim, {}}};
                std::array<i64, 3> p;
                if (pt.hit && hit_point_fx(cs.fmt, prim, pt.t, p)) {
                    RayFx s;
                    s.o = p;
                    const std::array<i64, 3> n = normal_fx(cs, pt.leaf, p, prim.d);
                    s.d = reflect_fx(prim.d, n, cs.fmt.frac);
                    rays.push_back({s, pt.flags_before});
                }
                for (auto& [ray, inherited] : rays) {
                    const bool secondary = !inherited.empty();
                    TraceResult<i64> tr;
                    try {
                        tr = secondary ? trace_secondary_fx(cs, ray, inherited, TiePolicy::Paper, true)
                                       : trace_primary_fx(cs, ray, TiePolicy::Paper, true);
                    } catch (const std::logic_error&) {
                        continue;
                    }
                    for (size_t i = 0; i < cb.nodes.size(); ++i) {
                        const CullNode& nd = cb.nodes[i];
                        if (nd.kind == CullNode::UNBOUNDED) continue;
                        if (nd.kind == CullNode::BOX && !segment_misses_box(nd, ray, cs.fmt.t_limit(), cs.fmt.frac))
                            continue;
                        bool stale = false;
                        for (uint32_t c = nd.cert_begin; c < nd.cert_end && secondary; ++c)
                            stale = stale || (inherited[cb.cert[c]] &&
                                              quadric_at_fx(cs.fmt, cs.leaves[cb.cert[c]].coef, ray.o) >= 0);
                        if (stale) continue;
                        // replay the full trace's events on the subtree
                        std::vector<uint8_t> flags = tr.origin_flags;
                        auto out_now = [&](int leaf, bool entering) {
                            const Class c = classify(sub[i], flags.data(), cs.leaf_material.data(), leaf, entering);
                            return c.kind == Class::OUT;
                        };
                        EXPECT_TRUE(out_now(-1, false)) << path << " node " << i << " at the origin";
                        for (const Event<i64>& e : tr.events) {
                            if (bool(flags[e.leaf]) == e.entering) continue;   // invalid: skipped
                            bool in_sub = false;
                            for (uint32_t q = nd.leaf_begin; q < nd.leaf_end; ++q)
                                in_sub = in_sub || cb.pre_leaves[q] == e.leaf;
                            if (in_sub) {
                                EXPECT_TRUE(out_now(e.leaf, e.entering)) << path << " node " << i << " t " << e.t;
                            }
                            flags[e.leaf] = e.entering;
                            EXPECT_TRUE(out_now(-1, false)) << path << " node " << i << " after t " << e.t;
                            ++checked;
                        }
                    }
                }
            }
        }
    }
    EXPECT_GT(checked, 10000);
}

// The box test is exact: it says "miss" iff no point of the closed segment
// lies in the closed box (reference: the slab intervals as exact fractions
// compared in 128 bits), for boxes and rays around the coordinate range.
TEST(Cull, SegmentBoxTestIsExact) {
    std::mt19937_64 rng(5);
    for (int bits : {12, 20, 28, 32}) {
        const Formats fmt(bits);
        const int F = fmt.frac;
        const i64 one = i64(1) << F;
        auto coord = [&](i64 range) { return i64(rng() % uint64_t(2 * range + 1)) - range; };
        int misses = 0, hits = 0;
        for (int k = 0; k < 200000; ++k) {
            CullNode nd;
            nd.kind = CullNode::BOX;
            for (int i = 0; i < 3; ++i) {
                const i64 a = coord(one), b = (rng() % 8 == 0) ? a : coord(one);   // some flat boxes
                nd.lo[i] = std::min(a, b), nd.hi[i] = std::max(a, b);
            }
            RayFx r;
            for (int i = 0; i < 3; ++i) r.o[i] = coord(one / 2), r.d[i] = (rng() % 6 == 0) ? 0 : coord(one - 1);
            if (r.d[0] == 0 && r.d[1] == 0 && r.d[2] == 0) r.d[0] = 1;
            const i64 t_end = (rng() % 2) ? fmt.t_limit() : i64(rng() % uint64_t(fmt.t_limit())) + 1;
            // reference: t in [lo_t, hi_t] as fractions num/den (den > 0)
            i128 lo_n = 0, lo_d = 1, hi_n = t_end, hi_d = one;
            bool empty = false;
            for (int i = 0; i < 3; ++i) {
                if (r.d[i] == 0) {
                    empty = empty || r.o[i] < nd.lo[i] || r.o[i] > nd.hi[i];
                    continue;
                }
                i128 a = nd.lo[i] - r.o[i], b = nd.hi[i] - r.o[i], d = r.d[i];
                if (d < 0) a = -a, b = -b, d = -d, std::swap(a, b);
                if (a * lo_d > lo_n * d) lo_n = a, lo_d = d;   // entry = max
                if (b * hi_d < hi_n * d) hi_n = b, hi_d = d;   // exit = min
            }
            const bool ref_miss = empty || lo_n * hi_d > hi_n * lo_d;
            ASSERT_EQ(segment_misses_box(nd, r, t_end, F), ref_miss) << "bits " << bits << " case " << k;
            (ref_miss ? misses : hits)++;
        }
        EXPECT_GT(misses, 10000);
        EXPECT_GT(hits, 10000);
    }
}

// quadric_at_fast and the one-line plane form are quadric_at_fx.
TEST(Cull, QuadricAtFastIsQuadricAt) {
    std::mt19937_64 rng(11);
    for (const std::string& path : all_scenes()) {
        if (is_big(path)) continue;
        for (int bits : {12, 16, 24, 28, 29, 32}) {
            CompiledScene cs;
            if (!compile_at(path, bits, true, cs)) continue;
            const i64 lim = i64(4) << cs.fmt.frac;
            for (int k = 0; k < 200; ++k) {
                std::array<i64, 3> p;
                for (int i = 0; i < 3; ++i) p[i] = i64(rng() % uint64_t(2 * lim)) - lim;
                for (size_t l = 0; l < cs.leaves.size(); ++l) {
                    const i64 want = quadric_at_fx(cs.fmt, cs.leaves[l].coef, p);
                    ASSERT_EQ(quadric_at_fast(cs.fmt, cs.leaves[l].coef, p), want) << path << " leaf " << l;
                    ASSERT_EQ(leaf_q(cs, int(l), p), want) << path << " leaf " << l;
                }
            }
        }
    }
}

// isqrt_fast's 64-bit path at its edges (perfect squares and their
// neighbours up to 2^64), as the bit-serial root.
TEST(Cull, IsqrtFastAtTheEdgesOf64Bits) {
    for (u128 r : {u128(1), u128(2), u128(3), u128(1) << 16, (u128(1) << 26) - 1, u128(1) << 26, (u128(1) << 31) + 7,
                   (u128(1) << 32) - 2, (u128(1) << 32) - 1})
        for (int delta = -2; delta <= 2; ++delta) {
            const u128 n = r * r + u128(i128(delta));
            if (n >> 64) continue;
            ASSERT_TRUE(isqrt_fast(n) == isqrt_bitwise(n, 33)) << "r " << uint64_t(r) << " delta " << delta;
        }
    const u128 top = (u128(1) << 64) - 1;
    ASSERT_TRUE(isqrt_fast(top) == isqrt_bitwise(top, 33));
}

// ClassTree::update reaches the state reset() computes, whatever state it
// starts from.
TEST(Cull, ClassTreeUpdateEqualsReset) {
    std::mt19937_64 rng(3);
    for (const std::string& path : all_scenes()) {
        if (is_big(path)) continue;
        CompiledScene cs;
        ASSERT_TRUE(compile_at(path, 24, true, cs));
        const size_t n = cs.leaves.size();
        ClassTree inc = cs.class_tree, ref = cs.class_tree;
        std::vector<uint8_t> flags(n);
        for (int k = 0; k < 300; ++k) {
            for (auto& f : flags) f = (rng() % 3 == 0);
            inc.update(flags.data(), cs.leaf_material.data());
            ref.reset(flags.data(), cs.leaf_material.data());
            for (size_t l = 0; l < n; ++l)
                for (bool ent : {false, true}) ASSERT_EQ(inc.classify(int(l), ent), ref.classify(int(l), ent)) << path;
        }
    }
}

// The comparison fails when the culling is wrong: with every box shrunk to
// a quarter of its size (so that rays are culled that meet the subtree),
// some frame must differ.
TEST(Cull, ShrunkBoxesAreCaught) {
    int differing = 0;
    for (const char* path : {"scenes/csg_mix.pov", "scenes/default.pov", "scenes/mirror.pov"}) {
        CompiledScene on, off;
        ASSERT_TRUE(compile_at(path, 24, true, on));
        ASSERT_TRUE(compile_at(path, 24, false, off));
        for (CullNode& nd : on.cull.nodes)
            for (int i = 0; i < 3; ++i) {
                const i64 c = (nd.lo[i] + nd.hi[i]) / 2, h = (nd.hi[i] - nd.lo[i]) / 8;
                nd.lo[i] = c - h, nd.hi[i] = c + h;
            }
        const Frame a = render(on, RenderOptions{}), b = render(off, RenderOptions{});
        differing += count_diff(a, b);
    }
    EXPECT_GT(differing, 100);
}
