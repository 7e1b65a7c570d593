// povray_test.cpp — csgrt against POV-Ray 3.7 (docs/povray-comparison.md).
//
// csgrt has no shadows yet and shows different materials on cut faces, so
// the colours of the two renderers differ; what must agree is which pixels
// show an object. For each scene in scenes/ this test renders:
//   - csgrt through the library (fixed point, 24 bits, paper ties, 160x120):
//     a pixel is object when Frame::hit_leaf >= 0;
//   - POV-Ray (`povray +W160 +H120 -A`, no anti-aliasing, PNG): a pixel is
//     object when its 8-bit RGB differs in any channel from the 8-bit code
//     POV-Ray writes for the scene's background colour.
// The background code is measured, not computed: POV-Ray renders a scene
// that holds only a camera and the same background {} (POV-Ray's own gamma
// and rounding give exactly the code it writes for background pixels).
//
// So that no object pixel can match the background code, the scenes written
// for this comparison use a background with red = 0 and give every object a
// pigment with red > 0 and ambient > 0: ambient alone then gives every object
// pixel a red code >= 1 (scenes/basic.pov predates this rule; its objects'
// ambient colours are far from its grey-blue background).
//
// The masks must agree on at least 99% of the pixels. A second test checks
// that csgrt's silhouette is not shifted against POV-Ray's: the bounding
// boxes of a single off-centre sphere agree within one pixel on each side.
//
// POV-Ray is installed by `make deps`; without it the tests fail (never
// skip). Tests run from the repository root (scene paths are relative to it).
// On failure the images and a mask-difference image are kept in the
// temporary folder the failure message names.
#include "compile.h"
#include "image.h"
#include "parse.h"
#include "render.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace csgrt {
namespace {

constexpr int kW = 160, kH = 120;

std::string quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) {
        if (c == '\'') out += "'\\''";
        else out += c;
    }
    return out + "'";
}

bool file_exists(const std::string& path) {
    struct stat st;
    return stat(path.c_str(), &st) == 0;
}

bool have_povray() { return std::system("command -v povray >/dev/null 2>&1") == 0; }

#define REQUIRE_POVRAY()                                                                      \
    ASSERT_TRUE(have_povray()) << "povray (POV-Ray 3.7) is not on PATH: this test compares " \
                                  "csgrt with it. Install it with `make deps`."

// A fresh folder under /tmp; removed at the end unless keep is set.
struct TempDir {
    std::string path;
    bool keep = false;
    TempDir() {
        char tmpl[] = "/tmp/povray_test_XXXXXX";
        const char* p = mkdtemp(tmpl);
        path = p ? p : "/tmp";
    }
    ~TempDir() {
        if (!keep && path != "/tmp") std::system(("rm -rf " + quote(path)).c_str());
    }
    std::string file(const std::string& name) const { return path + "/" + name; }
};

// Object masks, row-major, row 0 at the top.
struct Mask {
    int width = 0, height = 0;
    std::vector<uint8_t> on;
    bool at(int x, int y) const { return on[size_t(y) * width + x] != 0; }
};

Mask csgrt_mask(const std::string& scene_path, int w, int h) {
    const Scene scene = parse_scene_file(scene_path);
    CompileOptions co;
    co.bits = 24;
    co.width = w;
    co.height = h;
    const CompiledScene cs = compile_scene(scene, co);
    RenderOptions ro;
    ro.arith = Arith::Fixed;
    ro.ties = TiePolicy::Paper;
    const Frame f = render(cs, ro);
    Mask m{f.width, f.height, std::vector<uint8_t>(size_t(f.width) * f.height)};
    for (size_t i = 0; i < m.on.size(); ++i) m.on[i] = f.hit_leaf[i] >= 0;
    return m;
}

// Runs POV-Ray on `scene` into `out` (PNG, no anti-aliasing, quiet); its
// messages go to out + ".log". Returns "" or a description of the failure.
std::string run_povray(const std::string& scene, const std::string& out, int w, int h) {
    const std::string log = out + ".log";
    const std::string cmd = "povray +I" + quote(scene) + " +O" + quote(out) + " +W" + std::to_string(w) +
                            " +H" + std::to_string(h) + " -A +FN -D -V -GA -P >" + quote(log) + " 2>&1";
    const int rc = std::system(cmd.c_str());
    if (rc != 0 || !file_exists(out)) {
        std::ifstream in(log);
        std::stringstream ss;
        ss << in.rdbuf();
        return "`" + cmd + "` failed (status " + std::to_string(rc) + "):\n" + ss.str();
    }
    return "";
}

