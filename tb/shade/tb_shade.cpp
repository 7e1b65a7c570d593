// tb_shade.cpp — csgrt_shade against srgb_encode_fx(shade_fx(...))
// (model/render.cpp), every channel of every pixel, in order (nothing lost
// or duplicated).
//
// For each scene in scenes/*.pov at BITS 12, 16, 24, 32: the rays of a 64x48
// frame from camera_ray_fx, traced with trace_primary_fx (TiePolicy::Paper);
// the shade input is the trace result, the hit leaf's coefficients and the
// shown material (border.to, or border.from when it is air); misses included.
// Random input gaps and output back-pressure. Variants of the default scene
// with no lights and with 8 lights check the light sequencer; a back-to-back
// run measures the throughput (clocks per pixel) and the latency. The BITS 16
// and 32 instances are time-shared (II = 3, tb_shade.v), 12 and 24 not.
#include "Vtb_shade.h"
#include "compile.h"
#include "parse.h"
#include "render.h"
#include "stream.h"
#include "trace.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

namespace {

using Top = Vtb_shade;
using csgrt::i64;
using csgrt::i128;

using tb::repo_root;
// csgrt_srgb reads rtl/srgb_lut.hex relative to the working directory
void chdir_root() {
    if (chdir(repo_root().c_str()) != 0) std::perror("chdir");
}
const std::vector<std::string> kScenes = {"basic", "csg_mix", "default", "quadrics", "rotated"};

template <class W>
inline void set_field(W& w, int lsb, int width, i64 v) {
    if constexpr (std::is_integral_v<W>) {
        const uint64_t m = tb::mask(width) << lsb;
        w = W((uint64_t(w) & ~m) | ((uint64_t(v) << lsb) & m));
    } else {
        tb::set_bits(w, lsb, width, uint64_t(v));
    }
}

// One pixel's shade input and the model's answer.
struct Pixel {
    int x, y;
    bool hit;
    i64 t;
    csgrt::RayFx ray;
    std::array<i64, csgrt::kNumCoefs> coef{};
    const csgrt::MaterialInfo* mat = nullptr;
    int leaf = -1, mat_index = 0;
    std::array<i64, 3> col{};
    std::array<uint8_t, 3> rgb{};
};

template <int NB>
struct Dut;
#define SHADE_DUT(NB)                                                                            \
    template <>                                                                                  \
    struct Dut<NB> {                                                                             \
        static tb::StreamPorts ports(Top* t) {                                                   \
            return {&t->b##NB##_clk_i, &t->b##NB##_rst_ni, &t->b##NB##_valid_i,                  \
                    &t->b##NB##_ready_o, &t->b##NB##_valid_o, &t->b##NB##_ready_i};              \
        }                                                                                        \
        static void config(Top* t, const csgrt::CompiledScene& cs) {                             \
            t->b##NB##_num_lights_i = uint8_t(cs.lights.size());                                 \
            for (size_t k = 0; k < 8; ++k)                                                       \
                for (int i = 0; i < 3; ++i) {                                                    \
                    const bool have = k < cs.lights.size();                                      \
                    set_field(t->b##NB##_light_pos_i, int(k * 3 + i) * NB, NB,                   \
                              have ? cs.lights[k].pos_fx[i] : 0);                                \
                    set_field(t->b##NB##_light_color_i, int(k * 3 + i) * 16, 16,                 \
                              have ? cs.lights[k].color_fx[i] : 0);                              \
                }                                                                                \
            for (int c = 0; c < 3; ++c) set_field(t->b##NB##_background_i, c * 16, 16, cs.background_fx[c]); \
        }                                                                                        \
        static void drive(Top* t, const Pixel& p) {                                              \
            t->b##NB##_x_i = uint16_t(p.x);                                                      \
            t->b##NB##_y_i = uint16_t(p.y);                                                      \
            t->b##NB##_hit_i = p.hit;                                                            \
            set_field(t->b##NB##_t_i, 0, NB - 1, p.t);                                           \
            for (int i = 0; i < 3; ++i) {                                                        \
                set_field(t->b##NB##_o_i, i * NB, NB, p.ray.o[i]);                               \
                set_field(t->b##NB##_d_i, i * NB, NB, p.ray.d[i]);                               \
            }                                                                                    \
            for (int k = 0; k < csgrt::kNumCoefs; ++k) set_field(t->b##NB##_coef_i, k * NB, NB, p.coef[k]); \
            const csgrt::MaterialInfo* m = p.mat;                                                \
            for (int c = 0; c < 3; ++c) set_field(t->b##NB##_rgb_i, c * 16, 16, m ? m->rgb[c] : 0x5a5a); \
            t->b##NB##_ambient_i = uint16_t(m ? m->ambient : 0x1234);                            \
            t->b##NB##_diffuse_i = uint16_t(m ? m->diffuse : 0x4321);                            \
            t->b##NB##_phong_i = uint16_t(m ? m->phong : 0x777);                                 \
            t->b##NB##_phong_size_i = uint16_t(m ? m->phong_size : 3);                           \
        }                                                                                        \
        static std::array<int, 5> read(Top* t) {                                                 \
            return {t->b##NB##_x_o, t->b##NB##_y_o, t->b##NB##_r_o, t->b##NB##_g_o, t->b##NB##_b_o}; \
        }                                                                                        \
    };
SHADE_DUT(12)
SHADE_DUT(16)
SHADE_DUT(24)
SHADE_DUT(32)

csgrt::CompiledScene compile(const std::string& name, int bits, int w, int h) {
    csgrt::CompileOptions opt;
    opt.bits = bits;
    opt.width = w;
    opt.height = h;
    return csgrt::compile_scene(csgrt::parse_scene_file(repo_root() + "/scenes/" + name + ".pov"), opt);
}

std::vector<Pixel> pixels(const csgrt::CompiledScene& cs) {
    std::vector<Pixel> v;
    for (int y = 0; y < cs.height; ++y)
        for (int x = 0; x < cs.width; ++x) {
            Pixel p;
            p.x = x;
            p.y = y;
            p.ray = csgrt::camera_ray_fx(cs, x, y);
            const csgrt::TraceResult<i64> tr = csgrt::trace_primary_fx(cs, p.ray, csgrt::TiePolicy::Paper);
            p.hit = tr.hit;
            p.t = tr.hit ? tr.t : i64((x * 7919 + y * 104729) & 0xffff);   // a miss carries junk
            if (tr.hit) {
                p.leaf = tr.leaf;
                p.coef = cs.leaves[tr.leaf].coef;
                p.mat_index = tr.border.to ? tr.border.to : tr.border.from;
                p.mat = &cs.materials[p.mat_index];
            }
            p.col = csgrt::shade_fx(cs, p.ray, tr);
            for (int c = 0; c < 3; ++c) p.rgb[c] = csgrt::srgb_encode_fx(p.col[c]);
            v.push_back(p);
        }
    return v;
}

// The intermediate values of shade_fx, recomputed for a mismatch report.
i64 rnd(i128 x, int k) { return i64(csgrt::rshift_round(x, k)); }
i64 align(i64 v, int from, int to) { return from >= to ? rnd(v, from - to) : v << (to - from); }
std::string explain(const csgrt::CompiledScene& cs, const Pixel& p) {
    std::ostringstream s;
    s << "hit " << p.hit << " leaf " << p.leaf << " material " << p.mat_index << " t " << p.t << " o {"
      << p.ray.o[0] << " " << p.ray.o[1] << " " << p.ray.o[2] << "} d {" << p.ray.d[0] << " " << p.ray.d[1]
      << " " << p.ray.d[2] << "} linear col {" << p.col[0] << " " << p.col[1] << " " << p.col[2] << "}";
    if (!p.hit) return s.str();
    const int F = cs.fmt.frac, FC = cs.fmt.coef_frac;
    std::array<i64, 3> ps, ds, g;
    i64 ks[10];
    for (int i = 0; i < 3; ++i) {
        ps[i] = align(p.ray.o[i] + rnd(i128(p.t) * p.ray.d[i], F), F, 12);
        ds[i] = align(p.ray.d[i], F, 15);
    }
    for (int c = 0; c < 10; ++c) ks[c] = align(p.coef[c], FC, 15);
    const i64 A[3][3] = {{ks[0], ks[3], ks[4]}, {ks[3], ks[1], ks[5]}, {ks[4], ks[5], ks[2]}};
    for (int i = 0; i < 3; ++i) {
        i128 sum = i128(ks[6 + i]) << 12;
        for (int j = 0; j < 3; ++j) sum += i128(A[i][j]) * ps[j];
        g[i] = rnd(sum, 15);
    }
    std::array<i64, 3> n = csgrt::unit_fx(g, 15, 17);
    i128 nd = 0;
    for (int i = 0; i < 3; ++i) nd += i128(n[i]) * ds[i];
    if (nd > 0)
        for (i64& v : n) v = -v;
    i128 dn2 = 0;
    for (int i = 0; i < 3; ++i) dn2 += i128(ds[i]) * n[i];
    const i64 dn = rnd(dn2, 15);
    std::array<i64, 3> r;
    for (int i = 0; i < 3; ++i) r[i] = ds[i] - rnd(i128(2 * dn) * n[i], 15);
    s << "\n    ps {" << ps[0] << " " << ps[1] << " " << ps[2] << "} ds {" << ds[0] << " " << ds[1] << " " << ds[2]
      << "} g {" << g[0] << " " << g[1] << " " << g[2] << "} n {" << n[0] << " " << n[1] << " " << n[2]
      << "} dn " << dn << " r {" << r[0] << " " << r[1] << " " << r[2] << "}";
    for (size_t k = 0; k < cs.lights.size(); ++k) {
        std::array<i64, 3> lv;
        for (int i = 0; i < 3; ++i) lv[i] = align(cs.lights[k].pos_fx[i], F, 12) - ps[i];
        const std::array<i64, 3> l = csgrt::unit_fx(lv, 15, 17);
        i128 a = 0, b = 0;
        for (int i = 0; i < 3; ++i) a += i128(n[i]) * l[i], b += i128(r[i]) * l[i];
        const i64 ndl = rnd(a, 15), cr = rnd(b, 15);
        s << "\n    light " << k << ": l {" << l[0] << " " << l[1] << " " << l[2] << "} ndl " << ndl << " cos_r "
          << cr << " pow " << (cr > 0 ? csgrt::pow_fx(cr, p.mat->phong_size, 15) : 0);
    }
    s << "\n    material rgb {" << p.mat->rgb[0] << " " << p.mat->rgb[1] << " " << p.mat->rgb[2] << "} ambient "
      << p.mat->ambient << " diffuse " << p.mat->diffuse << " phong " << p.mat->phong << " size "
      << p.mat->phong_size;
    return s.str();
}

template <int NB>
tb::StreamResult run(const csgrt::CompiledScene& cs, const std::vector<Pixel>& px, double gap, double stall,
                     uint64_t seed) {
    tb::Harness<Top> h;
    Top* t = h.top.get();
    Dut<NB>::config(t, cs);
    return tb::run_stream(
        t, Dut<NB>::ports(t), px.size(), [&](size_t i) { Dut<NB>::drive(t, px[i]); },
        [&](size_t i) -> std::string {
            const std::array<int, 5> o = Dut<NB>::read(t);
            const Pixel& p = px[i];
            if (o[0] == p.x && o[1] == p.y && o[2] == p.rgb[0] && o[3] == p.rgb[1] && o[4] == p.rgb[2]) return "";
            std::ostringstream s;
            s << "pixel (" << p.x << "," << p.y << "): DUT (" << o[0] << "," << o[1] << ") rgb " << o[2] << " "
              << o[3] << " " << o[4] << ", model rgb " << int(p.rgb[0]) << " " << int(p.rgb[1]) << " "
              << int(p.rgb[2]) << "\n    " << explain(cs, p);
            return s.str();
        },
        gap, stall, seed);
}

template <int NB>
void check(const csgrt::CompiledScene& cs, const std::string& what, double gap, double stall, uint64_t seed) {
    const std::vector<Pixel> px = pixels(cs);
    size_t hits = 0;
    for (const Pixel& p : px) hits += p.hit;
    const tb::StreamResult r = run<NB>(cs, px, gap, stall, seed);
    EXPECT_TRUE(r.ok()) << "BITS=" << NB << " " << what << ": " << r.summary();
    std::printf("shade BITS=%d %s (%zu lights): %zu pixels (%zu hits), %s\n", NB, what.c_str(), cs.lights.size(),
                px.size(), hits, r.summary().c_str());
}

template <int NB>
void all_scenes(uint64_t seed) {
    chdir_root();
    for (const std::string& name : kScenes) check<NB>(compile(name, NB, 64, 48), name, 0.25, 0.25, seed++);
}

TEST(Shade, Bits12) { all_scenes<12>(tb::seed(12)); }
TEST(Shade, Bits16) { all_scenes<16>(tb::seed(16)); }
TEST(Shade, Bits24) { all_scenes<24>(tb::seed(24)); }
TEST(Shade, Bits32) { all_scenes<32>(tb::seed(32)); }

// No lights (ambient only), and 8 lights (the scene's and more around it).
TEST(Shade, LightCounts) {
    chdir_root();
    csgrt::CompiledScene cs = compile("default", 24, 64, 48);
    csgrt::CompiledScene none = cs;
    none.lights.clear();
    check<24>(none, "default, no lights", 0.25, 0.25, 41);
    csgrt::CompiledScene many = cs;
    std::mt19937_64 rng(42);
    while (many.lights.size() < 8) {
        csgrt::LightInfo l;
        for (int i = 0; i < 3; ++i) {
            l.pos_fx[i] = i64(rng() % (3u << cs.fmt.frac)) - (i64(3) << cs.fmt.frac) / 2;   // |.| < 1.5
            l.color_fx[i] = i64(rng() % (3u << csgrt::kColorFrac));                          // < 3.0
        }
        many.lights.push_back(l);
    }
    check<24>(many, "default, 8 lights", 0.25, 0.25, 43);
}

// Back to back: clocks per pixel = II max(1, lights) for hits, II for misses
// (II = 1 at BITS 24, 3 at BITS 16).
template <int NB>
void throughput(size_t ii) {
    chdir_root();
    for (size_t nl : {size_t(0), size_t(1), size_t(3)}) {
        csgrt::CompiledScene cs = compile("default", NB, 64, 48);
        while (cs.lights.size() > nl) cs.lights.pop_back();
        while (cs.lights.size() < nl) cs.lights.push_back(cs.lights.empty() ? csgrt::LightInfo{} : cs.lights[0]);
        const std::vector<Pixel> px = pixels(cs);
        size_t items = 0;
        for (const Pixel& p : px) items += (p.hit && nl > 0) ? nl : 1;
        const tb::StreamResult r = run<NB>(cs, px, 0.0, 0.0, 7);
        EXPECT_TRUE(r.ok()) << r.summary();
        std::printf("shade throughput, BITS %d, II %zu, %zu lights: %zu pixels, %zu light items, %llu cycles "
                    "(%.3f clocks/item), latency %d..%d\n",
                    NB, ii, nl, px.size(), items, (unsigned long long)r.cycles,
                    double(r.cycles - 200) / double(items), r.min_latency, r.max_latency);
        // every light item takes II clocks; the pipeline fill and 200 drain clocks on top
        EXPECT_LE(r.cycles, ii * items + size_t(r.max_latency) + 210);
        // and no fewer: the time-shared build cannot take an item sooner
        EXPECT_GE(r.cycles, ii * items);
    }
}
TEST(Shade, ThroughputAndLatency) { throughput<24>(1); }
TEST(Shade, ThroughputAndLatencyShared) { throughput<16>(3); }

}  // namespace
