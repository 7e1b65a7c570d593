// epsilon.h — the conventional CSG ray tracer, in the same code base and at
// the same fixed-point width as the exact one, for side-by-side comparison
// (docs/hard-cases.md, model/stability.*).
//
// This is Roth's method as POV-Ray implements it (csg.cpp: union/merge,
// intersection and difference accept a child's intersection by point-in-solid
// tests of the *other* children at the intersection point), with POV-Ray's
// tolerances scaled from POV-Ray units (world units) to the fixed-point frame:
//
//   - roots: intersect_fx, exactly the events the exact method sees;
//   - an intersection is a candidate only when t > DEPTH_TOLERANCE (1e-4
//     world units, POV-Ray's), so secondary rays drop self-intersections
//     closer than epsilon instead of keeping logical state;
//   - candidates are visited in (t, leaf) order; at each one the hit point
//     p = o + rnd(t d) (F fraction bits, the shading point) is classified
//     against every other leaf by evaluating that leaf's quantised quadric at
//     p exactly (Q(p) <= tol * |grad Q(p)|: inside; POV-Ray's Inside_Quadric,
//     Inside_Plane, ... use tol = 0, "<= 0.0"), and the struck leaf is the
//     BORDER it crosses (entering/leaving from the root's sense);
//   - the per-leaf IN/OUT answers are combined with the paper's tables
//     (classify.h): for union, difference and intersection these accept
//     exactly what POV-Ray's merge, difference and intersection accept, and
//     they give the volume material csgrt shows, so that colours compare;
//   - the first candidate whose classification is BORDER x,y with x != y is
//     the visible surface. No per-leaf state is carried along the ray.
//
// Secondary rays (when the model has them) start at the hit point nudged by
// epsilon along the normal (nudge_origin_fx), as POV-Ray and BRL-CAD do.
#pragma once

#include "compile.h"
#include "render.h"
#include "trace.h"

#include <array>
#include <vector>

namespace csgrt {

struct EpsilonOptions {
    // POV-Ray's DEPTH_TOLERANCE (world units): intersections at t <= this
    // are dropped.
    double depth_tolerance = 1e-4;
    // Inside tests: Q(p) <= inside_tolerance * |grad Q(p)| (world units) is
    // inside. POV-Ray's inside tests are exact (0); BRL-CAD's tol.dist is
    // 5e-4 mm, for users who want to try an on-surface band.
    double inside_tolerance = 0.0;
    // Secondary-ray origin offset along the normal (world units); POV-Ray
    // uses its SMALL_TOLERANCE / depth tolerance for this.
    double nudge = 1e-4;
};

class EpsilonTracer {
  public:
    EpsilonTracer(const CompiledScene& cs, const EpsilonOptions& opt = {});
    // Primary or secondary ray: the first accepted candidate. The result's
    // flags_before/flags_after hold the inside-test answers at the hit point
    // (the leaf struck: before/after its crossing), for diagnostics only.
    TraceResult<i64> trace(const RayFx& ray, bool keep_diagnostics = false) const;
    // Exact inside test of leaf `leaf` at fixed-point point p (F bits).
    bool inside(int leaf, const std::array<i64, 3>& p) const;
    // The secondary-ray origin: hit point moved by `nudge` along +-normal
    // (far side: against the normal facing the ray, near side: along it).
    std::array<i64, 3> nudge_origin(const std::array<i64, 3>& p, const std::array<i64, 3>& unit_normal_sf,
                                    bool far_side) const;
    i64 depth_tolerance_ulps() const { return eps_t_; }

  private:
    struct Node {
        Op op = Op::LEAF;
        int left = -1, right = -1, leaf = -1, parent = -1;
    };
    Class classify_up(int hit_leaf, bool entering, const std::array<i64, 3>& p) const;
    std::vector<int> leaf_node_;
    Class eval(int node, int hit_leaf, bool entering, const std::array<i64, 3>& p) const;
    const CompiledScene& cs_;
    EpsilonOptions opt_;
    std::vector<Node> nodes_;
    int root_ = -1;
    i64 eps_t_ = 0;          // depth tolerance in ulps of t
    double inside_tol_ = 0;  // inside tolerance in frame units
    i64 nudge_ulps_ = 0;
};

// Render a frame with the epsilon method (shading: shade_fx, the exact
// method's shading of the surface found). Fixed arithmetic only.
Frame render_epsilon(const CompiledScene& cs, const RenderOptions& opt, const EpsilonOptions& eopt = {});

// One pixel, for reports and the stability suite.
PixelTrace render_pixel_epsilon(const EpsilonTracer& tracer, const CompiledScene& cs, int x, int y);

}  // namespace csgrt
