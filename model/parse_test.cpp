// parse_test.cpp — googletest tests for the scene parser (parse.cpp): the AST
// each construct produces, transform order, camera resolution, #declare and
// #include, and a table of malformed inputs with the exact error position.
#include "parse.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace csgrt {
namespace {

Scene P(const std::string& text) { return parse_scene_string(text, "t.pov"); }

// The what() of the SceneError that `fn` throws ("" and a test failure if none).
template <class F>
std::string error_of(F fn) {
    try {
        fn();
    } catch (const SceneError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no SceneError thrown";
    return "";
}

glm::dvec3 apply(const glm::dmat4& m, const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }

void expect_vec(const glm::dvec3& got, const glm::dvec3& want, double tol = 1e-12) {
    EXPECT_NEAR(got.x, want.x, tol);
    EXPECT_NEAR(got.y, want.y, tol);
    EXPECT_NEAR(got.z, want.z, tol);
}

// A fresh directory under /tmp for files that #include each other.
struct TempDir {
    std::string path;
    TempDir() {
        char tmpl[] = "/tmp/parse_test_XXXXXX";
        path = mkdtemp(tmpl);
    }
    ~TempDir() { std::system(("rm -rf '" + path + "'").c_str()); }
    std::string write(const std::string& name, const std::string& text) const {
        std::string full = path + "/" + name;
        std::ofstream(full) << text;
        return full;
    }
};

// ------------------------------------------------------------- primitives

TEST(Parse, Sphere) {
    Scene s = P("sphere { <1, 2, 3>, 0.5 }");
    ASSERT_EQ(s.objects.size(), 1u);
    const Object& o = s.objects[0];
    EXPECT_FALSE(o.is_csg);
    EXPECT_EQ(o.prim, PrimKind::Sphere);
    EXPECT_EQ(o.keyword, "sphere");
    EXPECT_EQ(o.pos.str(), "t.pov:1:1");
    expect_vec(o.v0, {1, 2, 3});
    EXPECT_EQ(o.r0, 0.5);
    EXPECT_EQ(o.transform, glm::dmat4(1.0));
    EXPECT_FALSE(o.pigment || o.finish || o.interior);
    EXPECT_EQ(s.file, "t.pov");
}

TEST(Parse, BoxCylinderConePlaneQuadric) {
    Scene s = P("box { <-1,-2,-3>, <4,5,6> }\n"
                "cylinder { <0,0,0>, <0,2,0>, 0.25 open }\n"
                "cylinder { 0, x, 1 }\n"
                "cone { <0,0,0>, 1, <0,0,3>, 0 open }\n"
                "plane { y, -1 }\n"
                "quadric { <1,2,3>, <4,5,6>, <7,8,9>, -10 }\n");
    ASSERT_EQ(s.objects.size(), 6u);
    const Object& b = s.objects[0];
    EXPECT_EQ(b.prim, PrimKind::Box);
    expect_vec(b.v0, {-1, -2, -3});
    expect_vec(b.v1, {4, 5, 6});
    const Object& c = s.objects[1];
    EXPECT_EQ(c.prim, PrimKind::Cylinder);
    expect_vec(c.v1, {0, 2, 0});
    EXPECT_EQ(c.r0, 0.25);
    EXPECT_TRUE(c.open);
    EXPECT_FALSE(s.objects[2].open);
    expect_vec(s.objects[2].v1, {1, 0, 0});
    const Object& k = s.objects[3];
    EXPECT_EQ(k.prim, PrimKind::Cone);
    EXPECT_EQ(k.r0, 1.0);
    EXPECT_EQ(k.r1, 0.0);
    expect_vec(k.v1, {0, 0, 3});
    EXPECT_TRUE(k.open);
    const Object& p = s.objects[4];
    EXPECT_EQ(p.prim, PrimKind::Plane);
    expect_vec(p.v0, {0, 1, 0});
    EXPECT_EQ(p.r0, -1.0);
    const Object& q = s.objects[5];
    EXPECT_EQ(q.prim, PrimKind::Quadric);
    for (int i = 0; i < 9; ++i) EXPECT_EQ(q.coef[i], i + 1.0);
    EXPECT_EQ(q.coef[9], -10.0);
    EXPECT_EQ(q.pos.str(), "t.pov:6:1");
}

TEST(Parse, CommasAreOptionalAndFloatsPromote) {
    Scene s = P("sphere { 0 1 } cone { 0 1 y 0.5 } box { -1 1 }");
    expect_vec(s.objects[0].v0, {0, 0, 0});
    EXPECT_EQ(s.objects[1].r1, 0.5);
    expect_vec(s.objects[2].v0, {-1, -1, -1});
    expect_vec(s.objects[2].v1, {1, 1, 1});
}

TEST(Parse, Expressions) {
    Scene s = P("#declare A = 2*3+1;\n"
                "#declare V = <1,2,3>*2 - x;\n"
                "#local W = -(V + <1,1,1>) / 2;\n"
                "sphere { V, A/7 }\n"
                "sphere { W, .5 + 1e-3 }\n"
                "sphere { z*<1,2,3>, pi }\n");
    expect_vec(s.objects[0].v0, {1, 4, 6});
    EXPECT_DOUBLE_EQ(s.objects[0].r0, 1.0);
    expect_vec(s.objects[1].v0, {-1, -2.5, -3.5});
    EXPECT_DOUBLE_EQ(s.objects[1].r0, 0.501);
    expect_vec(s.objects[2].v0, {0, 0, 3});
    EXPECT_DOUBLE_EQ(s.objects[2].r0, 3.14159265358979323846);
}

TEST(Parse, CommentsAndVersion) {
    Scene s = P("#version 3.7;\n// line comment sphere { 0, 1 }\n/* block\n comment */ sphere { 0, /* inner */ 2 }");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].r0, 2.0);
    EXPECT_EQ(s.objects[0].pos.str(), "t.pov:4:13");
}

