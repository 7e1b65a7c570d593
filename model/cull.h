// cull.h — bounding-box culling for the fixed-point tracer.
//
// A subtree of the CSG tree whose relaxed IN-region the ray's segment does
// not meet is OUT at every event of the ray, so its leaves cannot change any
// classification above it: the tracer need not intersect them. The boxes are
// computed once per scene (in double, rounded outward), the per-ray test is
// integer arithmetic on the fixed-point ray, and the flags of the skipped
// leaves that a hit hands to child rays are reconstructed exactly (or the ray
// is traced again with them, or without culling). The argument, with every
// margin derived from the fixed-point error bounds, is docs/numerics.md,
// section 9. The pixels do not change by a single bit: cull_test.cpp
// renders every scene with culling on and off and compares.
#pragma once

#include "compile.h"
#include "trace.h"

#include <cstdint>
#include <vector>

namespace csgrt {

// A finite primitive as the compiler flattened it, in its own (object)
// space, with the leaves it became (consecutive indices):
//   Sphere: v0 centre, r0 radius; 1 leaf
//   Box:    v0, v1 corners; 6 leaves (-x, +x, -y, +y, -z, +z)
//   Capped: cylinder or cone from v0 (radius r0) to v1 (radius r1); 3 leaves
//           (side, base cap, top cap)
//   Quadric: quad, the object-space coefficients; 1 leaf (bounded when its
//           quadratic part is positive definite: an ellipsoid)
struct CullPrimitive {
    enum Kind : uint8_t { Sphere, Box, Capped, Quadric };
    Kind kind = Sphere;
    glm::dmat4 to_world{1.0};   // object -> world
    glm::dvec3 v0{0.0}, v1{0.0};
    double r0 = 0.0, r1 = 0.0;
    QuadricD quad;
    int first_leaf = 0, num_leaves = 0;
};

// Margins, in ulps of F (u = 2^-F), of docs/numerics.md section 9:
//  - kCullEtaQ: a leaf's flag is IN at an event time t only where its
//    quantised quadric Q(o + t d) <= kCullEtaQ u (rounding of a, b, c and of
//    the roots); the boxes bound the relaxed regions Q <= eta.
//  - kCullBoxEta: the same relaxation in the compiler's double quadrics
//    (adds the coefficient quantisation and double rounding).
//  - kCullHitMargin: |quadric_at_fx(hit point)| above it fixes a skipped
//    leaf's flag at the hit to the sign of Q, with no event at the hit's t.
//  - kCullOriginMargin: the same for c = quadric_at_fx(origin) at t = 0.
constexpr i64 kCullEtaQ = 110;        // 86 u (roots) + 24 u (a, b, c)
constexpr double kCullBoxEta = 176.0;  // (110 + 45.2) / (1 - 2^-11) + 16 = 171.3, rounded up
static_assert(kCullBoxEta >= (kCullEtaQ + 45.2) / (1.0 - 1.0 / 2048.0) + 16.0, "docs/numerics.md 9.3");
constexpr i64 kCullHitMargin = 192;    // > 110 + 58 (hit point rounding) + 13 (c's rounding) = 181
constexpr i64 kCullOriginMargin = 96;  // > 86 (roots; c is exact at t = 0)
// Primitives whose object-to-world map stretches one direction more than
// this many times another get no box (keeps the double error of the
// compiler's quadrics far below the margins).
constexpr double kCullMaxCondition = 16.0;

// The bounds of every node of `program` (the balanced classification
// program). leaf_scale[l]: largest |coefficient| of leaf l's frame quadric
// before the compiler normalised it; world_to_frame: the frame map.
CullBounds build_cull_bounds(const std::vector<Instr>& program, const std::vector<LeafInfo>& leaves,
                             const std::vector<CullPrimitive>& prims, const std::vector<double>& leaf_scale,
                             const glm::dmat4& world_to_frame, const Formats& fmt);

// True when no point o + t d, 0 <= t <= t_end (t_end with F fraction bits)
// lies in the node's box (closed). Integer arithmetic; conservative.
bool segment_misses_box(const CullNode& node, const RayFx& ray, i64 t_end, int frac);

// quadric_at_fx, the same value (64-bit arithmetic up to 28 bits).
i64 quadric_at_fast(const Formats& fmt, const std::array<i64, kNumCoefs>& coef, const std::array<i64, 3>& p);

// quadric_at_fx of leaf l at p (planes in one line: CullBounds::plane).
inline i64 leaf_q(const CompiledScene& cs, int l, const std::array<i64, 3>& p) {
    const CullBounds& cb = cs.cull;
    if (cb.is_plane[l] && cs.fmt.bits <= 28) {   // |p_i P_i| < 2^(2F+3): 64 bits
        const auto& P = cb.plane[l];
        return ((p[0] * P[0] + p[1] * P[1] + p[2] * P[2] + (i64(1) << (cs.fmt.frac - 1))) >> cs.fmt.frac) + P[3];
    }
    return quadric_at_fast(cs.fmt, cs.leaves[l].coef, p);
}

// The leaves a ray need not intersect on [0, t_end]: culled[l] = 1. For a
// secondary ray (inherited flags), a node is skipped only if every
// certificate leaf whose inherited flag is IN has quadric_at_fx(origin) < 0
// (its state at the origin is IN: the flag is not stale). Returns the
// number of culled leaves.
// With `live` (two entries per leaf), also the t range in which each
// intersected leaf's tested box is met: an event of the leaf outside it
// lies outside that box, where its subtree is OUT (the same certificate), so
// it cannot be a hit; [INT64_MIN, INT64_MAX] when no box vouches.
int select_culled(const CompiledScene& cs, const RayFx& ray, i64 t_end, const std::vector<uint8_t>* inherited,
                  std::vector<uint8_t>& culled, std::vector<std::array<i64, 2>>* live = nullptr);

// Counters of the culling (all threads), for tests and reports.
struct CullStats {
    uint64_t rays = 0;            // traces that could cull
    uint64_t culled_rays = 0;     // traces that culled at least one leaf
    uint64_t leaves = 0;          // leaves of those traces
    uint64_t culled_leaves = 0;   // leaves skipped
    uint64_t retraces = 0;        // traces done again with some culled leaves intersected
    uint64_t fallbacks = 0;       // traces done again without culling
};
CullStats cull_stats();
void reset_cull_stats();
void add_cull_stats(const CullStats& s);
void count_cull_fallback();   // this thread traced a ray again without culling
void count_cull_retrace();    // ... with some culled leaves intersected

}  // namespace csgrt
