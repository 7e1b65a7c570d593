// trace.cpp — ray-quadric events and the exact walk (see trace.h and
// docs/numerics.md). The fixed-point intersection is written step by step in
// the order the RTL pipeline computes it; every rounding is rshift_round
// (round half up) or sdiv_trunc (toward zero), nothing else.
#include "trace.h"

#include "cull.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace csgrt {

namespace {

// rshift_round on either accumulator type.
template <typename W>
W rshift_round_t(W x, int k) {
    return k <= 0 ? x : (x + (W(1) << (k - 1))) >> k;
}

// floor(sqrt(n)) as isqrt_fast, on either accumulator type.
template <typename W>
W isqrt_fast_t(W n) {
    if constexpr (sizeof(W) == 8) {
        if (n <= 0) return 0;
        W r = W(__builtin_sqrt(double(n)));
        while (r * r > n) --r;
        while ((r + 1) * (r + 1) <= n) ++r;
        return r;
    } else {
        return W(isqrt_fast(u128(n)));
    }
}

// Fixed-point quotient with saturation: t = n / d (F fraction bits in n
// already), |t| < 2^(F+1) ulps, i.e. |t| < 2 in scene units. Truncation
// toward zero, as sdiv_trunc.
template <typename W>
void set_t(Event<i64>& e, W num, W den, int quot_bits) {
    const W un = num < 0 ? -num : num, ud = den < 0 ? -den : den;
    if ((un >> quot_bits) < ud) {
        const W q = un / ud;
        e.t = i64(((num < 0) != (den < 0)) ? -q : q);
        e.range = TRange::Finite;
    } else {
        e.range = ((num < 0) != (den < 0)) ? TRange::NegInf : TRange::PosInf;
        e.t = 0;
    }
}


// Two events of one leaf that landed on the same t (a tangent ray, or a
// chord thinner than one ulp of t) cross nothing: both are dropped. Their
// net effect on the leaf's flag is zero either way.
template <typename T>
void drop_equal_pair(LeafEvents<T>& le) {
    if (le.count == 2 && le.ev[0].range == le.ev[1].range &&
        (le.ev[0].range != TRange::Finite || le.ev[0].t == le.ev[1].t))
        le.count = 0;
}

}  // namespace

