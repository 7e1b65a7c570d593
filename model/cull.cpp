// cull.cpp — the culling boxes and the per-ray choice of the leaves to skip
// (cull.h; the argument is docs/numerics.md, section 9).
#include "cull.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <mutex>

namespace csgrt {

namespace {

// ------------------------------------------------------------ statistics

std::mutex g_stats_mutex;
CullStats g_stats;   // flushed from finished threads

struct LocalStats {
    CullStats s;
    ~LocalStats() { add_cull_stats(s); }
};
thread_local LocalStats t_stats;

// ------------------------------------------------------ boxes (compile time)

struct DBox {
    CullNode::Kind kind = CullNode::UNBOUNDED;
    glm::dvec3 lo{0.0}, hi{0.0};
    std::vector<int> cert;
};

// Largest and smallest stretch of a 3x3 linear map (singular values), by
// the power method on L^T L and on its inverse.
double stretch(const glm::dmat3& l, bool largest) {
    const glm::dmat3 g = largest ? glm::transpose(l) * l : glm::inverse(glm::transpose(l) * l);
    glm::dvec3 v(0.577, 0.581, 0.573);
    double lambda = 0.0;
    for (int i = 0; i < 100; ++i) {
        const glm::dvec3 w = g * v;
        lambda = glm::length(w);
        if (!(lambda > 0.0) || !std::isfinite(lambda)) return largest ? 0.0 : std::numeric_limits<double>::infinity();
        v = w / lambda;
    }
    return largest ? std::sqrt(lambda) : 1.0 / std::sqrt(lambda);
}

// The object-space box of a primitive's relaxed region, each leaf l relaxed
// to Q_obj <= eps[l - first_leaf] (object units). False: no box.
bool object_box(const CullPrimitive& p, const double* eps, glm::dvec3& lo, glm::dvec3& hi) {
    switch (p.kind) {
    case CullPrimitive::Sphere: {
        // |y - c|^2 - r^2 <= eps
        const double r = std::sqrt(p.r0 * p.r0 + eps[0]);
        lo = p.v0 - glm::dvec3(r);
        hi = p.v0 + glm::dvec3(r);
        return true;
    }
    case CullPrimitive::Box: {
        // face -a: lo_a - y_a <= eps; face +a: y_a - hi_a <= eps
        for (int a = 0; a < 3; ++a) {
            lo[a] = p.v0[a] - eps[2 * a];
            hi[a] = p.v1[a] + eps[2 * a + 1];
        }
        return true;
    }
    case CullPrimitive::Capped: {
        // s = (y - v0).axis; base cap -s <= eps_b, top cap s - len <= eps_t,
        // side |y_perp|^2 - (r0 + slope s)^2 <= eps_s
        const glm::dvec3 axis_v = p.v1 - p.v0;
        const double len = glm::length(axis_v);
        if (!(len > 0.0)) return false;
        const glm::dvec3 axis = axis_v / len;
        const double slope = (p.r1 - p.r0) / len;
        const double s0 = -eps[1], s1 = len + eps[2];
        const double q0 = p.r0 + slope * s0, q1 = p.r0 + slope * s1;
        // (r0 + slope s)^2 is convex in s: its largest value is at an end
        const double R = std::sqrt(std::max(q0 * q0, q1 * q1) + eps[0]);
        for (int i = 0; i < 3; ++i) {
            const double c0 = p.v0[i] + s0 * axis[i], c1 = p.v0[i] + s1 * axis[i];
            const double ext = R * std::sqrt(std::max(0.0, 1.0 - axis[i] * axis[i]));
            lo[i] = std::min(c0, c1) - ext;
            hi[i] = std::max(c0, c1) + ext;
        }
        return true;
    }
    case CullPrimitive::Quadric: {
        // y'Ay + 2p'y + q <= eps with A positive definite: an ellipsoid
        // (y - y0)'A(y - y0) <= rho, y0 = -A^-1 p, rho = eps - q + p'A^-1 p,
        // half-extent sqrt(rho (A^-1)_ii) per axis.
        const glm::dmat3& A = p.quad.A;
        double scale = 0.0;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) scale = std::max(scale, std::fabs(A[j][i]));
        if (!(scale > 0.0)) return false;
        // leading principal minors, clearly positive (Sylvester)
        const double m1 = A[0][0];
        const double m2 = A[0][0] * A[1][1] - A[0][1] * A[1][0];
        const double m3 = glm::determinant(A);
        const double tiny = 1e-6;
        if (!(m1 > tiny * scale && m2 > tiny * scale * scale && m3 > tiny * scale * scale * scale)) return false;
        if (stretch(A, true) > 1e4 * stretch(A, false)) return false;
        const glm::dmat3 inv = glm::inverse(A);
        const glm::dvec3 y0 = -(inv * p.quad.p);
        const double rho = eps[0] - p.quad.q + glm::dot(p.quad.p, inv * p.quad.p);
        const double r = std::max(rho, 0.0) * (1.0 + 1e-9);
        for (int i = 0; i < 3; ++i) {
            const double h = std::sqrt(r * std::max(inv[i][i], 0.0)) * (1.0 + 1e-9);
            lo[i] = y0[i] - h;
            hi[i] = y0[i] + h;
        }
        return true;
    }
    }
    return false;
}

struct TNode {
    Op op;
    int leaf = -1, l = -1, r = -1;
};

void conjuncts(const std::vector<TNode>& t, int i, std::vector<int>& out) {
    if (t[i].op == Op::AND) {
        conjuncts(t, t[i].l, out);
        conjuncts(t, t[i].r, out);
    } else if (t[i].op == Op::SUB) {
        conjuncts(t, t[i].l, out);   // l - r lies inside l
    } else {
        out.push_back(i);
    }
}

}  // namespace

