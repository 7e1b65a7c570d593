// tb_spawn.cpp — csgrt_spawn against the model's secondary-ray geometry:
// hit_point_fx, normal_fx (half_gradient_fx, unit_fx, face_against),
// shadow_ray_fx, the lit test of trace_colour_fx, refract_fx and reflect_fx
// (model/trace.cpp, model/raytree.cpp, model/render.cpp). Every field of
// every child is compared, in order (nothing lost or duplicated, nothing
// extra afterwards).
//
// Hits at BITS 12, 16, 24, 32:
//   - scenes mirror, glass, nested_glass and paper/fig08_reflect: camera rays
//     (camera_ray_fx + trace_primary_fx) and the model's secondary rays
//     (reflected, transmitted, total internal reflection, shadow rays and
//     their continuations through transparent surfaces), each hit a request
//     with the scene's lights;
//   - random rays and quadrics within the documented bounds (origins in
//     [-4, 4), so some hit points leave the range; any iors in [1/4, 16)).
// Random input gaps and output back-pressure (per clock, and in long
// bursts that fill the front's queues). The bench asserts that it saw
// total internal reflection, unlit lights (m_lit_o = 0) and hits out of
// range. A back-to-back run measures the latency and the clocks per child.
// The same at BITS 16 for the builds without refraction (REFRACTION 0) and
// with shadows only (REFLECTION 0 too), fed only the kinds they have.
#include "Vtb_spawn.h"
#include "compile.h"
#include "parse.h"
#include "raytree.h"
#include "render.h"
#include "stream.h"
#include "trace.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

#include <unistd.h>