// The arithmetic is the same for any accumulator type W wide enough for
// the exact sums and the discriminant: i64 up to 28 bits (the widest value,
// the discriminant, needs 2B+7 bits signed), i128 above.
template <typename W>
LeafEvents<i64> intersect_impl(const Formats& fmt, const std::array<i64, kNumCoefs>& k, const RayFx& r) {
    const int F = fmt.frac;
    const int FC = fmt.coef_frac;
    LeafEvents<i64> le;

    // Stage 1: u = A d and w = A o + p (exact sums of products, FC+F fraction
    // bits), each rounded once to F fraction bits.
    const i64 A[3][3] = {{k[C_A00], k[C_A01], k[C_A02]},
                         {k[C_A01], k[C_A11], k[C_A12]},
                         {k[C_A02], k[C_A12], k[C_A22]}};
    const i64 p[3] = {k[C_P0], k[C_P1], k[C_P2]};
    i64 a, b, c;
    if (k[C_A00] == 0 && k[C_A11] == 0 && k[C_A22] == 0 && k[C_A01] == 0 && k[C_A02] == 0 && k[C_A12] == 0) {
        // A plane (A = 0), the same values with the zero products left out:
        // u = 0 and a = 0; w_i = rnd(p_i << F, FC) = rnd(p_i, FC - F) exactly
        // (the shift by F moves numerator and rounding constant alike).
        W sb = 0, sc = 0;
        for (int i = 0; i < 3; ++i) {
            const i64 w = i64(rshift_round_t<i64>(p[i], FC - F));
            sb += W(r.d[i]) * w;
            sc += W(r.o[i]) * (2 * w);
        }
        a = 0;
        b = i64(rshift_round_t<W>(sb, F));
        c = i64(rshift_round_t<W>(sc, F)) + i64(rshift_round_t<i64>(k[C_Q], FC - F));
    } else {
    i64 u[3], w[3];
    for (int i = 0; i < 3; ++i) {
        W su = 0, sw = W(p[i]) << F;
        for (int j = 0; j < 3; ++j) {
            su += W(A[i][j]) * r.d[j];
            sw += W(A[i][j]) * r.o[j];
        }
        u[i] = i64(rshift_round_t<W>(su, FC));
        w[i] = i64(rshift_round_t<W>(sw, FC));
    }

    // Stage 2: coefficients along the ray, Q(t) = a t^2 + 2 b t + c,
    //   a = d.u, b = d.w, c = o.(w + p) + q, each rounded once to F bits.
    W sa = 0, sb = 0, sc = 0;
    for (int i = 0; i < 3; ++i) {
        sa += W(r.d[i]) * u[i];
        sb += W(r.d[i]) * w[i];
        sc += W(r.o[i]) * (w[i] + i64(rshift_round_t<i64>(p[i], FC - F)));
    }
    a = i64(rshift_round_t<W>(sa, F));
    b = i64(rshift_round_t<W>(sb, F));
    c = i64(rshift_round_t<W>(sc, F)) + i64(rshift_round_t<i64>(k[C_Q], FC - F));
    }
    le.a = a;
    le.b = b;
    le.c = c;
    // the widths of the RTL's a, b, c registers (numerics.md section 3.1)
    if (a >= (i64(4) << F) || a <= -(i64(4) << F) || b >= (i64(32) << F) || b <= -(i64(32) << F) ||
        c >= (i64(256) << F) || c <= -(i64(256) << F))
        throw std::logic_error("intersect_fx: coefficient along the ray outside its bound");

    const int quot_bits = F + 1;   // |t| < 2
    if (a == 0) {
        // Linear along the ray: Q = 2 b t + c.
        if (b == 0) {
            le.inside_at_minus_inf = c <= 0;
            return le;
        }
        le.inside_at_minus_inf = b > 0;      // Q -> -inf as t -> -inf
        le.count = 1;
        le.ev[0].entering = b < 0;           // Q decreasing: entering Q <= 0
        set_t<W>(le.ev[0], -(W(c) << F), 2 * W(b), quot_bits);
        return le;
    }

    // Stage 3: discriminant, exact (2F fraction bits).
    le.inside_at_minus_inf = a < 0;
    const W disc = W(b) * b - W(a) * c;
    if (disc < 0) return le;
    const int sqrt_bits = F + 6;              // disc < 2^(2F+12): numerics.md
    if (u128(disc) >> (2 * sqrt_bits)) throw std::logic_error("intersect_fx: discriminant bound violated");
    const i64 s = i64(isqrt_fast_t<W>(disc));   // floor(sqrt), F bits (= isqrt_bitwise(disc, sqrt_bits))

    // Stage 4: roots by the stable formula qq = -(b + sgn(b) s), sgn(0) = +1:
    //   t_first = qq / a, t_second = c / qq.
    // At the root (-b - s)/a the ray enters (dQ/dt = -2s), at (-b + s)/a it
    // leaves: with b >= 0 t_first is the entering root, with b < 0 the leaving.
    const i64 qq = (b >= 0) ? -(b + s) : -(b - s);
    Event<i64>& first = le.ev[0];
    Event<i64>& second = le.ev[1];
    first.entering = (b >= 0);
    second.entering = !(b >= 0);
    set_t<W>(first, W(qq) << F, a, quot_bits);
    if (qq != 0)
        set_t<W>(second, W(c) << F, qq, quot_bits);
    else
        second.t = first.t, second.range = first.range;   // b = s = 0: c = 0, double root at 0
    le.count = 2;
    drop_equal_pair(le);
    return le;
}

LeafEvents<i64> intersect_fx(const Formats& fmt, const std::array<i64, kNumCoefs>& k, const RayFx& r) {
    return fmt.bits <= 28 ? intersect_impl<i64>(fmt, k, r) : intersect_impl<i128>(fmt, k, r);
}