CullBounds build_cull_bounds(const std::vector<Instr>& program, const std::vector<LeafInfo>& leaves,
                             const std::vector<CullPrimitive>& prims, const std::vector<double>& leaf_scale,
                             const glm::dmat4& world_to_frame, const Formats& fmt) {
    CullBounds cb;
    if (program.empty()) return cb;
    const int num_leaves = int(leaves.size());
    const int F = fmt.frac;
    const double u = std::ldexp(1.0, -F);

    cb.is_plane.assign(num_leaves, 0);
    cb.plane.assign(num_leaves, {0, 0, 0, 0});
    for (int l = 0; l < num_leaves; ++l) {
        const auto& k = leaves[l].coef;
        if (k[C_A00] || k[C_A11] || k[C_A22] || k[C_A01] || k[C_A02] || k[C_A12]) continue;
        const int sh = fmt.coef_frac - F;
        auto rnd = [sh](i64 x) { return (x + (i64(1) << (sh - 1))) >> sh; };
        cb.is_plane[l] = 1;
        cb.plane[l] = {2 * rnd(k[C_P0]), 2 * rnd(k[C_P1]), 2 * rnd(k[C_P2]), rnd(k[C_Q])};
    }

    // 1. Frame boxes of the primitives.
    std::vector<int> leaf_prim(num_leaves, -1);
    std::vector<DBox> prim_box(prims.size());
    for (size_t k = 0; k < prims.size(); ++k) {
        const CullPrimitive& p = prims[k];
        for (int j = 0; j < p.num_leaves; ++j) leaf_prim[p.first_leaf + j] = int(k);
        const glm::dmat3 lin(p.to_world);
        const double smax = stretch(lin, true), smin = stretch(lin, false);
        if (!(smin > 0.0) || !(smax <= kCullMaxCondition * smin)) continue;
        double eps[6];
        for (int j = 0; j < p.num_leaves; ++j) eps[j] = kCullBoxEta * u * leaf_scale[p.first_leaf + j];
        glm::dvec3 olo, ohi;
        if (!object_box(p, eps, olo, ohi)) continue;
        const glm::dmat4 T = world_to_frame * p.to_world;
        glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
        for (int c = 0; c < 8; ++c) {
            const glm::dvec3 y((c & 1) ? ohi.x : olo.x, (c & 2) ? ohi.y : olo.y, (c & 4) ? ohi.z : olo.z);
            const glm::dvec3 x(T * glm::dvec4(y, 1.0));
            lo = glm::min(lo, x);
            hi = glm::max(hi, x);
        }
        bool finite = true;
        for (int i = 0; i < 3; ++i) {
            // outward, far above the double rounding of the corners
            const double slack = 4.0 * u + 1e-9 * (1.0 + std::max(std::fabs(lo[i]), std::fabs(hi[i])));
            lo[i] -= slack;
            hi[i] += slack;
            finite = finite && std::isfinite(lo[i]) && std::isfinite(hi[i]);
        }
        if (!finite) continue;
        prim_box[k].kind = CullNode::BOX;
        prim_box[k].lo = lo;
        prim_box[k].hi = hi;
        for (int j = 0; j < p.num_leaves; ++j) prim_box[k].cert.push_back(p.first_leaf + j);
    }

    // 2. The tree (post-order program) and a box per node.
    std::vector<TNode> t;
    std::vector<int> st;
    for (const Instr& ins : program) {
        TNode n;
        n.op = ins.op;
        if (ins.op == Op::LEAF) {
            n.leaf = ins.arg;
        } else {
            n.r = st.back();
            st.pop_back();
            n.l = st.back();
            st.pop_back();
        }
        st.push_back(int(t.size()));
        t.push_back(n);
    }
    const int root = st.back();
    std::vector<DBox> box(t.size());
    auto merge_cert = [](std::vector<int>& into, const std::vector<int>& from) {
        into.insert(into.end(), from.begin(), from.end());
        std::sort(into.begin(), into.end());
        into.erase(std::unique(into.begin(), into.end()), into.end());
    };
    for (size_t i = 0; i < t.size(); ++i) {   // children precede parents
        const TNode& n = t[i];
        DBox& b = box[i];
        if (n.op == Op::LEAF) {
            const int k = leaf_prim[n.leaf];
            if (k >= 0 && prims[k].num_leaves == 1) b = prim_box[k];
        } else if (n.op == Op::ADD) {
            // l ++ r is OUT where both are
            const DBox &L = box[n.l], &R = box[n.r];
            if (L.kind == CullNode::UNBOUNDED || R.kind == CullNode::UNBOUNDED) continue;
            b.cert = L.cert;
            merge_cert(b.cert, R.cert);
            if (L.kind == CullNode::EMPTY && R.kind == CullNode::EMPTY) {
                b.kind = CullNode::EMPTY;
            } else if (L.kind == CullNode::EMPTY || R.kind == CullNode::EMPTY) {
                const DBox& B = L.kind == CullNode::EMPTY ? R : L;
                b.kind = CullNode::BOX, b.lo = B.lo, b.hi = B.hi;
            } else {
                b.kind = CullNode::BOX, b.lo = glm::min(L.lo, R.lo), b.hi = glm::max(L.hi, R.hi);
            }
        } else {
            // AND / SUB: OUT wherever one conjunct is OUT; a primitive whose
            // leaves are all conjuncts is OUT outside its box
            std::vector<int> items;
            conjuncts(t, int(i), items);
            std::vector<int> count(prims.size(), 0);
            std::vector<const DBox*> used;
            for (int it : items) {
                if (t[it].op == Op::LEAF) {
                    const int k = leaf_prim[t[it].leaf];
                    if (k >= 0 && ++count[k] == prims[k].num_leaves && prim_box[k].kind != CullNode::UNBOUNDED)
                        used.push_back(&prim_box[k]);
                } else if (box[it].kind != CullNode::UNBOUNDED) {
                    used.push_back(&box[it]);
                }
            }
            if (used.empty()) continue;
            b.kind = CullNode::BOX;
            b.lo = glm::dvec3(-std::numeric_limits<double>::infinity());
            b.hi = glm::dvec3(std::numeric_limits<double>::infinity());
            for (const DBox* u2 : used) {
                merge_cert(b.cert, u2->cert);
                if (u2->kind == CullNode::EMPTY) {
                    b.kind = CullNode::EMPTY;
                    continue;
                }
                b.lo = glm::max(b.lo, u2->lo);
                b.hi = glm::min(b.hi, u2->hi);
            }
            if (b.kind == CullNode::BOX && (b.lo.x > b.hi.x || b.lo.y > b.hi.y || b.lo.z > b.hi.z))
                b.kind = CullNode::EMPTY;
        }
    }

    // 3. Preorder nodes with integer boxes (outward), clamped to [-8, 8]:
    //    every point the tracer tests lies in (-6, 6)^3.
    const i64 lim = i64(8) << F;
    std::function<void(int)> emit = [&](int i) {
        const int me = int(cb.nodes.size());
        cb.nodes.emplace_back();
        {
            CullNode& cn = cb.nodes[me];
            const DBox& b = box[i];
            cn.kind = b.kind;
            if (b.kind == CullNode::BOX) {
                for (int a = 0; a < 3; ++a) {
                    const double l = std::floor(std::ldexp(b.lo[a], F)), h = std::ceil(std::ldexp(b.hi[a], F));
                    cn.lo[a] = l < double(-lim) ? -lim : l > double(lim) ? lim : i64(l);
                    cn.hi[a] = h > double(lim) ? lim : h < double(-lim) ? -lim : i64(h);
                    if (l > double(lim) || h < double(-lim)) cn.kind = CullNode::EMPTY;
                }
            }
            cn.cert_begin = uint32_t(cb.cert.size());
            for (int l : b.cert) cb.cert.push_back(uint16_t(l));
            cn.cert_end = uint32_t(cb.cert.size());
            cn.leaf_begin = uint32_t(cb.pre_leaves.size());
            if (t[i].op == Op::LEAF) {
                cn.leaf = t[i].leaf;
                cb.pre_leaves.push_back(uint16_t(t[i].leaf));
            }
        }
        if (t[i].op != Op::LEAF) {
            emit(t[i].l);
            emit(t[i].r);
        }
        cb.nodes[me].skip = int(cb.nodes.size());
        cb.nodes[me].leaf_end = uint32_t(cb.pre_leaves.size());
    };
    emit(root);

    // 4. Which boxes to test: a test costs about one intersection, so only
    //    boxes that can save two or more, and not one much like the box of
    //    a tested ancestor (which the ray has just met). Skipping a test
    //    only culls less.
    std::vector<int> tested_above(cb.nodes.size(), -1);
    for (size_t i = 0; i < cb.nodes.size(); ++i) {
        CullNode& n = cb.nodes[i];
        n.test = n.kind == CullNode::BOX && n.leaf_end - n.leaf_begin >= 2;
        const int a = tested_above[i];
        if (n.test && a >= 0) {
            bool similar = true;
            for (int x = 0; x < 3; ++x)
                similar = similar && double(n.hi[x] - n.lo[x]) >= 0.9 * double(cb.nodes[a].hi[x] - cb.nodes[a].lo[x]);
            n.test = !similar;
        }
        // a t range pays where many plane events lie outside the box (a
        // plane's surface leaves it) and each costs a deep classification
        int planes = 0;
        for (uint32_t k = n.leaf_begin; k < n.leaf_end; ++k) planes += cb.is_plane[cb.pre_leaves[k]];
        n.range = n.test && planes >= 12;
        // preorder: a node's descendants follow it, and each one's own
        // descendants overwrite this when the loop reaches it
        const int below = n.test ? int(i) : a;
        for (int j = int(i) + 1; j < n.skip; ++j) tested_above[j] = below;
    }
    for (size_t i = 0; i < cb.nodes.size(); ++i) {
        if (cb.nodes[i].test || cb.nodes[i].kind == CullNode::EMPTY) cb.visit.push_back(int(i));
        cb.any_range = cb.any_range || cb.nodes[i].range;
    }
    cb.visit_skip.resize(cb.visit.size());
    for (size_t k = 0; k < cb.visit.size(); ++k) {
        size_t j = k + 1;
        while (j < cb.visit.size() && cb.visit[j] < cb.nodes[cb.visit[k]].skip) ++j;
        cb.visit_skip[k] = int(j);
    }
    return cb;
}

