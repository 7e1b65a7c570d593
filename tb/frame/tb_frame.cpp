// tb_frame.cpp — whole frames through csgrt_top against the golden model,
// pixel for pixel: several scenes (coincident surfaces among them), both tie
// policies, at the width this binary was built for (FRAME_BITS); random
// back-pressure on the pixel stream; scene images the hardware must refuse.
// The model renders from the very scene image the RTL loads.
#include "Vcsgrt_top.h"
#include "Vcsgrt_top___024root.h"
#include "compile.h"
#include "parse.h"
#include "raytree.h"
#include "render.h"
#include "report.h"
#include "scene_image.h"
#include "top_sim.h"

#include <gtest/gtest.h>

#include <string>

using namespace csgrt;

#ifndef FRAME_SHADOWS
#define FRAME_SHADOWS 0
#endif
#ifndef FRAME_REFRACTION
#define FRAME_REFRACTION 0
#endif
#ifndef FRAME_REFLECTION
#define FRAME_REFLECTION 0
#endif
#ifndef FRAME_SPECULAR
#define FRAME_SPECULAR 1
#endif
// csgrt_top's MAX_LIGHTS of this build: a scene with more lights is refused
// with status 4 (the loader's limit), one with as many renders
#ifndef FRAME_MAX_LIGHTS
#define FRAME_MAX_LIGHTS 8
#endif

namespace {

const int kLeafBits = 6, kTreeHeight = 8;
constexpr bool kEffects = FRAME_SHADOWS || FRAME_REFLECTION || FRAME_REFRACTION;
// A frame that takes longer has hung: the slowest bench frame (Fig. 13 with
// refraction) needs about 290 cycles per pixel.
constexpr uint64_t kMaxCyclesPerPixel = 2000;

std::vector<uint32_t> compile_words(const Scene& s, int w, int h) {
    CompileOptions o;
    o.bits = FRAME_BITS;
    o.width = w;
    o.height = h;
    o.max_leaves = 64;
    o.tree_height = kTreeHeight;
    return encode_scene_image(compile_scene(s, o));
}

struct FrameResult {
    size_t pixels = 0, matched = 0, leaves = 0;
    bool in_order = true, completed = false;
    std::string report;
    csgrt_sim::SimStats stats;
};

FrameResult run_frame(const std::vector<uint32_t>& words, TiePolicy ties, int ready_percent) {
    const CompiledScene cs = decode_scene_image(words);
    RenderOptions ro;
    ro.ties = ties;
    ro.threads = 1;
    // what this build renders
    ro.effects = rtl_effects(cs, FRAME_SHADOWS, FRAME_REFLECTION, FRAME_REFRACTION, FRAME_SPECULAR);
    const Frame model = render(cs, ro);
    csgrt_sim::TopSim<Vcsgrt_top> sim(FRAME_BITS, kLeafBits, kTreeHeight, FRAME_UNITS);
    sim.reset();
    sim.set_logging(!kEffects);
    FrameResult r;
    r.leaves = cs.leaves.size();
    if (sim.load(words) != 0) {
        r.report = "the RTL refused the scene image";
        return r;
    }
    size_t expect = 0;
    r.completed = sim.render(
        cs.width, cs.height, ties == TiePolicy::Regular, ready_percent,
        [&](int x, int y, uint32_t c) {
            const size_t i = size_t(y) * cs.width + x;
            if (i != expect++) r.in_order = false;
            ++r.pixels;
            if (i >= model.hit_leaf.size()) return;
            const uint32_t m =
                uint32_t(model.rgb[3 * i]) << 16 | uint32_t(model.rgb[3 * i + 1]) << 8 | model.rgb[3 * i + 2];
            if (m == c)
                ++r.matched;
            else if (r.report.empty())
                r.report = kEffects ? csgrt_sim::mismatch_report(cs, ties, x, y, c, nullptr, m)
                                    : csgrt_sim::mismatch_report(cs, ties, x, y, c, sim.log_for(i));
        },
        nullptr, r.stats, uint64_t(cs.width) * cs.height * kMaxCyclesPerPixel);
    return r;
}

// the loader's status for an image on a freshly reset core (0: loaded)
int load_status(const std::vector<uint32_t>& words) {
    csgrt_sim::TopSim<Vcsgrt_top> sim(FRAME_BITS, kLeafBits, kTreeHeight, FRAME_UNITS);
    sim.reset();
    return sim.load(words);
}

void expect_pixel_exact(const std::string& name, const Scene& scene, int w, int h, TiePolicy ties,
                        int ready_percent = 100) {
    const FrameResult r = run_frame(compile_words(scene, w, h), ties, ready_percent);
    const size_t n = size_t(w) * h;
    std::printf("[ frame    ] %-22s %2d bits, %d unit(s)%s, ties %-7s: matched %zu of %zu pixels, %llu cycles, "
                "%.3f pairs/cycle/unit\n",
                name.c_str(), FRAME_BITS, FRAME_UNITS, kEffects ? " +fx" : "",
                ties == TiePolicy::Paper ? "paper" : "regular", r.matched, n,
                (unsigned long long)r.stats.cycles,
                r.stats.cycles ? double(r.stats.pairs) / r.stats.cycles / FRAME_UNITS : 0.0);
    EXPECT_TRUE(r.completed) << name << ": the frame did not complete";
    EXPECT_TRUE(r.in_order) << name << ": pixels out of raster order";
    EXPECT_EQ(r.pixels, n) << name << ": pixels lost or duplicated";
    EXPECT_EQ(r.matched, n) << name << "\n" << r.report;
    // primary rays only: every ray meets every leaf exactly once, in every
    // lane (a lane that took a pair twice was the two-lane hang)
    if (!kEffects) EXPECT_EQ(r.stats.pairs, n * r.leaves) << name << ": pairs lost or duplicated";
}

const char* kCoincident =
    "camera { location <2.5, 3, -6> look_at <0, 0, 0> angle 40 right x*4/3 }\n"
    "light_source { <-6, 6, -6> color rgb 1 }\n"
    "background { color rgb <0.1, 0.1, 0.2> }\n"
    "#declare S = sphere { <0, 0, 0>, 1 pigment { color rgb <0.9, 0.7, 0.2> } }\n"
    "union {\n"
    "  difference {\n"
    "    box { <-1, -1, -0.5>, <1, 1, 0.5> pigment { color rgb <0.8, 0.6, 0.3> } }\n"
    "    cylinder { <0.1, 0, -0.5>, <0.1, 0, 0.5>, 0.45 pigment { color rgb <0.2, 0.3, 0.9> } }\n"
    "    rotate <17, 31, 5> translate <-1.2, 0, 0>\n"
    "  }\n"
    "  union { box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5> rotate <10, 20, 30> pigment { color rgb <0.3, 0.9, 0.4> } }\n"
    "          box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5> rotate <10, 20, 30> pigment { color rgb <0.9, 0.3, 0.4> } }\n"
    "          translate <1.3, 0.6, 0> }\n"
    "  difference { object { S } object { S } plane { -y, -0.3 } translate <1.2, -1.2, 0> }\n"
    "}\n";

Scene scene_file(const std::string& name) { return parse_scene_file("scenes/" + name + ".pov"); }

}  // namespace

