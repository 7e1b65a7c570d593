// compile.cpp — scene compiler (see compile.h). Double precision with GLM:
// primitives become quadric half-spaces in world space, the scene is mapped
// into the fixed-point frame by one uniform scale and translation, each
// quadric is normalised (Q and kQ are the same half-space for k > 0) and then
// quantised. Anything that does not fit is a SceneError naming the object.
#include "compile.h"

#include "cull.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace csgrt {

namespace {

// Half-extent of the scene box in the normalised frame. With |origin| <= 0.5
// and t < 2 every hit point stays inside the coordinate range [-4, 4)
// (docs/numerics.md section 1).
constexpr double kSceneHalfExtent = 0.5;

// Smallest primitive dimension accepted, in units of the coordinate's last
// place: below this a primitive degenerates to a point or a film.
constexpr double kMinFeatureUlps = 4.0;

// Integer bits above the colour fraction: colours, finish coefficients and
// light intensities must stay below 2^kColorIntBits.
constexpr int kColorIntBits = 4;

std::string fmt_double(double v) {
    std::ostringstream s;
    s.precision(4);
    s << v;
    return s.str();
}

glm::dmat4 quadric_matrix(const QuadricD& q) {
    glm::dmat4 m(0.0);   // column-major: m[col][row]
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m[j][i] = q.A[j][i];
    for (int i = 0; i < 3; ++i) {
        m[3][i] = q.p[i];
        m[i][3] = q.p[i];
    }
    m[3][3] = q.q;
    return m;
}

QuadricD from_matrix(const glm::dmat4& m) {
    QuadricD q;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) q.A[j][i] = 0.5 * (m[j][i] + m[i][j]);
    for (int i = 0; i < 3; ++i) q.p[i] = 0.5 * (m[3][i] + m[i][3]);
    q.q = m[3][3];
    return q;
}

// Plane half-space n.x <= d (n need not be unit).
QuadricD plane_quadric(const glm::dvec3& n, double d) {
    QuadricD q;
    q.p = 0.5 * n;
    q.q = -d;
    return q;
}

QuadricD sphere_quadric(const glm::dvec3& c, double r) {
    QuadricD q;
    q.A = glm::dmat3(1.0);
    q.p = -c;
    q.q = glm::dot(c, c) - r * r;
    return q;
}

// Infinite cone (or cylinder when r0 == r1) around the axis through `base`
// along unit `axis`, radius r0 at base growing by `slope` per unit length:
// |x-b|^2 - s^2 - (r0 + slope*s)^2 <= 0 with s = (x-b).axis.
QuadricD cone_quadric(const glm::dvec3& base, const glm::dvec3& axis, double r0, double slope) {
    const glm::dmat3 aa = glm::outerProduct(axis, axis);
    QuadricD local;   // in coordinates relative to base: y = x - b
    local.A = glm::dmat3(1.0) - aa - slope * slope * aa;
    local.p = -r0 * slope * axis;
    local.q = -r0 * r0;
    // shift to world: y = x - b
    const glm::dmat4 shift = glm::translate(glm::dmat4(1.0), base);
    return transform_quadric(local, shift);
}

// Smallest singular value of the linear part of a transform: how much the
// transform can shrink a length.
double min_stretch(const glm::dmat4& m) {
    const glm::dmat3 l(m);
    const glm::dmat3 inv = glm::inverse(l);
    const glm::dmat3 g = glm::transpose(inv) * inv;
    glm::dvec3 v(0.577, 0.581, 0.573);
    double lambda = 1.0;
    for (int i = 0; i < 60; ++i) {
        glm::dvec3 w = g * v;
        lambda = glm::length(w);
        if (lambda == 0.0) break;
        v = w / lambda;
    }
    return lambda > 0.0 ? 1.0 / std::sqrt(lambda) : 0.0;
}

struct PendingLeaf {
    QuadricD world;
    int material;
    SourcePos pos;
    std::string what;
};

// Flattens the object tree into leaves (world-space quadrics) and a
// post-order program, and collects the scene's bounding box.
class Flattener {
  public:
    std::vector<PendingLeaf> leaves;
    std::vector<Instr> program;
    std::vector<MaterialInfo> materials{MaterialInfo{}};   // 0: air
    glm::dvec3 box_min{std::numeric_limits<double>::infinity()};
    glm::dvec3 box_max{-std::numeric_limits<double>::infinity()};
    std::vector<std::pair<const Object*, glm::dmat4>> finite;   // for the resolution check
    std::vector<CullPrimitive> prims;   // finite primitives, for the culling boxes (cull.h)
    int max_leaves = kMaxLeaves;