namespace {

// The ray as the box test uses it: per axis the origin, |d| and whether d
// is negative; axes with d = 0 are tested on the origin alone.
struct SlabRay {
    i64 o[3], den[3], t_end_den[3];
    bool neg[3];
    int zero_axes = 0;   // bit i: d_i = 0
    i64 one;
    SlabRay(const RayFx& r, i64 t_end, int F) : one(i64(1) << F) {
        for (int i = 0; i < 3; ++i) {
            o[i] = r.o[i];
            neg[i] = r.d[i] < 0;
            den[i] = neg[i] ? -r.d[i] : r.d[i];
            t_end_den[i] = t_end * den[i];
            if (r.d[i] == 0) zero_axes |= 1 << i, den[i] = 1, t_end_den[i] = t_end;
        }
    }
};

// Per axis the segment is inside the slab for t in [nin/den, nout/den]; the
// box is met iff every entry is at most every exit, 0 and t_end included.
// |nin|, |nout| < 2^(F+4), den < 2^F, t_end <= 2^(F+1): every product stays
// below 2^(2F+4) <= 2^62. An axis with d = 0 is met iff the origin lies in
// its slab (nin <= 0 <= nout with den = 1 says just that).
bool slab_misses(const CullNode& nd, const SlabRay& r) {
    i64 nin[3], nout[3];
    for (int i = 0; i < 3; ++i) {
        nin[i] = r.neg[i] ? r.o[i] - nd.hi[i] : nd.lo[i] - r.o[i];
        nout[i] = r.neg[i] ? r.o[i] - nd.lo[i] : nd.hi[i] - r.o[i];
    }
    bool miss = false;
    for (int i = 0; i < 3; ++i) miss |= (nout[i] < 0) | (nin[i] * r.one > r.t_end_den[i]);
    if (r.zero_axes) {
        for (int i = 0; i < 3; ++i)
            if (r.zero_axes >> i & 1) miss |= nin[i] > 0;   // (nout < 0 is tested above)
        if (miss) return true;
        // entries and exits of the other axes against each other
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                if (i != j && !(r.zero_axes >> i & 1) && !(r.zero_axes >> j & 1))
                    miss |= nin[i] * r.den[j] > nout[j] * r.den[i];
        return miss;
    }
    miss |= nin[0] * r.den[1] > nout[1] * r.den[0];
    miss |= nin[1] * r.den[0] > nout[0] * r.den[1];
    miss |= nin[0] * r.den[2] > nout[2] * r.den[0];
    miss |= nin[2] * r.den[0] > nout[0] * r.den[2];
    miss |= nin[1] * r.den[2] > nout[2] * r.den[1];
    miss |= nin[2] * r.den[1] > nout[1] * r.den[2];
    return miss;
}

// The t range (F fraction bits, rounded outward) in which the segment is in
// the box, for a box it meets: [max entry, min exit] over the axes, 0 and
// t_end included.
std::array<i64, 2> slab_range(const CullNode& nd, const SlabRay& r, i64 t_end) {
    i64 lo = 0, hi = t_end;
    for (int i = 0; i < 3; ++i) {
        if (r.zero_axes >> i & 1) continue;
        const i64 nin = r.neg[i] ? r.o[i] - nd.hi[i] : nd.lo[i] - r.o[i];
        const i64 nout = r.neg[i] ? r.o[i] - nd.lo[i] : nd.hi[i] - r.o[i];
        // floor(nin 2^F / den) and ceil(nout 2^F / den)
        const i64 a = nin * r.one, b = nout * r.one, d = r.den[i];
        i64 fl = a / d;
        if (a % d != 0 && a < 0) --fl;
        i64 cl = b / d;
        if (b % d != 0 && b > 0) ++cl;
        lo = std::max(lo, fl);
        hi = std::min(hi, cl);
    }
    return {lo, hi};
}

}  // namespace