// -------------------------------------------------------------------- CSG

TEST(Parse, NestedCsg) {
    Scene s = P("difference {\n"
                "  union { sphere { 0, 1 } box { -1, 1 } pigment { rgb <1,0,0> } }\n"
                "  intersection { cylinder { 0, y, 1 } merge { sphere { 0, 2 } } }\n"
                "  translate <1,2,3>\n"
                "}\n");
    ASSERT_EQ(s.objects.size(), 1u);
    const Object& d = s.objects[0];
    EXPECT_TRUE(d.is_csg);
    EXPECT_EQ(d.op, CsgOp::Difference);
    ASSERT_EQ(d.children.size(), 2u);
    expect_vec(apply(d.transform, {0, 0, 0}), {1, 2, 3});
    const Object& u = d.children[0];
    EXPECT_EQ(u.op, CsgOp::Union);
    ASSERT_EQ(u.children.size(), 2u);
    EXPECT_EQ(u.children[1].prim, PrimKind::Box);
    ASSERT_TRUE(u.pigment);
    expect_vec(u.pigment->rgb, {1, 0, 0});
    EXPECT_FALSE(u.children[0].pigment);   // children inherit; the parser does not copy down
    EXPECT_EQ(u.children[0].transform, glm::dmat4(1.0));  // group transform stays on the group
    const Object& i = d.children[1];
    EXPECT_EQ(i.op, CsgOp::Intersection);
    EXPECT_EQ(i.children[1].op, CsgOp::Merge);
    EXPECT_EQ(i.children[1].children.size(), 1u);
    EXPECT_EQ(i.pos.str(), "t.pov:3:3");
}

// ------------------------------------------------------------- transforms