    void add_point(const glm::dvec3& p) {
        box_min = glm::min(box_min, p);
        box_max = glm::max(box_max, p);
    }

    void object(const Object& o, const glm::dmat4& parent, const Pigment& pig, const Finish& fin,
                const Interior& inter) {
        const glm::dmat4 m = parent * o.transform;
        const Pigment p = o.pigment ? *o.pigment : pig;
        const Finish f = o.finish ? *o.finish : fin;
        const Interior in = o.interior ? *o.interior : inter;
        if (o.is_csg) {
            if (o.children.empty()) throw SceneError(o.pos, "empty " + o.keyword);
            const Op op = o.op == CsgOp::Difference     ? Op::SUB
                          : o.op == CsgOp::Intersection ? Op::AND
                                                        : Op::ADD;
            for (size_t i = 0; i < o.children.size(); ++i) {
                object(o.children[i], m, p, f, in);
                if (i > 0) program.push_back({op, 0});
            }
            return;
        }
        primitive(o, m, material_index(o, p, f, in));
    }

  private:
    int material_index(const Object& o, const Pigment& p, const Finish& f, const Interior& in) {
        for (size_t i = 1; i < materials.size(); ++i) {
            const MaterialInfo& m = materials[i];
            if (m.pigment.rgb == p.rgb && m.pigment.filter == p.filter && m.finish.ambient == f.ambient &&
                m.finish.diffuse == f.diffuse && m.finish.phong == f.phong &&
                m.finish.phong_size == f.phong_size && m.finish.reflection == f.reflection &&
                m.interior.ior == in.ior)
                return int(i);
        }
        if (int(materials.size()) > kMaxMaterials)
            throw SceneError(o.pos, o.keyword + ": the scene has more than " + std::to_string(kMaxMaterials) +
                                        " distinct materials, the hardware limit (MAX_MATERIALS)");
        MaterialInfo mi;
        mi.pigment = p;
        mi.finish = f;
        mi.interior = in;
        materials.push_back(mi);
        return int(materials.size()) - 1;
    }

    void leaf(const Object& o, const QuadricD& world, int mat, const std::string& what) {
        if (int(leaves.size()) >= max_leaves)
            throw SceneError(o.pos, o.keyword + ": the scene needs more than " + std::to_string(max_leaves) +
                                        " leaf half-spaces, the hardware limit (MAX_LEAVES = " +
                                        std::to_string(max_leaves) + ")");
        program.push_back({Op::LEAF, uint16_t(leaves.size())});
        leaves.push_back({world, mat, o.pos, what});
    }

    // Records a finite primitive whose leaves are the next ones added.
    void add_prim(CullPrimitive::Kind kind, const Object& o, const glm::dmat4& m, double r0, double r1) {
        CullPrimitive c;
        c.kind = kind;
        c.to_world = m;
        c.v0 = o.v0;
        c.v1 = o.v1;
        c.r0 = r0;
        c.r1 = r1;
        c.first_leaf = int(leaves.size());
        c.num_leaves = kind == CullPrimitive::Box ? 6 : kind == CullPrimitive::Capped ? 3 : 1;
        prims.push_back(c);
    }

