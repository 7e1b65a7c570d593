// render.cpp — camera rays, shading and the threaded frame loop (render.h).
// The fixed functions are written in the order and with the roundings of
// docs/numerics.md sections 2 and 6; the RTL's camera and shading units
// mirror them line by line.
#include "render.h"

#include "raytree.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <thread>

namespace csgrt {

namespace {

const uint8_t kSrgbLut[4096] = {
#include "srgb_lut.inc"
};

constexpr int kColorOne = 1 << kColorFrac;


}  // namespace

i64 dot_round(const std::array<i64, 3>& x, const std::array<i64, 3>& y, int shift) {
    i128 s = 0;
    for (int i = 0; i < 3; ++i) s += i128(x[i]) * y[i];
    return i64(rshift_round(s, shift));
}

std::array<i64, 3> unit_fx(const std::array<i64, 3>& v, int F, int sqrt_bits) {
    u128 len2 = 0;
    for (int i = 0; i < 3; ++i) len2 += u128(i128(v[i]) * v[i]);
    // +1 makes the length strictly larger than |v|, so |out_i| < 2^F.
    if (len2 >> (2 * sqrt_bits)) throw std::logic_error("unit_fx: length bound violated");
    const u128 len = isqrt_fast(len2) + 1;   // = isqrt_bitwise(len2, sqrt_bits) + 1
    std::array<i64, 3> out{};
    for (int i = 0; i < 3; ++i) {
        i128 q = 0;
        sdiv_trunc(i128(v[i]) << F, i128(len), F + 1, q);   // never overflows: |v_i| < len
        out[i] = i64(q);
    }
    return out;
}

i64 pow_fx(i64 x, int n, int F) {
    i64 result = i64(1) << F;
    i64 base = x;
    while (n > 0) {
        if (n & 1) result = i64(rshift_round(i128(result) * base, F));
        n >>= 1;
        if (n > 0) base = i64(rshift_round(i128(base) * base, F));
    }
    return result;
}

uint8_t srgb_encode_fx(i64 linear) {
    return kSrgbLut[std::clamp<i64>(linear, 0, 4095)];
}

uint8_t srgb_encode_d(double x) {
    x = std::clamp(x, 0.0, 1.0);
    const double s = x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
    return uint8_t(std::lround(255.0 * s));
}

RayFx camera_ray_fx(const CompiledScene& cs, int x, int y) {
    const int F = cs.fmt.frac;
    const CameraInfo& c = cs.camera;
    RayFx r;
    r.o = c.origin_fx;
    // v = base + x dx + y dy, exact with cam_frac = F + 12 fraction bits,
    // then rounded to F + 4 fraction bits before normalising.
    std::array<i64, 3> v;
    for (int i = 0; i < 3; ++i) {
        const i64 full = c.base_fx[i] + i64(x) * c.dx_fx[i] + i64(y) * c.dy_fx[i];
        v[i] = i64(rshift_round(full, cs.fmt.cam_frac - (F + 4)));
    }
    // |v_i| < 8 with F + 4 fraction bits: sum v^2 < 2^(2F + 16).
    r.d = unit_fx(v, F, F + 8);
    return r;
}

RayD camera_ray_d(const CompiledScene& cs, int x, int y) {
    const CameraInfo& c = cs.camera;
    RayD r;
    const glm::dvec3 v = c.base + double(x) * c.dx + double(y) * c.dy;
    const glm::dvec3 d = glm::normalize(v);
    for (int i = 0; i < 3; ++i) {
        r.o[i] = c.origin[i];
        r.d[i] = d[i];
    }
    return r;
}

// Re-align a fixed-point value from `from` to `to` fraction bits: rounded
// (rnd) when dropping bits, exact when adding them.
i64 align(i64 v, int from, int to) {
    return from >= to ? i64(rshift_round(v, from - to)) : v << (to - from);
}

std::array<i64, 3> shade_fx(const CompiledScene& cs, const RayFx& ray, const TraceResult<i64>& hit,
                            const LightScaleFx* light_scale, std::array<i64, 3>* spec_out) {
    if (!hit.hit) return cs.background_fx;
    const int F = cs.fmt.frac;
    const int FC = cs.fmt.coef_frac;
    const int CF = kColorFrac;
    const int SF = kShadeFrac;     // unit vectors
    const int PF = kShadePosFrac;  // positions and the gradient
    const auto& k = cs.leaves[hit.leaf].coef;
    const int mat_index = hit.border.to != 0 ? hit.border.to : hit.border.from;
    const MaterialInfo& m = cs.materials[mat_index];

    // Hit point p = o + t d (geometry: F fraction bits), then the shading
    // copies of point, coefficients and direction (fixed widths, any B).
    std::array<i64, 3> p, ps, ds;
    hit_point_fx(cs.fmt, ray, hit.t, p);
    for (int i = 0; i < 3; ++i) {
        ps[i] = align(p[i], F, PF);
        ds[i] = align(ray.d[i], F, SF);
    }
    i64 ks[kNumCoefs];
    for (int c = 0; c < kNumCoefs; ++c) ks[c] = align(k[c], FC, SF);

    // Normal: the gradient half A p + p_coef (PF bits), made unit (SF bits)
    // and turned to face the incoming ray.
    std::array<i64, 3> n = unit_fx(half_gradient_fx(ks, ps, PF, SF), SF, kShadeSqrtStages);
    face_against(n, ds);

    // Diffuse and phong from every light that reaches the point.
    std::array<i64, 3> diffuse{0, 0, 0}, spec{0, 0, 0};
    const i64 dn = dot_round(ds, n, SF);
    std::array<i64, 3> refl;   // the reflected view direction R = d - 2 (d.n) n
    for (int i = 0; i < 3; ++i) refl[i] = ds[i] - i64(rshift_round(i128(2 * dn) * n[i], SF));
    for (size_t k = 0; k < cs.lights.size(); ++k) {
        LightInfo li = cs.lights[k];
        if (light_scale) {
            bool dark = true;
            for (int c = 0; c < 3; ++c) {
                li.color_fx[c] = i64(rshift_round(i128(li.color_fx[c]) * (*light_scale)[k][c], CF));
                dark = dark && li.color_fx[c] == 0;
            }
            if (dark) continue;
        }
        std::array<i64, 3> lv;
        for (int i = 0; i < 3; ++i) lv[i] = align(li.pos_fx[i], F, PF) - ps[i];
        const std::array<i64, 3> l = unit_fx(lv, SF, kShadeSqrtStages);
        const i64 ndl = dot_round(n, l, SF);
        if (ndl > 0)
            for (int c = 0; c < 3; ++c) diffuse[c] += i64(rshift_round(i128(li.color_fx[c]) * ndl, SF));
        if (m.phong > 0) {
            const i64 cosr = dot_round(refl, l, SF);
            if (cosr > 0) {
                const i64 pw = pow_fx(cosr, m.phong_size, SF);
                const i64 ph = i64(rshift_round(i128(m.phong) * pw, SF));   // CF bits
                for (int c = 0; c < 3; ++c) spec[c] += i64(rshift_round(i128(li.color_fx[c]) * ph, CF));
            }
        }
    }
    std::array<i64, 3> col;
    for (int c = 0; c < 3; ++c) {
        const i64 intensity = m.ambient + i64(rshift_round(i128(m.diffuse) * diffuse[c], CF));
        col[c] = i64(rshift_round(i128(m.rgb[c]) * intensity, CF)) + spec[c];
    }
    if (spec_out) *spec_out = spec;
    return col;
}

std::array<double, 3> shade_d(const CompiledScene& cs, const RayD& ray, const TraceResult<double>& hit,
                              const LightScaleD* light_scale, std::array<double, 3>* spec_out) {
    if (!hit.hit) return {cs.background.x, cs.background.y, cs.background.z};
    const QuadricD& q = cs.leaves[hit.leaf].quad;
    const int mat_index = hit.border.to != 0 ? hit.border.to : hit.border.from;
    const MaterialInfo& m = cs.materials[mat_index];
    const glm::dvec3 o(ray.o[0], ray.o[1], ray.o[2]), d(ray.d[0], ray.d[1], ray.d[2]);
    const glm::dvec3 p = o + hit.t * d;
    glm::dvec3 n = q.A * p + q.p;
    const double nl = glm::length(n);
    n = nl > 0.0 ? n / nl : glm::dvec3(0.0);
    if (glm::dot(n, d) > 0.0) n = -n;
    const glm::dvec3 refl = d - 2.0 * glm::dot(d, n) * n;
    glm::dvec3 diffuse(0.0), spec(0.0);
    for (size_t k = 0; k < cs.lights.size(); ++k) {
        LightInfo li = cs.lights[k];
        if (light_scale) {
            for (int c = 0; c < 3; ++c) li.color[c] *= (*light_scale)[k][c];
            if (li.color == glm::dvec3(0.0)) continue;
        }
        const glm::dvec3 l = glm::normalize(li.pos - p);
        const double ndl = glm::dot(n, l);
        if (ndl > 0.0) diffuse += li.color * ndl;
        if (m.finish.phong > 0.0) {
            const double cosr = glm::dot(refl, l);
            if (cosr > 0.0) spec += li.color * (m.finish.phong * std::pow(cosr, double(m.phong_size)));
        }
    }
    std::array<double, 3> col;
    for (int c = 0; c < 3; ++c)
        col[c] = m.pigment.rgb[c] * (m.finish.ambient + m.finish.diffuse * diffuse[c]) + spec[c];
    if (spec_out) *spec_out = {spec[0], spec[1], spec[2]};
    return col;
}

PixelTrace render_pixel_fx(const CompiledScene& cs, int x, int y, TiePolicy ties, bool diag) {
    PixelTrace pt;
    pt.ray = camera_ray_fx(cs, x, y);
    pt.trace = trace_primary_fx(cs, pt.ray, ties, diag);
    const std::array<i64, 3> col = shade_fx(cs, pt.ray, pt.trace);
    for (int c = 0; c < 3; ++c) pt.rgb[c] = srgb_encode_fx(col[c]);
    return pt;
}

CompiledScene without_highlights(const CompiledScene& cs) {
    CompiledScene matte = cs;
    for (MaterialInfo& m : matte.materials) {
        m.phong = 0;
        m.finish.phong = 0.0;
    }
    return matte;
}

Frame render(const CompiledScene& scene, const RenderOptions& opt) {
    const EffectSet fx = opt.effects ? *opt.effects : scene_effects(scene);
    const CompiledScene matte = fx.specular ? CompiledScene() : without_highlights(scene);
    const CompiledScene& cs = fx.specular ? scene : matte;
    Frame f;
    f.width = cs.width;
    f.height = cs.height;
    const size_t npix = size_t(f.width) * f.height;
    f.rgb.assign(npix * 3, 0);
    f.hit_leaf.assign(npix, -1);
    f.material.assign(npix, 0);

    auto do_row = [&](int y) {
        for (int x = 0; x < f.width; ++x) {
            const size_t i = size_t(y) * f.width + x;
            int leaf = -1, mat = 0;
            uint8_t rgb[3];
            if (opt.arith == Arith::Fixed) {
                TraceResult<i64> tr;
                const std::array<i64, 3> col =
                    trace_colour_fx(cs, camera_ray_fx(cs, x, y), nullptr, 1, opt.ties, fx, &tr);
                for (int c = 0; c < 3; ++c) rgb[c] = srgb_encode_fx(col[c]);
                if (tr.hit) {
                    leaf = tr.leaf;
                    mat = tr.border.to ? tr.border.to : tr.border.from;
                }
            } else {
                TraceResult<double> tr;
                const std::array<double, 3> col =
                    trace_colour_d(cs, camera_ray_d(cs, x, y), nullptr, 1, opt.ties, fx, &tr);
                for (int c = 0; c < 3; ++c) rgb[c] = srgb_encode_d(col[c]);
                if (tr.hit) {
                    leaf = tr.leaf;
                    mat = tr.border.to ? tr.border.to : tr.border.from;
                }
            }
            for (int c = 0; c < 3; ++c) f.rgb[i * 3 + c] = rgb[c];
            f.hit_leaf[i] = int16_t(leaf);
            f.material[i] = uint8_t(mat);
        }
    };

    int nthreads = opt.threads > 0 ? opt.threads : int(std::max(1u, std::thread::hardware_concurrency()));
    std::atomic<int> next_row{0}, rows_done{0};
    const auto start = std::chrono::steady_clock::now();
    auto worker = [&]() {
        for (int y; (y = next_row.fetch_add(1)) < f.height;) {
            do_row(y);
            rows_done.fetch_add(1);
        }
    };
    std::vector<std::thread> pool;
    for (int i = 1; i < nthreads; ++i) pool.emplace_back(worker);
    if (opt.progress) {
        // the calling thread works too and reports about ten times a second
        std::thread reporter([&]() {
            while (rows_done.load() < f.height) {
                std::this_thread::sleep_for(std::chrono::milliseconds(200));
                const double s =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                std::fprintf(stderr, "\rrender: %3d%% (%d/%d rows, %.1f s)", 100 * rows_done.load() / f.height,
                             rows_done.load(), f.height, s);
            }
        });
        worker();
        reporter.join();
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "\rrender: 100%% (%d rows, %.2f s)          \n", f.height, s);
    } else {
        worker();
    }
    for (auto& t : pool) t.join();
    return f;
}

}  // namespace csgrt
