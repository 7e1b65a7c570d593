// stability.h — the hard-case stability suite (issue 4): the paper's hard
// cases (scenes/paper/*.pov) rendered under random rigid transforms, at
// several coordinate widths, under both tie policies, by the exact method and
// by the conventional epsilon method (epsilon.h), and checked by invariants
// computed from the images and from ray-level data.
//
// How a case is checked. Every case names, per tie policy, a reference
// scene: the *equivalent scene without coincident surfaces* (an overlap cut
// away, a cutter enlarged past the face it shares, an object written once),
// which shows the one answer the policy decides. The reference is rendered
// with the same camera and the same random transform, in double precision
// (no quantisation), and only its "stable" pixels are compared: a pixel
// whose 3x3 neighbourhood all shows the same surface colour at about the
// same depth (silhouettes and material edges move by a pixel with the
// width; that is geometry, not logic). On those pixels:
//
//   hole     the reference shows an object and the test shows background,
//            or a surface more than `depth_tolerance` behind the reference's
//            (a ray that went through the surface: Fig. 6, 7, 9, 14);
//   speckle  a different material than the reference (a coincident face
//            showing the wrong operand's material, or a surface where there
//            is none);
//   ghost    the same, on a case whose point is ghost surfaces (Fig. 4:
//            the top of one cylinder in the other's colour);
//   inside   ray-level: a lamina surface seen from inside (the ray leaves the
//            sphere there: d . grad Q > 0 at the hit), Fig. 15.
//
// The exact method is compared against its own policy's reference. The
// epsilon method has no tie policy: a pixel counts when it matches neither
// reference, plus, on the pixels where the two references differ, the
// smaller of the two groups that chose one answer or the other (a face
// showing a mixture of both answers is speckle whichever one is right).
//
// Waiting on secondary rays (`Case::pending`): self-shadowing (Fig. 8, 14),
// self-reflection speckle (Fig. 8), the lamina in the mirror (Fig. 15),
// consistent media behind coincident transparent faces (Fig. 13, 16). Add
// them in count_secondary() (stability.cpp) when the model traces them:
// the frame loop already hands it every pixel's trace.
#pragma once

#include "compile.h"
#include "render.h"
#include "trace.h"

#include <array>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace csgrt {
namespace stability {

enum class Method { Exact, Epsilon };
enum Kind { Hole = 0, Speckle = 1, Ghost = 2, Inside = 3, SelfShadow = 4, kNumKinds = 5 };
const char* kind_name(int k);

struct RefSpec {
    std::string front;         // scene file (relative to the suite's root)
    std::string back;          // optional: where `front` shows `see_through`, take `back`'s pixel
    std::array<double, 3> see_through{1, 0, 1};
};

struct Case {
    std::string name;          // e.g. "fig06_add_shared"
    std::string file;          // scenes/paper/<name>.pov
    std::string what;          // one line for tables and docs
    RefSpec ref_paper, ref_regular;
    bool ghost = false;        // material errors count as ghost colour
    bool lamina = false;       // check that lamina_rgb is never seen from inside
    std::array<double, 3> lamina_rgb{0, 0, 0};
    std::array<double, 3> pivot{0, 0, 0};   // world point the random rotations turn about
    double max_rotate_deg_override = -1;   // >= 0: replaces Config::max_rotate_deg
    double depth_tolerance = 0.25;          // world units (hole: surface this far behind)
    int max_transforms = 0;  // > 0: at most this many transforms (slow cases)
    bool large = false;        // the Fig. 17 class: model only, slow; not in the quick set
    int max_leaves = kMaxLeaves;
    std::vector<std::string> pending;       // invariants waiting on secondary rays
};

// The case list (scenes under `root`, normally "scenes/paper").
std::vector<Case> cases(const std::string& root = "scenes/paper");

struct Config {
    std::string root = "scenes/paper";
    std::vector<int> bits{12, 16, 20, 24, 32};
    int transforms = 8;        // transform 0 is the file as written, then random ones
    int width = 64, height = 48;
    uint64_t seed = 20240601;
    double max_rotate_deg = 40;   // per axis
    double max_shift = 0.15;      // world units, per axis
    int threads = 0;
    bool progress = false;
};

struct Counts {
    std::array<long, kNumKinds> v{};
    long checked = 0;          // stable pixels compared; -1: the scene does not fit the width
    long total() const {
        long t = 0;
        for (long x : v) t += x;
        return t;
    }
};

// One row of the result: a case, a method (and tie policy for the exact
// method), one width, summed over the transforms.
struct Row {
    std::string case_name;
    Method method = Method::Exact;
    TiePolicy ties = TiePolicy::Paper;   // ignored for Epsilon
    int bits = 0;
    Counts counts;
    std::string label() const;           // "exact/paper", "exact/regular", "epsilon"
};

std::vector<Row> run(const Config& cfg, const std::vector<Case>& cs);

// Violations per case and method (rows) and width (columns).
void print_table(std::FILE* out, const std::vector<Row>& rows, const std::vector<int>& bits);
// The same as markdown, one table per case (for docs/hard-cases.md).
std::string markdown_table(const std::vector<Row>& rows, const std::vector<int>& bits, const std::string& case_name);

}  // namespace stability

// `csgrt stability [--quick] [--transforms N] [--bits a,b,c] [--case NAME]
// [--size WxH] [--md FILE]`: runs the suite, prints the table; exit status 1
// when the exact method shows a violation or the epsilon method none.
int stability_main(int argc, char** argv);

}  // namespace csgrt