    void bound(const glm::dmat4& m, const glm::dvec3& lo, const glm::dvec3& hi) {
        for (int i = 0; i < 8; ++i) {
            glm::dvec3 c((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
            add_point(glm::dvec3(m * glm::dvec4(c, 1.0)));
        }
    }

    // A capped cylinder or cone: the infinite surface AND two cap planes.
    void capped(const Object& o, const glm::dmat4& m, int mat, double r0, double r1) {
        if (o.open)
            throw SceneError(o.pos, o.keyword + " with 'open' is not a solid; csgrt renders closed " +
                                        o.keyword + "s only");
        const glm::dvec3 axis_v = o.v1 - o.v0;
        const double len = glm::length(axis_v);
        const glm::dvec3 axis = axis_v / len;
        add_prim(CullPrimitive::Capped, o, m, r0, r1);
        leaf(o, transform_quadric(cone_quadric(o.v0, axis, r0, (r1 - r0) / len), m), mat, o.keyword + " (side)");
        leaf(o, transform_quadric(plane_quadric(-axis, -glm::dot(axis, o.v0)), m), mat, o.keyword + " (base cap)");
        program.push_back({Op::AND, 0});
        leaf(o, transform_quadric(plane_quadric(axis, glm::dot(axis, o.v1)), m), mat, o.keyword + " (top cap)");
        program.push_back({Op::AND, 0});
        // bounding box of the two end discs
        const double r = std::max(r0, r1);
        glm::dvec3 ext;
        for (int i = 0; i < 3; ++i) ext[i] = r * std::sqrt(std::max(0.0, 1.0 - axis[i] * axis[i]));
        bound(m, glm::min(o.v0, o.v1) - ext, glm::max(o.v0, o.v1) + ext);
        finite.push_back({&o, m});
    }

    void primitive(const Object& o, const glm::dmat4& m, int mat) {
        switch (o.prim) {
        case PrimKind::Sphere:
            add_prim(CullPrimitive::Sphere, o, m, o.r0, o.r0);
            leaf(o, transform_quadric(sphere_quadric(o.v0, o.r0), m), mat, "sphere");
            bound(m, o.v0 - glm::dvec3(o.r0), o.v0 + glm::dvec3(o.r0));
            finite.push_back({&o, m});
            return;
        case PrimKind::Box: {
            const glm::dvec3 lo = glm::min(o.v0, o.v1), hi = glm::max(o.v0, o.v1);
            add_prim(CullPrimitive::Box, o, m, 0.0, 0.0);
            prims.back().v0 = lo;
            prims.back().v1 = hi;
            static const char* names[3] = {"x", "y", "z"};
            bool first = true;
            for (int axis = 0; axis < 3; ++axis) {
                glm::dvec3 n(0.0);
                n[axis] = 1.0;
                leaf(o, transform_quadric(plane_quadric(-n, -lo[axis]), m), mat,
                     std::string("box (face -") + names[axis] + ")");
                if (!first) program.push_back({Op::AND, 0});
                first = false;
                leaf(o, transform_quadric(plane_quadric(n, hi[axis]), m), mat,
                     std::string("box (face +") + names[axis] + ")");
                program.push_back({Op::AND, 0});
            }
            bound(m, lo, hi);
            finite.push_back({&o, m});
            return;
        }
        case PrimKind::Cylinder: capped(o, m, mat, o.r0, o.r0); return;
        case PrimKind::Cone: capped(o, m, mat, o.r0, o.r1); return;
        case PrimKind::Plane:
            leaf(o, transform_quadric(plane_quadric(o.v0, o.r0), m), mat, "plane");
            return;
        case PrimKind::Quadric: {
            const auto& c = o.coef;   // A x2 + B y2 + C z2 + D xy + E xz + F yz + G x + H y + I z + J
            QuadricD q;
            q.A[0][0] = c[0];
            q.A[1][1] = c[1];
            q.A[2][2] = c[2];
            q.A[0][1] = q.A[1][0] = 0.5 * c[3];
            q.A[0][2] = q.A[2][0] = 0.5 * c[4];
            q.A[1][2] = q.A[2][1] = 0.5 * c[5];
            q.p = 0.5 * glm::dvec3(c[6], c[7], c[8]);
            q.q = c[9];
            add_prim(CullPrimitive::Quadric, o, m, 0.0, 0.0);
            prims.back().quad = q;
            leaf(o, transform_quadric(q, m), mat, "quadric");
            return;
        }
        }
    }
};

// Smallest dimension of a finite primitive in its own space.
double feature_size(const Object& o) {
    switch (o.prim) {
    case PrimKind::Sphere: return o.r0;
    case PrimKind::Box: {
        const glm::dvec3 e = glm::abs(o.v1 - o.v0);
        return std::min(e.x, std::min(e.y, e.z));
    }
    case PrimKind::Cylinder: return std::min(o.r0, glm::length(o.v1 - o.v0));
    case PrimKind::Cone: return std::min(std::max(o.r0, o.r1), glm::length(o.v1 - o.v0));
    default: return std::numeric_limits<double>::infinity();
    }
}

// Rounds v * 2^frac to the nearest integer (ties away from zero), and checks
// that the magnitude stays below 2^(frac + int_bits).
i64 quantise(double v, int frac, int int_bits, const SourcePos& pos, const std::string& what) {
    const double scaled = std::ldexp(v, frac);
    const double limit = std::ldexp(1.0, frac + int_bits);
    if (!(std::fabs(scaled) < limit))
        throw SceneError(pos, what + " = " + fmt_double(v) + " is outside the fixed-point range (|value| < " +
                                  fmt_double(std::ldexp(1.0, int_bits)) + ")");
    return i64(std::llround(scaled));
}

std::array<i64, 3> quantise3(const glm::dvec3& v, int frac, int int_bits, const SourcePos& pos,
                             const std::string& what) {
    return {quantise(v.x, frac, int_bits, pos, what + ".x"), quantise(v.y, frac, int_bits, pos, what + ".y"),
            quantise(v.z, frac, int_bits, pos, what + ".z")};
}

}  // namespace

QuadricD transform_quadric(const QuadricD& q, const glm::dmat4& obj_to_world) {
    const glm::dmat4 inv = glm::inverse(obj_to_world);
    return from_matrix(glm::transpose(inv) * quadric_matrix(q) * inv);
}

double eval_quadric(const QuadricD& q, const glm::dvec3& x) {
    return glm::dot(x, q.A * x) + 2.0 * glm::dot(q.p, x) + q.q;
}

CompiledScene compile_scene(const Scene& scene, const CompileOptions& opt) {
    const SourcePos scene_pos{scene.file, 1, 1};
    if (opt.bits < kMinBits || opt.bits > kMaxBits)
        throw SceneError(scene_pos, "--bits " + std::to_string(opt.bits) + " is outside the supported range " +
                                        std::to_string(kMinBits) + ".." + std::to_string(kMaxBits));
    if (opt.width < 1 || opt.height < 1 || opt.width > kMaxImageDim || opt.height > kMaxImageDim)
        throw SceneError(scene_pos, "image size " + std::to_string(opt.width) + "x" + std::to_string(opt.height) +
                                        " is outside 1.." + std::to_string(kMaxImageDim) +
                                        " (MAX_IMAGE_DIM, the camera's pixel counter width)");
    if (int(scene.lights.size()) > kMaxLights)
        throw SceneError(scene.lights[kMaxLights].pos,
                         "light_source: more than " + std::to_string(kMaxLights) +
                             " lights, the hardware limit (MAX_LIGHTS)");

    CompiledScene cs;
    cs.fmt = Formats(opt.bits);
    cs.width = opt.width;
    cs.height = opt.height;
    cs.source = scene.file;
    cs.max_trace_level = scene.max_trace_level;
    const int F = cs.fmt.frac;

    // 1. Flatten the tree; the top level is an implicit union.
    Flattener fl;
    fl.max_leaves = opt.max_leaves;
    std::vector<int> leaf_object;   // LeafInfo::object
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        fl.object(scene.objects[i], glm::dmat4(1.0), Pigment{}, Finish{}, Interior{});
        leaf_object.resize(fl.leaves.size(), int(i));
        if (i > 0) fl.program.push_back({Op::ADD, 0});
    }
    // 2. The frame: camera, lights and finite primitives into a cube of half
    //    extent kSceneHalfExtent around the origin.
    fl.add_point(scene.camera.location);
    for (const Light& l : scene.lights) fl.add_point(l.location);
    const glm::dvec3 centre = 0.5 * (fl.box_min + fl.box_max);
    const glm::dvec3 half = 0.5 * (fl.box_max - fl.box_min);
    const double max_half = std::max(half.x, std::max(half.y, half.z));
    cs.centre = centre;
    cs.scale = max_half > 0.0 ? kSceneHalfExtent / max_half : 1.0;
    const glm::dmat4 to_frame = glm::scale(glm::dmat4(1.0), glm::dvec3(cs.scale)) *
                                glm::translate(glm::dmat4(1.0), -centre);
    auto frame_point = [&](const glm::dvec3& w) { return glm::dvec3(to_frame * glm::dvec4(w, 1.0)); };