TEST(Parse, TransformsComposeInWrittenOrder) {
    Scene s = P("sphere { 0, 1 scale 2 rotate <0,0,90> translate <1,0,0> }");
    // (1,0,0) -> scale (2,0,0) -> rotate z 90 (0,2,0) -> translate (1,2,0)
    expect_vec(apply(s.objects[0].transform, {1, 0, 0}), {1, 2, 0});
    Scene t = P("sphere { 0, 1 translate <1,0,0> scale 2 }");
    expect_vec(apply(t.objects[0].transform, {0, 0, 0}), {2, 0, 0});
}

TEST(Parse, RotationFormulas) {
    auto rot = [](const std::string& r) { return P("sphere { 0, 1 rotate " + r + " }").objects[0].transform; };
    expect_vec(apply(rot("<90,0,0>"), {0, 1, 0}), {0, 0, 1}, 1e-12);   // y' = y cos - z sin, z' = y sin + z cos
    expect_vec(apply(rot("<0,90,0>"), {0, 0, 1}), {1, 0, 0}, 1e-12);   // x' = x cos + z sin
    expect_vec(apply(rot("<0,0,90>"), {1, 0, 0}), {0, 1, 0}, 1e-12);   // y' = x sin + y cos
    // x first, then y: (0,1,0) -x90-> (0,0,1) -y90-> (1,0,0)
    expect_vec(apply(rot("<90,90,0>"), {0, 1, 0}), {1, 0, 0}, 1e-12);
}

TEST(Parse, NonUniformScale) {
    Scene s = P("box { 0, 1 scale <1,2,-3> }");
    expect_vec(apply(s.objects[0].transform, {1, 1, 1}), {1, 2, -3});
}

// --------------------------------------------------------------- materials

TEST(Parse, Materials) {
    Scene s = P("sphere { 0, 1\n"
                "  pigment { color rgbf <0.1, 0.2, 0.3, 0.4> }\n"
                "  finish { ambient 0.2 phong 0.5 phong_size 20 reflection 0.3 }\n"
                "  interior { ior 1.5 }\n"
                "}\n"
                "sphere { 0, 1 pigment { rgb 0.5 } finish { diffuse 0.7 } finish { ambient 0 } }\n"
                "sphere { 0, 1 texture { pigment { colour <1, 0, 0> } finish { phong 1 } } }\n");
    const Object& a = s.objects[0];
    ASSERT_TRUE(a.pigment && a.finish && a.interior);
    expect_vec(a.pigment->rgb, {0.1, 0.2, 0.3});
    EXPECT_EQ(a.pigment->filter, 0.4);
    EXPECT_EQ(a.finish->ambient, 0.2);
    EXPECT_EQ(a.finish->diffuse, 0.6);  // default
    EXPECT_EQ(a.finish->phong, 0.5);
    EXPECT_EQ(a.finish->phong_size, 20.0);
    EXPECT_EQ(a.finish->reflection, 0.3);
    EXPECT_EQ(a.interior->ior, 1.5);
    const Object& b = s.objects[1];
    expect_vec(b.pigment->rgb, {0.5, 0.5, 0.5});
    EXPECT_EQ(b.finish->diffuse, 0.7);  // a second finish refines the first, as in POV-Ray
    EXPECT_EQ(b.finish->ambient, 0.0);
    const Object& c = s.objects[2];
    expect_vec(c.pigment->rgb, {1, 0, 0});
    EXPECT_EQ(c.finish->phong, 1.0);
    EXPECT_EQ(c.finish->ambient, 0.1);
}

// ------------------------------------------------------ #declare, object{}