TEST(Frame, BasicBothPolicies) {
    for (TiePolicy t : {TiePolicy::Paper, TiePolicy::Regular}) expect_pixel_exact("basic", scene_file("basic"), 48, 36, t);
}

TEST(Frame, DefaultSceneBothPolicies) {
    for (TiePolicy t : {TiePolicy::Paper, TiePolicy::Regular})
        expect_pixel_exact("default", scene_file("default"), 40, 30, t);
}

TEST(Frame, CsgMixAndRotated) {
    expect_pixel_exact("csg_mix", scene_file("csg_mix"), 40, 30, TiePolicy::Paper);
    expect_pixel_exact("rotated", scene_file("rotated"), 40, 30, TiePolicy::Regular);
}

// every light shadowless: on an effect build the ray tree spawns no shadow
// ray; on every build the loader reads the light flags word. Its three
// lights are more than a build for two holds: that build refuses it.
TEST(Frame, ShadowlessStudio) {
    const Scene s = scene_file("studio");
    ASSERT_EQ(s.lights.size(), 3u);
    if (int(s.lights.size()) <= FRAME_MAX_LIGHTS) {
        expect_pixel_exact("studio", s, 40, 30, TiePolicy::Paper);
    } else {
        EXPECT_EQ(load_status(compile_words(s, 8, 6)), 4) << "3 lights on a build for " << FRAME_MAX_LIGHTS;
    }
}

// a build for fewer lights than the loader's default: a scene with exactly
// as many renders (every light slot in use), one with one more is refused
#if FRAME_MAX_LIGHTS < 8
TEST(Frame, LightLimitOfTheBuild) {
    Scene s = scene_file("quadrics");
    ASSERT_EQ(s.lights.size(), 2u);
    while (int(s.lights.size()) < FRAME_MAX_LIGHTS) s.lights.push_back(s.lights[0]);
    while (int(s.lights.size()) > FRAME_MAX_LIGHTS) s.lights.pop_back();
    expect_pixel_exact("quadrics, MAX_LIGHTS lights", s, 32, 24, TiePolicy::Regular);
    s.lights.push_back(s.lights[0]);
    EXPECT_EQ(load_status(compile_words(s, 8, 6)), 4) << "one light more than MAX_LIGHTS " << FRAME_MAX_LIGHTS;
}
#endif

TEST(Frame, CoincidentSurfacesBothPolicies) {
    const Scene s = parse_scene_string(kCoincident, "coincident.pov");
    for (TiePolicy t : {TiePolicy::Paper, TiePolicy::Regular}) expect_pixel_exact("coincident", s, 48, 36, t);
}

TEST(Frame, RandomBackPressureLosesNothing) {
    expect_pixel_exact("basic, 35% ready", scene_file("basic"), 32, 24, TiePolicy::Paper, 35);
}

TEST(Frame, RefusesAnImageForAnotherConfiguration) {
    std::vector<uint32_t> words = compile_words(scene_file("basic"), 8, 6);
    words[H_BITS] = FRAME_BITS == 24 ? 16 : 24;   // compiled for another width
    EXPECT_EQ(load_status(words), 2);
}

