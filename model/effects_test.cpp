// effects_test.cpp — secondary rays without epsilon: the paper's Fig. 8
// property (a reflective, shadowed sphere shows no self-shadowing and no
// self-reflection at any width, checked ray by ray against the ground truth
// that nothing else can occlude it), consistent media along refracted rays
// through nested transparent solids, and the effect sets scenes report.
#include "compile.h"
#include "parse.h"
#include "raytree.h"
#include "render.h"

#include <gtest/gtest.h>

using namespace csgrt;

namespace {

CompiledScene compile_text(const std::string& text, int bits, int w = 64, int h = 48) {
    CompileOptions o;
    o.bits = bits;
    o.width = w;
    o.height = h;
    return compile_scene(parse_scene_string(text, "effects.pov"), o);
}

// Fig. 8: a mirror sphere above a slab, lit from above: no other object can
// occlude the sphere's lit side, and a convex sphere cannot see itself.
const char* kFig8 =
    "camera { location <0.3, 1.4, -4> look_at <0, 0.9, 0> angle 35 right x*4/3 }\n"
    "light_source { <-2, 6, -3> color rgb 1 }\n"
    "background { color rgb <0.1, 0.1, 0.2> }\n"
    "box { <-3, -0.2, -3>, <3, 0, 3> pigment { color rgb <0.6, 0.6, 0.6> } }\n"
    "sphere { <0, 0.9, 0>, 0.8 rotate <23, 41, 7> pigment { color rgb <0.8, 0.3, 0.3> }\n"
    "         finish { reflection 0.5 phong 0.5 } }\n";

}  // namespace

TEST(Effects, Fig8NoSelfShadowingNoSelfReflection) {
    for (int bits : {12, 16, 24, 32})
        for (TiePolicy ties : {TiePolicy::Paper, TiePolicy::Regular}) {
            const CompiledScene cs = compile_text(kFig8, bits);
            const int F = cs.fmt.frac;
            int sphere = -1;
            for (size_t l = 0; l < cs.leaves.size(); ++l)
                if (cs.leaves[l].what == "sphere") sphere = int(l);
            ASSERT_GE(sphere, 0);
            int lit_points = 0, self_shadow = 0, shadowed = 0, reflected = 0, self_reflect = 0;
            for (int y = 0; y < cs.height; ++y)
                for (int x = 0; x < cs.width; ++x) {
                    const RayFx ray = camera_ray_fx(cs, x, y);
                    const TraceResult<i64> tr = trace_primary_fx(cs, ray, ties);
                    if (!tr.hit || tr.leaf != sphere) continue;
                    std::array<i64, 3> p;
                    ASSERT_TRUE(hit_point_fx(cs.fmt, ray, tr.t, p));
                    const std::array<i64, 3> n = normal_fx(cs, sphere, p, ray.d);
                    // the shadow ray, as the renderer casts it
                    std::array<i64, 3> lv;
                    i128 nl = 0;
                    for (int i = 0; i < 3; ++i) lv[i] = cs.lights[0].pos_fx[i] - p[i], nl += i128(n[i]) * lv[i];
                    if (nl > 0) {
                        ++lit_points;
                        TraceOptions so;
                        const RayFx sh = shadow_ray_fx(F, p, lv, so.t_limit_fx);
                        const TraceResult<i64> st = trace_secondary_fx(cs, sh, tr.flags_before, ties, false, so);
                        shadowed += st.hit;   // ground truth: nothing can occlude the lit side
                        self_shadow += st.hit && st.leaf == sphere;
                    }
                    // the reflected ray, with the near side's flags
                    RayFx rf;
                    rf.o = p;
                    rf.d = reflect_fx(ray.d, n, F);
                    const TraceResult<i64> rt = trace_secondary_fx(cs, rf, tr.flags_before, ties);
                    ++reflected;
                    self_reflect += rt.hit && rt.leaf == sphere;
                }
            std::printf("[ fig8     ] %2d bits, ties %-7s: %d lit sphere points, %d shadowed (%d by itself); "
                        "%d reflected rays, %d hit the sphere\n",
                        bits, ties == TiePolicy::Paper ? "paper" : "regular", lit_points, shadowed, self_shadow,
                        reflected, self_reflect);
            EXPECT_GT(lit_points, 100);
            EXPECT_EQ(shadowed, 0) << bits << " bits";
            EXPECT_EQ(self_shadow, 0);
            EXPECT_EQ(self_reflect, 0) << bits << " bits";
        }
}

