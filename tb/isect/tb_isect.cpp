// tb_isect.cpp — csgrt_isect against intersect_fx() (model/trace.cpp), field
// by field: count, both events (t, range, entering; events past count carry
// the model's defaults too), inside_at_minus_inf, a, b, c, and the leaf tag
// (in-order check: nothing lost, nothing duplicated).
//
// Per width (BITS 12, 16, 24, 32): a mix of random dense quadrics, spheres,
// cylinders, cones, planes (axis-aligned and not), sparse dyadic quadrics
// and rays that make a = 0, b = 0, disc = 0, qq = 0, tangents and
// saturation happen, with unit directions (random or axis-aligned) and
// origins anywhere in the coordinate range; coverage counters must all be
// non-zero. Random input gaps and output back-pressure; a back-to-back run
// checks latency 2F+23 (2F+26 above 18 bits) and full throughput. The time-shared unit (II = 3,
// BITS 16 and 24) the same way, its latency and one pair per three clocks.
#include "Vtb_isect.h"
#include "compile.h"
#include "fixed.h"
#include "stream.h"
#include "trace.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

namespace {

using Top = Vtb_isect;
using csgrt::i64;
using Coefs = std::array<i64, csgrt::kNumCoefs>;

struct Case {
    Coefs coef{};
    csgrt::RayFx ray;
};

struct Out {
    int count = 0;
    bool inside = false;
    i64 t[2]{};
    int range[2]{};
    bool enter[2]{};
    i64 a = 0, b = 0, c = 0;
    unsigned tag = 0;
};

inline void set_field(uint64_t& w, int lsb, int width, i64 v) {
    w = (w & ~(tb::mask(width) << lsb)) | ((uint64_t(v) & tb::mask(width)) << lsb);
}
template <class W>
inline void set_field(W& w, int lsb, int width, i64 v) {
    tb::set_bits(w, lsb, width, uint64_t(v));
}

// Dut<NB, II>: the instance of width NB and initiation interval II (its
// ports b<NB>_*, or s<NB>_* for the time-shared II = 3 ones)
template <int NB, int II>
struct Dut;

#define ISECT_DUT(NB, II, PFX)                                                                          \
    template <>                                                                                       \
    struct Dut<NB, II> {                                                                              \
        static tb::StreamPorts ports(Top* t) {                                                        \
            return {&t->PFX##NB##_clk_i, &t->PFX##NB##_rst_ni, &t->PFX##NB##_valid_i,                       \
                    &t->PFX##NB##_ready_o, &t->PFX##NB##_valid_o, &t->PFX##NB##_ready_i};                   \
        }                                                                                             \
        static void drive(Top* t, const Case& c, unsigned tag) {                                      \
            for (int i = 0; i < 3; ++i) {                                                             \
                set_field(t->PFX##NB##_o_i, i * NB, NB, c.ray.o[i]);                                    \
                set_field(t->PFX##NB##_d_i, i * NB, NB, c.ray.d[i]);                                    \
            }                                                                                         \
            for (int k = 0; k < csgrt::kNumCoefs; ++k) set_field(t->PFX##NB##_coef_i, k * NB, NB, c.coef[k]); \
            t->PFX##NB##_leaf_i = uint16_t(tag);                                                        \
        }                                                                                             \
        static Out read(Top* t) {                                                                     \
            const int F = NB - 3;                                                                     \
            Out o;                                                                                    \
            o.count = t->PFX##NB##_count_o;                                                             \
            o.inside = t->PFX##NB##_inside_o;                                                           \
            o.t[0] = tb::sext(t->PFX##NB##_t0_o, F + 2);                                                \
            o.t[1] = tb::sext(t->PFX##NB##_t1_o, F + 2);                                                \
            o.range[0] = t->PFX##NB##_range0_o;                                                         \
            o.range[1] = t->PFX##NB##_range1_o;                                                         \
            o.enter[0] = t->PFX##NB##_enter0_o;                                                         \
            o.enter[1] = t->PFX##NB##_enter1_o;                                                         \
            o.a = tb::sext(t->PFX##NB##_a_o, F + 3);                                                    \
            o.b = tb::sext(t->PFX##NB##_b_o, F + 6);                                                    \
            o.c = tb::sext(t->PFX##NB##_c_o, F + 9);                                                    \
            o.tag = t->PFX##NB##_leaf_o;                                                                \
            return o;                                                                                 \
        }                                                                                             \
    };
ISECT_DUT(12, 1, b)
ISECT_DUT(16, 1, b)
ISECT_DUT(24, 1, b)
ISECT_DUT(32, 1, b)
ISECT_DUT(16, 3, s)
ISECT_DUT(24, 3, s)

std::string compare(const Out& o, const csgrt::LeafEvents<i64>& m, unsigned want_tag) {
    std::ostringstream s;
    auto field = [&](const char* name, i64 dut, i64 model) {
        if (dut != model) s << " " << name << ": DUT " << dut << " model " << model << ";";
    };
    field("tag", o.tag, want_tag);
    field("count", o.count, m.count);
    field("inside", o.inside, m.inside_at_minus_inf);
    field("a", o.a, m.a);
    field("b", o.b, m.b);
    field("c", o.c, m.c);
    for (int i = 0; i < 2; ++i) {
        const std::string e = "ev" + std::to_string(i) + ".";
        field((e + "t").c_str(), o.t[i], m.ev[i].t);
        field((e + "range").c_str(), o.range[i], int(m.ev[i].range));
        field((e + "entering").c_str(), o.enter[i], m.ev[i].entering);
    }
    return s.str();
}

std::string describe(const Case& c) {
    std::ostringstream s;
    s << "coef {";
    for (i64 k : c.coef) s << " " << k;
    s << " } o {" << c.ray.o[0] << " " << c.ray.o[1] << " " << c.ray.o[2] << "} d {" << c.ray.d[0] << " "
      << c.ray.d[1] << " " << c.ray.d[2] << "}";
    return s.str();
}

// ---- case generators ----------------------------------------------------------

class Gen {
   public:
    Gen(int bits, uint64_t seed) : fmt_(bits), rng_(seed) {}

    Case next() {
        Case c;
        switch (rng_() % 10) {
            case 0: c.coef = dense(); break;
            case 1: case 2: c.coef = sphere(); break;
            case 3: c.coef = cylinder(); break;
            case 4: c.coef = cone(); break;
            case 5: c.coef = plane(); break;
            case 6: c.coef = axis_plane(); break;
            case 7: case 8: return sparse();
            default: return tangent();
        }
        c.ray = ray();
        return c;
    }

   private:
    csgrt::Formats fmt_;
    std::mt19937_64 rng_;
    std::normal_distribution<double> gauss_{0.0, 1.0};

    double uni(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
    i64 cmax() const { return (i64(1) << (fmt_.bits - 1)) - 1; }
    i64 clampc(i64 v) const { return std::max(-cmax() - 1, std::min(cmax(), v)); }
    i64 qcoef(double x) const { return clampc(std::llround(std::ldexp(x, fmt_.coef_frac))); }
    i64 qcoord(double x) const { return clampc(std::llround(std::ldexp(x, fmt_.frac))); }
    i64 rand_bits() { return tb::sext(rng_(), fmt_.bits); }

    // a quadric given in double: scaled so that the largest |coefficient| < 1
    Coefs quantise(const std::array<double, 10>& q) {
        double m = 0;
        for (double x : q) m = std::max(m, std::fabs(x));
        const double k = (m > 0 ? 1.0 / m : 1.0) * uni(0.3, 1.0);
        Coefs c;
        for (int i = 0; i < 10; ++i) c[i] = qcoef(q[i] * k);
        return c;
    }
    // A = diag(ax, ay, az) + offdiag, centre cen, Q = (x-c)'A(x-c) - r2
    Coefs centred(const double A[3][3], const double cen[3], double r2) {
        std::array<double, 10> q{};
        q[csgrt::C_A00] = A[0][0], q[csgrt::C_A11] = A[1][1], q[csgrt::C_A22] = A[2][2];
        q[csgrt::C_A01] = A[0][1], q[csgrt::C_A02] = A[0][2], q[csgrt::C_A12] = A[1][2];
        double Ac[3], cAc = 0;
        for (int i = 0; i < 3; ++i) {
            Ac[i] = A[i][0] * cen[0] + A[i][1] * cen[1] + A[i][2] * cen[2];
            cAc += cen[i] * Ac[i];
        }
        q[csgrt::C_P0] = -Ac[0], q[csgrt::C_P1] = -Ac[1], q[csgrt::C_P2] = -Ac[2];
        q[csgrt::C_Q] = cAc - r2;
        if (rng_() & 1)   // the complement half-space
            for (double& x : q) x = -x;
        return quantise(q);
    }
    void rand_centre(double c[3], double r) {
        for (int i = 0; i < 3; ++i) c[i] = uni(-r, r);
    }
    Coefs dense() {
        Coefs c;
        for (i64& x : c) x = rand_bits();
        return c;
    }
    Coefs sphere() {
        const double A[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        double cen[3];
        rand_centre(cen, 2.0);
        const double r = uni(0.02, 2.0);
        return centred(A, cen, r * r);
    }
    Coefs cylinder() {
        double ax[3] = {gauss_(rng_), gauss_(rng_), gauss_(rng_)};
        if (rng_() & 1) ax[0] = ax[1] = 0, ax[2] = 1;   // axis-aligned
        const double n = std::sqrt(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]);
        double A[3][3];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) A[i][j] = (i == j) - ax[i] * ax[j] / (n * n);
        double cen[3];
        rand_centre(cen, 2.0);
        const double r = uni(0.02, 1.5);
        return centred(A, cen, r * r);
    }
    Coefs cone() {
        const double s = uni(0.1, 2.0);
        const double A[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, -s * s}};
        double cen[3];
        rand_centre(cen, 2.0);
        return centred(A, cen, rng_() % 3 == 0 ? uni(-0.5, 0.5) : 0.0);
    }
    Coefs plane() {
        std::array<double, 10> q{};
        q[csgrt::C_P0] = gauss_(rng_), q[csgrt::C_P1] = gauss_(rng_), q[csgrt::C_P2] = gauss_(rng_);
        q[csgrt::C_Q] = uni(-4.0, 4.0);
        return quantise(q);
    }
    Coefs axis_plane() {
        Coefs c{};
        const int ax = int(rng_() % 3);
        const i64 k = i64(1) << (fmt_.coef_frac - 1 - int(rng_() % 4));
        c[csgrt::C_P0 + ax] = (rng_() & 1) ? k : -k;
        c[csgrt::C_Q] = (rng_() % 4 == 0) ? 0 : rand_bits();
        return c;
    }
    // A unit direction: random, or axis-aligned, or diagonal.
    std::array<i64, 3> direction() {
        std::array<i64, 3> d{};
        const i64 one = fmt_.one();
        switch (rng_() % 4) {
            case 0: {
                d[rng_() % 3] = (rng_() & 1) ? one : -one;
                return d;
            }
            case 1: {
                const int i = int(rng_() % 3), j = (i + 1 + int(rng_() % 2)) % 3;
                d[i] = qcoord((rng_() & 1) ? M_SQRT1_2 : -M_SQRT1_2);
                d[j] = qcoord((rng_() & 1) ? M_SQRT1_2 : -M_SQRT1_2);
                return d;
            }
            default: {
                double v[3], n = 0;
                do {
                    n = 0;
                    for (double& x : v) x = gauss_(rng_), n += x * x;
                } while (n < 1e-6);
                n = std::sqrt(n);
                for (int i = 0; i < 3; ++i) d[i] = qcoord(v[i] / n);
                return d;
            }
        }
    }
    std::array<i64, 3> origin() {
        std::array<i64, 3> o{};
        switch (rng_() % 4) {
            case 0:
                for (i64& x : o) x = rand_bits();   // anywhere, |o_i| < 4
                return o;
            case 1:
                return o;   // the origin of the frame
            default:
                for (i64& x : o) x = qcoord(uni(-2.0, 2.0));
                return o;
        }
    }
    csgrt::RayFx ray() {
        csgrt::RayFx r;
        r.o = origin();
        r.d = direction();
        return r;
    }
    // Dyadic coefficients and origins with axis-aligned or diagonal
    // directions: exact coincidences (a = 0, b = 0, disc = 0, qq = 0).
    Case sparse() {
        Case c;
        for (int k = 0; k < 10; ++k) {
            if (rng_() % 2) continue;
            const i64 v = i64(1) << (fmt_.coef_frac - 1 - int(rng_() % 5));
            c.coef[k] = (rng_() & 1) ? v : -v;
        }
        for (i64& x : c.ray.o) x = i64(int(rng_() % 25) - 12) << (fmt_.frac - 2);   // k/4 in [-3, 3]
        std::array<i64, 3> d{};
        d[rng_() % 3] = (rng_() & 1) ? fmt_.one() : -fmt_.one();
        c.ray.d = (rng_() % 4 == 0) ? direction() : d;
        return c;
    }
    // A sphere k(|x|^2 - r^2) at the frame's origin and an axis-aligned ray
    // at distance r (tangent), or r +- 1 ulp, or tangent from a point on it.
    Case tangent() {
        Case c;
        const int e = 1 + int(rng_() % 3);
        const i64 k = i64(1) << (fmt_.coef_frac - e);   // 2^-e
        c.coef[csgrt::C_A00] = c.coef[csgrt::C_A11] = c.coef[csgrt::C_A22] = k;
        const int rs = int(rng_() % 4);                  // r = m / 2^rs, m small
        const double r = double(1 + rng_() % 3) / double(1 << rs);
        c.coef[csgrt::C_Q] = qcoef(-std::ldexp(r * r, -e));
        const int ax = int(rng_() % 3), off = (ax + 1) % 3;
        c.ray.d[ax] = (rng_() & 1) ? fmt_.one() : -fmt_.one();
        if (rng_() % 3 == 0) {
            // the origin on the sphere, the ray tangent there: b = c = 0, qq = 0
            c.ray.o[off] = (rng_() & 1) ? qcoord(r) : -qcoord(r);
        } else {
            c.ray.o[off] = qcoord(r) + i64(int(rng_() % 3) - 1);
            c.ray.o[ax] = qcoord(uni(-2.0, 2.0));
        }
        return c;
    }
};

// ---- the test -----------------------------------------------------------------

struct Coverage {
    std::map<std::string, uint64_t> n;
    void add(const csgrt::LeafEvents<i64>& m) {
        const bool linear = m.a == 0;
        if (linear && m.b == 0) ++n["a=0,b=0"];
        else if (linear) ++n["linear"];
        else {
            const csgrt::i128 disc = csgrt::i128(m.b) * m.b - csgrt::i128(m.a) * m.c;
            if (disc < 0) ++n["disc<0"];
            else if (disc == 0) ++n["disc=0"];
            if (m.b == 0) ++n["b=0 (a!=0)"];
            if (m.b == 0 && disc == 0) ++n["qq=0"];
            if (disc >= 0 && m.count == 0) ++n["equal pair dropped"];
            if (m.count == 2) ++n["two events"];
        }
        for (int i = 0; i < m.count; ++i) {
            if (m.ev[i].range == csgrt::TRange::NegInf) ++n["NegInf"];
            if (m.ev[i].range == csgrt::TRange::PosInf) ++n["PosInf"];
            if (m.ev[i].range == csgrt::TRange::Finite) ++n["finite"];
        }
    }
    std::string str() const {
        std::ostringstream s;
        for (auto& kv : n) s << kv.first << " " << kv.second << ", ";
        return s.str();
    }
};

template <int NB, int II = 1>
void run_width(size_t count, double gap, double stall, uint64_t seed, bool check_latency) {
    const csgrt::Formats fmt(NB);
    Gen gen(NB, seed);
    std::vector<Case> cases;
    std::vector<csgrt::LeafEvents<i64>> want;
    cases.reserve(count);
    want.reserve(count);
    size_t rejected = 0;
    Coverage cov;
    while (cases.size() < count) {
        Case c = gen.next();
        try {
            want.push_back(csgrt::intersect_fx(fmt, c.coef, c.ray));
        } catch (const std::logic_error&) {
            ++rejected;   // outside the model's bounds: must not happen for unit directions
            continue;
        }
        cov.add(want.back());
        cases.push_back(c);
    }
    tb::Harness<Top> h;
    Top* t = h.top.get();
    auto r = tb::run_stream(
        t, Dut<NB, II>::ports(t), cases.size(), [&](size_t i) { Dut<NB, II>::drive(t, cases[i], unsigned(i & 0xffff)); },
        [&](size_t i) -> std::string {
            const std::string m = compare(Dut<NB, II>::read(t), want[i], unsigned(i & 0xffff));
            return m.empty() ? m : m + "\n    " + describe(cases[i]);
        },
        gap, stall, seed + 1);
    EXPECT_TRUE(r.ok()) << "BITS=" << NB << " II=" << II << ": " << r.summary();
    EXPECT_EQ(rejected, 0u) << "cases outside the model's discriminant bound";
    std::printf("isect BITS=%d II=%d: %s\n  coverage: %s\n", NB, II, r.summary().c_str(), cov.str().c_str());
    if (check_latency) {
        // II = 1: 2F+23 clocks, 2F+22 stages and the skid, and 3 more
        // above 18 bits (P0, P2, P4's tile registers). II = 3: the
        // same stages less one in each of P0, P2, P4 (two beats where
        // II = 1 takes three clocks) plus the input register, with the
        // square root's F+6 stages and the dividers' F+1 iteration
        // stages folded three result bits to a stage: 13 + ceil((F+6)/3)
        // + ceil((F+1)/3) beats of three clocks (the pair is taken at a
        // beat's last clock and handed to the skid at one), and the
        // skid's clock
        const int F = NB - 3;
        const int beats = 13 + (F + 6 + 2) / 3 + (F + 1 + 2) / 3;
        const int latency = II == 1 ? 2 * F + 23 + (NB > 18 ? 3 : 0) : 3 * beats + 1;
        EXPECT_EQ(r.min_latency, latency);
        EXPECT_EQ(r.max_latency, latency);
        EXPECT_LE(r.cycles, size_t(II) * cases.size() + size_t(latency) + 2 + 201);
        EXPECT_GE(r.cycles, size_t(II) * cases.size());
    } else {
        for (const char* key : {"a=0,b=0", "linear", "disc<0", "disc=0", "b=0 (a!=0)", "qq=0", "equal pair dropped",
                                "two events", "NegInf", "PosInf", "finite"})
            EXPECT_GT(cov.n[key], 0u) << "BITS=" << NB << " never exercised: " << key;
    }
}

size_t scaled(size_t n) { return std::max<size_t>(1000, size_t(double(n) * tb::scale())); }

TEST(Isect, LatencyAndThroughput) {
    run_width<12>(2000, 0.0, 0.0, 101, true);
    run_width<16>(2000, 0.0, 0.0, 102, true);
    run_width<24>(2000, 0.0, 0.0, 103, true);
    run_width<32>(2000, 0.0, 0.0, 104, true);
}
TEST(Isect, Bits12) { run_width<12>(scaled(200000), 0.25, 0.25, tb::seed(112), false); }
TEST(Isect, Bits16) { run_width<16>(scaled(200000), 0.25, 0.25, tb::seed(116), false); }
TEST(Isect, Bits24) { run_width<24>(scaled(200000), 0.25, 0.25, tb::seed(124), false); }
TEST(Isect, Bits32) { run_width<32>(scaled(200000), 0.25, 0.25, tb::seed(132), false); }
// the time-shared unit (II = 3): the same results, one pair per three clocks
TEST(Isect, SharedLatencyAndThroughput) {
    run_width<16, 3>(2000, 0.0, 0.0, 202, true);
    run_width<24, 3>(2000, 0.0, 0.0, 203, true);
}
TEST(Isect, SharedBits16) { run_width<16, 3>(scaled(100000), 0.25, 0.25, tb::seed(216), false); }
TEST(Isect, SharedBits24) { run_width<24, 3>(scaled(100000), 0.25, 0.25, tb::seed(224), false); }

}  // namespace