bool segment_misses_box(const CullNode& nd, const RayFx& r, i64 t_end, int F) {
    return slab_misses(nd, SlabRay(r, t_end, F));
}

namespace {

template <typename W>
i64 quadric_at_impl(const Formats& fmt, const std::array<i64, kNumCoefs>& k, const std::array<i64, 3>& o) {
    const int F = fmt.frac, FC = fmt.coef_frac;
    const i64 A[3][3] = {{k[C_A00], k[C_A01], k[C_A02]},
                         {k[C_A01], k[C_A11], k[C_A12]},
                         {k[C_A02], k[C_A12], k[C_A22]}};
    auto rnd = [](W x, int s) { return s <= 0 ? x : (x + (W(1) << (s - 1))) >> s; };
    W sc = 0;
    for (int i = 0; i < 3; ++i) {
        W s = W(k[C_P0 + i]) << F;
        for (int j = 0; j < 3; ++j) s += W(A[i][j]) * o[j];
        const W w = rnd(s, FC);
        sc += W(o[i]) * (w + rnd(W(k[C_P0 + i]), FC - F));
    }
    return i64(rnd(sc, F)) + i64(rnd(W(k[C_Q]), FC - F));
}

}  // namespace

i64 quadric_at_fast(const Formats& fmt, const std::array<i64, kNumCoefs>& k, const std::array<i64, 3>& p) {
    if (fmt.bits <= 28 && k[C_A00] == 0 && k[C_A11] == 0 && k[C_A22] == 0 && k[C_A01] == 0 && k[C_A02] == 0 &&
        k[C_A12] == 0) {
        // a plane: w_i = rnd(p_i << F, FC) = rnd(p_i, FC - F) exactly, so
        // c = rnd(sum o_i 2 rnd(p_i, FC - F), F) + rnd(q, FC - F)
        const int F = fmt.frac, s = fmt.coef_frac - F;
        auto rnd = [](i64 x, int k2) { return (x + (i64(1) << (k2 - 1))) >> k2; };
        i64 sc = 0;
        for (int i = 0; i < 3; ++i) sc += p[i] * (2 * rnd(k[C_P0 + i], s));
        return rnd(sc, F) + rnd(k[C_Q], s);
    }
    return fmt.bits <= 28 ? quadric_at_impl<i64>(fmt, k, p) : quadric_at_impl<i128>(fmt, k, p);
}