LeafEvents<double> intersect_d(const QuadricD& q, const RayD& r) {
    LeafEvents<double> le;
    const glm::dvec3 o(r.o[0], r.o[1], r.o[2]), d(r.d[0], r.d[1], r.d[2]);
    const double a = glm::dot(d, q.A * d);
    const double b = glm::dot(d, q.A * o + q.p);
    const double c = glm::dot(o, q.A * o) + 2.0 * glm::dot(q.p, o) + q.q;
    le.a = a;
    le.b = b;
    le.c = c;
    auto set = [](Event<double>& e, double t) {
        e.t = t;
        e.range = (t >= 2.0) ? TRange::PosInf : (t <= -2.0) ? TRange::NegInf : TRange::Finite;
        if (!std::isfinite(t)) e.range = (t > 0) ? TRange::PosInf : TRange::NegInf;
    };
    if (a == 0.0) {
        if (b == 0.0) {
            le.inside_at_minus_inf = c <= 0.0;
            return le;
        }
        le.inside_at_minus_inf = b > 0.0;
        le.count = 1;
        le.ev[0].entering = b < 0.0;
        set(le.ev[0], -c / (2.0 * b));
        return le;
    }
    le.inside_at_minus_inf = a < 0.0;
    const double disc = b * b - a * c;
    if (disc < 0.0) return le;
    const double s = std::sqrt(disc);
    const double qq = (b >= 0.0) ? -(b + s) : -(b - s);
    le.ev[0].entering = (b >= 0.0);
    le.ev[1].entering = !(b >= 0.0);
    set(le.ev[0], qq / a);
    if (qq != 0.0)
        set(le.ev[1], c / qq);
    else
        le.ev[1].t = le.ev[0].t, le.ev[1].range = le.ev[0].range;
    le.count = 2;
    drop_equal_pair(le);
    return le;
}

template <typename T>
bool event_before(const Event<T>& x, const Event<T>& y, TiePolicy ties) {
    if (x.t != y.t) return x.t < y.t;
    if (ties == TiePolicy::Paper) return x.leaf < y.leaf;
    // regular: entering before leaving; entering in descending leaf order,
    // leaving in ascending leaf order.
    if (x.entering != y.entering) return x.entering;
    return x.entering ? x.leaf > y.leaf : x.leaf < y.leaf;
}
template bool event_before(const Event<i64>&, const Event<i64>&, TiePolicy);
template bool event_before(const Event<double>&, const Event<double>&, TiePolicy);