TEST(Parse, DeclaredObjectInstanceWithOverride) {
    Scene s = P("#declare R = 0.5;\n"
                "#declare Ball = sphere { 0, R translate x pigment { rgb <1,0,0> } finish { phong 1 } }\n"
                "#declare Pair = union { object { Ball } object { Ball translate y } };\n"
                "object { Ball translate z pigment { rgb <0,1,0> } finish { ambient 0.3 } }\n"
                "object { Pair scale 2 }\n"
                "Ball\n");
    ASSERT_EQ(s.objects.size(), 3u);
    const Object& o = s.objects[0];
    EXPECT_EQ(o.prim, PrimKind::Sphere);
    EXPECT_EQ(o.r0, 0.5);
    expect_vec(apply(o.transform, {0, 0, 0}), {1, 0, 1});  // mods * copy.transform
    expect_vec(o.pigment->rgb, {0, 1, 0});
    EXPECT_EQ(o.finish->phong, 1.0);    // kept from the declaration
    EXPECT_EQ(o.finish->ambient, 0.3);  // given in the instance
    const Object& p = s.objects[1];
    EXPECT_TRUE(p.is_csg);
    ASSERT_EQ(p.children.size(), 2u);
    expect_vec(apply(p.transform * p.children[1].transform, {0, 0, 0}), {2, 2, 0});
    expect_vec(s.objects[2].pigment->rgb, {1, 0, 0});  // the declaration itself is unchanged
}

TEST(Parse, DeclaredValuesCanBeRedeclared) {
    Scene s = P("#declare A = 1; #declare A = A + 1; sphere { 0, A }");
    EXPECT_EQ(s.objects[0].r0, 2.0);
}

// ---------------------------------------------------------------- #include

TEST(Parse, IncludeRelativeToIncludingFile) {
    TempDir d;
    std::system(("mkdir -p '" + d.path + "/sub'").c_str());
    d.write("sub/a.inc", "#include \"b.inc\"\n#declare Big = sphere { 0, Radius * 2 }\n");
    d.write("sub/b.inc", "#declare Radius = 1.5;\n");
    std::string main = d.write("main.pov", "#include \"sub/a.inc\"\nobject { Big }\nsphere { 0, Radius }\n");
    Scene s = parse_scene_file(main);
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_EQ(s.objects[0].r0, 3.0);
    EXPECT_EQ(s.objects[0].pos.str(), d.path + "/sub/a.inc:2:16");
    EXPECT_EQ(s.objects[1].pos.str(), main + ":3:1");
    EXPECT_EQ(s.file, main);
}

TEST(Parse, StringIncludeRelativeToCwd) {
    TempDir d;
    d.write("c.inc", "sphere { 0, 4 }");
    char old[4096];
    ASSERT_NE(getcwd(old, sizeof old), nullptr);
    ASSERT_EQ(chdir(d.path.c_str()), 0);
    Scene s = P("#include \"c.inc\"");
    ASSERT_EQ(chdir(old), 0);
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].r0, 4.0);
}

// ------------------------------------------------------------------ camera

TEST(Parse, CameraDefaults) {
    Scene s = P("sphere { 0, 1 }");
    EXPECT_FALSE(s.has_camera);
    Scene c = P("camera { }");
    EXPECT_TRUE(c.has_camera);
    expect_vec(c.camera.location, {0, 0, 0});
    expect_vec(c.camera.direction, {0, 0, 1});
    expect_vec(c.camera.right, {1.33, 0, 0});
    expect_vec(c.camera.up, {0, 1, 0});
}

TEST(Parse, CameraLookAt) {
    Scene s = P("camera { location <1,2,-5> right x*4/3 up y direction 2*z look_at <0,1,0> }");
    const Camera& c = s.camera;
    glm::dvec3 want = glm::normalize(glm::dvec3(-1, -1, 5));
    expect_vec(glm::normalize(c.direction), want);
    EXPECT_NEAR(glm::length(c.direction), 2.0, 1e-12);
    EXPECT_NEAR(glm::length(c.right), 4.0 / 3.0, 1e-12);
    EXPECT_NEAR(glm::length(c.up), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(c.right, c.direction), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(c.up, c.direction), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(c.up, c.right), 0.0, 1e-12);
    EXPECT_NEAR(c.right.y, 0.0, 1e-12);  // right = cross(sky, direction) is horizontal
    EXPECT_GT(c.right.x, 0.0);           // POV-Ray's left-handed default keeps right towards +x
    EXPECT_GT(c.up.y, 0.0);
    expect_vec(c.location, {1, 2, -5});
    EXPECT_EQ(c.pos.str(), "t.pov:1:1");
}

