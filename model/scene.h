// scene.h — the parsed scene: a POV-Ray-subset scene as a tree of objects in
// double precision, exactly as written (no normalisation, no quantisation).
// The parser (parse.cpp) produces it; the scene compiler (compile.cpp) turns
// it into quadric half-spaces and a post-order program.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace csgrt {

// Where a token or object was written: for error messages "file:line:col".
struct SourcePos {
    std::string file;
    int line = 0;
    int col = 0;
    std::string str() const { return file + ":" + std::to_string(line) + ":" + std::to_string(col); }
};

// Every user-facing error (parse, range, hardware limit) is a SceneError whose
// what() already reads "file:line:col: message".
struct SceneError : std::runtime_error {
    SourcePos pos;
    SceneError(const SourcePos& p, const std::string& msg)
        : std::runtime_error(p.str() + ": " + msg), pos(p) {}
};

// finish { ambient diffuse phong phong_size reflection } with POV-Ray 3.7's
// defaults.
struct Finish {
    double ambient = 0.1;
    double diffuse = 0.6;
    double phong = 0.0;
    double phong_size = 40.0;
    double reflection = 0.0;
};

// pigment { color rgb <r,g,b> } or rgbf <r,g,b,f>. POV-Ray's default pigment
// is black.
struct Pigment {
    glm::dvec3 rgb{0.0};
    double filter = 0.0;
};

// interior { ior }
struct Interior {
    double ior = 1.0;
};

enum class PrimKind { Sphere, Box, Cylinder, Cone, Plane, Quadric };
enum class CsgOp { Union, Merge, Difference, Intersection };

// One object: a primitive or a CSG group. Material parts that are not given
// are inherited from the nearest enclosing CSG group that gives them.
struct Object {
    SourcePos pos;          // position of the object's keyword
    std::string keyword;    // "sphere", "union", ... (for messages)
    bool is_csg = false;

    // Primitive parameters, in the object's own (untransformed) space:
    //   sphere   : v0 = centre, r0 = radius
    //   box      : v0, v1 = opposite corners
    //   cylinder : v0 = base, v1 = cap, r0 = radius, open
    //   cone     : v0 = base, r0 = base radius, v1 = cap, r1 = cap radius, open
    //   plane    : v0 = normal, r0 = distance (inside: dot(normal, x) < distance)
    //   quadric  : coef = A B C D E F G H I J of POV-Ray's quadric
    //              A x2 + B y2 + C z2 + D xy + E xz + F yz + G x + H y + I z + J
    //              (inside where negative)
    PrimKind prim = PrimKind::Sphere;
    glm::dvec3 v0{0.0}, v1{0.0};
    double r0 = 0.0, r1 = 0.0;
    bool open = false;
    std::array<double, 10> coef{};

    // CSG group
    CsgOp op = CsgOp::Union;
    std::vector<Object> children;

    // Object space -> world space, column-vector convention (world = M * obj),
    // accumulated from translate/rotate/scale in the order written.
    glm::dmat4 transform{1.0};

    std::optional<Pigment> pigment;
    std::optional<Finish> finish;
    std::optional<Interior> interior;
};

// camera { location look_at angle right up direction sky }, resolved the way
// POV-Ray 3.7 resolves it: the ray through normalised screen position
// (x0, y0) in [-0.5, 0.5] is direction + x0 * right + y0 * up.
struct Camera {
    SourcePos pos;
    glm::dvec3 location{0.0, 0.0, 0.0};
    glm::dvec3 direction{0.0, 0.0, 1.0};
    glm::dvec3 right{1.33, 0.0, 0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
};

struct Light {
    SourcePos pos;
    glm::dvec3 location{0.0};
    glm::dvec3 color{1.0};
    bool shadowless = false;       // POV-Ray's shadowless: no shadow rays to this light
};

struct Scene {
    std::string file;
    Camera camera;
    bool has_camera = false;
    std::vector<Light> lights;
    glm::dvec3 background{0.0};
    int max_trace_level = 5;            // POV-Ray's default
    bool has_max_trace_level = false;
    std::vector<Object> objects;        // top-level objects (an implicit union)
};

}  // namespace csgrt
