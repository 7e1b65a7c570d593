// stability_test.cpp — the quick subset of the hard-case stability suite
// (model/stability.h; the whole suite is `make stability`): the paper's
// cases under the file's own orientation and two random rigid transforms,
// at 16 and 24 bits, both tie policies, small images. The exact method must
// show no violation but the known, ray-level-explained ones; the epsilon
// method must show some of every kind it can fail, and deliberate faults in
// the exact method's secondary rays must make the other checks fail, which
// proves every check can fail (the false-shadow check on Fig. 7, which is
// not convex, under far-side and rederived flags; the look-ahead border on
// Fig. 13 without the look-ahead). Ray-level tests pin down the two decisions
// the suite's references rest on (Fig. 4 under regular ties, Fig. 9's
// method holes and what is below resolution).
#include "epsilon.h"
#include "parse.h"
#include "stability.h"

#include <gtest/gtest.h>

#include <map>

using namespace csgrt;
using namespace csgrt::stability;

namespace {

std::vector<Case> quick_cases(const std::string& only = "") {
    std::vector<Case> out;
    for (const Case& c : cases("scenes/paper"))
        if (!c.large && c.name.find(only) != std::string::npos) out.push_back(c);
    return out;
}

Config quick_config() {
    Config cfg;
    cfg.bits = {16, 24};
    cfg.transforms = 3;
    cfg.width = 48;
    cfg.height = 36;
    return cfg;
}

// Known issues of the exact model, reported rather than hidden (see
// docs/hard-cases.md), each identified ray by ray by the suite:
//  - edge ties: a self-shadow or self-reflection whose primary hit's t ties
//    with a surface that is not the hit leaf's (under ties regular a right
//    operand's edge plane becomes the hit leaf and its normal is internal
//    to the union);
//  - own-leaf look-ahead: a ray segment in the wrong medium because the
//    look-ahead crossed the hit leaf's own far side (the ray passes through
//    a glass sphere);
//  - look-behind overflow: a self-shadow, self-reflection or false shadow
//    whose primary hit's near-side flags leave a face coincident with the
//    hit surface crossed (more than kLookBehind coincident crossings before
//    the hit: Fig. 17, not in this quick set).
// Every exact violation must be one of them.
long explained(const Counts& k) {
    return k.notes[EdgeTies] + k.notes[OwnLeafLookahead] + k.notes[LookBehindOverflow];
}

long sum_kind(const std::vector<Row>& rows, Method m, int kind) {
    long n = 0;
    for (const Row& r : rows)
        if (r.method == m && r.counts.checked >= 0) n += r.counts.v[kind];
    return n;
}

long rays_of(const std::vector<Row>& rows, int kind) {
    long n = 0;
    for (const Row& r : rows)
        if (r.method == Method::Exact && r.counts.checked >= 0) n += r.counts.rays[kind];
    return n;
}

}  // namespace