    // 3. Resolution check: every finite primitive keeps a few ulps of size.
    const double ulp = std::ldexp(1.0, -F);
    for (const auto& [obj, m] : fl.finite) {
        const double size = feature_size(*obj) * min_stretch(m) * cs.scale;
        if (size < kMinFeatureUlps * ulp)
            throw SceneError(obj->pos, obj->keyword + ": its smallest dimension becomes " + fmt_double(size) +
                                           " in the normalised frame, below the " + std::to_string(opt.bits) +
                                           "-bit resolution limit of " + fmt_double(kMinFeatureUlps) +
                                           " ulp = " + fmt_double(kMinFeatureUlps * ulp) +
                                           "; use more --bits or make it larger relative to the scene");
    }

    // 4. Leaves: quadric into the frame, normalise, quantise.
    const int FC = cs.fmt.coef_frac;
    const double coef_max = std::ldexp(1.0, FC) - 1.0;   // largest coefficient magnitude, in ulps
    std::vector<double> leaf_scale;   // the normalisation divisor of each leaf (for the culling boxes)
    for (const PendingLeaf& pl : fl.leaves) {
        LeafInfo li;
        QuadricD q = transform_quadric(pl.world, to_frame);   // world -> frame
        double maxabs = std::fabs(q.q);
        for (int i = 0; i < 3; ++i) {
            maxabs = std::max(maxabs, std::fabs(q.p[i]));
            for (int j = 0; j < 3; ++j) maxabs = std::max(maxabs, std::fabs(q.A[j][i]));
        }
        if (!(maxabs > 0.0) || !std::isfinite(maxabs))
            throw SceneError(pl.pos, pl.what + ": degenerate half-space (all coefficients zero)");
        leaf_scale.push_back(maxabs);
        const double k = 1.0 / maxabs;
        q.A *= k;
        q.p *= k;
        q.q *= k;
        li.quad = q;
        const double vals[kNumCoefs] = {q.A[0][0], q.A[1][1], q.A[2][2], q.A[0][1], q.A[0][2],
                                        q.A[1][2], q.p[0],    q.p[1],    q.p[2],    q.q};
        bool any_nonconst = false;
        for (int i = 0; i < kNumCoefs; ++i) {
            li.coef[i] = i64(std::llround(vals[i] * coef_max));
            if (i != C_Q && li.coef[i] != 0) any_nonconst = true;
        }
        if (!any_nonconst)
            throw SceneError(pl.pos, pl.what + ": every non-constant coefficient rounds to zero at " +
                                         std::to_string(opt.bits) + " bits (the surface is lost); use more --bits");
        li.material = pl.material;
        li.pos = pl.pos;
        li.what = pl.what;
        li.object = leaf_object[cs.leaves.size()];
        cs.leaves.push_back(li);
        cs.leaf_material.push_back(uint8_t(pl.material));
    }
    // The balanced tree is the one model and RTL classify with.
    cs.program = balance_program(fl.program);
    cs.class_tree = ClassTree(cs.program);
    cs.stack_depth = stack_depth(cs.program);
    if (opt.cull)
        cs.cull = build_cull_bounds(cs.program, cs.leaves, fl.prims, leaf_scale, to_frame, cs.fmt);
    if (cs.stack_depth > kMaxStackDepth)
        throw SceneError(scene_pos, "the CSG tree needs a classifier stack of " + std::to_string(cs.stack_depth) +
                                        " entries, more than the limit of " + std::to_string(kMaxStackDepth) +
                                        " (MAX_STACK); nest groups less deeply");
    if (opt.tree_height > 0) {
        try {
            cs.layout = layout_tree(cs.program, opt.tree_height, int(cs.leaves.size()));
        } catch (const std::runtime_error& e) {
            throw SceneError(scene_pos, std::string(e.what()) + "; simplify the scene or raise TREE_HEIGHT");
        }
    }