namespace {

// Set when a look-ahead run crosses (or skips as invalid) an event at a later
// t than its hit: a culled trace then cannot vouch for its flags and is
// traced again without culling (trace_fx).
thread_local bool t_lookahead_passed_later = false;

// The index in `crossed` of the first crossing of the hit's tie group: the
// crossings at the hit's t are the last ones in `crossed` (the hit's is the
// very last), since the sorted events at one t lie next to each other.
template <typename T>
size_t tie_group_start(const std::vector<Event<T>>& ahead, const std::vector<size_t>& crossed, T t) {
    size_t c = crossed.size() - 1;
    while (c > 0 && ahead[crossed[c - 1]].t == t) --c;
    return c;
}

// The surface a hit reports, whose normal the hit takes (docs/numerics.md
// section 5, "the hit's surface"): the hit's tie group is the run of events
// at the hit's t (the sorted list holds them next to each other); the
// surface is the first event of the group, in the sort order, whose crossing
// alone, from the flags before the group, would change the root's
// classification (BORDER x,y with x != y): that surface bounds the solid at
// the hit point. A group of one is the hit itself. Where no event of the
// group does (the ray meets an edge of the solid, where crossing either face
// alone would not enter it) the hit leaf. Without this the tie key alone
// would decide: under ties "regular" a right operand's edge plane, entered
// last, is the hit leaf at a shared face's edge, and its normal points into
// the union (docs/hard-cases.md).
// Events of dead leaves (outside their live range, cull.h) are classified
// here like any other: a culled trace then reports what the full one does
// (no culled leaf has an event at the hit's t, complete_culled()).
template <typename T>
int surface_leaf(const std::vector<Event<T>>& ahead, const std::vector<size_t>& crossed, std::vector<uint8_t>& flags,
                 ClassTree& tree, size_t hit) {
    const T t = ahead[hit].t;
    size_t g0 = hit, g1 = hit + 1;
    while (g0 > 0 && ahead[g0 - 1].t == t) --g0;
    while (g1 < ahead.size() && ahead[g1].t == t) ++g1;
    // The first event of the group was classified against the flags before
    // the group: if it is the hit, it is the surface.
    if (g0 == hit) return ahead[hit].leaf;
    // The tree (holding the flags after the hit's toggle) taken back to the
    // flags before the group, the candidates classified there, and the
    // group's crossings done again.
    const size_t c0 = tie_group_start(ahead, crossed, t);
    for (size_t k = crossed.size(); k-- > c0;) {
        const Event<T>& e = ahead[crossed[k]];
        flags[e.leaf] = !e.entering;
        tree.set_flag(e.leaf, !e.entering);
    }
    int surface = ahead[hit].leaf;
    for (size_t k = g0; k < g1; ++k) {
        const Event<T>& e = ahead[k];
        if (bool(flags[e.leaf]) == e.entering) continue;
        const Class c = tree.classify(e.leaf, e.entering);
        if (c.kind == Class::BORDER && c.from != c.to) {
            surface = e.leaf;
            break;
        }
    }
    for (size_t k = c0; k < crossed.size(); ++k) {
        const Event<T>& e = ahead[crossed[k]];
        flags[e.leaf] = e.entering;
        tree.set_flag(e.leaf, e.entering);
    }
    return surface;
}

// The walk shared by both arithmetics. `flags` holds the origin flags on
// entry; events behind the origin have already been applied (primary) or are
// ignored (secondary).
// `beyond(e, hit_t)`: does the hit point at hit_t already lie beyond the
// surface of event e (for the look-ahead).
// `live` (optional, per leaf): the t range outside which an event of the
// leaf lies outside a box that vouches its subtree OUT (cull.h): such an
// event is not classified (it cannot be a hit), only checked and toggled.
template <typename T, typename Beyond>
TraceResult<T> walk(const CompiledScene& cs, std::vector<Event<T>>& ahead, std::vector<uint8_t>& flags,
                    TiePolicy ties, bool diag, bool lookahead, Beyond beyond,
                    const std::array<i64, 2>* live = nullptr) {
    TraceResult<T> res;
    if (diag) res.origin_flags = flags;
    std::sort(ahead.begin(), ahead.end(),
              [ties](const Event<T>& x, const Event<T>& y) { return event_before(x, y, ties); });
    if (diag) res.events = ahead;
    thread_local ClassTree tree;
    if (!ahead.empty()) {
        if (tree.shape_id() != cs.class_tree.shape_id()) tree = cs.class_tree;   // same shape: reset() suffices
        tree.update(flags.data(), cs.leaf_material.data());   // = reset(), incrementally
    }
    thread_local std::vector<size_t> crossed;   // the valid events so far, in order
    crossed.clear();
    for (size_t i = 0; i < ahead.size(); ++i) {
        const Event<T>& e = ahead[i];
        // Validity check: entering while IN or leaving while OUT is impossible.
        if (bool(flags[e.leaf]) == e.entering) continue;
        // classify(cs.program, flags, ...) evaluated incrementally (ClassTree)
        const bool dead = live && (e.t < T(live[e.leaf][0]) || e.t > T(live[e.leaf][1]));
        const Class cl = dead ? Class::out() : tree.classify(e.leaf, e.entering);
        flags[e.leaf] = e.entering;
        tree.set_flag(e.leaf, e.entering);
        crossed.push_back(i);
        if (cl.kind == Class::BORDER && cl.from != cl.to) {
            res.hit = true;
            res.t = e.t;
            res.leaf = surface_leaf(ahead, crossed, flags, tree, i);
            res.cross_leaf = e.leaf;
            res.entering = e.entering;
            res.border = cl;
            res.flags_before = flags;
            res.flags_before[e.leaf] = !e.entering;
            // Look-behind, the near side's mirror of the look-ahead below:
            // crossings just before the hit that lie at the same t, or whose
            // surface the hit point does not lie beyond, have not happened
            // at the hit point; the near side (shadow and reflected rays)
            // is before them too (docs/effects.md).
            // Every crossing of the hit's tie group is undone (the flags
            // before the group: the RTL keeps them as the group starts), and
            // of the crossings before the group at most kLookBehind (the RTL
            // carries that many beside the hit).
            // (latest first, so that a leaf crossed twice in the group gets
            // its flag from before its earlier crossing)
            const size_t group = tie_group_start(ahead, crossed, e.t);   // crossed[group]: the group's first crossing
            for (size_t k = crossed.size() - 1; k-- > group;)
                res.flags_before[ahead[crossed[k]].leaf] = !ahead[crossed[k]].entering;
            const size_t oldest = group > size_t(kLookBehind) ? group - kLookBehind : 0;
            res.flags_hit_near = res.flags_before;
            for (size_t k = group; k-- > oldest;) res.near_run.push_back(ahead[crossed[k]]);
            for (const Event<T>& b : res.near_run) {
                if (!(b.t == e.t || !beyond(b, e.t))) break;
                res.flags_before[b.leaf] = !b.entering;
            }
            // Look-ahead through coincident surfaces behind a transparent
            // crossing (algorithm.md section 6).
            size_t j = i + 1;
            for (; lookahead && is_transparent(cs, res.border.to) && j < ahead.size(); ++j) {
                const Event<T>& n = ahead[j];
                // The hit point lies on the hit leaf's own surface, where the
                // sign of its Q is rounding noise: the hit leaf's own later
                // events (a sphere's far side) join the run only at the
                // same t.
                if (!(n.t == e.t || (n.leaf != e.leaf && beyond(n, e.t)))) break;
                if (n.t != e.t) t_lookahead_passed_later = true;   // for the culling's check (cull.h)
                if (bool(flags[n.leaf]) == n.entering) continue;   // invalid: skipped
                const Class c2 = tree.classify(n.leaf, n.entering);
                flags[n.leaf] = n.entering;
                tree.set_flag(n.leaf, n.entering);
                crossed.push_back(j);
                if (c2.kind == Class::BORDER && c2.from != c2.to) res.border.to = c2.to;   // BORDER a1, an
            }
            if (res.border.from == res.border.to) {
                // The run came back to where it started: the run is one
                // crossing BORDER a1, a1, discarded like any other; the walk
                // goes on after the run, whose crossings stand (each was
                // valid and is toggled). The run's events are not walked
                // again: a leaf with two events in the run (a tangent ray's
                // enter and leave at one t) would otherwise be crossed anew.
                // The walker in the RTL, which classifies the run's tokens
                // once, in order, does the same.
                res.hit = false;
                res.near_run.clear();
                i = j - 1;
                continue;
            }
            res.flags_after = flags;
            return res;
        }
    }
    return res;
}

// The candidates of one leaf: its events ahead (before t_limit) appended to
// `ahead`, and its origin flag.
template <typename T, typename Intersect>
void collect_leaf(size_t l, Intersect& isect, const std::vector<uint8_t>* inherited, T t_limit,
                  std::vector<Event<T>>& ahead, std::vector<uint8_t>& flags) {
    LeafEvents<T> le = isect(l);
    bool f = inherited ? (*inherited)[l] : le.inside_at_minus_inf;
    for (int i = 0; i < le.count; ++i) {
        Event<T> e = le.ev[i];
        e.leaf = uint16_t(l);
        if (e.ahead()) {
            if (!(t_limit > T(0)) || e.t < t_limit) ahead.push_back(e);
        }
        else if (!inherited && e.behind())
            f = !f;   // each crossing behind the origin toggles the state
    }
    flags[l] = f;
}

// `culled` (optional, one byte per leaf): leaves not intersected; their
// flags are OUT for the walk (every subtree made of them is then OUT, as it
// is at every event of the full trace: cull.h). With keep_ahead and
// keep_flags, the candidates (events and origin flags, before the walk) are
// also copied there.
template <typename T, typename Intersect, typename Beyond>
TraceResult<T> trace_generic(const CompiledScene& cs, Intersect isect, const std::vector<uint8_t>* inherited,
                             TiePolicy ties, bool diag, T t_limit, bool lookahead, Beyond beyond,
                             const uint8_t* culled = nullptr, const std::array<i64, 2>* live = nullptr,
                             std::vector<Event<T>>* keep_ahead = nullptr, std::vector<uint8_t>* keep_flags = nullptr) {
    const size_t n = cs.leaves.size();
    thread_local std::vector<uint8_t> flags;
    thread_local std::vector<Event<T>> ahead;
    flags.assign(n, 0);
    ahead.clear();
    for (size_t l = 0; l < n; ++l)
        if (!(culled && culled[l])) collect_leaf<T>(l, isect, inherited, t_limit, ahead, flags);
    if (keep_ahead) *keep_ahead = ahead, *keep_flags = flags;
    return walk<T>(cs, ahead, flags, ties, diag, lookahead, beyond, live);
}

}  // namespace