// The 8-bit code POV-Ray writes for background colour `bg`, measured by
// rendering a scene that holds nothing but the background.
std::array<uint8_t, 3> povray_background_code(const glm::dvec3& bg, const TempDir& dir) {
    const std::string pov = dir.file("background_only.pov");
    const std::string png = dir.file("background_only.png");
    char text[512];
    std::snprintf(text, sizeof text,
                  "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
                  "camera { location <0, 0, -1> look_at <0, 0, 0> }\n"
                  "background { color rgb <%.17g, %.17g, %.17g> }\n",
                  bg.x, bg.y, bg.z);
    std::ofstream(pov) << text;
    const std::string err = run_povray(pov, png, 4, 3);
    if (!err.empty()) throw std::runtime_error(err);
    const ImageRGB8 img = read_image(png);
    return {img.rgb[0], img.rgb[1], img.rgb[2]};
}

Mask povray_mask(const std::string& scene_path, int w, int h, TempDir& dir, const std::string& png) {
    const Scene scene = parse_scene_file(scene_path);
    const std::array<uint8_t, 3> bg = povray_background_code(scene.background, dir);
    const std::string err = run_povray(scene_path, png, w, h);
    if (!err.empty()) throw std::runtime_error(err);
    const ImageRGB8 img = read_image(png);
    if (img.width != w || img.height != h)
        throw std::runtime_error("POV-Ray wrote " + std::to_string(img.width) + "x" + std::to_string(img.height));
    Mask m{w, h, std::vector<uint8_t>(size_t(w) * h)};
    for (size_t i = 0; i < m.on.size(); ++i) {
        const uint8_t* p = &img.rgb[i * 3];
        m.on[i] = p[0] != bg[0] || p[1] != bg[1] || p[2] != bg[2];
    }
    return m;
}

// Black: background in both; grey: object in both; red: object only in
// csgrt; green: object only in POV-Ray.
void write_mask_diff(const std::string& path, const Mask& a, const Mask& b) {
    std::vector<uint8_t> rgb(size_t(a.width) * a.height * 3);
    for (size_t i = 0; i < a.on.size(); ++i) {
        uint8_t* p = &rgb[i * 3];
        if (a.on[i] && b.on[i]) p[0] = p[1] = p[2] = 128;
        else if (a.on[i]) p[0] = 255;
        else if (b.on[i]) p[1] = 255;
    }
    write_image(path, a.width, a.height, rgb);
}

struct Box {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;   // inclusive; empty: x1 < x0
    bool empty() const { return x1 < x0; }
};

Box bounding_box(const Mask& m) {
    Box b;
    for (int y = 0; y < m.height; ++y)
        for (int x = 0; x < m.width; ++x)
            if (m.at(x, y)) {
                b.x0 = std::min(b.x0, x);
                b.x1 = std::max(b.x1, x);
                b.y0 = std::min(b.y0, y);
                b.y1 = std::max(b.y1, y);
            }
    return b;
}

// ------------------------------------------------------ scene mask agreement

class PovrayMask : public ::testing::TestWithParam<std::string> {};

