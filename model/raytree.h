// raytree.h — secondary rays: shadows, mirror reflection and refraction, with
// no epsilon and no origin offset. A child ray starts at the rounded hit
// point and inherits its parent's leaf flags: the near side's (before the
// crossing) for shadow and reflected rays, the far side's (after it, and
// after the coincident-surface look-ahead) for transmitted rays. The
// validity check alone rejects the surface the ray starts on
// (docs/effects.md).
#pragma once

#include "compile.h"
#include "render.h"
#include "trace.h"

#include <array>
#include <string>

namespace csgrt {

// The effects a scene uses (EffectSet is declared in render.h).
EffectSet scene_effects(const CompiledScene& cs);

// The effects an RTL build renders for a scene: local shading always;
// shadows, specular highlights (phong), reflection and refraction when the
// build has those units (csgrt_top's SHADOWS, SPECULAR, REFLECTION,
// REFRACTION) and the scene uses them. Co-simulation renders the model with
// these (render() shades without highlights when specular is off).
EffectSet rtl_effects(const CompiledScene& cs, bool shadows, bool reflection, bool refraction, bool specular);

// Geometry of secondary rays (F fraction bits, docs/effects.md):
// square-root stages for unit vectors of geometry vectors with |v_i| < 128
int geo_sqrt_stages(int F);
// the unit surface normal of `leaf` at p, turned to face direction d
std::array<i64, 3> normal_fx(const CompiledScene& cs, int leaf, const std::array<i64, 3>& p,
                             const std::array<i64, 3>& d);
// d - 2 (d.n) n, made unit
std::array<i64, 3> reflect_fx(const std::array<i64, 3>& d, const std::array<i64, 3>& n, int F);
// Snell's law from index ior1 into ior2 (kColorFrac bits); false on total
// internal reflection
bool refract_fx(const std::array<i64, 3>& d, const std::array<i64, 3>& n, i64 ior1, i64 ior2, int F,
                std::array<i64, 3>& out);
// the ray from p towards a light at p + lv, and the distance to the light
// (F bits): events at t >= that distance are not reached
RayFx shadow_ray_fx(int F, const std::array<i64, 3>& p, const std::array<i64, 3>& lv, i64& distance);
// the index of refraction of a material (air: 1)
i64 ior_of(const CompiledScene& cs, int material);

// Colour of a ray (linear, kColorFrac fraction bits, not yet saturated),
// following shadows, reflection and refraction as `fx` allows.
// `flags` is null for a primary ray.
std::array<i64, 3> trace_colour_fx(const CompiledScene& cs, const RayFx& ray, const std::vector<uint8_t>* flags,
                                   int depth, TiePolicy ties, const EffectSet& fx, TraceResult<i64>* first = nullptr);
std::array<double, 3> trace_colour_d(const CompiledScene& cs, const RayD& ray, const std::vector<uint8_t>* flags,
                                     int depth, TiePolicy ties, const EffectSet& fx,
                                     TraceResult<double>* first = nullptr);

}  // namespace csgrt
