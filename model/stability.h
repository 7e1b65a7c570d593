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
// with the same camera and the same random transform, by the exact method at
// the same width (so what the width does to every surface, such as coarse
// silhouettes at 12 bits, is shared by test and reference), and only its
// "stable" pixels are compared: a pixel whose 3x3 neighbourhood all shows
// the same surface colour at about the same depth (silhouettes and material
// edges move by a pixel with the width; that is geometry, not logic). On
// those pixels (image level):
//
//   hole     the reference shows an object and the test shows background,
//            or a surface more than `depth_tolerance` behind the reference's
//            (a ray that went through the surface: Fig. 6, 7, 14);
//   speckle  a different material than the reference (a coincident face
//            showing the wrong operand's material, or a surface where there
//            is none);
//   ghost    the same, on a case whose point is ghost surfaces (Fig. 4:
//            the top of one cylinder in the other's colour);
//   mirror   the same comparison for what a mirror shows (Fig. 15): one
//            reflected ray per pixel whose primary hit is reflective, in
//            the test and in the reference.
//
// Ray-level invariants, on every pixel (no reference, no mask):
//
//   inside       a lamina surface seen from inside (the ray leaves the
//                sphere there: d . grad Q > 0 at the hit), by the primary
//                ray or by the mirror's reflected ray (Fig. 15);
//   method hole  (thin shells, Fig. 9) the computed events of the ray put
//                the outer surface's entry strictly first (t_outer <
//                t_inner, or equal t and the policy sorts the outer one
//                first) and the ray nevertheless does not show the outer
//                surface there. Rays whose computed order is tied the other
//                way or flipped are "below resolution": the arithmetic of
//                that width cannot tell the two surfaces apart there, for
//                any method; they are reported (Counts::notes), not
//                counted, and so are the image-level holes of such a case;
//   self-shadow  (cases whose top-level objects are all convex: Fig. 6, 8,
//                13, 14) a lit point (n . (light - p) > 0) whose shadow ray
//                first strikes the object it starts on: a convex solid
//                cannot occlude its own lit side, so the ground truth is
//                "no occluder" (coincident copies belong to the same
//                top-level object, so Fig. 6 and 14 are covered);
//   self-reflection  (the same cases) a reflected ray that first strikes
//                the convex object it leaves;
//   media        (transparent cases, Fig. 13, 16) along the chain of
//                transmitted rays of a pixel, a crossing whose BORDER from
//                is not the medium the previous crossing entered;
//   medium       (the same rays) a ray segment, from its origin to its next
//                crossing, whose midpoint does not lie in the medium the
//                walk says the ray travels in: the material there by the
//                unquantised quadrics (the ground truth; a midpoint where
//                some leaf's |Q| is within a few ulps of zero, the
//                resolution of the rays' rounded quadratics, is not judged).
//                Consistency alone does not see a lost crossing (a ray that
//                never crossed the coincident faces behind a transparent
//                one stays consistent in the wrong medium); this does.
//
// Secondary rays are cast as the renderer casts them (accumulate_fx in
// raytree.cpp): from the primary hit the renderer finds (with the
// look-ahead when the scene refracts), from the rounded hit point with no
// offset, shadow and reflected rays with the near side's flags, transmitted
// rays with the far side's (after the look-ahead). The epsilon method casts
// them as POV-Ray does: from the hit point nudged by its epsilon along the
// normal, traced by its own tracer (EpsilonTracer::trace drops hits closer
// than its depth tolerance). The primary image is the hit's classification
// without the look-ahead; with it, the renderer shades a run of coincident
// transparent faces with the run's last material (Fig. 13's shared front
// shows the innermost box under both policies): not compared here.
//
// Known issues of the exact model, still counted as violations, and
// identified ray by ray (Counts::notes) so that a test can insist that
// nothing else shows:
//
//   edge ties          a self-shadow or self-reflection whose primary hit's
//                      computed t ties with a surface that is not the hit
//                      leaf's: the ray strikes an edge at that width's
//                      resolution and the tie key picks whose normal the hit
//                      takes; under ties "regular" the right operand's edge
//                      plane is entered last, becomes the hit leaf, and its
//                      normal is internal to the union (Fig. 6, 13, 12-20
//                      bits);
//   own-leaf look-ahead  a medium violation where the look-ahead after a
//                      transparent hit crossed the hit leaf's own far side:
//                      its test "the hit point already lies beyond the next
//                      surface" is the sign of Q at the rounded hit point,
//                      noise for the hit's own quadric, so the run can cross
//                      a whole glass sphere and drop the hit (Fig. 16, any
//                      width).
//
// The exact method is compared against its own policy's reference. The
// epsilon method has no tie policy (its candidates sort by (t, leaf), the
// paper order, which the thin-shell check uses for it): an image pixel
// counts when it matches neither reference, plus, on the pixels where the
// two references differ, the smaller of the two groups that chose one
// answer or the other (a face showing a mixture of both answers is speckle
// whichever one is right).
//
// Still hooks (`Case::pending`): secondary rays of the Fig. 17 class.
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
// Violations.
enum Kind {
    Hole = 0,
    Speckle,
    Ghost,
    Inside,
    Mirror,
    MethodHole,
    SelfShadow,
    SelfReflect,
    Media,
    Medium,
    kNumKinds
};
const char* kind_name(int k);
char kind_letter(int k);   // the letter of the tables: h s g i w m a r c v
// Figures reported beside the violations.
enum Note {
    // not violations (thin shells):
    BelowResolution = 0,   // rays whose computed order of the two surfaces is tied the other way or flipped
    ImageHoles,            // the image-level holes against the reference (what the width and the method lose, mixed)
    // the known issues' share of the exact method's violations:
    EdgeTies,              // self-shadows and self-reflections at an edge tie
    OwnLeafLookahead,      // medium violations where the look-ahead crossed the hit leaf's own far side
    kNumNotes
};