TEST_P(PovrayMask, AgreesWithCsgrt) {
    REQUIRE_POVRAY();
    const std::string name = GetParam();
    const std::string scene = "scenes/" + name + ".pov";
    ASSERT_TRUE(file_exists(scene)) << scene << " not found: run the tests from the repository root";

    TempDir dir;
    Mask ours, theirs;
    try {
        ours = csgrt_mask(scene, kW, kH);
        theirs = povray_mask(scene, kW, kH, dir, dir.file(name + "_povray.png"));
    } catch (const std::exception& e) {
        dir.keep = true;
        FAIL() << scene << ": " << e.what()
               << "\n(if csgrt cannot parse the scene, that is a parser issue: report it)";
    }
    ASSERT_EQ(ours.on.size(), theirs.on.size());

    size_t agree = 0, ours_only = 0, theirs_only = 0, objects = 0;
    for (size_t i = 0; i < ours.on.size(); ++i) {
        agree += ours.on[i] == theirs.on[i];
        ours_only += ours.on[i] && !theirs.on[i];
        theirs_only += !ours.on[i] && theirs.on[i];
        objects += theirs.on[i];
    }
    const double pct = 100.0 * double(agree) / double(ours.on.size());
    std::printf("[ povray   ] %-10s mask agreement %.2f%% (%zu of %zu pixels; object only in csgrt %zu, only in "
                "POV-Ray %zu; POV-Ray object pixels %zu)\n",
                name.c_str(), pct, agree, ours.on.size(), ours_only, theirs_only, objects);
    RecordProperty("agreement_percent", std::to_string(pct));
    // A scene that POV-Ray draws empty would pass trivially.
    EXPECT_GT(objects, ours.on.size() / 20) << "POV-Ray's image is almost all background";

    if (pct < 99.0) {
        dir.keep = true;
        write_mask_diff(dir.file(name + "_maskdiff.png"), ours, theirs);
        ADD_FAILURE() << scene << ": masks agree on " << pct << "% of the pixels, below 99%. Images in " << dir.path
                      << " (" << name << "_maskdiff.png: red = object only in csgrt, green = only in POV-Ray)";
    }
}

INSTANTIATE_TEST_SUITE_P(Povray, PovrayMask,
                         ::testing::Values("basic", "default", "csg_mix", "quadrics", "rotated", "studio"),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

// ------------------------------------------------------- silhouette offset

TEST(PovraySilhouette, SphereBoundingBoxMatches) {
    REQUIRE_POVRAY();
    constexpr int W = 320, H = 240;
    TempDir dir;
    // Off-centre in x and y, so a shift or a mirror of either axis shows.
    const std::string scene = dir.file("sphere.pov");
    std::ofstream(scene) << "#version 3.7;\n"
                            "global_settings { assumed_gamma 1.0 }\n"
                            "camera { location <0, 0, -6> look_at <0, 0, 0> angle 40 right x*4/3 up y }\n"
                            "light_source { <-3, 5, -6> color rgb <1, 1, 1> }\n"
                            "background { color rgb <0, 0, 0> }\n"
                            "sphere { <0.7, -0.4, 0.5>, 0.9\n"
                            "  pigment { color rgb <0.8, 0.5, 0.3> } finish { ambient 0.2 } }\n";
    Mask ours, theirs;
    try {
        ours = csgrt_mask(scene, W, H);
        theirs = povray_mask(scene, W, H, dir, dir.file("sphere_povray.png"));
    } catch (const std::exception& e) {
        dir.keep = true;
        FAIL() << e.what();
    }
    const Box a = bounding_box(ours), b = bounding_box(theirs);
    ASSERT_FALSE(a.empty()) << "csgrt drew no sphere";
    ASSERT_FALSE(b.empty()) << "POV-Ray drew no sphere";
    std::printf("[ povray   ] sphere bounding box csgrt x %d..%d y %d..%d, POV-Ray x %d..%d y %d..%d "
                "(csgrt - POV-Ray: left %+d right %+d top %+d bottom %+d)\n",
                a.x0, a.x1, a.y0, a.y1, b.x0, b.x1, b.y0, b.y1, a.x0 - b.x0, a.x1 - b.x1, a.y0 - b.y0,
                a.y1 - b.y1);
    const bool ok = std::abs(a.x0 - b.x0) <= 1 && std::abs(a.x1 - b.x1) <= 1 && std::abs(a.y0 - b.y0) <= 1 &&
                    std::abs(a.y1 - b.y1) <= 1;
    if (!ok) {
        dir.keep = true;
        write_mask_diff(dir.file("sphere_maskdiff.png"), ours, theirs);
    }
    EXPECT_TRUE(ok) << "csgrt's silhouette is shifted against POV-Ray's by more than one pixel (camera mapping?); "
                    << "images in " << dir.path;
}

}  // namespace
}  // namespace csgrt
