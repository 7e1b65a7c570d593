// main.cpp — the csgrt command line: render a scene with the golden model,
// compile it to the binary scene image the RTL loads, or describe it.
#include "compile.h"
#include "epsilon.h"
#include "image.h"
#include "parse.h"
#include "raytree.h"
#include "render.h"
#include "scene_image.h"
#include "stability.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

using namespace csgrt;

namespace {

const char* kUsage =
    "usage:\n"
    "  csgrt render SCENE.pov -o OUT.png [options]   render with the golden model\n"
    "  csgrt compile SCENE.pov -o OUT.bin [options]  write the binary scene image (and OUT.hex)\n"
    "  csgrt info SCENE.pov [options]                print the compiled scene\n"
    "  csgrt units SCENE.pov                         the RTL effect units the scene needs, as make\n"
    "                                                variables (SHADOWS=0|1 REFLECTION=0|1 REFRACTION=0|1)\n"
    "  csgrt stability [--quick] [--transforms N] [--case NAME] [--md FILE]\n"
    "                                                the hard-case stability suite (model/stability.h)\n"
    "options:\n"
    "  --width W --height H       image size (default 320x240)\n"
    "  --bits B                   coordinate width, 12..32 (default 24)\n"
    "  --arith fixed|double       fixed-point model or double reference (default fixed)\n"
    "  --ties paper|regular       tie policy at equal t (default paper)\n"
    "  --method exact|epsilon     exact CSG (default) or the conventional epsilon method (model/epsilon.h)\n"
    "  --threads N                worker threads (default: all cores)\n"
    "  --max-leaves N             hardware limit on leaves (compile: default 64, the RTL's)\n"
    "  --tree-height H            hardware classification-tree height (compile: default 8)\n"
    "  --no-cull                  intersect every leaf for every ray (no bounding-box culling;\n"
    "                             the image is the same bit for bit, only slower)\n"
    "  --primary-only             render: primary rays only (local shading, no shadow, reflected or\n"
    "                             transmitted rays), as the epsilon method renders; for comparisons\n"
    "  --quiet                    no progress line\n";

struct Args {
    std::string cmd, scene, out;
    CompileOptions copt;
    RenderOptions ropt;
    bool quiet = false;
    bool epsilon = false;
    bool primary_only = false;
};

[[noreturn]] void usage_error(const std::string& msg) {
    std::fprintf(stderr, "csgrt: %s\n%s", msg.c_str(), kUsage);
    std::exit(2);
}

int int_arg(const std::string& flag, const char* v) {
    char* end = nullptr;
    const long x = std::strtol(v, &end, 10);
    if (!*v || *end) usage_error(flag + " expects an integer, got '" + v + "'");
    return int(x);
}

Args parse_args(int argc, char** argv) {
    Args a;
    if (argc < 2) usage_error("no command");
    a.cmd = argv[1];
    for (int i = 2; i < argc; ++i) {
        const std::string s = argv[i];
        auto value = [&]() -> const char* {
            if (i + 1 >= argc) usage_error(s + " needs a value");
            return argv[++i];
        };
        if (s == "-o") a.out = value();
        else if (s == "--width") a.copt.width = int_arg(s, value());
        else if (s == "--height") a.copt.height = int_arg(s, value());
        else if (s == "--bits") a.copt.bits = int_arg(s, value());
        else if (s == "--threads") a.ropt.threads = int_arg(s, value());
        else if (s == "--max-leaves") a.copt.max_leaves = int_arg(s, value());
        else if (s == "--tree-height") a.copt.tree_height = int_arg(s, value());
        else if (s == "--quiet") a.quiet = true;
        else if (s == "--no-cull") a.copt.cull = false;
        else if (s == "--primary-only") a.primary_only = true;
        else if (s == "--arith") {
            const std::string v = value();
            if (v == "fixed") a.ropt.arith = Arith::Fixed;
            else if (v == "double") a.ropt.arith = Arith::Double;
            else usage_error("--arith expects fixed or double, got '" + v + "'");
        } else if (s == "--ties") {
            const std::string v = value();
            if (v == "paper") a.ropt.ties = TiePolicy::Paper;
            else if (v == "regular") a.ropt.ties = TiePolicy::Regular;
            else usage_error("--ties expects paper or regular, got '" + v + "'");
        } else if (s == "--method") {
            const std::string v = value();
            if (v == "exact") a.epsilon = false;
            else if (v == "epsilon") a.epsilon = true;
            else usage_error("--method expects exact or epsilon, got '" + v + "'");
        } else if (!s.empty() && s[0] == '-') usage_error("unknown option " + s);
        else if (a.scene.empty()) a.scene = s;
        else usage_error("unexpected argument " + s);
    }
    if (a.scene.empty()) usage_error("no scene file");
    return a;
}

void print_info(const CompiledScene& cs) {
    std::printf("scene %s: %zu leaves, %zu instructions (stack %d), %zu materials, %zu lights, %d bits\n",
                cs.source.c_str(), cs.leaves.size(), cs.program.size(), cs.stack_depth, cs.materials.size() - 1,
                cs.lights.size(), cs.fmt.bits);
    std::printf("frame: centre (%g, %g, %g), scale %g\n", cs.centre.x, cs.centre.y, cs.centre.z, cs.scale);
    for (size_t i = 0; i < cs.leaves.size(); ++i) {
        const LeafInfo& l = cs.leaves[i];
        std::printf("  leaf %3zu  %-22s material %d  %s\n", i, l.what.c_str(), l.material, l.pos.str().c_str());
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc >= 2 && (!std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "--help"))) {
        std::fputs(kUsage, stdout);
        return 0;
    }
    if (argc >= 2 && !std::strcmp(argv[1], "stability")) return stability_main(argc - 1, argv + 1);
    Args a = parse_args(argc, argv);
    if (a.cmd == "compile") {
        // a scene image is for the RTL: check its limits and lay out its tree
        if (a.copt.tree_height == 0) a.copt.tree_height = kRtlTreeHeight;
        if (a.copt.max_leaves == kMaxLeaves) a.copt.max_leaves = kRtlMaxLeaves;
    }
    try {
        const Scene scene = parse_scene_file(a.scene);
        const CompiledScene cs = compile_scene(scene, a.copt);
        if (a.cmd == "units") {
            const EffectSet fx = scene_effects(cs);
            std::printf("SHADOWS=%d REFLECTION=%d REFRACTION=%d SPECULAR=%d\n", int(fx.shadows), int(fx.reflection),
                        int(fx.refraction), int(fx.specular));
            return 0;
        }
        if (a.cmd == "info") {
            print_info(cs);
            std::printf("effects: %s\n", scene_effects(cs).str().c_str());
            return 0;
        }
        if (a.out.empty()) usage_error(a.cmd + " needs -o OUT");
        if (a.cmd == "compile") {
            std::string hex = a.out;
            const size_t dot = hex.rfind('.');
            hex = (dot == std::string::npos ? hex : hex.substr(0, dot)) + ".hex";
            write_scene_image(cs, a.out, hex);
            std::fprintf(stderr, "csgrt: wrote %s and %s (%zu leaves, %d bits, %dx%d)\n", a.out.c_str(),
                         hex.c_str(), cs.leaves.size(), cs.fmt.bits, cs.width, cs.height);
            return 0;
        }
        if (a.cmd == "render") {
            RenderOptions ro = a.ropt;
            ro.progress = !a.quiet;
            if (a.primary_only) {
                // the scene's local shading (specular) stays: only the rays that spawn rays go
                EffectSet fx = scene_effects(cs);
                fx.shadows = fx.reflection = fx.refraction = false;
                ro.effects = fx;
            }
            if (!a.quiet) std::fprintf(stderr, "csgrt: effects: %s\n", scene_effects(cs).str().c_str());
            const auto t0 = std::chrono::steady_clock::now();
            const Frame f = a.epsilon ? render_epsilon(cs, ro) : render(cs, ro);
            const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            write_image(a.out, f.width, f.height, f.rgb);
            if (!a.quiet)
                std::fprintf(stderr, "csgrt: wrote %s (%dx%d, %s, %d bits, ties %s, %.3f s)\n", a.out.c_str(),
                             f.width, f.height, ro.arith == Arith::Fixed ? "fixed" : "double", cs.fmt.bits,
                             a.epsilon ? "epsilon" : ro.ties == TiePolicy::Paper ? "paper" : "regular", secs);
            return 0;
        }
        usage_error("unknown command '" + a.cmd + "'");
    } catch (const SceneError& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "csgrt: %s\n", e.what());
        return 1;
    }
}
