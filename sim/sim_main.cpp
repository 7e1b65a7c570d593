// sim_main.cpp — `make sim`: runs csgrt_top in Verilator on a compiled scene
// image, writes the image, prints cycles and utilisation, and compares every
// pixel with the golden model rendering the very same scene image.
#include "Vcsgrt_top.h"
#include "Vcsgrt_top___024root.h"   // the signals the harness logs
#include "image.h"
#include "raytree.h"
#include "render.h"
#include "report.h"
#include "scene_image.h"
#include "top_sim.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

using namespace csgrt;
using Clock = std::chrono::steady_clock;

// The effect units this binary was built with (csgrt_top's SHADOWS,
// REFLECTION, REFRACTION, SPECULAR; the Makefile passes them).
#ifndef CSGRT_SHADOWS
#define CSGRT_SHADOWS 0
#endif
#ifndef CSGRT_REFLECTION
#define CSGRT_REFLECTION 0
#endif
#ifndef CSGRT_REFRACTION
#define CSGRT_REFRACTION 0
#endif
#ifndef CSGRT_SPECULAR
#define CSGRT_SPECULAR 1
#endif
// csgrt_top's CONTEXTS (pixels in flight in the ray tree; make sim CONTEXTS=N)
#ifndef CSGRT_CONTEXTS
#define CSGRT_CONTEXTS 8
#endif