    // 5. Materials.
    cs.materials = fl.materials;
    for (size_t i = 1; i < cs.materials.size(); ++i) {
        MaterialInfo& m = cs.materials[i];
        // find an object using it, for messages
        SourcePos where = scene_pos;
        for (const LeafInfo& l : cs.leaves)
            if (l.material == int(i)) { where = l.pos; break; }
        const int CF = kColorFrac, CI = kColorIntBits;
        for (int c = 0; c < 3; ++c)
            m.rgb[c] = quantise(std::max(0.0, m.pigment.rgb[c]), CF, CI, where, "pigment colour");
        m.filter = quantise(m.pigment.filter, CF, CI, where, "pigment filter");
        m.ambient = quantise(m.finish.ambient, CF, CI, where, "finish ambient");
        m.diffuse = quantise(m.finish.diffuse, CF, CI, where, "finish diffuse");
        m.phong = quantise(m.finish.phong, CF, CI, where, "finish phong");
        m.reflection = quantise(m.finish.reflection, CF, CI, where, "finish reflection");
        m.ior = quantise(m.interior.ior, CF, CI, where, "interior ior");
        if (m.interior.ior < 0.25)
            throw SceneError(where, "interior ior " + fmt_double(m.interior.ior) +
                                        " is below 0.25, the smallest index the refraction unit takes");
        // Ray weights (docs/effects.md) stay at most 1, so the RTL carries
        // them in 13 bits: reflection and filter in [0, 1], and the pigment
        // of a transparent material (its filter x pigment weighs the light
        // through it) at most 1.
        if (m.finish.reflection > 1.0)
            throw SceneError(where, "finish reflection " + fmt_double(m.finish.reflection) +
                                        " is above 1, the largest ray weight the hardware carries");
        if (m.pigment.filter > 1.0)
            throw SceneError(where, "pigment filter " + fmt_double(m.pigment.filter) +
                                        " is above 1, the largest ray weight the hardware carries");
        for (int c = 0; c < 3; ++c)
            if (m.pigment.filter > 0.0 && m.pigment.rgb[c] > 1.0)
                throw SceneError(where, "pigment colour " + fmt_double(m.pigment.rgb[c]) +
                                            " of a transparent material is above 1, the largest ray weight"
                                            " the hardware carries");
        m.phong_size = int(std::lround(m.finish.phong_size));
        if (m.phong_size < 1 || m.phong_size > 1023)
            throw SceneError(where, "finish phong_size " + fmt_double(m.finish.phong_size) +
                                        " is outside 1..1023 (it is used as an integer exponent)");
    }