TEST(Parse, CameraRightHandedFlipsRight) {
    Scene s = P("camera { location <0,0,-5> right -x*4/3 look_at 0 }");
    EXPECT_NEAR(s.camera.right.x, -4.0 / 3.0, 1e-12);
    expect_vec(s.camera.direction, {0, 0, 1});
}

TEST(Parse, CameraAngleAppliedAfterItemsAndBeforeLookAt) {
    // angle 90 with |right| = 1: |direction| = 0.5 / tan(45 deg) = 0.5,
    // whatever order angle, direction and look_at are written in.
    for (const char* text : {"camera { angle 90 direction 3*z right x location <0,0,-5> look_at <5,0,0> }",
                             "camera { location <0,0,-5> look_at <5,0,0> right x direction 3*z angle 90 }"}) {
        Scene s = P(text);
        EXPECT_NEAR(glm::length(s.camera.direction), 0.5, 1e-12) << text;
        expect_vec(glm::normalize(s.camera.direction), glm::normalize(glm::dvec3(5, 0, 5)));
    }
    Scene d = P("camera { angle 60 }");  // default right 1.33
    EXPECT_NEAR(glm::length(d.camera.direction), 0.5 * 1.33 / std::tan(30.0 * M_PI / 180.0), 1e-12);
}

TEST(Parse, CameraSky) {
    Scene s = P("camera { location 0 sky z look_at <0,5,0> }");
    expect_vec(s.camera.direction, {0, 1, 0});
    EXPECT_NEAR(s.camera.up.z, 1.0, 1e-12);
}

// ------------------------------------------------ lights, background, global

TEST(Parse, LightsBackgroundGlobals) {
    Scene s = P("light_source { <1,2,3> color rgb <0.5,0.25,1> }\n"
                "light_source { <0,10,0> }\n"
                "light_source { 0, rgb 2 }\n"
                "light_source { x colour <1,1,0> }\n"
                "background { color rgb <0.1,0.2,0.3> }\n"
                "global_settings { assumed_gamma 1.0 max_trace_level 12 }\n");
    ASSERT_EQ(s.lights.size(), 4u);
    expect_vec(s.lights[0].location, {1, 2, 3});
    expect_vec(s.lights[0].color, {0.5, 0.25, 1});
    expect_vec(s.lights[1].color, {1, 1, 1});
    expect_vec(s.lights[2].color, {2, 2, 2});
    expect_vec(s.lights[3].color, {1, 1, 0});
    EXPECT_EQ(s.lights[1].pos.str(), "t.pov:2:1");
    expect_vec(s.background, {0.1, 0.2, 0.3});
    EXPECT_EQ(s.max_trace_level, 12);
    EXPECT_TRUE(s.has_max_trace_level);
    Scene d = P("");
    EXPECT_EQ(d.max_trace_level, 5);
    EXPECT_FALSE(d.has_max_trace_level);
    for (const Light& l : s.lights) EXPECT_FALSE(l.shadowless);
}

TEST(Parse, ShadowlessLights) {
    // POV-Ray's keyword, before or after the colour
    Scene s = P("light_source { <1,2,3> color rgb <0.5,0.25,1> shadowless }\n"
                "light_source { <0,10,0> shadowless rgb 2 }\n"
                "light_source { <0,10,0> }\n");
    ASSERT_EQ(s.lights.size(), 3u);
    EXPECT_TRUE(s.lights[0].shadowless);
    EXPECT_TRUE(s.lights[1].shadowless);
    expect_vec(s.lights[1].color, {2, 2, 2});
    EXPECT_FALSE(s.lights[2].shadowless);
    const std::string err = error_of([] { P("light_source { <0,10,0> shadowles }"); });
    EXPECT_NE(err.find("t.pov:1:25"), std::string::npos) << err;
}