TEST(Effects, Fig8ImageShadowsChangeNothingOnTheLitSide) {
    // Image-level form of the same property: with shadows on and off, the
    // sphere's lit side renders identically (no acne), and the floor under
    // the sphere does get a shadow (the check can fail).
    for (int bits : {12, 16, 24, 32}) {
        const CompiledScene cs = compile_text(kFig8, bits);
        RenderOptions on, off;
        EffectSet fx = scene_effects(cs);
        fx.reflection = false;
        on.effects = fx;
        fx.shadows = false;
        off.effects = fx;
        const Frame a = render(cs, on), b = render(cs, off);
        int sphere_same = 0, sphere_diff = 0, floor_shadowed = 0;
        for (size_t i = 0; i < a.hit_leaf.size(); ++i) {
            const bool differ = a.rgb_differs(b, i);
            if (a.hit_leaf[i] >= 0 && cs.leaves[a.hit_leaf[i]].what == "sphere") {
                // shadows may only darken the side turned away from the light,
                // where diffuse is zero anyway: the sphere must be identical
                (differ ? sphere_diff : sphere_same)++;
            } else if (a.hit_leaf[i] >= 0) {
                floor_shadowed += differ;
            }
        }
        EXPECT_GT(sphere_same, 100);
        EXPECT_EQ(sphere_diff, 0) << bits << " bits: shadow acne on the sphere";
        EXPECT_GT(floor_shadowed, 20) << bits << " bits: the sphere casts no shadow";
    }
}

TEST(Effects, ShadowlessLightsCastNoShadow) {
    // The Fig. 8 scene with its light shadowless. Ground truth: the same
    // scene with the sphere made empty (cut by a half-space below the floor:
    // the same leaves' bounds, so the same fixed-point frame), where nothing
    // can shadow the floor; every floor pixel of the shadowless scene must
    // equal it bit for bit.
    // The shadowed scene must differ there (the check can fail), and a
    // shadows-on render (a build with the shadow unit) of the shadowless
    // scene must equal its render without shadows (the specialised build).
    std::string shadowless = kFig8;
    const std::string light = "light_source { <-2, 6, -3> color rgb 1 }";
    const size_t at = shadowless.find(light);
    ASSERT_NE(at, std::string::npos);
    shadowless.replace(at, light.size(), "light_source { <-2, 6, -3> color rgb 1 shadowless }");
    const size_t sphere_at = shadowless.find("sphere {");
    const std::string empty_sphere = shadowless.substr(0, sphere_at) + "intersection { " +
                                  shadowless.substr(sphere_at) + " plane { y, -10 } }\n";
    for (int bits : {12, 16, 24, 32}) {
        const CompiledScene cs = compile_text(shadowless, bits), shadowed = compile_text(kFig8, bits),
                            truth = compile_text(empty_sphere, bits);
        EXPECT_FALSE(scene_effects(cs).shadows);
        EXPECT_TRUE(scene_effects(shadowed).shadows);
        EffectSet fx = scene_effects(cs);
        fx.reflection = false;
        RenderOptions plain, full;
        plain.effects = fx;
        fx.shadows = true;
        full.effects = fx;
        const Frame a = render(cs, plain), b = render(cs, full), t = render(truth, plain),
                    sh = render(shadowed, full);
        EXPECT_EQ(a.rgb, b.rgb) << bits << " bits: shadows on changed a shadowless scene";
        int floor = 0, floor_diff = 0, shadowed_diff = 0;
        for (size_t i = 0; i < a.hit_leaf.size(); ++i) {
            if (a.hit_leaf[i] < 0 || cs.leaves[a.hit_leaf[i]].what == "sphere") continue;
            ASSERT_GE(t.hit_leaf[i], 0);
            ++floor;
            floor_diff += a.rgb_differs(t, i);
            shadowed_diff += sh.rgb_differs(t, i);
        }
        EXPECT_GT(floor, 500);
        EXPECT_EQ(floor_diff, 0) << bits << " bits: a shadowless light cast a shadow";
        EXPECT_GT(shadowed_diff, 20) << bits << " bits: the shadowed light casts no shadow either";
    }
}