TEST(Stability, ExactHasNoViolationsEpsilonHasSome) {
    const Config cfg = quick_config();
    const std::vector<Row> rows = run(cfg, quick_cases());
    for (const Row& r : rows) {
        if (r.method != Method::Exact) continue;
        const Counts& k = r.counts;
        EXPECT_GT(k.checked, 0) << r.case_name << ": no stable reference pixel was compared";
        EXPECT_LE(k.notes[EdgeTies] + k.notes[LookBehindOverflow], k.v[SelfShadow] + k.v[SelfReflect] + k.v[FalseShadow]);
        EXPECT_LE(k.notes[OwnLeafLookahead], k.v[Medium]);
        EXPECT_EQ(k.total(), explained(k)) << r.case_name << " " << r.label() << " at " << r.bits << " bits";
        if (explained(k))
            std::printf("[ known    ] %s %s at %d bits: %ld violations (%ld at edge ties, %ld own-leaf look-ahead, "
                        "%ld look-behind overflow)\n",
                        r.case_name.c_str(), r.label().c_str(), r.bits, k.total(), k.notes[EdgeTies],
                        k.notes[OwnLeafLookahead], k.notes[LookBehindOverflow]);
    }
    // each ray-level check examined rays
    for (int kind : {Inside, Mirror, MethodHole, SelfShadow, SelfReflect, Media, Medium, FalseShadow, Border})
        EXPECT_GT(rays_of(rows, kind), 0) << "the " << kind_name(kind) << " check examined nothing";
    // the ground-truth checks judge most of what they see (edges, contacts
    // and grazing rays are left out; a check that judged nothing would pass)
    long blocked = 0, unjudged = 0, border_unjudged = 0;
    for (const Row& r : rows)
        if (r.method == Method::Exact && r.counts.checked >= 0)
            blocked += r.counts.notes[ShadowBlocked], unjudged += r.counts.notes[ShadowUnjudged],
                border_unjudged += r.counts.notes[BorderUnjudged];
    EXPECT_LT(unjudged, blocked / 2) << "false shadow: " << unjudged << " of " << blocked << " blocked rays not judged";
    EXPECT_LT(border_unjudged, rays_of(rows, Border)) << "look-ahead border: most hits not judged";
    // the epsilon method fails every check it can fail here (the ghost
    // colour and the mirror image only show in the whole suite, or under
    // the faults of the next test)
    for (int kind : {Hole, Speckle, Inside, MethodHole, SelfShadow, SelfReflect, Media, Medium, FalseShadow, Border})
        EXPECT_GT(sum_kind(rows, Method::Epsilon, kind), 0)
            << "the epsilon method passed every " << kind_name(kind) << " check: it cannot fail";
    if (::testing::Test::HasFailure()) print_table(stdout, rows, cfg.bits);
}

// Deliberate faults in how the exact method's secondary rays are cast (the
// suite's own casting; the renderer is untouched): each makes its check
// count violations, which proves the check can fail.
TEST(Stability, EveryCheckFailsUnderADeliberateFault) {
    struct Expect {
        const char* name;
        Fault fault;
        const char* only;   // case name filter
        std::vector<int> kinds;
        int transforms, size;
    };
    const Expect expects[] = {
        // shadow and reflected rays starting logically inside the surface
        // strike it: self-shadow, self-reflection, the mirror shows itself
        {"FarSideFlags", Fault::FarSideFlags, "fig08", {SelfShadow, SelfReflect}, 1, 48},
        {"FarSideFlags", Fault::FarSideFlags, "fig15", {Mirror}, 1, 48},
        // flags derived at the rounded origin (a point-in-solid answer)
        // instead of inherited: the surface's own root near t = 0 decides
        {"RederiveFlags", Fault::RederiveFlags, "fig08", {SelfShadow, SelfReflect}, 1, 48},
        {"RederiveFlags", Fault::RederiveFlags, "fig15", {Mirror}, 1, 48},
        // the same on a case that is not convex (a slot cut into a box),
        // where only the ground truth can tell: false shadows (d)
        {"FarSideFlags", Fault::FarSideFlags, "fig07", {FalseShadow}, 1, 48},
        {"RederiveFlags", Fault::RederiveFlags, "fig07", {FalseShadow}, 1, 48},
        // transmitted rays with the near side's flags: inconsistent media
        {"TransmittedNearSide", Fault::TransmittedNearSide, "fig13", {Media}, 1, 48},
        // no look-ahead on the primary ray: the shared front of the nested
        // glass boxes reads the outer box's BORDER, not the innermost box
        // that lies beyond it (b)
        {"NoLookahead", Fault::NoLookahead, "fig13", {Border}, 1, 48},
        // no look-ahead: where a coincident face's root falls just behind
        // the child's origin, the ray travels in the outer box's medium
        // inside the inner ones (rare: 7 segments here)
        {"NoLookahead", Fault::NoLookahead, "fig1", {Medium}, 8, 64},
    };
    for (const Expect& e : expects) {
        Config cfg;
        cfg.bits = {16};
        cfg.transforms = e.transforms;
        cfg.width = e.size;
        cfg.height = e.size * 3 / 4;
        cfg.fault = e.fault;
        std::vector<Case> list;
        for (const Case& c : quick_cases(e.only))
            if (e.fault != Fault::NoLookahead || c.media) list.push_back(c);
        ASSERT_FALSE(list.empty());
        std::string names;
        for (const Case& c : list) names += (names.empty() ? "" : "+") + c.name;
        const std::vector<Row> rows = run(cfg, list);
        for (int kind : e.kinds) {
            const long n = sum_kind(rows, Method::Exact, kind);
            std::printf("[ fault    ] %s on %s: %ld %s violations\n", e.name, names.c_str(), n, kind_name(kind));
            EXPECT_GT(n, 0) << e.name << " on " << names << ": the " << kind_name(kind) << " check did not fail";
        }
    }
}

