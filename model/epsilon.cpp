// epsilon.cpp — the conventional (Roth / POV-Ray) CSG tracer at fixed
// point, see epsilon.h.
#include "epsilon.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <thread>

namespace csgrt {

EpsilonTracer::EpsilonTracer(const CompiledScene& cs, const EpsilonOptions& opt) : cs_(cs), opt_(opt) {
    // the post-order program as a tree
    std::vector<int> stack;
    for (const Instr& in : cs.program) {
        Node n;
        n.op = in.op;
        if (in.op == Op::LEAF) {
            n.leaf = in.arg;
        } else {
            if (stack.size() < 2) throw std::logic_error("EpsilonTracer: malformed program");
            n.right = stack.back();
            stack.pop_back();
            n.left = stack.back();
            stack.pop_back();
            nodes_[n.left].parent = nodes_[n.right].parent = int(nodes_.size());
        }
        nodes_.push_back(n);
        stack.push_back(int(nodes_.size()) - 1);
    }
    if (stack.size() != 1) throw std::logic_error("EpsilonTracer: malformed program");
    root_ = stack.back();
    leaf_node_.assign(cs.leaves.size(), -1);
    for (size_t i = 0; i < nodes_.size(); ++i)
        if (nodes_[i].op == Op::LEAF) leaf_node_[nodes_[i].leaf] = int(i);
    // world units -> frame units (x_n = scale * x_w) -> ulps (F fraction bits)
    const double one = double(i64(1) << cs.fmt.frac);
    eps_t_ = i64(std::llround(opt.depth_tolerance * cs.scale * one));
    inside_tol_ = opt.inside_tolerance * cs.scale;
    nudge_ulps_ = std::max<i64>(1, i64(std::llround(opt.nudge * cs.scale * one)));
}

bool EpsilonTracer::inside(int leaf, const std::array<i64, 3>& p) const {
    // Q(p) = p'Ap + 2 k_p.p + q, exact: 2F + FC fraction bits.
    const auto& k = cs_.leaves[leaf].coef;
    const int F = cs_.fmt.frac;
    const i128 x = p[0], y = p[1], z = p[2];
    i128 quad = i128(k[C_A00]) * x * x + i128(k[C_A11]) * y * y + i128(k[C_A22]) * z * z +
                2 * (i128(k[C_A01]) * x * y + i128(k[C_A02]) * x * z + i128(k[C_A12]) * y * z);
    i128 lin = 2 * (i128(k[C_P0]) * x + i128(k[C_P1]) * y + i128(k[C_P2]) * z);
    const i128 q = quad + (lin << F) + (i128(k[C_Q]) << (2 * F));
    if (inside_tol_ <= 0.0) return q <= 0;   // POV-Ray: Inside_Quadric "<= 0.0"
    // with a band: Q(p) <= tol * |grad Q(p)|, in doubles (the value is exact)
    const double s = std::ldexp(1.0, -(2 * F + cs_.fmt.coef_frac));
    const double qd = double(q) * s;
    const double FCs = std::ldexp(1.0, -cs_.fmt.coef_frac), Fs = std::ldexp(1.0, -F);
    const double px = double(p[0]) * Fs, py = double(p[1]) * Fs, pz = double(p[2]) * Fs;
    const double gx = 2 * (k[C_A00] * px + k[C_A01] * py + k[C_A02] * pz + k[C_P0]) * FCs;
    const double gy = 2 * (k[C_A01] * px + k[C_A11] * py + k[C_A12] * pz + k[C_P1]) * FCs;
    const double gz = 2 * (k[C_A02] * px + k[C_A12] * py + k[C_A22] * pz + k[C_P2]) * FCs;
    return qd <= inside_tol_ * std::sqrt(gx * gx + gy * gy + gz * gz);
}

// Classification of the candidate point against subtree `node`, evaluating
// only the leaves the tables need (POV-Ray stops its Inside loops early
// too). Short cuts follow the tables: l ++ (IN r) = IN r, (OUT) - r = OUT,
// l - (IN r) = OUT, (OUT) & r = OUT, l & OUT = OUT, whatever the other side.
Class EpsilonTracer::eval(int ni, int hit, bool entering, const std::array<i64, 3>& p) const {
    const Node& n = nodes_[ni];
    switch (n.op) {
        case Op::LEAF: {
            const uint8_t m = cs_.leaf_material[n.leaf];
            if (n.leaf == hit) return entering ? Class::border(0, m) : Class::border(m, 0);
            return inside(n.leaf, p) ? Class::in(m) : Class::out();
        }
        case Op::ADD: {
            const Class r = eval(n.right, hit, entering, p);
            if (r.kind == Class::IN) return r;
            return table_add(eval(n.left, hit, entering, p), r);
        }
        case Op::SUB: {
            const Class l = eval(n.left, hit, entering, p);
            if (l.kind == Class::OUT) return l;
            return table_sub(l, eval(n.right, hit, entering, p));
        }
        case Op::AND: {
            const Class l = eval(n.left, hit, entering, p);
            if (l.kind == Class::OUT) return l;
            const Class r = eval(n.right, hit, entering, p);
            return table_and(l, r);
        }
    }
    return Class::out();
}

// The same classification bottom-up from the struck leaf: each ancestor
// combines the path's value with its other child's (steady) value. Only a
// BORDER operand gives a BORDER, so once the path value is IN or OUT the
// candidate is rejected without looking further up (the box's other faces
// reject a hit on its face plane, as POV-Ray's box intersection would).
Class EpsilonTracer::classify_up(int hit, bool entering, const std::array<i64, 3>& p) const {
    const uint8_t m = cs_.leaf_material[hit];
    Class v = entering ? Class::border(0, m) : Class::border(m, 0);
    for (int cur = leaf_node_[hit]; nodes_[cur].parent >= 0;) {
        const int par = nodes_[cur].parent;
        const Node& pn = nodes_[par];
        const bool is_left = pn.left == cur;
        const Class sib = eval(is_left ? pn.right : pn.left, -1, false, p);
        v = is_left ? combine(pn.op, v, sib) : combine(pn.op, sib, v);
        if (v.kind != Class::BORDER) return v;
        cur = par;
    }
    return v;
}

TraceResult<i64> EpsilonTracer::trace(const RayFx& ray, bool diag) const {
    const int F = cs_.fmt.frac;
    TraceResult<i64> res;
    std::vector<Event<i64>> cand;
    cand.reserve(2 * cs_.leaves.size());
    for (size_t l = 0; l < cs_.leaves.size(); ++l) {
        const LeafEvents<i64> le = intersect_fx(cs_.fmt, cs_.leaves[l].coef, ray);
        for (int i = 0; i < le.count; ++i) {
            Event<i64> e = le.ev[i];
            e.leaf = uint16_t(l);
            // POV-Ray: Depth > DEPTH_TOLERANCE (and below the horizon)
            if (e.range == TRange::Finite && e.t > eps_t_) cand.push_back(e);
        }
    }
    std::sort(cand.begin(), cand.end(), [](const Event<i64>& a, const Event<i64>& b) {
        return a.t != b.t ? a.t < b.t : a.leaf < b.leaf;
    });
    if (diag) res.events = cand;
    for (const Event<i64>& e : cand) {
        std::array<i64, 3> p;
        for (int i = 0; i < 3; ++i) p[i] = ray.o[i] + i64(rshift_round(i128(e.t) * ray.d[i], F));
        const Class cl = classify_up(e.leaf, e.entering, p);
        if (cl.kind == Class::BORDER && cl.from != cl.to) {
            res.hit = true;
            res.t = e.t;
            res.leaf = e.leaf;
            res.entering = e.entering;
            res.border = cl;
            if (diag) {
                res.flags_before.resize(cs_.leaves.size());
                for (size_t l = 0; l < cs_.leaves.size(); ++l) res.flags_before[l] = inside(int(l), p);
                res.flags_after = res.flags_before;
                res.flags_before[e.leaf] = !e.entering;
                res.flags_after[e.leaf] = e.entering;
            }
            return res;
        }
    }
    return res;
}

std::array<i64, 3> EpsilonTracer::nudge_origin(const std::array<i64, 3>& p, const std::array<i64, 3>& n,
                                               bool far_side) const {
    // n: unit normal facing the incoming ray, kShadeFrac fraction bits
    std::array<i64, 3> o;
    for (int i = 0; i < 3; ++i) {
        const i64 off = i64(rshift_round(i128(n[i]) * nudge_ulps_, kShadeFrac));
        o[i] = far_side ? p[i] - off : p[i] + off;
    }
    return o;
}

PixelTrace render_pixel_epsilon(const EpsilonTracer& tracer, const CompiledScene& cs, int x, int y) {
    PixelTrace pt;
    pt.ray = camera_ray_fx(cs, x, y);
    pt.trace = tracer.trace(pt.ray);
    // TODO(secondary rays): when shade_fx follows reflected, transmitted and
    // shadow rays, the epsilon method needs its own shading loop that starts
    // them at tracer.nudge_origin(...) and traces them with tracer.trace().
    const std::array<i64, 3> col = shade_fx(cs, pt.ray, pt.trace);
    for (int c = 0; c < 3; ++c) pt.rgb[c] = srgb_encode_fx(col[c]);
    return pt;
}

Frame render_epsilon(const CompiledScene& cs, const RenderOptions& opt, const EpsilonOptions& eopt) {
    if (opt.arith != Arith::Fixed) throw std::runtime_error("the epsilon method runs in fixed point only");
    const EpsilonTracer tracer(cs, eopt);
    Frame f;
    f.width = cs.width;
    f.height = cs.height;
    const size_t npix = size_t(f.width) * f.height;
    f.rgb.assign(npix * 3, 0);
    f.hit_leaf.assign(npix, -1);
    f.material.assign(npix, 0);
    std::atomic<int> next_row{0};
    auto worker = [&]() {
        for (int y; (y = next_row.fetch_add(1)) < f.height;)
            for (int x = 0; x < f.width; ++x) {
                const size_t i = size_t(y) * f.width + x;
                const PixelTrace pt = render_pixel_epsilon(tracer, cs, x, y);
                for (int c = 0; c < 3; ++c) f.rgb[i * 3 + c] = pt.rgb[c];
                if (pt.trace.hit) {
                    f.hit_leaf[i] = int16_t(pt.trace.leaf);
                    f.material[i] = pt.trace.border.to ? pt.trace.border.to : pt.trace.border.from;
                }
            }
    };
    const int nthreads = opt.threads > 0 ? opt.threads : int(std::max(1u, std::thread::hardware_concurrency()));
    std::vector<std::thread> pool;
    for (int i = 1; i < nthreads; ++i) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    return f;
}

}  // namespace csgrt