    // The RTL's ray tree keeps one pending child per level: a scene that
    // reflects or refracts may not ask for more levels than it holds.
    bool spawns = false;
    for (size_t i = 1; i < cs.materials.size(); ++i)
        spawns = spawns || cs.materials[i].reflection > 0 || cs.materials[i].filter > 0;
    if (opt.tree_height > 0 && spawns && cs.max_trace_level > kRtlMaxDepth)
        throw SceneError(scene_pos, "global_settings max_trace_level " + std::to_string(cs.max_trace_level) +
                                        " is above the ray tree depth the hardware holds (MAX_DEPTH = " +
                                        std::to_string(kRtlMaxDepth) + ")");

    // 6. Lights and background.
    for (const Light& l : scene.lights) {
        LightInfo li;
        li.pos = frame_point(l.location);
        li.color = l.color;
        li.shadowless = l.shadowless;
        li.pos_fx = quantise3(li.pos, F, 3, l.pos, "light_source location");
        for (int c = 0; c < 3; ++c)
            li.color_fx[c] = quantise(std::max(0.0, l.color[c]), kColorFrac, kColorIntBits, l.pos, "light_source colour");
        cs.lights.push_back(li);
    }
    cs.background = scene.background;
    for (int c = 0; c < 3; ++c)
        cs.background_fx[c] = quantise(std::clamp(scene.background[c], 0.0, 1.0), kColorFrac, 1, scene_pos,
                                       "background colour");

    // 7. Camera: pixel (x, y) looks along base + x*dx + y*dy, the centre of
    //    the pixel as POV-Ray samples it without anti-aliasing.
    const Camera& cam = scene.camera;
    const double dlen = glm::length(cam.direction);
    if (!(dlen > 0.0)) throw SceneError(cam.pos, "camera: zero direction");
    const glm::dvec3 D = cam.direction / dlen, R = cam.right / dlen, U = cam.up / dlen;
    CameraInfo& ci = cs.camera;
    ci.origin = frame_point(cam.location);
    ci.dx = R / double(opt.width);
    ci.dy = -U / double(opt.height);
    ci.base = D - 0.5 * R + 0.5 * U + 0.5 * ci.dx + 0.5 * ci.dy;
    ci.origin_fx = quantise3(ci.origin, F, 3, cam.pos, "camera location");
    // |base|, |R|, |U| below 4 keep every pixel's direction below 8 per axis.
    ci.base_fx = quantise3(ci.base, cs.fmt.cam_frac, 2, cam.pos,
                           "camera corner direction (field of view too wide?)");
    ci.dx_fx = quantise3(ci.dx, cs.fmt.cam_frac, 2, cam.pos, "camera right/width");
    ci.dy_fx = quantise3(ci.dy, cs.fmt.cam_frac, 2, cam.pos, "camera up/height");
    if (glm::length(R) >= 4.0 || glm::length(U) >= 4.0)
        throw SceneError(cam.pos, "camera: field of view too wide (|right| or |up| is 4 or more times "
                                  "|direction|; the fixed-point camera needs less than that)");
    return cs;
}

}  // namespace csgrt