std::array<i64, 3> half_gradient_fx(const i64* k, const std::array<i64, 3>& p, int p_shift, int round) {
    const i64 A[3][3] = {{k[C_A00], k[C_A01], k[C_A02]},
                         {k[C_A01], k[C_A11], k[C_A12]},
                         {k[C_A02], k[C_A12], k[C_A22]}};
    std::array<i64, 3> g;
    for (int i = 0; i < 3; ++i) {
        i128 s = i128(k[C_P0 + i]) << p_shift;
        for (int j = 0; j < 3; ++j) s += i128(A[i][j]) * p[j];
        g[i] = i64(rshift_round(s, round));
    }
    return g;
}

void face_against(std::array<i64, 3>& n, const std::array<i64, 3>& d) {
    i128 nd = 0;
    for (int i = 0; i < 3; ++i) nd += i128(n[i]) * d[i];
    if (nd > 0)
        for (i64& v : n) v = -v;
}

i64 quadric_at_fx(const Formats& fmt, const std::array<i64, kNumCoefs>& k, const std::array<i64, 3>& o) {
    const int F = fmt.frac, FC = fmt.coef_frac;
    const std::array<i64, 3> w = half_gradient_fx(k.data(), o, F, FC);
    i128 sc = 0;
    for (int i = 0; i < 3; ++i) sc += i128(o[i]) * (w[i] + i64(rshift_round(k[C_P0 + i], FC - F)));
    return i64(rshift_round(sc, F)) + i64(rshift_round(k[C_Q], FC - F));
}

