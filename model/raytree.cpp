// raytree.cpp — shadows, reflection and refraction (raytree.h). The fixed
// functions use the geometry formats of docs/numerics.md (F fraction bits for
// points and directions) and round only with rnd, isqrt and div; docs/effects.md
// lists each step. The double functions follow the same algorithm.
#include "raytree.h"

#include <cmath>

namespace csgrt {

namespace {

constexpr int CF = kColorFrac;
constexpr i64 kColorOne = i64(1) << kColorFrac;

}  // namespace

int geo_sqrt_stages(int F) { return F + 8; }

std::array<i64, 3> normal_fx(const CompiledScene& cs, int leaf, const std::array<i64, 3>& p,
                             const std::array<i64, 3>& d) {
    const int F = cs.fmt.frac;
    const std::array<i64, 3> g = half_gradient_fx(cs.leaves[leaf].coef.data(), p, F, cs.fmt.coef_frac);   // |g_i| < 16
    std::array<i64, 3> n = unit_fx(g, F, geo_sqrt_stages(F));
    face_against(n, d);
    return n;
}

std::array<i64, 3> reflect_fx(const std::array<i64, 3>& d, const std::array<i64, 3>& n, int F) {
    const i64 dn = dot_round(d, n, F);
    std::array<i64, 3> r;
    for (int i = 0; i < 3; ++i) r[i] = d[i] - i64(rshift_round(i128(2 * dn) * n[i], F));
    return unit_fx(r, F, geo_sqrt_stages(F));
}

bool refract_fx(const std::array<i64, 3>& d, const std::array<i64, 3>& n, i64 ior1, i64 ior2, int F,
                std::array<i64, 3>& out) {
    const i64 one = i64(1) << F;
    i128 eta128 = 0;
    sdiv_trunc(i128(ior1) << F, ior2, F + 7, eta128);   // iors in [1/4, 16): eta < 64
    const i64 eta = i64(eta128);
    const i64 cos_i = -dot_round(d, n, F);                 // n faces the ray: cos_i >= 0
    const i64 sin2 = one - i64(rshift_round(i128(cos_i) * cos_i, F));
    const i64 k = one - i64(rshift_round(i128(rshift_round(i128(eta) * eta, F)) * sin2, F));
    if (k < 0) return false;
    const i64 sk = i64(isqrt_fast(u128(k) << F));      // sqrt(k), F bits
    const i64 a = i64(rshift_round(i128(eta) * cos_i, F)) - sk;
    std::array<i64, 3> t;
    for (int i = 0; i < 3; ++i)
        t[i] = i64(rshift_round(i128(eta) * d[i], F)) + i64(rshift_round(i128(a) * n[i], F));
    out = unit_fx(t, F, geo_sqrt_stages(F));
    return true;
}

RayFx shadow_ray_fx(int F, const std::array<i64, 3>& p, const std::array<i64, 3>& lv, i64& distance) {
    RayFx ray;
    ray.o = p;
    ray.d = unit_fx(lv, F, geo_sqrt_stages(F));
    u128 len2 = 0;
    for (int i = 0; i < 3; ++i) len2 += u128(i128(lv[i]) * lv[i]);
    distance = i64(isqrt_fast(len2));
    return ray;
}

i64 ior_of(const CompiledScene& cs, int material) {
    return material == 0 ? kColorOne : cs.materials[material].ior;
}

namespace {

// Most crossings a shadow ray follows through transparent solids.
constexpr int kMaxShadowCrossings = 16;

// The light reaching point p from a light at p + lv, through transparent
// solids (kColorFrac bits per channel): the shadow ray runs straight, and
// every crossing into a material multiplies the light by that material's
// filter x pigment colour; an opaque material (filter 0) stops it.
std::array<i64, 3> shadow_fx(const CompiledScene& cs, const std::array<i64, 3>& p, const std::array<i64, 3>& lv,
                             const std::vector<uint8_t>& near_flags, TiePolicy ties, const EffectSet& fx) {
    const int F = cs.fmt.frac;
    std::array<i64, 3> atten{kColorOne, kColorOne, kColorOne};
    TraceOptions so;
    RayFx ray = shadow_ray_fx(F, p, lv, so.t_limit_fx);
    so.lookahead = fx.refraction;
    std::vector<uint8_t> flags = near_flags;
    for (int crossing = 0; crossing < kMaxShadowCrossings; ++crossing) {
        const TraceResult<i64> tr = trace_secondary_fx(cs, ray, flags, ties, false, so);
        if (!tr.hit) return atten;
        const int m = tr.border.to;
        if (m != 0) {
            if (!is_transparent(cs, m)) return {0, 0, 0};
            for (int c = 0; c < 3; ++c)
                atten[c] = i64(rshift_round(
                    i128(atten[c]) * i64(rshift_round(i128(cs.materials[m].filter) * cs.materials[m].rgb[c], CF)), CF));
        }
        // continue from the crossing, on its far side
        std::array<i64, 3> q;
        if (!hit_point_fx(cs.fmt, ray, tr.t, q)) return atten;
        ray.o = q;
        flags = tr.flags_after;
        so.t_limit_fx -= tr.t;
        if (so.t_limit_fx <= 0) return atten;
    }
    return {0, 0, 0};   // too many crossings: treated as blocked
}

std::array<double, 3> shadow_d(const CompiledScene& cs, const glm::dvec3& p, const glm::dvec3& lv,
                               const std::vector<uint8_t>& near_flags, TiePolicy ties, const EffectSet& fx) {
    std::array<double, 3> atten{1.0, 1.0, 1.0};
    const glm::dvec3 dir = glm::normalize(lv);
    RayD ray;
    for (int i = 0; i < 3; ++i) ray.o[i] = p[i], ray.d[i] = dir[i];
    TraceOptions so;
    so.t_limit_d = glm::length(lv);
    so.lookahead = fx.refraction;
    std::vector<uint8_t> flags = near_flags;
    for (int crossing = 0; crossing < kMaxShadowCrossings; ++crossing) {
        const TraceResult<double> tr = trace_secondary_d(cs, ray, flags, ties, false, so);
        if (!tr.hit) return atten;
        const int m = tr.border.to;
        if (m != 0) {
            if (!is_transparent(cs, m)) return {0, 0, 0};
            for (int c = 0; c < 3; ++c) atten[c] *= cs.materials[m].pigment.filter * cs.materials[m].pigment.rgb[c];
        }
        for (int i = 0; i < 3; ++i) ray.o[i] += tr.t * ray.d[i];
        flags = tr.flags_after;
        so.t_limit_d -= tr.t;
        if (so.t_limit_d <= 0.0) return atten;
    }
    return {0, 0, 0};
}

}  // namespace

std::string EffectSet::str() const {
    std::string s;
    auto add = [&](bool on, const char* name) {
        if (on) s += (s.empty() ? "" : ", ") + std::string(name);
    };
    add(shadows, "shadows");
    add(specular, "specular");
    add(reflection, "reflection");
    add(refraction, "refraction");
    if (reflection || refraction) s += ", depth " + std::to_string(depth);
    return s.empty() ? "none" : s;
}

EffectSet scene_effects(const CompiledScene& cs) {
    EffectSet e;
    // shadows: a light that casts them (not shadowless) and an object
    for (const LightInfo& l : cs.lights) e.shadows = e.shadows || !l.shadowless;
    e.shadows = e.shadows && !cs.leaves.empty();
    for (size_t m = 1; m < cs.materials.size(); ++m) {
        e.specular = e.specular || cs.materials[m].phong > 0;
        e.reflection = e.reflection || cs.materials[m].reflection > 0;
        e.refraction = e.refraction || cs.materials[m].filter > 0;
    }
    e.depth = (e.reflection || e.refraction) ? cs.max_trace_level : 1;
    return e;
}

EffectSet rtl_effects(const CompiledScene& cs, bool shadows, bool reflection, bool refraction, bool specular) {
    const EffectSet scene = scene_effects(cs);
    EffectSet e;
    e.specular = specular && scene.specular;
    e.shadows = shadows && scene.shadows;
    e.reflection = reflection && scene.reflection;
    e.refraction = refraction && scene.refraction;
    e.depth = (e.reflection || e.refraction) ? cs.max_trace_level : 1;
    return e;
}

namespace {

// One ray of a pixel's ray tree with weight w (kColorFrac bits per channel):
// adds the ray's own contribution rnd(w L) to acc and traces its children
// with their weights (docs/effects.md, "Colour"). The sum over the tree does
// not depend on the order the rays are traced in, which lets the RTL trace
// them as they come.
void accumulate_fx(const CompiledScene& cs, const RayFx& ray, const std::vector<uint8_t>* flags, int depth,
                   const std::array<i64, 3>& w, TiePolicy ties, const EffectSet& fx, std::array<i64, 3>& acc,
                   TraceResult<i64>* first) {
    const int F = cs.fmt.frac;
    auto weigh = [](i64 a, i64 b) { return i64(rshift_round(i128(a) * b, CF)); };
    TraceOptions topt;
    topt.lookahead = fx.refraction;
    const TraceResult<i64> tr =
        flags ? trace_secondary_fx(cs, ray, *flags, ties, false, topt) : trace_primary_fx(cs, ray, ties, false, topt);
    if (first) *first = tr;
    std::array<i64, 3> p;
    if (!tr.hit || !hit_point_fx(cs.fmt, ray, tr.t, p)) {
        for (int c = 0; c < 3; ++c) acc[c] += weigh(w[c], cs.background_fx[c]);
        return;
    }
    const int mat = tr.border.to ? tr.border.to : tr.border.from;
    const MaterialInfo& m = cs.materials[mat];
    const bool spawn = fx.reflection || fx.refraction || fx.shadows;
    const std::array<i64, 3> n = spawn ? normal_fx(cs, tr.leaf, p, ray.d) : std::array<i64, 3>{};

    // Shadows: a ray from the hit point towards each light, with the flags
    // of the near side. A light behind the surface leaves it unlit. A
    // shadowless light keeps its full colour (shading alone decides, as in a
    // build without shadows).
    LightScaleFx scale(cs.lights.size(), {kColorOne, kColorOne, kColorOne});
    if (fx.shadows) {
        for (size_t k = 0; k < cs.lights.size(); ++k) {
            if (cs.lights[k].shadowless) continue;
            std::array<i64, 3> lv;
            for (int i = 0; i < 3; ++i) lv[i] = cs.lights[k].pos_fx[i] - p[i];
            i128 nl = 0;
            for (int i = 0; i < 3; ++i) nl += i128(n[i]) * lv[i];
            if (nl <= 0)
                scale[k] = {0, 0, 0};
            else
                scale[k] = shadow_fx(cs, p, lv, tr.flags_before, ties, fx);
        }
    }
    std::array<i64, 3> spec;
    std::array<i64, 3> local = shade_fx(cs, ray, tr, &scale, &spec);
    const bool leaf_of_tree = depth >= cs.max_trace_level;
    const bool transmits = !leaf_of_tree && fx.refraction && m.filter > 0;
    if (transmits)   // what the surface shows itself; the rest comes through it
        for (int c = 0; c < 3; ++c) local[c] = weigh(kColorOne - m.filter, local[c] - spec[c]) + spec[c];
    for (int c = 0; c < 3; ++c) acc[c] += weigh(w[c], local[c]);
    if (leaf_of_tree) return;

    // Refraction: the transmitted ray takes the far side's flags.
    if (transmits) {
        RayFx child;
        child.o = p;
        const std::vector<uint8_t>* child_flags = &tr.flags_after;
        if (!refract_fx(ray.d, n, ior_of(cs, tr.border.from), ior_of(cs, tr.border.to), F, child.d)) {
            child.d = reflect_fx(ray.d, n, F);   // total internal reflection
            child_flags = &tr.flags_before;
        }
        std::array<i64, 3> wt;
        for (int c = 0; c < 3; ++c) wt[c] = weigh(w[c], weigh(m.filter, m.rgb[c]));
        accumulate_fx(cs, child, child_flags, depth + 1, wt, ties, fx, acc, nullptr);
    }
    // Mirror reflection: the reflected ray takes the near side's flags.
    if (fx.reflection && m.reflection > 0) {
        RayFx child;
        child.o = p;
        child.d = reflect_fx(ray.d, n, F);
        std::array<i64, 3> wr;
        for (int c = 0; c < 3; ++c) wr[c] = weigh(w[c], m.reflection);
        accumulate_fx(cs, child, &tr.flags_before, depth + 1, wr, ties, fx, acc, nullptr);
    }
}

}  // namespace

std::array<i64, 3> trace_colour_fx(const CompiledScene& cs, const RayFx& ray, const std::vector<uint8_t>* flags,
                                   int depth, TiePolicy ties, const EffectSet& fx, TraceResult<i64>* first) {
    std::array<i64, 3> acc{0, 0, 0};
    accumulate_fx(cs, ray, flags, depth, {kColorOne, kColorOne, kColorOne}, ties, fx, acc, first);
    return acc;
}

std::array<double, 3> trace_colour_d(const CompiledScene& cs, const RayD& ray, const std::vector<uint8_t>* flags,
                                     int depth, TiePolicy ties, const EffectSet& fx, TraceResult<double>* first) {
    TraceOptions topt;
    topt.lookahead = fx.refraction;
    const TraceResult<double> tr =
        flags ? trace_secondary_d(cs, ray, *flags, ties, false, topt) : trace_primary_d(cs, ray, ties, false, topt);
    if (first) *first = tr;
    const glm::dvec3 o(ray.o[0], ray.o[1], ray.o[2]), d(ray.d[0], ray.d[1], ray.d[2]);
    const glm::dvec3 p = o + tr.t * d;
    const bool in_range = std::fabs(p.x) < 4.0 && std::fabs(p.y) < 4.0 && std::fabs(p.z) < 4.0;
    if (!tr.hit || !in_range) return {cs.background.x, cs.background.y, cs.background.z};
    const int mat = tr.border.to ? tr.border.to : tr.border.from;
    const MaterialInfo& m = cs.materials[mat];
    const QuadricD& q = cs.leaves[tr.leaf].quad;
    glm::dvec3 n = q.A * p + q.p;
    n = glm::length(n) > 0.0 ? glm::normalize(n) : glm::dvec3(0.0);
    if (glm::dot(n, d) > 0.0) n = -n;
    auto to_ray = [](const glm::dvec3& org, const glm::dvec3& dir) {
        RayD r;
        for (int i = 0; i < 3; ++i) r.o[i] = org[i], r.d[i] = dir[i];
        return r;
    };

    LightScaleD scale(cs.lights.size(), {1.0, 1.0, 1.0});
    if (fx.shadows) {
        for (size_t k = 0; k < cs.lights.size(); ++k) {
            if (cs.lights[k].shadowless) continue;
            const glm::dvec3 lv = cs.lights[k].pos - p;
            scale[k] = glm::dot(n, lv) <= 0.0 ? std::array<double, 3>{0, 0, 0}
                                               : shadow_d(cs, p, lv, tr.flags_before, ties, fx);
        }
    }
    std::array<double, 3> spec;
    const std::array<double, 3> local = shade_d(cs, ray, tr, &scale, &spec);
    std::array<double, 3> col = local;
    if (depth >= cs.max_trace_level) return col;
    const glm::dvec3 refl = glm::normalize(d - 2.0 * glm::dot(d, n) * n);
    if (fx.refraction && m.filter > 0) {
        const double ior1 = tr.border.from ? cs.materials[tr.border.from].interior.ior : 1.0;
        const double ior2 = tr.border.to ? cs.materials[tr.border.to].interior.ior : 1.0;
        const double eta = ior1 / ior2, cos_i = -glm::dot(d, n);
        const double k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
        const std::vector<uint8_t>* child_flags = &tr.flags_after;
        glm::dvec3 dir;
        if (k < 0.0) {
            dir = refl;
            child_flags = &tr.flags_before;
        } else {
            dir = glm::normalize(eta * d + (eta * cos_i - std::sqrt(k)) * n);
        }
        const std::array<double, 3> tc = trace_colour_d(cs, to_ray(p, dir), child_flags, depth + 1, ties, fx);
        const double f = m.pigment.filter;
        for (int c = 0; c < 3; ++c) col[c] = (1.0 - f) * (local[c] - spec[c]) + spec[c] + f * m.pigment.rgb[c] * tc[c];
    }
    if (fx.reflection && m.finish.reflection > 0.0) {
        const std::array<double, 3> rc = trace_colour_d(cs, to_ray(p, refl), &tr.flags_before, depth + 1, ties, fx);
        for (int c = 0; c < 3; ++c) col[c] += m.finish.reflection * rc[c];
    }
    return col;
}

}  // namespace csgrt