TEST(Effects, RefractedRaysCarryConsistentMedia) {
    // Through nested transparent solids, every crossing a transmitted ray
    // finds starts in the medium the previous crossing entered.
    const Scene s = parse_scene_file("scenes/nested_glass.pov");
    for (int bits : {16, 24, 32}) {
        CompileOptions o;
        o.bits = bits;
        o.width = 48;
        o.height = 36;
        const CompiledScene cs = compile_scene(s, o);
        const int F = cs.fmt.frac;
        int crossings = 0, inconsistent = 0;
        for (int y = 0; y < cs.height; ++y)
            for (int x = 0; x < cs.width; ++x) {
                RayFx ray = camera_ray_fx(cs, x, y);
                TraceOptions to;
                to.lookahead = true;
                TraceResult<i64> tr = trace_primary_fx(cs, ray, TiePolicy::Paper, false, to);
                int medium = 0;
                for (int depth = 0; depth < 8 && tr.hit; ++depth) {
                    ++crossings;
                    inconsistent += tr.border.from != medium;
                    if (!is_transparent(cs, tr.border.to ? tr.border.to : tr.border.from)) break;
                    std::array<i64, 3> p;
                    if (!hit_point_fx(cs.fmt, ray, tr.t, p)) break;
                    const std::array<i64, 3> n = normal_fx(cs, tr.leaf, p, ray.d);
                    RayFx child;
                    child.o = p;
                    const std::vector<uint8_t>* flags = &tr.flags_after;
                    if (refract_fx(ray.d, n, ior_of(cs, tr.border.from), ior_of(cs, tr.border.to), F, child.d)) {
                        medium = tr.border.to;
                    } else {
                        child.d = reflect_fx(ray.d, n, F);   // total internal reflection: same medium
                        flags = &tr.flags_before;
                    }
                    const std::vector<uint8_t> keep = *flags;
                    ray = child;
                    tr = trace_secondary_fx(cs, ray, keep, TiePolicy::Paper, false, to);
                }
            }
        std::printf("[ media    ] %2d bits: %d crossings, %d start in another medium than the ray is in\n", bits,
                    crossings, inconsistent);
        EXPECT_GT(crossings, 1000);
        EXPECT_EQ(inconsistent, 0);
    }
}

TEST(Effects, WithoutTheSpecularUnitHighlightsAreGoneAndNothingElse) {
    // A build without the specular unit (SPECULAR = 0) shades as if every
    // phong were 0. Checked against the same scene written without phong
    // (an independent route through the parser and compiler), with shadows
    // and reflection on: the images must be identical, and must differ
    // from the render with highlights (the check can fail).
    std::string matte = kFig8;
    const std::string phong = " phong 0.5";
    matte.erase(matte.find(phong), phong.size());
    for (int bits : {16, 24}) {
        const CompiledScene cs = compile_text(kFig8, bits), plain = compile_text(matte, bits);
        EXPECT_TRUE(scene_effects(cs).specular);
        EXPECT_FALSE(scene_effects(plain).specular);
        RenderOptions with, without;
        with.effects = rtl_effects(cs, true, true, false, true);
        without.effects = rtl_effects(cs, true, true, false, false);
        EXPECT_FALSE(without.effects->specular);
        const Frame a = render(cs, with), b = render(cs, without), ref = render(plain, with);
        int highlights = 0, other = 0;
        for (size_t i = 0; i < b.hit_leaf.size(); ++i) {
            highlights += a.rgb_differs(b, i);
            other += b.rgb_differs(ref, i);
            // a highlight only adds light
            for (int c = 0; c < 3; ++c) EXPECT_LE(b.rgb[i * 3 + c], a.rgb[i * 3 + c]);
        }
        EXPECT_GT(highlights, 10) << bits << " bits: the highlight is missing from the render with it";
        EXPECT_EQ(other, 0) << bits << " bits: without the specular unit, pixels differ from the scene without phong";
        // a scene without phong renders the same either way
        without.effects = rtl_effects(plain, true, true, false, false);
        const Frame c = render(plain, without);
        EXPECT_EQ(c.rgb, ref.rgb);
    }
}

TEST(Effects, ScenesReportTheEffectsTheyUse) {
    auto fx = [](const std::string& name) {
        CompileOptions o;
        return scene_effects(compile_scene(parse_scene_file("scenes/" + name + ".pov"), o));
    };
    const EffectSet basic = fx("basic"), mirror = fx("mirror"), glass = fx("glass");
    EXPECT_TRUE(basic.shadows && basic.specular);
    EXPECT_FALSE(basic.reflection || basic.refraction);
    EXPECT_EQ(basic.str(), "shadows, specular");
    EXPECT_TRUE(mirror.reflection && !mirror.refraction);
    EXPECT_EQ(mirror.depth, 5);
    EXPECT_TRUE(glass.refraction && glass.reflection);
    EXPECT_EQ(glass.depth, 6);
    // every light shadowless: no shadow unit
    const EffectSet studio = fx("studio");
    EXPECT_EQ(studio.str(), "specular");
    EXPECT_FALSE(studio.any_secondary());
}