bool hit_point_fx(const Formats& fmt, const RayFx& ray, i64 t, std::array<i64, 3>& p) {
    const i64 limit = i64(4) << fmt.frac;
    bool inside = true;
    for (int i = 0; i < 3; ++i) {
        p[i] = ray.o[i] + i64(rshift_round(i128(t) * ray.d[i], fmt.frac));
        inside = inside && p[i] >= -limit && p[i] < limit;
    }
    return inside;
}

bool is_transparent(const CompiledScene& cs, int material) {
    return material == 0 || (material < int(cs.materials.size()) && cs.materials[material].filter > 0);
}

namespace {

// "The hit point already lies beyond the next surface": inside it already
// for an entering event (Q(p) <= 0), outside it already for a leaving one.
auto beyond_fx(const CompiledScene& cs, const RayFx& ray) {
    return [&cs, &ray](const Event<i64>& n, i64 hit_t) {
        std::array<i64, 3> p;
        hit_point_fx(cs.fmt, ray, hit_t, p);
        const i64 q = quadric_at_fx(cs.fmt, cs.leaves[n.leaf].coef, p);
        return n.entering ? q <= 0 : q > 0;
    };
}

auto beyond_d(const CompiledScene& cs, const RayD& ray) {
    return [&cs, &ray](const Event<double>& n, double hit_t) {
        glm::dvec3 p;
        for (int i = 0; i < 3; ++i) p[i] = ray.o[i] + hit_t * ray.d[i];
        const double q = eval_quadric(cs.leaves[n.leaf].quad, p);
        return n.entering ? q <= 0.0 : q > 0.0;
    };
}

}  // namespace

