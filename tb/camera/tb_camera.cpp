// tb_camera.cpp — csgrt_camera against camera_ray_fx() (model/render.cpp):
// every ray of a frame, in raster order, field by field (x, y, o, d), the
// last flag and the done pulse; nothing lost, duplicated or extra.
//
// For each scene in scenes/*.pov at BITS 12, 16, 24, 32: a 64x48 frame
// with random output back-pressure; then at BITS 24 a 640x480 frame of each
// scene (every pixel compared). A back-to-back run checks one ray per clock
// (per three clocks for the time-shared BITS 16 instance, tb_camera.v) and
// the latency from start to the first ray.
#include "Vtb_camera.h"
#include "compile.h"
#include "parse.h"
#include "render.h"
#include "stream.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

namespace {

using Top = Vtb_camera;
using csgrt::i64;

// the repository root, from this file's absolute path (tb/camera/tb_camera.cpp)
using tb::repo_root;
const std::vector<std::string> kScenes = {"basic", "csg_mix", "default", "quadrics", "rotated"};

inline void set_field(uint64_t& w, int lsb, int width, i64 v) {
    w = (w & ~(tb::mask(width) << lsb)) | ((uint64_t(v) & tb::mask(width)) << lsb);
}
template <class W>
inline void set_field(W& w, int lsb, int width, i64 v) {
    tb::set_bits(w, lsb, width, uint64_t(v));
}
inline i64 get_field(uint64_t w, int lsb, int width) { return tb::sext(w >> lsb, width); }
template <class W>
inline i64 get_field(const W& w, int lsb, int width) {
    return tb::sext(tb::get_bits(w, lsb, width), width);
}

struct Out {
    int x, y;
    bool last;
    std::array<i64, 3> o, d;
};

template <int NB>
struct Dut;
#define CAMERA_DUT(NB)                                                                        \
    template <>                                                                               \
    struct Dut<NB> {                                                                          \
        static uint8_t& clk(Top* t) { return t->b##NB##_clk_i; }                              \
        static uint8_t& rst(Top* t) { return t->b##NB##_rst_ni; }                             \
        static uint8_t& start(Top* t) { return t->b##NB##_start_i; }                          \
        static uint8_t& ready(Top* t) { return t->b##NB##_ready_i; }                          \
        static bool valid(Top* t) { return t->b##NB##_valid_o; }                              \
        static bool done(Top* t) { return t->b##NB##_done_o; }                                \
        static bool busy(Top* t) { return t->b##NB##_busy_o; }                                \
        static void config(Top* t, const csgrt::CompiledScene& cs) {                          \
            const csgrt::CameraInfo& c = cs.camera;                                           \
            for (int i = 0; i < 3; ++i) {                                                     \
                set_field(t->b##NB##_origin_i, i * NB, NB, c.origin_fx[i]);                   \
                set_field(t->b##NB##_base_i, i * 64, 64, c.base_fx[i]);                       \
                set_field(t->b##NB##_dx_i, i * 64, 64, c.dx_fx[i]);                           \
                set_field(t->b##NB##_dy_i, i * 64, 64, c.dy_fx[i]);                           \
            }                                                                                 \
            t->b##NB##_width_i = uint16_t(cs.width & 0xfff);                                  \
            t->b##NB##_height_i = uint16_t(cs.height & 0xfff);                                \
        }                                                                                     \
        static Out read(Top* t) {                                                             \
            Out o;                                                                            \
            o.x = t->b##NB##_x_o;                                                             \
            o.y = t->b##NB##_y_o;                                                             \
            o.last = t->b##NB##_last_o;                                                       \
            for (int i = 0; i < 3; ++i) {                                                     \
                o.o[i] = get_field(t->b##NB##_o_o, i * NB, NB);                               \
                o.d[i] = get_field(t->b##NB##_d_o, i * NB, NB);                               \
            }                                                                                 \
            return o;                                                                         \
        }                                                                                     \
    };
CAMERA_DUT(12)
CAMERA_DUT(16)
CAMERA_DUT(24)
CAMERA_DUT(32)

csgrt::CompiledScene compile(const std::string& name, int bits, int w, int h) {
    csgrt::CompileOptions opt;
    opt.bits = bits;
    opt.width = w;
    opt.height = h;
    return csgrt::compile_scene(csgrt::parse_scene_file(repo_root() + "/scenes/" + name + ".pov"), opt);
}

struct FrameResult {
    uint64_t rays = 0, mismatches = 0, extra = 0, cycles = 0;
    int first_latency = -1;
    bool done_ok = false, timeout = false;
    std::vector<std::string> messages;
};

// One frame through the DUT; p_stall: probability that ready is low.
template <int NB>
FrameResult run_frame(Top* t, const csgrt::CompiledScene& cs, double p_stall, uint64_t seed) {
    FrameResult r;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    auto tick = [&] {
        Dut<NB>::clk(t) = 1;
        t->eval();
        Dut<NB>::clk(t) = 0;
        t->eval();
    };
    Dut<NB>::clk(t) = 0;
    Dut<NB>::rst(t) = 0;
    Dut<NB>::start(t) = 0;
    Dut<NB>::ready(t) = 0;
    t->eval();
    for (int i = 0; i < 4; ++i) tick();
    Dut<NB>::rst(t) = 1;
    Dut<NB>::config(t, cs);
    t->eval();
    tick();
    Dut<NB>::start(t) = 1;
    tick();
    Dut<NB>::start(t) = 0;
    const uint64_t n = uint64_t(cs.width) * cs.height;
    uint64_t idle = 0, after = 0;
    int done_pulses = 0;
    bool done_expected_next = false;
    for (uint64_t cyc = 0;; ++cyc) {
        const bool drained = r.rays == n;
        Dut<NB>::ready(t) = (drained || !(u01(rng) < p_stall)) ? 1 : 0;
        t->eval();
        if (Dut<NB>::done(t)) {
            ++done_pulses;
            if (!done_expected_next) r.messages.push_back("done at the wrong time, cycle " + std::to_string(cyc));
        }
        done_expected_next = false;
        const bool fire = Dut<NB>::valid(t) && Dut<NB>::ready(t);
        if (fire) {
            if (r.rays >= n) {
                ++r.extra;
            } else {
                const int x = int(r.rays % cs.width), y = int(r.rays / cs.width);
                const Out o = Dut<NB>::read(t);
                const csgrt::RayFx m = csgrt::camera_ray_fx(cs, x, y);
                const bool last = r.rays + 1 == n;
                if (o.x != x || o.y != y || o.o != m.o || o.d != m.d || o.last != last) {
                    ++r.mismatches;
                    if (r.messages.size() < 8) {
                        std::ostringstream s;
                        s << "pixel (" << x << "," << y << "): DUT (" << o.x << "," << o.y << ") o {" << o.o[0]
                          << " " << o.o[1] << " " << o.o[2] << "} d {" << o.d[0] << " " << o.d[1] << " " << o.d[2]
                          << "} last " << o.last << "; model o {" << m.o[0] << " " << m.o[1] << " " << m.o[2]
                          << "} d {" << m.d[0] << " " << m.d[1] << " " << m.d[2] << "} last " << last;
                        r.messages.push_back(s.str());
                    }
                }
                if (r.rays == 0) r.first_latency = int(cyc) + 1;   // clocks after the start edge
                ++r.rays;
                if (last) done_expected_next = true;
            }
        }
        tick();
        r.cycles = cyc + 1;
        idle = fire ? 0 : idle + 1;
        if (r.rays == n && ++after > 200) break;
        if (idle > 10000) {
            r.timeout = true;
            break;
        }
    }
    r.done_ok = done_pulses == 1 && !Dut<NB>::busy(t);
    return r;
}

template <int NB>
void check_scene(const std::string& name, int w, int h, double p_stall, uint64_t seed, bool timing) {
    const csgrt::CompiledScene cs = compile(name, NB, w, h);
    tb::Harness<Top> hs;
    const FrameResult r = run_frame<NB>(hs.top.get(), cs, p_stall, seed);
    std::ostringstream s;
    s << "camera BITS=" << NB << " " << name << " " << w << "x" << h << ": matched " << (r.rays - r.mismatches)
      << "/" << uint64_t(w) * h << " rays, mismatches " << r.mismatches << ", extra " << r.extra << ", "
      << r.cycles << " cycles, first ray " << r.first_latency << " clocks after start"
      << (r.done_ok ? "" : ", DONE WRONG") << (r.timeout ? ", TIMEOUT" : "");
    for (const std::string& m : r.messages) s << "\n  " << m;
    std::printf("%s\n", s.str().c_str());
    EXPECT_EQ(r.rays, uint64_t(w) * h) << s.str();
    EXPECT_EQ(r.mismatches, 0u) << s.str();
    EXPECT_EQ(r.extra, 0u) << s.str();
    EXPECT_TRUE(r.done_ok) << s.str();
    EXPECT_FALSE(r.timeout) << s.str();
    EXPECT_TRUE(r.messages.empty()) << s.str();
    if (timing) {
        const int F = NB - 3;
        if (NB != 16) {
            EXPECT_EQ(r.first_latency, 2 * F + 19) << s.str();
            // one ray per clock: the last ray leaves n - 1 clocks after the first (+ 200 drain clocks)
            EXPECT_EQ(r.cycles, uint64_t(2 * F + 19) + uint64_t(w) * h - 1 + 200) << s.str();
        } else {
            // II = 3: G, R and csgrt_unit's stages (its division in (F+2+pad+4)/3 beats, its
            // F+8-bit square root in ceil((F+8)/3), three result bits a stage) take three
            // clocks each, the skid one; then a ray every third clock
            const int div_beats = (F + 2 + (5 - (F + 2) % 3) % 3 + 4) / 3;
            const int beats = 2 + (F + 8 + 2) / 3 + 5 + div_beats;
            EXPECT_GE(r.first_latency, 3 * beats) << s.str();
            EXPECT_LE(r.first_latency, 3 * beats + 3) << s.str();
            EXPECT_EQ(r.cycles, uint64_t(r.first_latency) + 3 * (uint64_t(w) * h - 1) + 200) << s.str();
        }
    }
}

template <int NB>
void all_scenes(int w, int h, double p_stall, uint64_t seed) {
    for (const std::string& name : kScenes) check_scene<NB>(name, w, h, p_stall, seed++, false);
}

TEST(Camera, ThroughputAndLatency) {
    check_scene<12>("default", 64, 48, 0.0, 1, true);
    check_scene<16>("default", 64, 48, 0.0, 1, true);
    check_scene<24>("default", 64, 48, 0.0, 1, true);
    check_scene<32>("default", 64, 48, 0.0, 1, true);
}
TEST(Camera, Bits12) { all_scenes<12>(64, 48, 0.3, tb::seed(12)); }
TEST(Camera, Bits16) { all_scenes<16>(64, 48, 0.3, tb::seed(16)); }
TEST(Camera, Bits24) { all_scenes<24>(64, 48, 0.3, tb::seed(24)); }
TEST(Camera, Bits32) { all_scenes<32>(64, 48, 0.3, tb::seed(32)); }
TEST(Camera, Bits24_640x480) { all_scenes<24>(640, 480, 0.2, tb::seed(640)); }
// odd sizes: one row, one column
TEST(Camera, OddSizes) {
    check_scene<24>("default", 1, 7, 0.5, 3, false);
    check_scene<24>("default", 7, 1, 0.5, 4, false);
    check_scene<24>("default", 1, 1, 0.5, 5, false);
}

}  // namespace
