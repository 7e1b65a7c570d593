// render.h — camera, shading and the frame loop of the golden model.
//
// The fixed path (Arith::Fixed) is integer-only and defines the pixels the
// RTL must produce; the double path (Arith::Double) runs the same algorithm
// on the unquantised scene, to measure the fixed-point error.
#pragma once

#include "compile.h"
#include "trace.h"

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace csgrt {

enum class Arith { Fixed, Double };

// Shading works at fixed widths whatever the coordinate width B
// (docs/numerics.md section 6): positions and gradients with kShadePosFrac
// fraction bits (|.| < 16, 17-bit signed), unit vectors with kShadeFrac
// (|.| < 1, 16-bit signed), so that every shading product fits an 18x18
// multiplier.
constexpr int kShadePosFrac = 12;
constexpr int kShadeFrac = 15;
// sum of squares of a vector with |v_i| < 16 at 12 fraction bits < 2^34
constexpr int kShadeSqrtStages = 17;

// Effects a render follows (raytree.h): what the scene uses, or fewer (the
// RTL implements primary rays only so far).
struct EffectSet {
    bool shadows = false;      // any light and any object
    bool specular = false;     // any phong > 0: highlights (local shading; off: every phong taken as 0)
    bool reflection = false;   // any reflection > 0
    bool refraction = false;   // any filter > 0
    int depth = 1;             // ray-tree depth limit (max_trace_level) when rays spawn rays
    std::string str() const;
    bool any_secondary() const { return shadows || reflection || refraction; }
};

struct RenderOptions {
    Arith arith = Arith::Fixed;
    TiePolicy ties = TiePolicy::Paper;
    // the effects to follow; unset: every effect the scene uses
    std::optional<EffectSet> effects;
    int threads = 0;                 // 0: all cores
    bool progress = false;           // a progress line on stderr
};

// One rendered frame: 8-bit sRGB pixels and, per pixel, what the primary
// ray struck (for masks, tests and co-simulation reports).
struct Frame {
    int width = 0, height = 0;
    std::vector<uint8_t> rgb;        // width * height * 3
    std::vector<int16_t> hit_leaf;   // -1: background
    std::vector<uint8_t> material;   // material shown, 0: background
    bool is_object(int x, int y) const { return hit_leaf[size_t(y) * width + x] >= 0; }
    // Pixel i (raster order) has another colour in `o` (any channel).
    bool rgb_differs(const Frame& o, size_t i) const {
        return rgb[3 * i] != o.rgb[3 * i] || rgb[3 * i + 1] != o.rgb[3 * i + 1] || rgb[3 * i + 2] != o.rgb[3 * i + 2];
    }
};

// Primary ray of pixel (x, y) (numerics.md section 2).
RayFx camera_ray_fx(const CompiledScene& cs, int x, int y);
RayD camera_ray_d(const CompiledScene& cs, int x, int y);

// Unit vector of v (any common fraction) with F fraction bits, |out_i| <
// 2^F: out_i = trunc(v_i * 2^F / (isqrt(sum v^2) + 1)). sqrt_bits is the
// number of square-root stages: sum v^2 must be below 4^sqrt_bits.
std::array<i64, 3> unit_fx(const std::array<i64, 3>& v, int F, int sqrt_bits);

// rnd(x . y, shift): a dot product rounded once.
i64 dot_round(const std::array<i64, 3>& x, const std::array<i64, 3>& y, int shift);

// x^n with F fraction bits, binary exponentiation from the exponent's least
// significant bit, rounding each product (numerics.md section 6).
i64 pow_fx(i64 x, int n, int F);

// Linear colour (kColorFrac bits) to an 8-bit sRGB code.
uint8_t srgb_encode_fx(i64 linear);
uint8_t srgb_encode_d(double linear);

// Local shading of a hit: linear colour, kColorFrac fraction bits. With
// `light_scale`, light k's colour is first multiplied by light_scale[k]
// (kColorFrac bits per channel: what reaches the point through shadows).
using LightScaleFx = std::vector<std::array<i64, 3>>;
using LightScaleD = std::vector<std::array<double, 3>>;
// `spec_out`, when given, receives the phong part of the result (a filter
// does not dim highlights, as in POV-Ray).
std::array<i64, 3> shade_fx(const CompiledScene& cs, const RayFx& ray, const TraceResult<i64>& hit,
                            const LightScaleFx* light_scale = nullptr, std::array<i64, 3>* spec_out = nullptr);
std::array<double, 3> shade_d(const CompiledScene& cs, const RayD& ray, const TraceResult<double>& hit,
                              const LightScaleD* light_scale = nullptr, std::array<double, 3>* spec_out = nullptr);

// The whole frame.
Frame render(const CompiledScene& cs, const RenderOptions& opt);

// The scene shaded without highlights, as a build without the specular unit
// (csgrt_top's SPECULAR = 0) shades it: every material's phong set to 0.
// render() uses it when the effects leave specular out.
CompiledScene without_highlights(const CompiledScene& cs);

// Render one pixel of the fixed path, with the trace kept for reports.
struct PixelTrace {
    RayFx ray;
    TraceResult<i64> trace;
    std::array<uint8_t, 3> rgb{};
};
PixelTrace render_pixel_fx(const CompiledScene& cs, int x, int y, TiePolicy ties, bool keep_diagnostics);

}  // namespace csgrt