namespace {

using Top = Vtb_spawn;
using csgrt::i128;
using csgrt::i64;
using V3 = std::array<i64, 3>;

constexpr int kLights = 8;   // MAX_LIGHTS of the instances
enum Kind { CONTINUE = 0, SHADOW = 1, REFRACT = 2, TIR_REFLECT = 3, REFLECT = 4 };
const char* kKindName[5] = {"continue", "shadow", "refract", "tir_reflect", "reflect"};
enum Source { PRIMARY = 0, SECONDARY = 1, SHADOW_CROSSING = 2, RANDOM = 3 };
const char* kSourceName[4] = {"camera-ray hits", "secondary-ray hits", "shadow-ray crossings", "random"};

using tb::repo_root;

using tb::get_field;
using tb::set_field;
template <class W>
inline uint64_t get_ufield(const W& w, int lsb, int width) {
    if constexpr (std::is_integral_v<W>)
        return (uint64_t(w) >> lsb) & tb::mask(width);
    else
        return tb::get_bits(w, lsb, width);
}

// One hit, as the walker hands it over.
struct Request {
    csgrt::RayFx ray;
    i64 t = 0;
    std::array<i64, csgrt::kNumCoefs> coef{};
    i64 ior_from = 4096, ior_to = 4096;
    uint32_t lights = 0;
    bool reflect = false, refract = false, cont = false;
    Source source = RANDOM;
};

// One child, as the model computes it.
struct Child {
    int kind = 0, light = 0;
    bool last = false;
    V3 o{}, d{};
    bool in_range = false;
    i64 dist = 0;
    bool lit = false;
    size_t req = 0;
};

struct Out {
    int kind, light;
    bool last, in_range, lit;
    V3 o, d;
    i64 dist;
    uint32_t user;
};

// Dut<ID>: the instance ID; 12, 16, 24, 32 have every child kind (BITS = ID),
// kB16Refl is BITS 16 without refraction, kB16Shadow BITS 16 with shadows only.
constexpr int kB16Refl = 1016, kB16Shadow = 2016;
// the children's clocks per child (tb_spawn.v: b32 and b16r are time-shared)
template <int ID>
constexpr int kII = (ID == 32 || ID == kB16Refl) ? 3 : 1;
template <int ID>
struct Dut;
#define SPAWN_DUT(ID, TAG, NB)                                                                     \
    template <>                                                                                    \
    struct Dut<ID> {                                                                               \
        static constexpr int kBits = NB;                                                           \
        static tb::StreamPorts ports(Top* t) {                                                     \
            return {&t->TAG##_clk_i, &t->TAG##_rst_ni, &t->TAG##_valid_i,                    \
                    &t->TAG##_ready_o, &t->TAG##_valid_o, &t->TAG##_ready_i};                \
        }                                                                                          \
        static void lights(Top* t, const std::vector<V3>& l) {                                     \
            for (int k = 0; k < kLights; ++k)                                                      \
                for (int i = 0; i < 3; ++i)                                                        \
                    set_field(t->TAG##_light_pos_i, (3 * k + i) * NB, NB,                        \
                              k < int(l.size()) ? l[k][i] : 0);                                    \
        }                                                                                          \
        static void drive(Top* t, const Request& q, uint32_t user) {                               \
            for (int i = 0; i < 3; ++i) {                                                          \
                set_field(t->TAG##_o_i, i * NB, NB, q.ray.o[i]);                                 \
                set_field(t->TAG##_d_i, i * NB, NB, q.ray.d[i]);                                 \
            }                                                                                      \
            set_field(t->TAG##_t_i, 0, NB - 1, q.t);                                             \
            for (int c = 0; c < csgrt::kNumCoefs; ++c) set_field(t->TAG##_coef_i, c * NB, NB, q.coef[c]); \
            t->TAG##_ior_from_i = uint16_t(q.ior_from);                                          \
            t->TAG##_ior_to_i = uint16_t(q.ior_to);                                              \
            t->TAG##_lights_i = uint8_t(q.lights);                                               \
            t->TAG##_reflect_i = q.reflect;                                                      \
            t->TAG##_refract_i = q.refract;                                                      \
            t->TAG##_continue_i = q.cont;                                                        \
            t->TAG##_user_i = uint16_t(user);                                                    \
        }                                                                                          \
        static Out read(Top* t) {                                                                  \
            Out o;                                                                                 \
            o.kind = t->TAG##_kind_o;                                                            \
            o.light = t->TAG##_light_o;                                                          \
            o.last = t->TAG##_last_o;                                                            \
            o.in_range = t->TAG##_in_range_o;                                                    \
            o.lit = t->TAG##_lit_o;                                                              \
            for (int i = 0; i < 3; ++i) {                                                          \
                o.o[i] = get_field(t->TAG##_o_o, i * NB, NB);                                    \
                o.d[i] = get_field(t->TAG##_d_o, i * NB, NB);                                    \
            }                                                                                      \
            o.dist = i64(get_ufield(t->TAG##_dist_o, 0, NB + 1));                                \
            o.user = t->TAG##_user_o;                                                            \
            return o;                                                                              \
        }                                                                                          \
    };
SPAWN_DUT(12, b12, 12)
SPAWN_DUT(16, b16, 16)
SPAWN_DUT(24, b24, 24)
SPAWN_DUT(32, b32, 32)
SPAWN_DUT(kB16Refl, b16r, 16)
SPAWN_DUT(kB16Shadow, b16s, 16)

// ---- the model's answer ---------------------------------------------------------
// normal_fx needs a scene: one leaf holding the request's quadric.
struct Model {
    csgrt::CompiledScene cs;
    // exact decisions and ties seen (in range): n . d = 0 with n != 0, n . lv = 0
    // with n != 0, k = 0 (refract at the TIR boundary), rnd(t d_i, F) ties
    uint64_t face_zero = 0, lit_zero = 0, k_zero = 0, p_ties = 0, e2_ties = 0;
    explicit Model(int bits) {
        cs.fmt = csgrt::Formats(bits);
        cs.leaves.resize(1);
    }
    void children(const Request& q, const std::vector<V3>& lights, size_t req, std::vector<Child>& out) {
        const csgrt::Formats& fmt = cs.fmt;
        const int F = fmt.frac;
        Child c;
        c.req = req;
        c.in_range = csgrt::hit_point_fx(fmt, q.ray, q.t, c.o);
        V3 n{};
        const bool n_zero = [&] {
            if (!c.in_range) return true;
            cs.leaves[0].coef = q.coef;
            n = csgrt::normal_fx(cs, 0, c.o, q.ray.d);
            return n[0] == 0 && n[1] == 0 && n[2] == 0;
        }();
        if (c.in_range) {
            i128 nd = 0;
            for (int i = 0; i < 3; ++i) {
                nd += i128(n[i]) * q.ray.d[i];
                p_ties += ((i128(q.t) * q.ray.d[i]) & ((i128(1) << F) - 1)) == (i128(1) << (F - 1));
            }
            face_zero += !n_zero && nd == 0;
            if (q.refract) {
                // k of refract_fx, as the model computes it
                i128 e = 0;
                csgrt::sdiv_trunc(i128(q.ior_from) << F, q.ior_to, F + 7, e);
                const i64 one = i64(1) << F, cos_i = -csgrt::dot_round(q.ray.d, n, F);
                const i64 sin2 = one - i64(csgrt::rshift_round(i128(cos_i) * cos_i, F));
                const i64 k = one - i64(csgrt::rshift_round(i128(csgrt::rshift_round(e * e, F)) * sin2, F));
                k_zero += k == 0;
                e2_ties += ((e * e) & ((i128(1) << F) - 1)) == (i128(1) << (F - 1));
            }
        }
        const size_t first = out.size();
        auto add = [&](int kind, int light, const V3& d, i64 dist, bool lit) {
            Child x = c;
            x.kind = kind;
            x.light = light;
            x.d = d;
            x.dist = dist;
            x.lit = lit;
            out.push_back(x);
        };
        if (q.cont) add(CONTINUE, 0, q.ray.d, 0, false);
        for (int k = 0; k < kLights; ++k) {
            if (!((q.lights >> k) & 1)) continue;
            if (!c.in_range) {
                add(SHADOW, k, {}, 0, false);
                continue;
            }
            V3 lv;
            i128 nl = 0;
            for (int i = 0; i < 3; ++i) lv[i] = lights[k][i] - c.o[i], nl += i128(n[i]) * lv[i];
            i64 dist = 0;
            const csgrt::RayFx s = csgrt::shadow_ray_fx(F, c.o, lv, dist);
            add(SHADOW, k, s.d, dist, nl > 0);
            lit_zero += !n_zero && nl == 0;
        }
        if (q.refract) {
            V3 t{};
            if (!c.in_range)
                add(REFRACT, 0, {}, 0, false);
            else if (csgrt::refract_fx(q.ray.d, n, q.ior_from, q.ior_to, F, t))
                add(REFRACT, 0, t, 0, false);
            else
                add(TIR_REFLECT, 0, csgrt::reflect_fx(q.ray.d, n, F), 0, false);
        }
        if (q.reflect) add(REFLECT, 0, c.in_range ? csgrt::reflect_fx(q.ray.d, n, F) : V3{}, 0, false);
        if (out.size() > first) out.back().last = true;
    }
};

std::string v3(const V3& v) {
    return "{" + std::to_string(v[0]) + " " + std::to_string(v[1]) + " " + std::to_string(v[2]) + "}";
}
std::string describe(const Request& q) {
    std::ostringstream s;
    s << kSourceName[q.source] << " o " << v3(q.ray.o) << " d " << v3(q.ray.d) << " t " << q.t << " coef {";
    for (i64 c : q.coef) s << " " << c;
    s << " } ior " << q.ior_from << " -> " << q.ior_to << " lights " << q.lights << " refl " << q.reflect
      << " refr " << q.refract << " cont " << q.cont;
    return s.str();
}

// Compare one output with the model's child; "" when they agree. Out of
// range, only the fields that do not depend on the (meaningless) geometry:
// kind (REFRACT and TIR_REFLECT alike), light, last, user, in_range, the
// low B bits of p, and CONTINUE's d.
std::string compare(int bits, const Out& o, const Child& c, uint32_t user) {
    bool ok = o.light == c.light && o.last == c.last && o.user == user && o.in_range == c.in_range;
    for (int i = 0; i < 3; ++i) ok = ok && o.o[i] == tb::sext(uint64_t(c.o[i]), bits);
    if (c.in_range) {
        ok = ok && o.kind == c.kind && o.d == c.d && o.dist == c.dist && o.lit == c.lit;
    } else {
        const bool transmitted = c.kind == REFRACT || c.kind == TIR_REFLECT;
        ok = ok && (transmitted ? (o.kind == REFRACT || o.kind == TIR_REFLECT) : o.kind == c.kind);
        if (c.kind == CONTINUE) ok = ok && o.d == c.d;
    }
    if (ok) return "";
    std::ostringstream s;
    s << "DUT kind " << o.kind << " light " << o.light << " last " << o.last << " user " << o.user << " in_range "
      << o.in_range << " o " << v3(o.o) << " d " << v3(o.d) << " dist " << o.dist << " lit " << o.lit
      << "\n    model kind " << c.kind << " light " << c.light << " last " << c.last << " user " << user
      << " in_range " << c.in_range << " o " << v3(c.o) << " d " << v3(c.d) << " dist " << c.dist << " lit "
      << c.lit;
    return s.str();
}

// ---- requests ----------------------------------------------------------------------
csgrt::CompiledScene compile(const std::string& name, int bits, int w, int h) {
    csgrt::CompileOptions opt;
    opt.bits = bits;
    opt.width = w;
    opt.height = h;
    return csgrt::compile_scene(csgrt::parse_scene_file(repo_root() + "/scenes/" + name + ".pov"), opt);
}

std::vector<V3> scene_lights(const csgrt::CompiledScene& cs) {
    std::vector<V3> l;
    for (const csgrt::LightInfo& li : cs.lights) l.push_back(li.pos_fx);
    return l;
}

// Every hit of the model's ray tree (camera rays, reflected and transmitted
// rays to the scene's depth, shadow rays and their crossings), as requests,
// up to `cap`. Reflection and refraction are also requested at a quarter of
// the surfaces that have neither (the geometry does not care).
std::vector<Request> scene_requests(const csgrt::CompiledScene& cs, size_t cap, std::mt19937_64& rng) {
    std::vector<Request> out;
    const int F = cs.fmt.frac;
    const csgrt::EffectSet fx = csgrt::scene_effects(cs);
    csgrt::TraceOptions topt;
    topt.lookahead = fx.refraction;
    const uint32_t all_lights = (1u << cs.lights.size()) - 1;
    auto request = [&](const csgrt::RayFx& ray, const csgrt::TraceResult<i64>& tr, Source src) {
        Request q;
        q.ray = ray;
        q.t = tr.t;
        q.coef = cs.leaves[tr.leaf].coef;
        q.ior_from = csgrt::ior_of(cs, tr.border.from);
        q.ior_to = csgrt::ior_of(cs, tr.border.to);
        q.source = src;
        return q;
    };
    std::function<void(const csgrt::RayFx&, const std::vector<uint8_t>*, int)> rec =
        [&](const csgrt::RayFx& ray, const std::vector<uint8_t>* flags, int depth) {
            if (out.size() >= cap) return;
            const csgrt::TraceResult<i64> tr =
                flags ? csgrt::trace_secondary_fx(cs, ray, *flags, csgrt::TiePolicy::Paper, false, topt)
                      : csgrt::trace_primary_fx(cs, ray, csgrt::TiePolicy::Paper, false, topt);
            if (!tr.hit) return;
            const int mat = tr.border.to ? tr.border.to : tr.border.from;
            const csgrt::MaterialInfo& m = cs.materials[mat];
            Request q = request(ray, tr, flags ? SECONDARY : PRIMARY);
            q.lights = all_lights;
            q.reflect = m.reflection > 0 || rng() % 4 == 0;
            q.refract = m.filter > 0 || rng() % 4 == 0;
            out.push_back(q);
            V3 p;
            if (!csgrt::hit_point_fx(cs.fmt, ray, tr.t, p)) return;
            const V3 n = csgrt::normal_fx(cs, tr.leaf, p, ray.d);
            // shadow rays, and a continuation at every crossing (shadow_fx)
            for (size_t k = 0; k < cs.lights.size() && out.size() < cap; ++k) {
                V3 lv;
                i128 nl = 0;
                for (int i = 0; i < 3; ++i) lv[i] = cs.lights[k].pos_fx[i] - p[i], nl += i128(n[i]) * lv[i];
                if (nl <= 0) continue;
                csgrt::TraceOptions so;
                so.lookahead = fx.refraction;
                csgrt::RayFx s = csgrt::shadow_ray_fx(F, p, lv, so.t_limit_fx);
                std::vector<uint8_t> sf = tr.flags_before;
                for (int crossing = 0; crossing < 16 && out.size() < cap; ++crossing) {
                    const csgrt::TraceResult<i64> st =
                        csgrt::trace_secondary_fx(cs, s, sf, csgrt::TiePolicy::Paper, false, so);
                    if (!st.hit) break;
                    Request c = request(s, st, SHADOW_CROSSING);
                    c.cont = true;
                    out.push_back(c);
                    if (st.border.to != 0 && !csgrt::is_transparent(cs, st.border.to)) break;
                    V3 qp;
                    if (!csgrt::hit_point_fx(cs.fmt, s, st.t, qp)) break;
                    s.o = qp;
                    sf = st.flags_after;
                    so.t_limit_fx -= st.t;
                    if (so.t_limit_fx <= 0) break;
                }
            }
            if (depth >= cs.max_trace_level) return;
            if (q.refract) {
                csgrt::RayFx child;
                child.o = p;
                const std::vector<uint8_t>* cf = &tr.flags_after;
                if (!csgrt::refract_fx(ray.d, n, q.ior_from, q.ior_to, F, child.d)) {
                    child.d = csgrt::reflect_fx(ray.d, n, F);
                    cf = &tr.flags_before;
                }
                rec(child, cf, depth + 1);
            }
            if (q.reflect) {
                csgrt::RayFx child;
                child.o = p;
                child.d = csgrt::reflect_fx(ray.d, n, F);
                rec(child, &tr.flags_before, depth + 1);
            }
        };
    // pixels in a scrambled order, so that a cap still covers the frame
    std::vector<int> order(cs.width * cs.height);
    for (size_t i = 0; i < order.size(); ++i) order[i] = int(i);
    std::shuffle(order.begin(), order.end(), rng);
    for (int px : order) {
        if (out.size() >= cap) break;
        rec(csgrt::camera_ray_fx(cs, px % cs.width, px / cs.width), nullptr, 1);
    }
    return out;
}

i64 urand(std::mt19937_64& rng, i64 lo, i64 hi) {   // [lo, hi]
    return lo + i64(rng() % uint64_t(hi - lo + 1));
}

// Random rays and quadrics within the documented bounds: o in [-4, 4)
// (mostly [-1, 1)), d = unit_fx(random), t in [0, 2), |coef| < 1 (general,
// spheres, planes), iors in [1/4, 16) (air, glass, water, diamond, extremes).
// Directed cases for the exact decisions and the ties:
//   - t = 0.5 or 1.5: rnd(t d_i, F) is a tie for every odd d_i;
//   - an axis plane (only P_i and q) hit by a ray with d_i = 0 whose o_i is
//     light k's coordinate: n = +-e_i, so n . d = 0 (face_against must not
//     flip), n . (light_k - p) = 0 (unlit), cos = 0 (with equal iors k = 0:
//     no total internal reflection).
Request random_request(const csgrt::Formats& fmt, std::mt19937_64& rng, const std::vector<V3>& lights) {
    const int F = fmt.frac, FC = fmt.coef_frac;
    const i64 one = i64(1) << F, cmax = (i64(1) << FC) - 1;
    Request q;
    const bool wide = rng() % 3 == 0;
    for (int i = 0; i < 3; ++i) q.ray.o[i] = wide ? urand(rng, -4 * one, 4 * one - 1) : urand(rng, -one, one - 1);
    const bool axis_case = rng() % 12 == 0;
    const int axis = int(rng() % 3), light = int(rng() % kLights);
    V3 v;
    do {
        for (int i = 0; i < 3; ++i) v[i] = urand(rng, -one, one);
        if (axis_case) v[axis] = 0;
    } while (v[0] == 0 && v[1] == 0 && v[2] == 0);
    q.ray.d = csgrt::unit_fx(v, F, csgrt::geo_sqrt_stages(F));
    q.t = rng() % 8 == 0 ? (2 * urand(rng, 0, 1) + 1) * (one / 2) : urand(rng, 0, 2 * one - 1);
    if (axis_case) {
        q.ray.o[axis] = lights[light][axis];
        q.coef = {0, 0, 0, 0, 0, 0, 0, 0, 0, urand(rng, -cmax, cmax)};
        i64 pc;
        do pc = urand(rng, -cmax, cmax);
        while (pc == 0);
        q.coef[csgrt::C_P0 + axis] = pc;
    } else {
        switch (rng() % 4) {
            case 0:   // sphere-like: A = a I
            {
                const i64 a = urand(rng, -cmax, cmax);
                q.coef = {a, a, a, 0, 0, 0, urand(rng, -cmax, cmax), urand(rng, -cmax, cmax),
                          urand(rng, -cmax, cmax), urand(rng, -cmax, cmax)};
                break;
            }
            case 1:   // plane
                q.coef = {0, 0, 0, 0, 0, 0, urand(rng, -cmax, cmax), urand(rng, -cmax, cmax),
                          urand(rng, -cmax, cmax), urand(rng, -cmax, cmax)};
                break;
            default:   // general quadric, some coefficients at the extremes
                for (i64& c : q.coef) {
                    const int r = int(rng() % 16);
                    c = r == 0 ? cmax : r == 1 ? -cmax : r == 2 ? 0 : urand(rng, -cmax, cmax);
                }
        }
    }
    const i64 iors[] = {4096, 4096, 5448, 6144, 9830, 1024, 65535};
    auto ior = [&]() { return rng() % 3 == 0 ? urand(rng, 1024, 65535) : iors[rng() % 7]; };
    q.ior_from = ior();
    q.ior_to = rng() % (axis_case ? 2 : 8) == 0 ? q.ior_from : ior();
    // eta = odd * 2^((F-1)/2) makes rnd(eta^2, F) a tie: ior_to = 4096 * 2^j,
    // j = (F+1)/2 - 12, an odd ior_from (ior_to must stay a valid ior)
    const int j = (F + 1) / 2 - 12;
    if (!axis_case && j >= -2 && rng() % 16 == 0) {
        q.ior_to = j >= 0 ? i64(4096) << j : i64(4096) >> -j;
        q.ior_from = 2 * urand(rng, 512, 32767) + 1;
    }
    do {
        q.lights = rng() % 3 == 0 ? 0u : uint32_t(rng() & 0xff);
        q.reflect = rng() % 2;
        q.refract = rng() % 2;
        q.cont = rng() % 4 == 0;
    } while (!q.lights && !q.reflect && !q.refract && !q.cont);
    if (axis_case) {
        q.lights |= 1u << light;
        q.refract = true;
    }
    q.source = RANDOM;
    return q;
}

std::vector<V3> random_lights(const csgrt::Formats& fmt, std::mt19937_64& rng) {
    const i64 one = i64(1) << fmt.frac;
    std::vector<V3> l(kLights);
    for (V3& p : l)
        for (i64& c : p) c = rng() % 2 ? urand(rng, -one, one) : urand(rng, -4 * one, 4 * one - 1);
    return l;
}

// ---- the run -------------------------------------------------------------------------
struct Stats {
    uint64_t requests = 0, children = 0, cycles = 0, mismatches = 0, extra = 0, in_blocked = 0;
    size_t max_outstanding = 0;   // hits accepted whose last child has not left yet
    bool timeout = false;
    int min_latency = 1 << 30, max_latency = 0;
    uint64_t kinds[5] = {0, 0, 0, 0, 0};
    uint64_t unlit = 0, lit = 0, out_of_range = 0;
    uint64_t sources[4] = {0, 0, 0, 0};
    uint64_t face_zero = 0, lit_zero = 0, k_zero = 0, p_ties = 0, e2_ties = 0;
    std::vector<std::string> messages;
    bool ok() const { return !timeout && mismatches == 0 && extra == 0; }
    std::string summary() const {
        std::ostringstream s;
        s << requests << " hits (";
        for (int i = 0; i < 4; ++i) s << (i ? ", " : "") << sources[i] << " " << kSourceName[i];
        s << "), " << children << " children (";
        for (int i = 0; i < 5; ++i) s << (i ? ", " : "") << kinds[i] << " " << kKindName[i];
        s << "; lit " << lit << ", unlit " << unlit << "; out of range " << out_of_range << "; exact n.d = 0 "
          << face_zero << ", n.lv = 0 " << lit_zero << ", k = 0 " << k_zero << ", hit-point ties " << p_ties
          << ", eta^2 ties " << e2_ties << "), mismatches "
          << mismatches << ", extra " << extra << (timeout ? ", TIMEOUT" : "") << ", " << cycles
          << " cycles, latency " << min_latency << ".." << max_latency;
        for (const std::string& m : messages) s << "\n  " << m;
        return s.str();
    }
};

// Stall modes for the output: per clock with probability p_stall, or in
// bursts (ready low for up to ~400 clocks at a time) that fill the front.
template <int ID>
Stats run(const std::vector<Request>& reqs, const std::vector<V3>& lights, double p_gap, double p_stall,
          bool bursts, uint64_t seed) {
    constexpr int NB = Dut<ID>::kBits;
    Stats st;
    Model model(NB);
    std::vector<Child> exp;
    std::vector<size_t> first(reqs.size());
    for (size_t r = 0; r < reqs.size(); ++r) {
        first[r] = exp.size();
        model.children(reqs[r], lights, r, exp);
        st.sources[reqs[r].source]++;
    }
    st.requests = reqs.size();
    st.face_zero = model.face_zero;
    st.lit_zero = model.lit_zero;
    st.k_zero = model.k_zero;
    st.p_ties = model.p_ties;
    st.e2_ties = model.e2_ties;
    for (const Child& c : exp) {
        st.kinds[c.kind]++;
        if (!c.in_range) st.out_of_range++;
        if (c.kind == SHADOW && c.in_range) (c.lit ? st.lit : st.unlit)++;
    }

    tb::Harness<Top> h;
    Top* t = h.top.get();
    const tb::StreamPorts p = Dut<ID>::ports(t);
    Dut<ID>::lights(t, lights);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    auto tick = [&] {
        *p.clk = 1;
        t->eval();
        *p.clk = 0;
        t->eval();
    };
    *p.valid_i = 0;
    *p.ready_i = 0;
    *p.clk = 0;
    *p.rst_n = 0;
    t->eval();
    for (int i = 0; i < 4; ++i) tick();
    *p.rst_n = 1;
    t->eval();

    std::vector<uint64_t> accept_cycle(reqs.size());
    size_t sent = 0, received = 0, drain = 0, done_hits = 0;
    bool pending = false, stalled = false;
    uint64_t idle = 0;
    for (uint64_t cyc = 0;; ++cyc) {
        if (sent < reqs.size() && !pending) pending = !(u01(rng) < p_gap);
        *p.valid_i = pending;
        if (pending) Dut<ID>::drive(t, reqs[sent], uint32_t(sent & 0xffff));
        if (bursts) {
            if (u01(rng) < (stalled ? 1.0 / 200 : 1.0 / 300)) stalled = !stalled;
        } else {
            stalled = u01(rng) < p_stall;
        }
        const bool draining = received == exp.size();
        *p.ready_i = (draining || !stalled) ? 1 : 0;
        t->eval();
        const bool in_fire = *p.valid_i && *p.ready_o;
        const bool out_fire = *p.valid_o && *p.ready_i;
        if (*p.valid_i && !*p.ready_o) ++st.in_blocked;
        if (out_fire) {
            if (received >= exp.size()) {
                ++st.extra;
            } else {
                const Child& c = exp[received];
                const std::string msg = compare(NB, Dut<ID>::read(t), c, uint32_t(c.req & 0xffff));
                if (!msg.empty()) {
                    ++st.mismatches;
                    if (st.messages.size() < 6)
                        st.messages.push_back("child #" + std::to_string(received) + " (" + kKindName[c.kind] +
                                              ") of hit #" + std::to_string(c.req) + ": " + msg + "\n    " +
                                              describe(reqs[c.req]));
                }
                if (c.last) ++done_hits;
                if (first[c.req] == received) {
                    const int lat = int(cyc - accept_cycle[c.req]);
                    st.min_latency = std::min(st.min_latency, lat);
                    st.max_latency = std::max(st.max_latency, lat);
                }
                ++received;
            }
        }
        if (in_fire) {
            accept_cycle[sent++] = cyc;
            pending = false;
        }
        st.max_outstanding = std::max(st.max_outstanding, sent - done_hits);
        tick();
        st.cycles = cyc + 1;
        idle = (in_fire || out_fire) ? 0 : idle + 1;
        if (received == exp.size() && sent == reqs.size() && ++drain > 300) break;
        if (idle > 20000) {
            st.timeout = true;
            break;
        }
    }
    *p.valid_i = 0;
    st.children = received;
    return st;
}

void add(Stats& total, const Stats& s) {
    total.requests += s.requests;
    total.children += s.children;
    for (int i = 0; i < 5; ++i) total.kinds[i] += s.kinds[i];
    for (int i = 0; i < 4; ++i) total.sources[i] += s.sources[i];
    total.unlit += s.unlit;
    total.lit += s.lit;
    total.out_of_range += s.out_of_range;
    total.face_zero += s.face_zero;
    total.lit_zero += s.lit_zero;
    total.k_zero += s.k_zero;
    total.p_ties += s.p_ties;
    total.e2_ties += s.e2_ties;
}

size_t scaled(size_t n) { return std::max<size_t>(16, size_t(double(n) * tb::scale())); }

template <int NB>
void all_checks(uint64_t seed) {
    Stats total;
    uint64_t tir_scenes = 0;
    // scenes: the model's ray trees
    for (const char* name : {"mirror", "glass", "nested_glass", "paper/fig08_reflect"}) {
        const csgrt::CompiledScene cs = compile(name, NB, 64, 48);
        std::mt19937_64 rng(seed++);
        const std::vector<Request> reqs = scene_requests(cs, scaled(6000), rng);
        const Stats s = run<NB>(reqs, scene_lights(cs), 0.3, 0.25, false, seed++);
        EXPECT_TRUE(s.ok()) << "BITS=" << NB << " " << name << ": " << s.summary();
        std::printf("spawn BITS=%d %s (%zu lights): %s\n", NB, name, cs.lights.size(), s.summary().c_str());
        add(total, s);
        tir_scenes += s.kinds[TIR_REFLECT];
    }
    // random rays and quadrics, with random lights; once with per-clock
    // back-pressure, once with long output stalls (the front fills up)
    const csgrt::Formats fmt(NB);
    for (bool bursts : {false, true}) {
        std::mt19937_64 rng(seed++);
        const std::vector<V3> lights = random_lights(fmt, rng);
        std::vector<Request> reqs;
        for (size_t i = 0; i < scaled(bursts ? 6000 : 20000); ++i) reqs.push_back(random_request(fmt, rng, lights));
        const Stats s = run<NB>(reqs, lights, bursts ? 0.1 : 0.3, 0.3, bursts, seed++);
        EXPECT_TRUE(s.ok()) << "BITS=" << NB << " random: " << s.summary();
        std::printf("spawn BITS=%d random%s: %s (input refused on %llu clocks, at most %zu hits outstanding)\n",
                    NB, bursts ? ", output stalled in bursts" : "", s.summary().c_str(),
                    (unsigned long long)s.in_blocked, s.max_outstanding);
        add(total, s);
        // long stalls fill the front's 32 hits and more wait in the child pipeline
        if (bursts) EXPECT_GT(s.max_outstanding, 32u) << "the bursts should fill the front";
    }
    EXPECT_GT(tir_scenes, 0u) << "BITS=" << NB << ": no total internal reflection in the scenes";
    EXPECT_GT(total.kinds[TIR_REFLECT], 0u);
    EXPECT_GT(total.kinds[REFRACT], 0u);
    EXPECT_GT(total.kinds[CONTINUE], 0u);
    EXPECT_GT(total.unlit, 0u) << "no light behind a surface";
    EXPECT_GT(total.lit, 0u);
    EXPECT_GT(total.out_of_range, 0u) << "no hit point out of range";
    EXPECT_GT(total.face_zero, 0u) << "no n . d = 0";
    EXPECT_GT(total.lit_zero, 0u) << "no n . (light - p) = 0";
    EXPECT_GT(total.k_zero, 0u) << "no k = 0";
    EXPECT_GT(total.p_ties, 0u) << "no tie in the hit point";
    EXPECT_GT(total.e2_ties, 0u) << "no tie in rnd(eta^2, F)";
    std::printf("spawn BITS=%d total: %llu hits, %llu children (%llu TIR, %llu in the scenes; %llu unlit; %llu out "
                "of range; exact n.d = 0 %llu, n.lv = 0 %llu, k = 0 %llu, hit-point ties %llu, eta^2 ties %llu)\n",
                NB, (unsigned long long)total.requests, (unsigned long long)total.children,
                (unsigned long long)total.kinds[TIR_REFLECT], (unsigned long long)tir_scenes,
                (unsigned long long)total.unlit, (unsigned long long)total.out_of_range,
                (unsigned long long)total.face_zero, (unsigned long long)total.lit_zero,
                (unsigned long long)total.k_zero, (unsigned long long)total.p_ties,
                (unsigned long long)total.e2_ties);
}

TEST(Spawn, Bits12) { all_checks<12>(tb::seed(1200)); }
TEST(Spawn, Bits16) { all_checks<16>(tb::seed(1600)); }
TEST(Spawn, Bits24) { all_checks<24>(tb::seed(2400)); }
TEST(Spawn, Bits32) { all_checks<32>(tb::seed(3200)); }

// Back to back (no gaps, no back-pressure): the latency of an idle unit
// (5F+67), one child per clock when hits are waiting, a hit every third
// clock at most; the front holds a hit's credit for 3F+46 clocks and has 32,
// so at BITS 24 and 32 a hit every (3F+46)/32 clocks at most.
// Without refraction the sequencer waits for the normal's queue instead of
// the refraction stages' (F+6 clocks fewer: the normal's queue is block
// RAM, its head one clock behind a push): latency 4F+61, a credit held
// for 2F+40 clocks. Time-shared children (II = 3): the children's stages
// before the output skid (2F+19, X one more at II 3, U2's F+2 division stages replaced by the
// shared divider's beats) take three clocks each (up to two more to reach
// a beat's end), a child every third clock, and the hits between the
// sequencer and their last child's exit (the output queue, CTX = 32 of
// them, each there for its n children's issue and those stages) bound a
// hit every 3 (stages+1+n) / 32 clocks when hits have few children (5.5 at
// BITS 32; the ray tree sends a hit every 25 clocks or more).
template <int ID>
void throughput(bool reflection = true, bool refraction = true) {
    constexpr int NB = Dut<ID>::kBits;
    const csgrt::Formats fmt(NB);
    const int F = fmt.frac;
    constexpr int ii = kII<ID>;
    const int latency = refraction ? 5 * F + 67 : 4 * F + 61, hold = refraction ? 3 * F + 46 : 2 * F + 40;
    // the children's stages before the output skid: C0, X, C3 and U2 (2F+19
    // clocks); time-shared, U2's three divisions on one divider take
    // (F+2+pad+4)/3 beats instead of F+2 and its F+8-bit square root
    // ceil((F+8)/3) instead of F+8 (rtl/csgrt_unit.v). Written out here
    // from the divider's schedule on purpose, not read from the RTL's
    // csgrt_unit_div_beats(): a test that took the unit's own count would
    // pass with that count wrong.
    const int child_clocks = 2 * F + 19;
    const int div_beats = (F + 2 + (5 - (F + 2) % 3) % 3 + 4) / 3;
    const int sqrt_beats = (F + 8 + 2) / 3;
    // and X's and Y's products one beat more at II 3 (their operands
    // registered before the multiplier: rtl/csgrt_spawn.v X_OP_REG)
    const int child_stages =
        ii == 3 ? child_clocks - (F + 2) + div_beats - (F + 8) + sqrt_beats + 1 : child_clocks;
    std::mt19937_64 rng(77);
    const std::vector<V3> lights = random_lights(fmt, rng);
    for (int per_hit : {1, 2, 3, 4, 5, 11}) {
        std::vector<Request> reqs;
        // children: 1 light, + refract, + reflect, + 1 light, + continue; 11: everything
        // (the kinds the build does not have are replaced by lights)
        int n = 0;
        for (int i = 0; i < 600; ++i) {
            Request q = random_request(fmt, rng, lights);
            q.lights = per_hit >= 11 ? 0xff : per_hit >= 4 ? 0x41 : 0x10;
            q.refract = refraction && per_hit >= 2;
            q.reflect = reflection && per_hit >= 3;
            if (!refraction && per_hit >= 2) q.lights |= 0x02;
            if (!reflection && per_hit >= 3) q.lights |= 0x04;
            q.cont = per_hit == 5 || per_hit == 11;
            reqs.push_back(q);
            n = __builtin_popcount(q.lights) + q.refract + q.reflect + q.cont;
        }
        const Stats s = run<ID>(reqs, lights, 0.0, 0.0, false, 5);
        EXPECT_TRUE(s.ok()) << s.summary();
        EXPECT_EQ(s.children, size_t(n) * reqs.size());
        const double busy = double(s.cycles - 300 - s.min_latency);
        const double hit_interval = std::max({double(ii * n), 3.0, double(hold) / 32.0,
                                              ii == 3 ? 3.0 * (child_stages + n + 1) / 32.0 : 0.0});
        std::printf("spawn BITS=%d%s back to back, %d children per hit: %llu children in %llu cycles: %.3f clocks "
                    "per child, %.3f per hit (bound %.3f); latency %d..%d%s\n",
                    NB, refraction ? "" : reflection ? " (no refraction)" : " (shadows only)", n,
                    (unsigned long long)s.children, (unsigned long long)s.cycles, busy / double(s.children),
                    busy / double(s.requests), hit_interval, s.min_latency, s.max_latency,
                    ii == 3 ? " (II 3)" : "");
        if (ii == 1) {
            EXPECT_EQ(s.min_latency, latency);
        } else {
            EXPECT_GE(s.min_latency, latency - child_clocks + 3 * child_stages);
            EXPECT_LE(s.min_latency, latency - child_clocks + 3 * child_stages + 2);
        }
        EXPECT_LE(busy / double(s.requests), hit_interval + 0.02);
    }
}

TEST(Spawn, ThroughputAndLatency) {
    throughput<12>();
    throughput<16>();
    throughput<24>();
    throughput<32>();
}

// The builds without refraction (b16r) and with shadows only (b16s): the
// scenes' hits and random hits with only the kinds the build has
// (s_refract_i = 0; for b16s also s_reflect_i = 0), against the model like
// the full builds.
template <int ID>
void reduced_checks(bool reflection, uint64_t seed) {
    constexpr int NB = Dut<ID>::kBits;
    const char* what = reflection ? "no refraction" : "shadows only";
    auto restrict_kinds = [&](std::vector<Request> reqs) {
        std::vector<Request> out;
        for (Request q : reqs) {
            q.refract = false;
            if (!reflection) q.reflect = false;
            if (q.lights || q.reflect || q.cont) out.push_back(q);
        }
        return out;
    };
    Stats total;
    for (const char* name : {"mirror", "glass", "paper/fig08_reflect"}) {
        const csgrt::CompiledScene cs = compile(name, NB, 64, 48);
        std::mt19937_64 rng(seed++);
        const std::vector<Request> reqs = restrict_kinds(scene_requests(cs, scaled(4000), rng));
        const Stats s = run<ID>(reqs, scene_lights(cs), 0.3, 0.25, false, seed++);
        EXPECT_TRUE(s.ok()) << "BITS=" << NB << " (" << what << ") " << name << ": " << s.summary();
        std::printf("spawn BITS=%d (%s) %s (%zu lights): %s\n", NB, what, name, cs.lights.size(),
                    s.summary().c_str());
        add(total, s);
    }
    const csgrt::Formats fmt(NB);
    for (bool bursts : {false, true}) {
        std::mt19937_64 rng(seed++);
        const std::vector<V3> lights = random_lights(fmt, rng);
        std::vector<Request> reqs;
        for (size_t i = 0; i < scaled(bursts ? 4000 : 12000); ++i) reqs.push_back(random_request(fmt, rng, lights));
        reqs = restrict_kinds(reqs);
        const Stats s = run<ID>(reqs, lights, bursts ? 0.1 : 0.3, 0.3, bursts, seed++);
        EXPECT_TRUE(s.ok()) << "BITS=" << NB << " (" << what << ") random: " << s.summary();
        std::printf("spawn BITS=%d (%s) random%s: %s (input refused on %llu clocks, at most %zu hits outstanding)\n",
                    NB, what, bursts ? ", output stalled in bursts" : "", s.summary().c_str(),
                    (unsigned long long)s.in_blocked, s.max_outstanding);
        add(total, s);
        if (bursts) EXPECT_GT(s.max_outstanding, 32u) << "the bursts should fill the front";
    }
    EXPECT_EQ(total.kinds[REFRACT] + total.kinds[TIR_REFLECT], 0u);
    if (reflection)
        EXPECT_GT(total.kinds[REFLECT], 0u);
    else
        EXPECT_EQ(total.kinds[REFLECT], 0u);
    EXPECT_GT(total.kinds[SHADOW], 0u);
    EXPECT_GT(total.kinds[CONTINUE], 0u);
    EXPECT_GT(total.unlit, 0u) << "no light behind a surface";
    EXPECT_GT(total.lit, 0u);
    EXPECT_GT(total.out_of_range, 0u) << "no hit point out of range";
    EXPECT_GT(total.face_zero, 0u) << "no n . d = 0";
    EXPECT_GT(total.lit_zero, 0u) << "no n . (light - p) = 0";
    EXPECT_GT(total.p_ties, 0u) << "no tie in the hit point";
}

TEST(Spawn, Bits16NoRefraction) {
    reduced_checks<kB16Refl>(true, tb::seed(1610));
    throughput<kB16Refl>(true, false);
}
// A request for a kind the build does not have stops the simulation.
template <int ID>
void requests_missing_kind(bool reflect, bool refract) {
    // (in the death test's child) $display's message to stderr, unbuffered
    std::fflush(stdout);
    dup2(2, 1);
    setvbuf(stdout, nullptr, _IONBF, 0);
    tb::Harness<Top> h;
    Top* t = h.top.get();
    const tb::StreamPorts p = Dut<ID>::ports(t);
    const csgrt::Formats fmt(Dut<ID>::kBits);
    std::mt19937_64 rng(3);
    const std::vector<V3> lights = random_lights(fmt, rng);
    Dut<ID>::lights(t, lights);
    Request q = random_request(fmt, rng, lights);
    q.lights = 1;
    q.reflect = reflect;
    q.refract = refract;
    auto tick = [&] {
        *p.clk = 1;
        t->eval();
        *p.clk = 0;
        t->eval();
    };
    *p.rst_n = 0;
    *p.valid_i = 0;
    *p.ready_i = 1;
    for (int i = 0; i < 4; ++i) tick();
    *p.rst_n = 1;
    *p.valid_i = 1;
    Dut<ID>::drive(t, q, 0);
    for (int i = 0; i < 8; ++i) tick();
}
TEST(SpawnDeathTest, RequestForAMissingKindStops) {
    EXPECT_DEATH(requests_missing_kind<kB16Refl>(false, true), "child kind this build does not have");
    EXPECT_DEATH(requests_missing_kind<kB16Shadow>(true, false), "child kind this build does not have");
}

TEST(Spawn, Bits16ShadowsOnly) {
    reduced_checks<kB16Shadow>(false, tb::seed(1620));
    throughput<kB16Shadow>(false, false);
}

}  // namespace
