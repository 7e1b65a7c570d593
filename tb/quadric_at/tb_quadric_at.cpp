// tb_quadric_at.cpp — csgrt_quadric_at against the model's look-ahead test:
// q = quadric_at_fx(coef, hit_point_fx(o, d, t)) (model/trace.cpp), the
// value whose sign says whether a hit point already lies beyond a surface
// (algorithm.md section 6). Every result is compared, in order, at BITS 12,
// 16, 24 and 32, under random input gaps and output back-pressure:
//   - scenes glass, nested_glass and the paper's Fig. 13 and Fig. 16: every
//     leaf of the scene at the hit point of camera rays (the look-ahead's
//     own inputs: a hit t and the leaves whose events follow it);
//   - random rays and quadrics at the edges of the documented bounds
//     (|o| < 4, |t| < 2, |coef| < 1), the hit point's ties (t = 1/2 and
//     3/2 with odd d_i), and planes through the hit point (q = 0 exactly,
//     where beyond_fx's q <= 0 / q > 0 decides).
// A back-to-back run checks the documented latency (20 clocks).
#include "Vtb_quadric_at.h"
#include "compile.h"
#include "parse.h"
#include "render.h"
#include "stream.h"
#include "trace.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

namespace {

using Top = Vtb_quadric_at;
using csgrt::i64;
using V3 = std::array<i64, 3>;
using Coef = std::array<i64, csgrt::kNumCoefs>;

using tb::repo_root;

using tb::get_field;
using tb::set_field;

struct Request {
    csgrt::RayFx ray;
    i64 t = 0;
    Coef coef{};
};

template <int NB>
struct Dut;
#define QAT_DUT(NB)                                                                                      \
    template <>                                                                                          \
    struct Dut<NB> {                                                                                     \
        static tb::StreamPorts ports(Top* t) {                                                           \
            return {&t->b##NB##_clk_i, &t->b##NB##_rst_ni, &t->b##NB##_valid_i,                          \
                    &t->b##NB##_ready_o, &t->b##NB##_valid_o, &t->b##NB##_ready_i};                      \
        }                                                                                                \
        static void drive(Top* t, const Request& r, uint32_t user) {                                     \
            for (int i = 0; i < 3; ++i) {                                                                \
                set_field(t->b##NB##_o_i, i * NB, NB, r.ray.o[i]);                                       \
                set_field(t->b##NB##_d_i, i * NB, NB, r.ray.d[i]);                                       \
            }                                                                                            \
            set_field(t->b##NB##_t_i, 0, NB - 1, r.t);                                                   \
            for (int k = 0; k < csgrt::kNumCoefs; ++k) set_field(t->b##NB##_coef_i, k * NB, NB, r.coef[k]); \
            t->b##NB##_user_i = user;                                                                    \
        }                                                                                                \
        static i64 q(Top* t) { return get_field(t->b##NB##_q_o, 0, NB + 8); }                            \
        static uint32_t user(Top* t) { return t->b##NB##_user_o; }                                      \
    };
QAT_DUT(12)
QAT_DUT(16)
QAT_DUT(24)
QAT_DUT(32)

i64 model_q(const csgrt::Formats& fmt, const Request& r) {
    V3 p;
    csgrt::hit_point_fx(fmt, r.ray, r.t, p);   // beyond_fx ignores the range check too
    return csgrt::quadric_at_fx(fmt, r.coef, p);
}

// One Verilated model for the whole process: every instance lives in it.
Top* model() {
    static tb::Harness<Top> h;
    return h.top.get();
}

template <int NB>
tb::StreamResult run(const std::vector<Request>& reqs, double p_gap, double p_stall, uint64_t seed) {
    Top* top = model();
    const csgrt::Formats fmt(NB);
    std::vector<i64> want(reqs.size());
    for (size_t i = 0; i < reqs.size(); ++i) want[i] = model_q(fmt, reqs[i]);
    return tb::run_stream(
        top, Dut<NB>::ports(top), reqs.size(), [&](size_t i) { Dut<NB>::drive(top, reqs[i], uint32_t(i & 0xffff)); },
        [&](size_t i) -> std::string {
            const i64 q = Dut<NB>::q(top);
            const uint32_t u = Dut<NB>::user(top);
            if (q == want[i] && u == (i & 0xffff)) return "";
            const Request& r = reqs[i];
            char buf[256];
            std::snprintf(buf, sizeof buf, "DUT q %lld user %u, model q %lld (o %lld %lld %lld, d %lld %lld %lld, t %lld)",
                          (long long)q, u, (long long)want[i], (long long)r.ray.o[0], (long long)r.ray.o[1],
                          (long long)r.ray.o[2], (long long)r.ray.d[0], (long long)r.ray.d[1], (long long)r.ray.d[2],
                          (long long)r.t);
            return buf;
        },
        p_gap, p_stall, seed);
}

size_t scaled(size_t n) { return std::max<size_t>(50, size_t(double(n) * tb::scale())); }

i64 urand(std::mt19937_64& rng, i64 lo, i64 hi) { return lo + i64(rng() % uint64_t(hi - lo + 1)); }

// Every leaf at the hit point of the scene's camera rays.
std::vector<Request> scene_requests(const std::string& name, int bits, size_t cap) {
    csgrt::CompileOptions opt;
    opt.bits = bits;
    opt.width = 40;
    opt.height = 30;
    const csgrt::CompiledScene cs =
        csgrt::compile_scene(csgrt::parse_scene_file(repo_root() + "/scenes/" + name + ".pov"), opt);
    std::vector<Request> out;
    for (int y = 0; y < cs.height && out.size() < cap; ++y)
        for (int x = 0; x < cs.width && out.size() < cap; ++x) {
            const csgrt::RayFx ray = csgrt::camera_ray_fx(cs, x, y);
            const csgrt::TraceResult<i64> tr = csgrt::trace_primary_fx(cs, ray, csgrt::TiePolicy::Paper);
            if (!tr.hit) continue;
            for (const auto& leaf : cs.leaves) out.push_back({ray, tr.t, leaf.coef});
        }
    return out;
}

struct Counts {
    size_t zero = 0, neg = 0, pos = 0, p_ties = 0, far = 0;
};

// Random requests at the edges of the bounds; `counts` tallies the cases the
// bench must have seen.
Request random_request(const csgrt::Formats& fmt, std::mt19937_64& rng, Counts& c) {
    const int F = fmt.frac, FC = fmt.coef_frac;
    const i64 one = i64(1) << F, cone = i64(1) << FC;
    Request r;
    const int kind = int(rng() % 4);
    for (int i = 0; i < 3; ++i) {
        r.ray.o[i] = kind == 0 ? urand(rng, -4 * one, 4 * one - 1) : urand(rng, -one, one - 1);
        r.ray.d[i] = urand(rng, -one, one);   // |d_i| <= 1: the bound the unit is sized for
    }
    if (kind == 1) {
        r.t = (rng() & 1) ? one / 2 : 3 * one / 2;   // rnd(t d_i, F) ties for odd d_i
        for (int i = 0; i < 3; ++i) r.ray.d[i] |= 1;
        ++c.p_ties;
    } else {
        r.t = kind == 0 ? urand(rng, -2 * one, 2 * one - 1) : urand(rng, 0, 2 * one - 1);
    }
    for (int k = 0; k < csgrt::kNumCoefs; ++k) r.coef[k] = urand(rng, -(cone - 1), cone - 1);
    if (kind == 3) {
        // a plane 2 P . x + Q through the hit point: P = e_i / 2, Q = -p_i
        // (exact when p_i has no bits below FC's grid), q = 0 exactly
        V3 p;
        csgrt::hit_point_fx(fmt, r.ray, r.t, p);
        const int i = int(rng() % 3);
        if (p[i] > -one && p[i] < one) {
            r.coef.fill(0);
            r.coef[csgrt::C_P0 + i] = cone / 2;
            r.coef[csgrt::C_Q] = -(p[i] << (FC - F));
        }
    }
    if (kind == 0) ++c.far;
    const i64 q = model_q(fmt, r);
    (q == 0 ? c.zero : q < 0 ? c.neg : c.pos)++;
    return r;
}

template <int NB>
void all_checks(uint64_t seed) {
    for (const char* name : {"glass", "nested_glass", "paper/fig13_coincident_transparent", "paper/fig16_transparency"}) {
        const std::vector<Request> reqs = scene_requests(name, NB, scaled(3000));
        ASSERT_FALSE(reqs.empty()) << name;
        const tb::StreamResult s = run<NB>(reqs, 0.3, 0.3, seed++);
        EXPECT_TRUE(s.ok()) << "BITS=" << NB << " " << name << ": " << s.summary();
        std::printf("quadric_at BITS=%d %s: %s\n", NB, name, s.summary().c_str());
    }
    const csgrt::Formats fmt(NB);
    std::mt19937_64 rng(seed++);
    Counts c;
    std::vector<Request> reqs;
    for (size_t i = 0; i < scaled(20000); ++i) reqs.push_back(random_request(fmt, rng, c));
    const tb::StreamResult s = run<NB>(reqs, 0.3, 0.3, seed++);
    EXPECT_TRUE(s.ok()) << "BITS=" << NB << " random: " << s.summary();
    std::printf("quadric_at BITS=%d random: %s (q = 0: %zu, q < 0: %zu, q > 0: %zu, hit-point ties %zu, "
                "|o| up to 4 and t < 0: %zu)\n",
                NB, s.summary().c_str(), c.zero, c.neg, c.pos, c.p_ties, c.far);
    EXPECT_GT(c.zero, 0u) << "no plane through the hit point";
    EXPECT_GT(c.neg, 0u);
    EXPECT_GT(c.pos, 0u);
    // back to back: one evaluation every 20 clocks, latency 20
    std::vector<Request> b2b(reqs.begin(), reqs.begin() + 200);
    const tb::StreamResult bb = run<NB>(b2b, 0.0, 0.0, seed++);
    EXPECT_TRUE(bb.ok()) << bb.summary();
    EXPECT_EQ(bb.min_latency, 20);
    EXPECT_EQ(bb.max_latency, 20);
}

TEST(QuadricAt, Bits12) { all_checks<12>(tb::seed(1200)); }
TEST(QuadricAt, Bits16) { all_checks<16>(tb::seed(1600)); }
TEST(QuadricAt, Bits24) { all_checks<24>(tb::seed(2400)); }
TEST(QuadricAt, Bits32) { all_checks<32>(tb::seed(3200)); }

}  // namespace
