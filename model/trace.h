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
    int leaf = -1;
    bool entering = false;
    Class border;                      // BORDER from,to of the hit
    std::vector<uint8_t> flags_before; // leaf flags just before the hit (near side)
    std::vector<uint8_t> flags_after;  // leaf flags just after it (far side)
    // diagnostics: the sorted events ahead, and the origin flags
    std::vector<Event<T>> events;
    std::vector<uint8_t> origin_flags;
};

// Trace a primary ray: origin flags from the state at -infinity toggled by
// the events behind the origin. With keep_diagnostics the result carries
// the event list and origin flags.
TraceResult<i64> trace_primary_fx(const CompiledScene& cs, const RayFx& ray, TiePolicy ties,
                                  bool keep_diagnostics = false);
TraceResult<double> trace_primary_d(const CompiledScene& cs, const RayD& ray, TiePolicy ties,
                                    bool keep_diagnostics = false);

// Trace a secondary ray that inherits `flags` (one per leaf).
TraceResult<i64> trace_secondary_fx(const CompiledScene& cs, const RayFx& ray, const std::vector<uint8_t>& flags,
                                    TiePolicy ties, bool keep_diagnostics = false);

}  // namespace csgrt