namespace {

// Shadow rays cast, as the renderer casts them, from every lit point of
// every primary hit; returns {lit points, shadowed}.
std::pair<int, int> lit_points_shadowed(const CompiledScene& cs, TiePolicy ties) {
    const int F = cs.fmt.frac;
    int lit = 0, shadowed = 0;
    for (int y = 0; y < cs.height; ++y)
        for (int x = 0; x < cs.width; ++x) {
            const RayFx ray = camera_ray_fx(cs, x, y);
            const TraceResult<i64> tr = trace_primary_fx(cs, ray, ties);
            std::array<i64, 3> p;
            if (!tr.hit || !hit_point_fx(cs.fmt, ray, tr.t, p)) continue;
            const std::array<i64, 3> n = normal_fx(cs, tr.leaf, p, ray.d);
            for (const LightInfo& light : cs.lights) {
                std::array<i64, 3> lv;
                i128 nl = 0;
                for (int i = 0; i < 3; ++i) lv[i] = light.pos_fx[i] - p[i], nl += i128(n[i]) * lv[i];
                if (nl <= 0) continue;
                ++lit;
                TraceOptions so;
                const RayFx sh = shadow_ray_fx(F, p, lv, so.t_limit_fx);
                shadowed += trace_secondary_fx(cs, sh, tr.flags_before, ties, false, so).hit;
            }
        }
    return {lit, shadowed};
}

}  // namespace

TEST(Effects, ConvexSolidsWithCoincidentFacesCastNoShadowOnThemselves) {
    // Two overlapping boxes sharing four faces (Fig. 6), and a box added to
    // itself (Fig. 14): each union is one convex solid, alone in the scene,
    // so no lit point may be shadowed. Before the near side's look-behind,
    // a crossing of the other box's coplanar face left a stale flag and
    // speckled the faces with shadow.
    const char* solids[] = {
        "union { box { <-1, 0, -0.8>, <0.3, 1, 0.8> pigment { color rgb <0.85, 0.25, 0.2> } }\n"
        "        box { <-0.3, 0, -0.8>, <1, 1, 0.8> pigment { color rgb <0.2, 0.35, 0.85> } } rotate ROT }\n",
        "#declare B = box { <-0.8, -0.5, -0.6>, <0.8, 0.5, 0.6> pigment { color rgb <0.3, 0.8, 0.4> } }\n"
        "union { object { B } object { B } rotate ROT }\n",
    };
    const char* rotations[] = {"<11, 27, -7>", "<-23, 41, 13>", "<37, -8, 29>"};
    for (const char* solid : solids)
        for (const char* rot : rotations)
            for (int bits : {12, 16, 24, 32})
                for (TiePolicy ties : {TiePolicy::Paper, TiePolicy::Regular}) {
                    std::string text = std::string(
                                           "camera { location <0, 3, -4.8> look_at <0, 0.4, 0> angle 44 right x*4/3 }\n"
                                           "light_source { <-5, 9, -6> color rgb 1 }\n"
                                           "light_source { <6, 4, -5> color rgb 0.3 }\n") +
                                       solid;
                    text.replace(text.find("ROT"), 3, rot);
                    const auto [lit, shadowed] = lit_points_shadowed(compile_text(text, bits), ties);
                    EXPECT_GT(lit, 500);
                    EXPECT_EQ(shadowed, 0) << "rotate " << rot << ", " << bits << " bits, ties " << int(ties)
                                           << ": self-shadowing on a convex solid";
                }
}

// Ray weights stay at most 1 (the RTL carries them in 13 bits): a heavier
// reflection, filter or transparent pigment is refused, naming the object's
// position and the limit.
TEST(Effects, RayWeightsAboveOneAreRefusedWithTheObjectAndTheLimit) {
    const std::string head = "camera { location <0, 0, -3> look_at <0, 0, 0> }\n";
    const struct {
        const char* object;
        const char* expect;
    } cases[] = {
        {"sphere { 0, 1 pigment { color rgb 1 } finish { reflection 1.5 } }", "finish reflection 1.5 is above 1"},
        {"sphere { 0, 1 pigment { color rgbf <1, 1, 1, 1.2> } }", "pigment filter 1.2 is above 1"},
        {"sphere { 0, 1 pigment { color rgbf <2, 1, 1, 0.5> } }", "pigment colour 2 of a transparent material"},
    };
    for (const auto& c : cases) {
        try {
            compile_text(head + c.object + "\n", 24);
            ADD_FAILURE() << "accepted: " << c.object;
        } catch (const SceneError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(c.expect), std::string::npos) << what;
            EXPECT_NE(what.find("effects.pov:2:"), std::string::npos) << what;
        }
    }
    // the limits themselves are accepted
    EXPECT_NO_THROW(compile_text(head + "sphere { 0, 1 pigment { color rgbf <1, 1, 1, 1> } finish { reflection 1 } }\n", 24));
}