// ---------------------------------------------------------- malformed input

struct BadCase {
    const char* text;
    const char* where;    // "line:col" in t.pov, or "FILE:line:col" for an included file
    const char* message;  // substring of the message
};

const BadCase kBad[] = {
    {"torus { 1, 0.25 }", "1:1", "unsupported keyword 'torus' (csgrt supports here: sphere"},
    {"sphere { 0, 1\n  inverse\n}", "2:3", "unsupported keyword 'inverse'"},
    {"sphere { 0, 1 normal { bumps 0.5 } }", "1:15", "unsupported keyword 'normal'"},
    {"sphere { 0, 1\n", "2:1", "unexpected end of file: expected '}' to close 'sphere' opened at 1:1"},
    {"sphere { 0, 1\nsphere { 0, 2 }", "2:1", "expected '}' to close 'sphere' opened at 1:1, found 'sphere'"},
    {"camera { location 0 translate x }", "1:21", "expected '}' to close 'camera' opened at 1:1, found 'translate'"},
    {"sphere { 0, 1 }\n  /* oops\n", "2:3", "unterminated comment"},
    {"sphere { 0, 1.2.3 }", "1:13", "malformed number '1.2.3'"},
    {"sphere { 0, 1e }", "1:13", "malformed number '1e'"},
    {"sphere { <1 2 3>, 1 }", "1:13", "expected ',' or '>' in the vector opened at 1:10, found '2'"},
    {"sphere { <1,2,3, 1 }", "1:20", "expected ',' or '>'"},
    {"sphere { Centre, 1 }", "1:10", "undeclared identifier 'Centre'"},
    {"object { Foo }", "1:10", "undeclared identifier 'Foo'"},
    {"\n  #include \"nope.inc\"\n", "2:3", "cannot open include file 'nope.inc'"},
    {"#include \"@DIR@/bad.inc\"", "@DIR@/bad.inc:2:13", "sphere radius must be positive, got -1"},
    {"sphere { 0, 0 }", "1:13", "sphere radius must be positive, got 0"},
    {"cylinder { 0, y, -1 }", "1:18", "negative cylinder radius -1"},
    {"cone { 0, -1, y, 1 }", "1:11", "negative cone base radius"},
    {"cone { 0, 0, y, 0 }", "1:11", "cone radii are both zero"},
    {"cylinder { y, y, 1 }", "1:12", "zero-length axis"},
    {"plane { 0, 1 }", "1:9", "plane normal must not be zero"},
    {"sphere { 0, 1 scale <1,0,1> }", "1:21", "scale component is zero"},
    {"sphere { 0, 1 scale 0 }", "1:21", "scale component is zero"},
    {"camera { location -z look_at 0 }\ncamera { }", "2:1", "duplicate camera (the first is at t.pov:1:1)"},
    {"global_settings { assumed_gamma 2.2 }", "1:33", "assumed_gamma must be 1.0"},
    {"global_settings { max_trace_level 2.5 }", "1:35", "max_trace_level must be a positive integer"},
    {"sphere { <1,2,", "1:15", "unexpected end of file: expected a float or vector for sphere centre"},
    {"sphere { 0, 1 }\n}", "2:1", "found '}'"},
    {"42", "1:1", "expected a scene item"},
    {"sphere { 0, 1 } @", "1:17", "unexpected character '@'"},
    {"sphere { <1,2>, 1 }", "1:10", "expected a 3-component vector for sphere centre, found a 2-component vector"},
    {"sphere { 0, <1,2,3> }", "1:13", "expected a float for sphere radius, found a 3-component vector"},
    {"sphere { 0, 1 interior { ior 0 } }", "1:30", "interior ior must be positive, got 0"},
    {"sphere { 0, 1 finish { ambient -0.1 } }", "1:32", "finish ambient must not be negative"},
    {"sphere { 0, 1 finish { phong_size 0 } }", "1:35", "finish phong_size must be positive"},
    {"sphere { 0, 1 finish { specular 0.5 } }", "1:24", "unsupported keyword 'specular'"},
    {"union { }", "1:1", "'union' needs at least 1 object, found 0"},
    {"difference { sphere { 0, 1 } }", "1:1", "'difference' needs at least 2 objects, found 1"},
    {"difference { sphere { 0, 1 } torus { 1, 0.1 } }", "1:30", "unsupported keyword 'torus'"},
    {"union { sphere{0,1} translate x sphere{0,1} }", "1:33", "must come before the modifiers of 'union'"},
    {"#declare S = sphere { 0, 1 }\nunion { S }", "2:9", "use 'object { S }'"},
    {"#declare R = 2\nsphere { 0, R }", "2:1", "expected ';' after the value of '#declare R', found 'sphere'"},
    {"#declare sphere = 1;", "1:10", "cannot #declare 'sphere': it is a keyword"},
    {"#declare S = sphere { 0, 1 }\nsphere { S, 1 }", "2:10", "'S' is an object, not a float or vector"},
    {"sphere { 0, 1/0 }", "1:14", "division by zero"},
    {"#include \"abc", "1:10", "unterminated string"},
    {"#if (1) #end", "1:1", "unsupported directive '#if'"},
    {"sphere { 0, 1 pigment { color <1,0,0,0,0.5> } }", "1:31", "transmit"},
    {"sphere { 0, 1 pigment { checker } }", "1:25", "unsupported keyword 'checker'"},
    {"light_source { 0 color rgbf <1,1,1,0.5> }", "1:24", "'rgbf' is not allowed in light_source colour"},
    {"camera { location z look_at z }", "1:29", "camera location and look_at must be different"},
    {"camera { angle 180 }", "1:16", "camera angle must be between 0 and 180"},
    {"sphere { 0, 1 translate <1,2,3,4,5,6> }", "1:36", "too many vector components"},
    {"box { 0, 1 open }", "1:12", "expected '}' to close 'box' opened at 1:1, found 'open'"},
    {"sphere { 0 1 translate x+<1,2,3,4> }", "1:25", "cannot combine a 3-component vector and a 4-component vector"},
};