// Fig. 4 under both tie policies: where the two cylinders overlap, a ray
// from above leaves the two top cutters (leaves 1 and 4, coincident planes)
// at the same t; paper sorts the lower leaf first, regular sorts leaving
// events in ascending leaf order, so both leave A's cutter first and strike
// A's top (scenes/paper/ref/fig04_ghost_*.pov rest on this).
TEST(Stability, Fig4OverlapShowsAUnderBothTiePolicies) {
    for (int bits : {12, 16, 24, 32}) {
        CompileOptions co;
        co.bits = bits;
        co.width = 64;
        co.height = 48;
        const CompiledScene cs = compile_scene(parse_scene_file("scenes/paper/fig04_ghost.pov"), co);
        ASSERT_EQ(cs.leaves.size(), 6u);
        ASSERT_TRUE(cs.identical_coefs(1, 4)) << "the top cutters are no longer coincident at " << bits << " bits";
        for (TiePolicy ties : {TiePolicy::Paper, TiePolicy::Regular}) {
            int overlap = 0;
            for (int y = 0; y < cs.height; ++y)
                for (int x = 0; x < cs.width; ++x) {
                    const TraceResult<i64> tr = trace_primary_fx(cs, camera_ray_fx(cs, x, y), ties, true);
                    if (!tr.hit) continue;
                    bool l1 = false, l4 = false;
                    for (const Event<i64>& e : tr.events)
                        if (e.t == tr.t && !e.entering) l1 = l1 || e.leaf == 1, l4 = l4 || e.leaf == 4;
                    // inside both infinite cylinders where the ray reaches the tops
                    if (!l1 || !l4 || !tr.flags_hit_near[0] || !tr.flags_hit_near[3]) continue;
                    ++overlap;
                    EXPECT_EQ(tr.leaf, 1) << bits << " bits, ties " << int(ties);
                    EXPECT_EQ(tr.border.to, cs.leaves[0].material) << bits << " bits, ties " << int(ties);
                }
            EXPECT_GT(overlap, 10) << bits << " bits";
        }
    }
}