int select_culled(const CompiledScene& cs, const RayFx& ray, i64 t_end, const std::vector<uint8_t>* inherited,
                  std::vector<uint8_t>& culled, std::vector<std::array<i64, 2>>* live) {
    const CullBounds& cb = cs.cull;
    const size_t n = cs.leaves.size();
    culled.assign(n, 0);
    if (live && cb.any_range) live->assign(n, {INT64_MIN, INT64_MAX});
    if (!cb.any_range) live = nullptr;
    int count = 0;
    const SlabRay sr(ray, t_end, cs.fmt.frac);
    for (size_t v = 0; v < cb.visit.size();) {
        const CullNode& nd = cb.nodes[cb.visit[v]];
        const bool missed = nd.kind == CullNode::EMPTY || slab_misses(nd, sr);
        bool vouched = true;
        const bool want_range = live && nd.range;
        if (inherited && (missed || want_range)) {
            // a certificate leaf that the ray starts IN must be IN at the
            // origin by its own quadric too (not a stale flag)
            for (uint32_t c = nd.cert_begin; c < nd.cert_end && vouched; ++c) {
                const int l = cb.cert[c];
                if (!(*inherited)[l]) continue;
                vouched = leaf_q(cs, l, ray.o) < 0;
            }
        }
        const bool skip = missed && vouched;
        if (!skip && want_range && vouched) {
            const std::array<i64, 2> r = slab_range(nd, sr, t_end);
            for (uint32_t k = nd.leaf_begin; k < nd.leaf_end; ++k) (*live)[cb.pre_leaves[k]] = r;
        }
        if (skip) {
            for (uint32_t k = nd.leaf_begin; k < nd.leaf_end; ++k) culled[cb.pre_leaves[k]] = 1;
            count += int(nd.leaf_end - nd.leaf_begin);
            v = size_t(cb.visit_skip[v]);
        } else {
            ++v;
        }
    }
    CullStats& s = t_stats.s;
    ++s.rays;
    s.leaves += n;
    if (count) ++s.culled_rays, s.culled_leaves += uint64_t(count);
    return count;
}

void add_cull_stats(const CullStats& s) {
    std::lock_guard<std::mutex> lock(g_stats_mutex);
    g_stats.rays += s.rays;
    g_stats.culled_rays += s.culled_rays;
    g_stats.leaves += s.leaves;
    g_stats.culled_leaves += s.culled_leaves;
    g_stats.fallbacks += s.fallbacks;
    g_stats.retraces += s.retraces;
}

CullStats cull_stats() {
    std::lock_guard<std::mutex> lock(g_stats_mutex);
    CullStats s = g_stats;
    const CullStats& m = t_stats.s;
    s.rays += m.rays, s.culled_rays += m.culled_rays, s.leaves += m.leaves, s.culled_leaves += m.culled_leaves;
    s.fallbacks += m.fallbacks, s.retraces += m.retraces;
    return s;
}

void reset_cull_stats() {
    std::lock_guard<std::mutex> lock(g_stats_mutex);
    g_stats = CullStats{};
    t_stats.s = CullStats{};
}

// used by trace.cpp
void count_cull_fallback() { ++t_stats.s.fallbacks; }
void count_cull_retrace() { ++t_stats.s.retraces; }

}  // namespace csgrt
