// trace.h — the exact CSG tracer of Wyvill & Trotman: ray-quadric events
// with entering/leaving from exact signs, the state at t = -infinity, the
// sorted walk with the validity check, and classification by table look-ups.
//
// Two arithmetics share the walk: Fixed (integers only, bit-exact with the
// RTL; docs/numerics.md) and Double (the reference used to measure error).
#pragma once

#include "classify.h"
#include "compile.h"
#include "fixed.h"

#include <array>
#include <cstdint>
#include <vector>

namespace csgrt {

enum class TiePolicy : uint8_t { Paper = 0, Regular = 1 };

// Where an event's t lies: saturated values are "infinitely far".
enum class TRange : uint8_t { NegInf = 0, Finite = 1, PosInf = 2 };

// One intersection of a ray's line with one leaf's surface.
template <typename T>
struct Event {
    T t{};
    TRange range = TRange::Finite;
    uint16_t leaf = 0;
    bool entering = false;
    bool behind() const { return range == TRange::NegInf || (range == TRange::Finite && t < T(0)); }
    bool ahead() const { return range == TRange::Finite && !(t < T(0)); }
};

// What one leaf's quadric tells about one ray: up to two events and whether
// the ray's line is inside the half-space at t = -infinity.
template <typename T>
struct LeafEvents {
    int count = 0;
    Event<T> ev[2];
    bool inside_at_minus_inf = false;
    // the rounded coefficients along the ray (for reports and RTL checks)
    T a{}, b{}, c{};
};

// A ray in the fixed-point frame: origin with F fraction bits, unit
// direction with F fraction bits (|d_i| < 2^F).
struct RayFx {
    std::array<i64, 3> o{}, d{};
};
struct RayD {
    std::array<double, 3> o{}, d{};
};

// Ray-quadric intersection (numerics.md section 3).
LeafEvents<i64> intersect_fx(const Formats& fmt, const std::array<i64, kNumCoefs>& coef, const RayFx& ray);
LeafEvents<double> intersect_d(const QuadricD& q, const RayD& ray);

// The tie key: a strict total order on the events ahead of the origin.
template <typename T>
bool event_before(const Event<T>& x, const Event<T>& y, TiePolicy ties);

// The outcome of tracing one ray.
template <typename T>
struct TraceResult {
    bool hit = false;
    T t{};
    int leaf = -1;                     // the surface the hit reports (its normal; surface_leaf())
    int cross_leaf = -1;               // the leaf whose crossing is the hit (entering: its direction)
    bool entering = false;
    Class border;                      // BORDER from,to of the hit
    std::vector<uint8_t> flags_before; // leaf flags just before the hit (near side)
    std::vector<uint8_t> flags_after;  // leaf flags just after it (far side)
    // The look-behind's inputs, as the RTL hands them to child rays:
    // flags_hit_near are the flags just before the hit's tie group (every
    // crossing at the hit's t undone), near_run the up to kLookBehind valid
    // crossings before that group, most recent first; flags_before =
    // flags_hit_near with the longest prefix of near_run undone whose events
    // lie at the hit's t (none: the group is undone already) or whose
    // surface the hit point does not lie beyond.
    std::vector<uint8_t> flags_hit_near;
    std::vector<Event<T>> near_run;
    // diagnostics: the sorted events ahead, and the origin flags
    std::vector<Event<T>> events;
    std::vector<uint8_t> origin_flags;
};

// Optional behaviour of a trace (secondary rays, effects):
//  - t_limit: events at t >= t_limit are never reached (a shadow ray stops
//    at its light); 0 means no limit beyond the format's.
//  - lookahead: after a hit whose far side is transparent (air or a
//    material with filter > 0), cross the following coincident surfaces too
//    (algorithm.md section 6): while the next event has the same t, or the
//    hit point already lies beyond that next surface (exact sign of its
//    quadric at the hit point; never for the hit leaf's own events, whose
//    surface the hit point lies on), apply the validity check, classify, toggle;
//    stop at an opaque material. The hit then reads BORDER a1, an and
//    flags_after are the flags beyond the whole run.
// The look-behind (docs/effects.md) undoes at most this many crossings
// just before a hit; the RTL hands them to the child rays beside the hit.
constexpr int kLookBehind = 4;

//  - cull: the fixed-point tracer skips the leaves of subtrees whose
//    bounding box (CompiledScene::cull) the ray's segment misses; the result
//    is the same TraceResult bit for bit (model/cull.h) except near_run,
//    which then lists the crossings of intersected leaves only. Off with
//    keep_diagnostics (events and origin_flags need every leaf), and when
//    the scene was compiled without boxes (--no-cull).
struct TraceOptions {
    i64 t_limit_fx = 0;
    double t_limit_d = 0.0;
    bool lookahead = false;
    bool cull = true;
};

// Trace a primary ray: origin flags from the state at -infinity toggled by
// the events behind the origin. With keep_diagnostics the result carries
// the event list and origin flags.
TraceResult<i64> trace_primary_fx(const CompiledScene& cs, const RayFx& ray, TiePolicy ties,
                                  bool keep_diagnostics = false, const TraceOptions& opt = {});
TraceResult<double> trace_primary_d(const CompiledScene& cs, const RayD& ray, TiePolicy ties,
                                    bool keep_diagnostics = false, const TraceOptions& opt = {});

// Trace a secondary ray that inherits `flags` (one per leaf): events behind
// its origin are ignored.
TraceResult<i64> trace_secondary_fx(const CompiledScene& cs, const RayFx& ray, const std::vector<uint8_t>& flags,
                                    TiePolicy ties, bool keep_diagnostics = false, const TraceOptions& opt = {});
TraceResult<double> trace_secondary_d(const CompiledScene& cs, const RayD& ray, const std::vector<uint8_t>& flags,
                                      TiePolicy ties, bool keep_diagnostics = false, const TraceOptions& opt = {});

// Half the gradient of a quadric at p, per axis rnd(A p + (p_coef << p_shift),
// round), coefficients in CoefIndex order: the w of intersect_fx (p_shift F,
// round FC), the normal of secondary rays, and the shading normal.
std::array<i64, 3> half_gradient_fx(const i64* coef, const std::array<i64, 3>& p, int p_shift, int round);

// Turns a normal to face a direction: negated when n.d > 0 (exact sign).
void face_against(std::array<i64, 3>& n, const std::array<i64, 3>& d);

// Q(p) of one leaf at a point (F fraction bits), computed as c is in
// intersect_fx with the origin at p: its sign is exact for the rounded
// coefficients along any ray from p.
i64 quadric_at_fx(const Formats& fmt, const std::array<i64, kNumCoefs>& coef, const std::array<i64, 3>& p);

// The hit point o + t d (F fraction bits); false when a coordinate leaves
// the range [-4, 4) (such a hit counts as no hit: numerics.md section 7).
bool hit_point_fx(const Formats& fmt, const RayFx& ray, i64 t, std::array<i64, 3>& p);

// Whether a material lets a ray through: air, or filter > 0.
bool is_transparent(const CompiledScene& cs, int material);

}  // namespace csgrt