namespace {

// The fixed-point trace of every leaf that is not culled.
TraceResult<i64> trace_fx_full(const CompiledScene& cs, const RayFx& ray, const std::vector<uint8_t>* inherited,
                               TiePolicy ties, bool diag, const TraceOptions& opt, const uint8_t* culled = nullptr,
                               const std::array<i64, 2>* live = nullptr) {
    return trace_generic<i64>(
        cs, [&](size_t l) { return intersect_fx(cs.fmt, cs.leaves[l].coef, ray); }, inherited, ties, diag,
        opt.t_limit_fx, opt.lookahead, beyond_fx(cs, ray), culled, live);
}

// Completes a culled trace's result where it differs from the full trace's:
// the flags of the culled leaves at the hit. The argument is
// docs/numerics.md, section 9:
//  - the look-behind undid only crossings at the hit's t (no culled leaf has
//    an event there, so none sits among them in the full trace's order),
//  - no look-ahead run passed an event at a later t (a culled event there
//    would have stopped the full trace's run),
//  - every culled leaf's surface is clear of the hit point by
//    kCullHitMargin: its flag at the hit is its state by its own quadric,
//    the sign of Q at the hit point (for a secondary ray whose inherited
//    flag differs from that state, the leaf must have crossed between the
//    origin and the hit: its state at the origin, clear of the surface by
//    kCullOriginMargin, must be the other one).
// Culled leaves that fail the last condition go to `uncull` (traced again
// with them intersected: Done is then false); Full: trace without culling.
enum class Completion { Done, Uncull, Full };
Completion complete_culled(const CompiledScene& cs, const RayFx& ray, const std::vector<uint8_t>* inherited,
                           const std::vector<uint8_t>& culled, TraceResult<i64>& r,
                           std::vector<int>& uncull) {
    if (!r.hit || t_lookahead_passed_later) return Completion::Full;
    const auto beyond = beyond_fx(cs, ray);
    for (const Event<i64>& b : r.near_run) {   // the prefix walk() undid
        if (!(b.t == r.t || !beyond(b, r.t))) break;
        if (b.t != r.t) return Completion::Full;
    }
    std::array<i64, 3> p;
    if (!hit_point_fx(cs.fmt, ray, r.t, p)) return Completion::Full;
    uncull.clear();
    for (size_t l = 0; l < culled.size(); ++l) {
        if (!culled[l]) continue;
        const i64 q = leaf_q(cs, int(l), p);
        if (q >= -kCullHitMargin && q <= kCullHitMargin) {
            uncull.push_back(int(l));
            continue;
        }
        const uint8_t state = q < 0;
        if (inherited && (*inherited)[l] != state) {
            const i64 q0 = leaf_q(cs, int(l), ray.o);
            // the same state at both ends: crossed twice or never
            if ((q0 >= -kCullOriginMargin && q0 <= kCullOriginMargin) || uint8_t(q0 < 0) == state) {
                uncull.push_back(int(l));
                continue;
            }
        }
        if (uncull.empty()) r.flags_before[l] = r.flags_after[l] = r.flags_hit_near[l] = state;
    }
    return uncull.empty() ? Completion::Done : Completion::Uncull;
}

// The margins of the culling argument assume a ray as the renderer makes
// them: origin inside the coordinate range [-4, 4), |d| <= 1.
bool cullable(const Formats& fmt, const RayFx& ray) {
    const i64 lim = i64(4) << fmt.frac;
    i128 d2 = 0;
    for (int i = 0; i < 3; ++i) {
        if (ray.o[i] < -lim || ray.o[i] >= lim) return false;
        d2 += i128(ray.d[i]) * ray.d[i];
    }
    return d2 <= i128(1) << (2 * fmt.frac);
}

// The fixed-point trace, culled when the scene has boxes (cull.h): a leaf of
// a subtree that is OUT along the whole segment is not intersected; if some
// culled leaf's flag at the hit cannot be vouched for, the ray is traced
// again with those leaves intersected (the rest of their subtrees still
// culled: forcing a leaf OUT keeps every certificate), and in the rare
// cases the completion does not cover, without culling.
TraceResult<i64> trace_fx(const CompiledScene& cs, const RayFx& ray, const std::vector<uint8_t>* inherited,
                          TiePolicy ties, bool diag, const TraceOptions& opt) {
    if (!opt.cull || diag || cs.cull.empty() || !cullable(cs.fmt, ray))
        return trace_fx_full(cs, ray, inherited, ties, diag, opt);
    thread_local std::vector<uint8_t> culled;
    thread_local std::vector<int> uncull;
    const i64 t_end = opt.t_limit_fx > 0 ? std::min(opt.t_limit_fx, cs.fmt.t_limit()) : cs.fmt.t_limit();
    thread_local std::vector<std::array<i64, 2>> live;
    const int n_culled = select_culled(cs, ray, t_end, inherited, culled, &live);
    const std::array<i64, 2>* lv = cs.cull.any_range ? live.data() : nullptr;
    if (n_culled == 0) return trace_fx_full(cs, ray, inherited, ties, diag, opt, nullptr, lv);
    // the first trace leaves its candidates here; a second one adds the
    // events of the leaves it intersects after all
    thread_local std::vector<Event<i64>> ahead0, ahead;
    thread_local std::vector<uint8_t> flags0, flags;
    auto isect = [&](size_t l) { return intersect_fx(cs.fmt, cs.leaves[l].coef, ray); };
    for (int pass = 0; pass < 2; ++pass) {
        t_lookahead_passed_later = false;
        TraceResult<i64> r;
        if (pass == 0) {
            r = trace_generic<i64>(cs, isect, inherited, ties, diag, opt.t_limit_fx, opt.lookahead, beyond_fx(cs, ray),
                                   culled.data(), lv, &ahead0, &flags0);
        } else {
            for (int l : uncull) collect_leaf<i64>(size_t(l), isect, inherited, opt.t_limit_fx, ahead0, flags0);
            ahead = ahead0;
            flags = flags0;
            r = walk<i64>(cs, ahead, flags, ties, diag, opt.lookahead, beyond_fx(cs, ray), lv);
        }
        if (r.flags_before.empty()) return r;   // no crossing was ever a hit candidate
        const Completion c = complete_culled(cs, ray, inherited, culled, r, uncull);
        if (c == Completion::Done) return r;
        if (c == Completion::Full) break;
        for (int l : uncull) culled[l] = 0;
        if (pass == 0) count_cull_retrace();
    }
    count_cull_fallback();
    return trace_fx_full(cs, ray, inherited, ties, diag, opt);
}

}  // namespace

