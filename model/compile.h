// compile.h — the scene compiler: parsed scene -> quadric half-spaces, a
// post-order classification program, materials, camera and lights, in two
// forms that describe the same scene:
//   - double precision, normalised into the fixed-point frame (used by the
//     double reference, --arith double), and
//   - quantised integers in the formats of docs/numerics.md (used by the
//     fixed-point model and, through the binary scene image, by the RTL).
// All floating point of csgrt's fixed path happens here, before rendering.
#pragma once

#include "classify.h"
#include "fixed.h"
#include "scene.h"
#include "tree_layout.h"

#include <glm/glm.hpp>

#include <array>
#include <string>
#include <vector>

namespace csgrt {

// Hardware limits of the default RTL configuration (csgrt_top parameters).
constexpr int kMaxLeaves = 1024;
constexpr int kMaxMaterials = 255;     // material 0 is air
constexpr int kMaxLights = 8;
constexpr int kMaxImageDim = 4096;

// Colour and shading coefficients: unsigned fixed point with kColorFrac
// fraction bits (docs/numerics.md section 6).
constexpr int kColorFrac = 12;

// Q(x) = x'Ax + 2p'x + q <= 0 is inside.
struct QuadricD {
    glm::dmat3 A{0.0};
    glm::dvec3 p{0.0};
    double q = 0.0;
};

// Coefficient order of a quantised quadric, in the scene image and the RTL.
enum CoefIndex { C_A00, C_A11, C_A22, C_A01, C_A02, C_A12, C_P0, C_P1, C_P2, C_Q, kNumCoefs };

struct LeafInfo {
    QuadricD quad;                 // normalised frame, coefficients scaled to max |c| = 1
    std::array<i64, kNumCoefs> coef{};   // quantised, coef_frac fraction bits
    int material = 1;              // 1-based; 0 is air
    SourcePos pos;                 // the primitive's source position
    std::string what;              // e.g. "box (face -x)"
    int object = 0;                // the top-level object (index into Scene::objects) it belongs to
};

struct MaterialInfo {
    Pigment pigment;
    Finish finish;
    Interior interior;
    // quantised (kColorFrac fraction bits)
    std::array<i64, 3> rgb{};
    i64 filter = 0, ambient = 0, diffuse = 0, phong = 0, reflection = 0;
    int phong_size = 40;           // rounded to an integer exponent
    i64 ior = 0;                   // kColorFrac fraction bits
};

struct LightInfo {
    glm::dvec3 pos{0.0};           // normalised frame
    glm::dvec3 color{1.0};
    std::array<i64, 3> pos_fx{};   // frac bits
    std::array<i64, 3> color_fx{}; // kColorFrac bits
    bool shadowless = false;       // casts no shadows: never a shadow ray
};

struct CameraInfo {
    // double, normalised frame; direction scaled to unit length
    glm::dvec3 origin{0.0}, base{0.0}, dx{0.0}, dy{0.0};
    // quantised: origin with frac bits, base/dx/dy with cam_frac bits
    std::array<i64, 3> origin_fx{}, base_fx{}, dx_fx{}, dy_fx{};
};

// Bounding boxes of the classification tree's subtrees, for culling
// (model/cull.h, docs/numerics.md section 9). Nodes are in
// preorder; node i's subtree is nodes [i, skip) and its leaves are
// pre_leaves[leaf_begin, leaf_end). A bounded node's box contains every
// point of the coordinate range where its subtree can be anything but OUT
// for the fixed-point tracer; cert[cert_begin, cert_end) are the leaves
// whose relaxed half-spaces that box bounds.
struct CullNode {
    enum Kind : uint8_t { UNBOUNDED = 0, BOX = 1, EMPTY = 2 };
    Kind kind = UNBOUNDED;
    bool test = false;                      // BOX worth testing (a speed choice)
    bool range = false;                     // tested, and worth a t range for its events (cull.h)
    int skip = 0;
    int leaf = -1;                          // a LEAF node's leaf
    uint32_t leaf_begin = 0, leaf_end = 0;  // its leaves in pre_leaves
    uint32_t cert_begin = 0, cert_end = 0;  // its certificate leaves in cert
    std::array<i64, 3> lo{}, hi{};          // F fraction bits, rounded outward
};
struct CullBounds {
    std::vector<CullNode> nodes;
    std::vector<uint16_t> pre_leaves;
    std::vector<uint16_t> cert;
    // per leaf: a plane (A = 0) with its quadric_at_fx in one line,
    // Q(p) = rnd(sum p_i P_i, F) + Q0 with P_i = 2 rnd(p_i, FC - F),
    // Q0 = rnd(q, FC - F): plane[l] = {P0, P1, P2, Q0}
    std::vector<uint8_t> is_plane;
    std::vector<std::array<i64, 4>> plane;
    // the nodes a ray visits (tested or EMPTY), in preorder, and for each the
    // position in this list after its subtree
    std::vector<int> visit, visit_skip;
    bool any_range = false;                // some node has a t range
    bool empty() const { return nodes.empty(); }
};

struct CompiledScene {
    Formats fmt;
    int width = 320, height = 240;
    std::string source;            // scene file name
    // world -> normalised frame: x_n = scale * (x_w - centre)
    glm::dvec3 centre{0.0};
    double scale = 1.0;
    CameraInfo camera;
    std::vector<LightInfo> lights;
    glm::dvec3 background{0.0};
    std::array<i64, 3> background_fx{};
    std::vector<MaterialInfo> materials;   // index 0 is air (unused fields)
    std::vector<LeafInfo> leaves;
    std::vector<Instr> program;
    std::vector<uint8_t> leaf_material;    // leaves[i].material, for classify()
    ClassTree class_tree;                  // the program as a tree (set with the program)
    TreeLayout layout;                     // the tree as the RTL evaluates it (when requested)
    int max_trace_level = 5;
    int stack_depth = 0;
    CullBounds cull;                       // empty: the tracer intersects every leaf
    bool identical_coefs(int leaf_a, int leaf_b) const { return leaves[leaf_a].coef == leaves[leaf_b].coef; }
};

struct CompileOptions {
    int bits = 24;
    int width = 320;
    int height = 240;
    int max_leaves = kMaxLeaves;   // the target's MAX_LEAVES
    int tree_height = 0;           // the target's TREE_HEIGHT; 0: no layout (model only)
    bool cull = true;              // bounding boxes for culling (model/cull.h); off: none
};

// Defaults of the RTL configuration (csgrt_top's parameters).
constexpr int kRtlMaxLeaves = 64;
constexpr int kRtlTreeHeight = 8;
constexpr int kRtlMaxDepth = 8;   // ray tree levels the RTL's stack holds (MAX_DEPTH)

// Throws SceneError naming the object and the limit for anything that does
// not fit: range, resolution, hardware limits.
CompiledScene compile_scene(const Scene& scene, const CompileOptions& opt);

// The quadric of one primitive half-space in world space (exposed for tests).
QuadricD transform_quadric(const QuadricD& q, const glm::dmat4& obj_to_world);
double eval_quadric(const QuadricD& q, const glm::dvec3& x);

}  // namespace csgrt