namespace {

constexpr bool kEffects = CSGRT_SHADOWS || CSGRT_REFLECTION || CSGRT_REFRACTION;
const char* kBuildUnits = !kEffects ? "no effect units"
                          : CSGRT_SHADOWS && CSGRT_REFLECTION && CSGRT_REFRACTION ? "shadow, reflection and refraction units"
                          : CSGRT_SHADOWS && CSGRT_REFLECTION ? "shadows and reflection units"
                          : CSGRT_SHADOWS && CSGRT_REFRACTION ? "shadow and refraction units"
                          : CSGRT_REFLECTION && CSGRT_REFRACTION ? "reflection and refraction units"
                          : CSGRT_SHADOWS ? "a shadow unit"
                          : CSGRT_REFLECTION ? "a reflection unit"
                                             : "a refraction unit";
const char* kSpecularUnit = CSGRT_SPECULAR ? ", with the specular unit" : ", without the specular unit";

const char* kUsage =
    "usage: csgrt_sim --scene-image SCENE.bin --out OUT.png [--ties paper|regular] [--trace OUT.fst]\n"
    "                 [--ready-percent P] [--no-compare] [--max-cycles N]\n";

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace

int main(int argc, char** argv) {
    std::string image_path, out_path, trace_path;
    TiePolicy ties = TiePolicy::Paper;
    int ready_percent = 100;
    bool compare = true;
    uint64_t max_cycles = 0;   // 0: the default limit (100,000 cycles per pixel)
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "csgrt_sim: %s needs a value\n%s", a.c_str(), kUsage);
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--scene-image") image_path = next();
        else if (a == "--out") out_path = next();
        else if (a == "--trace") trace_path = next();
        else if (a == "--ready-percent") ready_percent = std::atoi(next().c_str());
        else if (a == "--no-compare") compare = false;
        else if (a == "--max-cycles") max_cycles = std::strtoull(next().c_str(), nullptr, 10);
        else if (a == "--ties") {
            const std::string v = next();
            if (v == "paper") ties = TiePolicy::Paper;
            else if (v == "regular") ties = TiePolicy::Regular;
            else { std::fprintf(stderr, "csgrt_sim: --ties paper|regular\n"); return 2; }
        } else { std::fprintf(stderr, "csgrt_sim: unknown argument %s\n%s", a.c_str(), kUsage); return 2; }
    }
    if (image_path.empty() || out_path.empty()) { std::fputs(kUsage, stderr); return 2; }

    std::vector<uint32_t> words;
    CompiledScene cs;
    try {
        words = read_scene_image(image_path);
        cs = decode_scene_image(words);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "csgrt_sim: %s: %s\n", image_path.c_str(), e.what());
        return 1;
    }
    const int W = cs.width, H = cs.height;
    const EffectSet rtl_fx = rtl_effects(cs, CSGRT_SHADOWS, CSGRT_REFLECTION, CSGRT_REFRACTION, CSGRT_SPECULAR);
    std::printf("scene effects: %s; this build has %s%s; it renders: %s\n", scene_effects(cs).str().c_str(),
                kBuildUnits, kSpecularUnit, rtl_fx.str().c_str());

    csgrt_sim::TopSim<Vcsgrt_top> sim(cs.fmt.bits, CSGRT_LEAF_BITS, CSGRT_TREE_HEIGHT, CSGRT_NUM_UNITS, trace_path);
    sim.reset();
    sim.set_logging(!kEffects);   // the per-ray log follows primary rays only
    const int err = sim.load(words);
    if (err) {
        static const char* what[] = {"", "bad magic or version", "BITS differs from this build's BITS",
                                     "more leaves than MAX_LEAVES", "more lights or materials than the hardware holds",
                                     "classification tree height differs from TREE_HEIGHT"};
        std::fprintf(stderr, "csgrt_sim: the RTL refused the scene image: %s (code %d)\n",
                     err < 6 ? what[err] : "loading did not finish", err);
        return 1;
    }

    // The model renders the same scene image first, so that each RTL pixel
    // is checked as it arrives and the first mismatch is reported while the
    // RTL's log of that ray is still kept.
    Frame model;
    double model_s = 0;
    if (compare) {
        const auto m0 = Clock::now();
        RenderOptions ro;
        ro.ties = ties;
        ro.threads = 1;
        ro.effects = rtl_fx;   // the effects this RTL build renders
        model = render(cs, ro);
        model_s = seconds_since(m0);
    }
    size_t matched = 0;
    std::string first_mismatch;

    std::vector<uint8_t> rgb(size_t(W) * H * 3, 0);
    csgrt_sim::SimStats st;
    const auto t0 = Clock::now();
    bool order_ok = true;
    size_t expect = 0;
    const bool ok = sim.render(
        W, H, ties == TiePolicy::Regular, ready_percent,
        [&](int x, int y, uint32_t c) {
            if (size_t(y) * W + x != expect) order_ok = false;
            ++expect;
            const size_t i = size_t(y) * W + x;
            if (i >= size_t(W) * H) return;
            rgb[i * 3] = uint8_t(c >> 16), rgb[i * 3 + 1] = uint8_t(c >> 8), rgb[i * 3 + 2] = uint8_t(c);
            if (!compare) return;
            const uint32_t m = uint32_t(model.rgb[i * 3]) << 16 | uint32_t(model.rgb[i * 3 + 1]) << 8 | model.rgb[i * 3 + 2];
            if (m == c)
                ++matched;
            else if (first_mismatch.empty())
                first_mismatch = kEffects ? csgrt_sim::mismatch_report(cs, ties, x, y, c, nullptr, m)
                                          : csgrt_sim::mismatch_report(cs, ties, x, y, c, sim.log_for(i));
        },
        [&](int row) {
            if (row % 4 == 3 || row == H - 1)
                std::fprintf(stderr, "\rsim: row %d/%d, %.1f s", row + 1, H, seconds_since(t0));
        },
        st, max_cycles ? max_cycles : uint64_t(W) * H * 100000);
    st.wall_seconds = seconds_since(t0);
    std::fprintf(stderr, "\n");
    if (!ok) {
        std::fprintf(stderr, "csgrt_sim: timeout: the frame did not complete\n");
        return 1;
    }
    write_image(out_path, W, H, rgb);
    std::printf("wrote %s (%dx%d, %d bits, ties %s)\n", out_path.c_str(), W, H, cs.fmt.bits,
                ties == TiePolicy::Paper ? "paper" : "regular");
    const double npix = double(W) * H;
    std::printf("cycles per frame        %llu\n", (unsigned long long)st.cycles);
    std::printf("cycles per pixel        %.2f\n", st.cycles / npix);
    const double rays = cs.leaves.empty() ? 0.0 : double(st.pairs) / double(cs.leaves.size());
    std::printf("pairs issued            %llu (%zu leaves x %.0f rays, %.2f rays per pixel)\n",
                (unsigned long long)st.pairs, cs.leaves.size(), rays, rays / npix);
    const double bound = double(st.pairs) / CSGRT_NUM_UNITS;   // cycles if every unit took a pair every clock
    std::printf("intersection units      %d\n", CSGRT_NUM_UNITS);
    std::printf("intersection-unit utilisation  %.3f pairs/cycle per unit (bound pairs/units = %.0f cycles, frame at %.3fx)\n",
                double(st.pairs) / double(st.cycles) / CSGRT_NUM_UNITS, bound, double(st.cycles) / bound);
    if (kEffects) {
        std::printf("ray-tree contexts       %d (pixels in flight)\n", CSGRT_CONTEXTS);
        // well above the bound, the contexts rather than the intersection
        // unit set the rate (docs/architecture.md "Contexts": basic.pov at
        // 64x48 is 2.88x its bound with 8 contexts, 1.10x with 32)
        if (st.cycles > 1.2 * bound && CSGRT_CONTEXTS < 64)
            std::printf("note: the frame took %.2fx the intersection bound; more ray-tree contexts may bring it "
                        "closer (make sim CONTEXTS=%d)\n",
                        double(st.cycles) / bound, 2 * CSGRT_CONTEXTS);
    }
    std::printf("simulation wall time    %.2f s (%.0f simulated cycles/s)\n", st.wall_seconds,
                st.total_cycles / st.wall_seconds);
    if (!order_ok) std::printf("pixel order: NOT raster order\n");
    if (!compare) return order_ok ? 0 : 1;

    std::printf("%s", first_mismatch.c_str());
    std::printf("model time (1 thread)   %.3f s; simulation / model = %.0fx\n", model_s, st.wall_seconds / model_s);
    std::printf("matched %zu of %zu pixels\n", matched, size_t(W) * H);
    return (matched == size_t(W) * H && order_ok) ? 0 : 1;
}