TraceResult<i64> trace_primary_fx(const CompiledScene& cs, const RayFx& ray, TiePolicy ties, bool diag,
                                  const TraceOptions& opt) {
    return trace_fx(cs, ray, nullptr, ties, diag, opt);
}

TraceResult<double> trace_primary_d(const CompiledScene& cs, const RayD& ray, TiePolicy ties, bool diag,
                                    const TraceOptions& opt) {
    return trace_generic<double>(
        cs, [&](size_t l) { return intersect_d(cs.leaves[l].quad, ray); }, nullptr, ties, diag, opt.t_limit_d,
        opt.lookahead, beyond_d(cs, ray));
}

TraceResult<i64> trace_secondary_fx(const CompiledScene& cs, const RayFx& ray, const std::vector<uint8_t>& flags,
                                    TiePolicy ties, bool diag, const TraceOptions& opt) {
    return trace_fx(cs, ray, &flags, ties, diag, opt);
}

TraceResult<double> trace_secondary_d(const CompiledScene& cs, const RayD& ray, const std::vector<uint8_t>& flags,
                                      TiePolicy ties, bool diag, const TraceOptions& opt) {
    return trace_generic<double>(
        cs, [&](size_t l) { return intersect_d(cs.leaves[l].quad, ray); }, &flags, ties, diag, opt.t_limit_d,
        opt.lookahead, beyond_d(cs, ray));
}

}  // namespace csgrt