// every header word the loader checks, each with its code (csgrt_scene_loader's
// header and docs/fpga.md: 1 magic or version, 3 leaves, 4 materials or lights)
TEST(Frame, RefusesBadHeaderWordsWithTheirCodes) {
    const std::vector<uint32_t> good = compile_words(scene_file("basic"), 8, 6);
    ASSERT_EQ(load_status(good), 0);
    const struct { int word; uint32_t value; int code; } cases[] = {
        {H_MAGIC, good[H_MAGIC] ^ 1u, 1}, {H_VERSION, good[H_VERSION] + 1u, 1},
        {H_LEAVES, 1000u, 3}, {H_MATERIALS, 1000u, 4}, {H_LIGHTS, 100u, 4}};
    for (const auto& c : cases) {
        std::vector<uint32_t> words = good;
        words[c.word] = c.value;
        EXPECT_EQ(load_status(words), c.code) << "header word " << c.word << " = " << c.value;
    }
}

#if FRAME_SHADOWS || FRAME_REFLECTION
// Effect builds: the ray tree (csgrt_raytree, csgrt_spawn, secondary rays in
// the walk units) against the model's accumulate_fx, pixel for pixel.
Scene paper_file(const std::string& name) { return parse_scene_file("scenes/paper/" + name + ".pov"); }

TEST(FrameEffects, ShadowsAndReflectionOnTheEffectScenes) {
    expect_pixel_exact("mirror", scene_file("mirror"), 40, 30, TiePolicy::Paper);
    expect_pixel_exact("fig08 (Fig. 8)", paper_file("fig08_reflect"), 40, 30, TiePolicy::Paper);
    expect_pixel_exact("fig08 (Fig. 8)", paper_file("fig08_reflect"), 40, 30, TiePolicy::Regular);
}

// Coincident faces cast shadows and reflect: the look-behind of the walk
// unit and the child's fix-up in the event sorter decide these pixels.
TEST(FrameEffects, CoincidentFacesWithShadows) {
    expect_pixel_exact("fig06 (Fig. 6)", paper_file("fig06_add_shared"), 40, 30, TiePolicy::Paper);
    expect_pixel_exact("fig14 (Fig. 14)", paper_file("fig14_self_add"), 40, 30, TiePolicy::Regular);
}

// Shadowless lights (docs/effects.md): the ray tree sends no shadow ray to
// them and shades with their own colour. Frame.ShadowlessStudio (every
// light shadowless: the spawn unit gets an empty light mask) runs on these
// builds too; here quadrics.pov with its fill light made shadowless mixes
// both kinds in one hit.
TEST(FrameEffects, ShadowlessLights) {
    Scene mixed = scene_file("quadrics");
    ASSERT_EQ(mixed.lights.size(), 2u);
    mixed.lights[1].shadowless = true;
    expect_pixel_exact("quadrics, fill light shadowless", mixed, 40, 30, TiePolicy::Regular);
    // the check can fail: at this size the fill light's shadows show, so a
    // build that cast them anyway would not match
    RenderOptions ro;
    ro.ties = TiePolicy::Regular;
    const Frame a = render(decode_scene_image(compile_words(mixed, 40, 30)), ro),
                b = render(decode_scene_image(compile_words(scene_file("quadrics"), 40, 30)), ro);
    EXPECT_NE(a.rgb, b.rgb) << "the fill light casts no visible shadow at 40x30";
}

// A light inside an object: a shadow ray from outside crosses a leaf once
// before the light and once past it, so the ray's t limit keeps one of the
// leaf's two events (the event sorter's input stage counts them: no other
// scene here has a leaf straddle a light).
TEST(FrameEffects, LightInsideAnObject) {
    expect_pixel_exact("lantern", scene_file("lantern"), 40, 30, TiePolicy::Regular);
}

TEST(FrameEffects, BackPressureLosesNothing) {
    expect_pixel_exact("mirror, 40% ready", scene_file("mirror"), 24, 18, TiePolicy::Paper, 40);
}
#endif

#if FRAME_REFRACTION
// Refraction: transmitted rays, total internal reflection, the look-ahead
// through coincident transparent surfaces (the walker and csgrt_quadric_at),
// transparent shadows.
TEST(FrameEffects, RefractionOnTheGlassScenes) {
    expect_pixel_exact("glass", scene_file("glass"), 40, 30, TiePolicy::Paper);
    expect_pixel_exact("nested_glass", scene_file("nested_glass"), 40, 30, TiePolicy::Regular);
}

TEST(FrameEffects, CoincidentTransparentSurfaces) {
    expect_pixel_exact("fig13 (Fig. 13)", paper_file("fig13_coincident_transparent"), 40, 30, TiePolicy::Paper);
    expect_pixel_exact("fig13 (Fig. 13)", paper_file("fig13_coincident_transparent"), 40, 30, TiePolicy::Regular);
    expect_pixel_exact("fig16 (Fig. 16)", paper_file("fig16_transparency"), 40, 30, TiePolicy::Paper);
}
#endif