// Deliberate faults in how the suite casts the exact method's secondary
// rays, for the suite's own tests: each must make some count go above zero,
// which proves that check can fail. Never set outside tests.
enum class Fault {
    None,
    FarSideFlags,          // shadow and reflected rays take the far side's flags (flags_after)
    RederiveFlags,         // shadow and reflected rays derive their flags at the origin, as primary rays do
    TransmittedNearSide,   // transmitted rays take the near side's flags
    NoLookahead,           // transmitted rays without the coincident-surface look-ahead
};

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
    bool lamina = false;       // check that lamina_rgb is never seen from inside (primary and mirror rays)
    bool mirror = false;       // compare the reflected rays off reflective surfaces with the reference's
    bool convex = false;       // every top-level object is convex: self-shadow and self-reflection checks
    bool media = false;        // transmitted rays: media and medium checks (transparent scenes)
    // thin shell (Fig. 9): the leaves of the outer and the inner surface; the
    // image-level holes are reported (notes), the ray-level method holes counted
    int shell_outer = -1, shell_inner = -1;
    std::array<double, 3> lamina_rgb{0, 0, 0};
    std::array<double, 3> pivot{0, 0, 0};   // world point the random rotations turn about
    double max_rotate_deg_override = -1;   // >= 0: replaces Config::max_rotate_deg
    double depth_tolerance = 0.25;          // world units (hole: surface this far behind)
    int max_transforms = 0;  // > 0: at most this many transforms (slow cases)
    bool large = false;        // the Fig. 17 class: model only, slow; not in the quick set
    int max_leaves = kMaxLeaves;
    std::vector<std::string> pending;       // invariants not checked yet (hooks)
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
    Fault fault = Fault::None;   // tests only (see Fault)
};

struct Counts {
    std::array<long, kNumKinds> v{};
    std::array<long, kNumKinds> rays{};    // per kind, the pixels or rays that check examined
    std::array<long, kNumNotes> notes{};
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
    bool has_notes = false;              // the case reports below-resolution figures (thin shells)
    Counts counts;
    std::string label() const;           // "exact/paper", "exact/regular", "epsilon"
};

std::vector<Row> run(const Config& cfg, const std::vector<Case>& cs);

// Violations per case and method (rows) and width (columns), then the
// figures reported beside them (below resolution) and what was checked.
void print_table(std::FILE* out, const std::vector<Row>& rows, const std::vector<int>& bits);
// The same as markdown, one table per case (for docs/hard-cases.md), with a
// second table of the reported figures when the case has any.
std::string markdown_table(const std::vector<Row>& rows, const std::vector<int>& bits, const std::string& case_name);

}  // namespace stability

// `csgrt stability [--quick] [--transforms N] [--bits a,b,c] [--case NAME]
// [--size WxH] [--md FILE]`: runs the suite, prints the table; exit status 1
// when the exact method shows a violation that is not one of the known
// issues identified ray by ray (Note::EdgeTies, Note::OwnLeafLookahead), or
// the epsilon method none.
int stability_main(int argc, char** argv);

}  // namespace csgrt