TEST(ParseErrors, Table) {
    TempDir d;
    d.write("bad.inc", "// a bad sphere\nsphere { 0, -1 }\n");
    auto subst = [&](std::string s) {
        for (size_t k; (k = s.find("@DIR@")) != std::string::npos;) s.replace(k, 5, d.path);
        return s;
    };
    for (const BadCase& c : kBad) {
        std::string text = subst(c.text);
        std::string where = subst(c.where);
        if (where.find(".inc") == std::string::npos) where = "t.pov:" + where;
        std::string what = error_of([&] { P(text); });
        EXPECT_EQ(what.rfind(where + ": ", 0), 0u) << "input: " << text << "\nerror: " << what;
        EXPECT_NE(what.find(c.message), std::string::npos) << "input: " << text << "\nerror: " << what;
    }
    EXPECT_GE(sizeof kBad / sizeof kBad[0], 22u);
}

TEST(ParseErrors, MissingSceneFile) {
    std::string what = error_of([] { parse_scene_file("/nonexistent/dir/scene.pov"); });
    EXPECT_NE(what.find("cannot open scene file"), std::string::npos) << what;
}

TEST(ParseErrors, ExceptionCarriesPosition) {
    try {
        P("\n\n   torus { 1, 0.5 }");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.pos.file, "t.pov");
        EXPECT_EQ(e.pos.line, 3);
        EXPECT_EQ(e.pos.col, 4);
    }
}

}  // namespace
}  // namespace csgrt