// Fig. 9: the exact method shows the outer surface on every ray whose
// computed events put its entry first (no method hole, any width, both
// policies); the epsilon method loses some of them (its inside test at the
// rounded point puts the outer hit inside the inner sphere). What the
// computed order cannot resolve shrinks with the width and is gone at 32
// bits; under regular ties the tied rays are among it.
TEST(Stability, Fig9MethodHolesAndBelowResolution) {
    Config cfg;
    cfg.bits = {12, 16, 24, 32};
    cfg.transforms = 3;
    const std::vector<Row> rows = run(cfg, quick_cases("fig09"));
    std::map<std::string, std::vector<long>> below;
    for (const Row& r : rows) {
        ASSERT_GE(r.counts.checked, 0);
        EXPECT_GT(r.counts.rays[MethodHole], 1000) << r.label() << " at " << r.bits << " bits";
        if (r.method == Method::Exact) {
            EXPECT_EQ(r.counts.total(), 0) << r.label() << " at " << r.bits << " bits";
        }
        below[r.label()].push_back(r.counts.notes[BelowResolution]);
        std::printf("[ fig9     ] %-13s %2d bits: %ld method holes; below resolution %ld rays, %ld image holes\n",
                    r.label().c_str(), r.bits, r.counts.v[MethodHole], r.counts.notes[BelowResolution],
                    r.counts.notes[ImageHoles]);
    }
    EXPECT_GT(sum_kind(rows, Method::Epsilon, MethodHole), 0) << "the method-hole check cannot fail";
    for (const auto& [label, b] : below) {
        EXPECT_GT(b[1], b[2]) << label << ": below resolution does not shrink from 16 to 24 bits";
        EXPECT_EQ(b[3], 0) << label << ": below resolution at 32 bits";
    }
    EXPECT_GE(below["exact/regular"][1], below["exact/paper"][1]) << "regular ties put tied rays below resolution";
}

// The convex checks tell a leaf's own object by LeafInfo::object: the
// top-level object, so that a coincident copy inside one union (Fig. 14)
// is the same object and a separate object (Fig. 8's floor) is not.
TEST(Stability, LeavesKnowTheirTopLevelObject) {
    CompileOptions co;
    co.bits = 24;
    const CompiledScene f8 = compile_scene(parse_scene_file("scenes/paper/fig08_reflect.pov"), co);
    // sphere (1 leaf), box (6), box (6), plane (1)
    std::vector<int> expect8{0};
    for (int b = 1; b <= 2; ++b) expect8.insert(expect8.end(), 6, b);
    expect8.push_back(3);
    ASSERT_EQ(f8.leaves.size(), expect8.size());
    for (size_t l = 0; l < f8.leaves.size(); ++l) EXPECT_EQ(f8.leaves[l].object, expect8[l]) << "leaf " << l;
    const CompiledScene f14 = compile_scene(parse_scene_file("scenes/paper/fig14_self_add.pov"), co);
    ASSERT_GE(f14.leaves.size(), 2u);
    EXPECT_EQ(f14.leaves[0].object, 0);   // the sphere added to itself: one object
    EXPECT_EQ(f14.leaves[1].object, 0);
    EXPECT_EQ(f14.leaves[2].object, 1);   // the box's first face
    EXPECT_EQ(f14.leaves.back().object, 3);
}

// The epsilon method agrees with the exact one on a scene without coincident
// surfaces (it is a working ray tracer, not a strawman).
TEST(Stability, EpsilonMatchesExactWithoutCoincidences) {
    CompileOptions co;
    co.width = 48;
    co.height = 36;
    co.bits = 24;
    const CompiledScene cs = compile_scene(parse_scene_file("scenes/csg_mix.pov"), co);
    RenderOptions ro;
    ro.threads = 1;
    const Frame ex = render(cs, ro), ep = render_epsilon(cs, ro);
    int diff = 0;
    for (size_t i = 0; i < ex.material.size(); ++i) diff += ex.material[i] != ep.material[i];
    EXPECT_LE(diff, int(ex.material.size() / 100)) << "material differs at " << diff << " pixels";
}

// The on-surface band changes answers only near surfaces and the depth
// tolerance scales with the frame.
TEST(Stability, EpsilonTolerancesScaleWithTheFrame) {
    CompileOptions co;
    co.bits = 32;
    const CompiledScene cs = compile_scene(parse_scene_file("scenes/paper/fig06_add_shared.pov"), co);
    const EpsilonTracer t(cs);
    const double expect = 1e-4 * cs.scale * std::ldexp(1.0, cs.fmt.frac);
    EXPECT_NEAR(double(t.depth_tolerance_ulps()), expect, 1.0);
}
