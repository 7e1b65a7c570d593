// stability.cpp — the hard-case stability suite (stability.h).
#include "stability.h"

#include "epsilon.h"
#include "parse.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <random>
#include <sstream>
#include <thread>

namespace csgrt {
namespace stability {

const char* kind_name(int k) {
    static const char* n[] = {"hole", "speckle", "ghost", "inside", "self-shadow"};
    return (k >= 0 && k < kNumKinds) ? n[k] : "?";
}

std::string Row::label() const {
    if (method == Method::Epsilon) return "epsilon";
    return ties == TiePolicy::Paper ? "exact/paper" : "exact/regular";
}

std::vector<Case> cases(const std::string& root) {
    std::vector<Case> v;
    auto add = [&](const std::string& name, const std::string& what, const std::string& rp, const std::string& rr) {
        Case c;
        c.name = name;
        c.file = root + "/" + name + ".pov";
        c.what = what;
        c.ref_paper.front = root + "/ref/" + rp + ".pov";
        c.ref_regular.front = root + "/ref/" + rr + ".pov";
        v.push_back(c);
        return &v.back();
    };
    Case* c;
    c = add("fig04_ghost", "Fig. 4 ghost surfaces: overlapping cylinders with coplanar tops", "fig04_ghost_paper",
            "fig04_ghost_regular");
    c->ghost = true;
    c->pivot = {0, 0.5, 0};
    c = add("fig06_add_shared", "Fig. 6 A + B sharing faces", "fig06_add_shared_paper", "fig06_add_shared_regular");
    c->pivot = {0, 0.5, 0};
    c = add("fig07_sub_shared", "Fig. 7 A - B sharing faces (a slot whose cutter lies on three faces)",
            "fig07_sub_shared_paper", "fig07_sub_shared_regular");
    c->pivot = {0, 0.5, 0};
    c = add("fig08_reflect", "Fig. 8 reflective sphere on a plane", "../fig08_reflect", "../fig08_reflect");
    c->pivot = {0, 0.75, 0};
    c->max_rotate_deg_override = 15;   // keep the camera above the ground plane
    c->pending = {"no self-reflection speckle on the mirror (reflected rays)",
                  "no self-shadowing (shadow rays)"};
    c = add("fig09_thin_point", "Fig. 9 two spheres subtracted: a zero-thickness point", "fig09_thin_point",
            "fig09_thin_point");
    c->pivot = {0, 0.5, 0};
    c = add("fig10_eggcup", "Fig. 10 eggcup carved from touching layers of wood", "fig10_eggcup", "fig10_eggcup");
    c->pivot = {0, 1.1, 0};
    c = add("fig13_coincident_transparent", "Fig. 13 coincident transparent faces (three nested glass boxes)",
            "fig13_coincident_transparent_paper", "fig13_coincident_transparent_regular");
    c->pivot = {0, 0.5, 0};
    c->pending = {"transmitted rays continue with consistent media (section 3.6 look-ahead)"};
    c = add("fig14_self_add", "Fig. 14 simple objects each added to itself", "fig14_self_add_paper",
            "fig14_self_add_regular");
    c->pivot = {0, 0.5, 0};
    c->pending = {"no shadow acne (shadow rays)"};
    c = add("fig15_lamina", "Fig. 15 spherical lamina (sphere minus itself, cut) with a reflective backplane",
            "fig15_lamina_front", "fig15_lamina_back");
    c->ref_paper.back = root + "/ref/fig15_lamina_back.pov";
    c->lamina = true;
    c->lamina_rgb = {0.95, 0.75, 0.25};
    c->pivot = {0, 0, 0};
    c->pending = {"the lamina's far wall visible in the mirror under ties paper (reflected rays)"};
    c = add("fig16_transparency", "Fig. 16 transparency: a glass sphere and box", "../fig16_transparency",
            "../fig16_transparency");
    c->pivot = {0, 0.5, 0};
    c->pending = {"transmitted rays (refraction through coincident glass)"};
    c = add("fig17_masterpiece", "Fig. 17 class: ~900 primitives with coincident faces (model only)", "fig17_paper",
            "fig17_regular");
    c->pivot = {0, 0.3, 0};
    c->large = true;
    c->max_leaves = 16384;
    c->max_transforms = 3;
    c->pending = {"reflection and shadows (secondary rays)"};
    return v;
}

namespace {

// What one pixel shows, for comparison across scenes: the pigment colour of
// the material (scenes differ in material numbering) and the depth in world
// units (scenes differ in frame scale).
struct Px {
    bool hit = false;
    int key = -1;          // packed pigment colour, -1: background
    double t = 0;          // world units
    bool from_inside = false;
};
using Image = std::vector<Px>;

int colour_key(const std::array<double, 3>& rgb) {
    int k = 0;
    for (int c = 0; c < 3; ++c) k = (k << 10) | int(std::lround(std::clamp(rgb[c], 0.0, 1.0) * 1000));
    return k;
}
int material_key(const CompiledScene& cs, int mat) {
    const glm::dvec3& p = cs.materials[mat].pigment.rgb;
    return colour_key({p.x, p.y, p.z});
}

// grad Q . d > 0 at the hit: the ray leaves the leaf's half-space there.
bool leaves_surface(const QuadricD& q, const glm::dvec3& o, const glm::dvec3& d, double t) {
    const glm::dvec3 p = o + t * d;
    return glm::dot(q.A * p + q.p, d) > 0.0;
}

template <typename T>
Px pixel_of(const CompiledScene& cs, const TraceResult<T>& tr, const glm::dvec3& o, const glm::dvec3& d,
            double t_frame) {
    Px px;
    if (!tr.hit) return px;
    px.hit = true;
    const int mat = tr.border.to ? tr.border.to : tr.border.from;
    px.key = material_key(cs, mat);
    px.t = t_frame / cs.scale;
    px.from_inside = leaves_surface(cs.leaves[tr.leaf].quad, o, d, t_frame);
    return px;
}

Scene transformed(const Scene& s, const glm::dmat4& m) {
    Scene r = s;
    for (Object& o : r.objects) o.transform = m * o.transform;
    return r;
}

CompiledScene compile_at(const Scene& s, int bits, int w, int h, int max_leaves) {
    CompileOptions co;
    co.bits = bits;
    co.width = w;
    co.height = h;
    co.max_leaves = max_leaves;
    return compile_scene(s, co);
}

Image render_test(const CompiledScene& cs, Method method, TiePolicy ties);

// The reference: the equivalent scene without coincident surfaces, traced by
// the exact method at the same width. A reference at the same width
// separates what coincident surfaces do from what the width does to every
// surface (coarse geometry at 12 bits is not a hole). Throws SceneError
// when the reference does not fit the width.
Image render_ref(const Scene& s, const Config& cfg, int max_leaves, int bits, TiePolicy ties) {
    return render_test(compile_at(s, bits, cfg.width, cfg.height, max_leaves), Method::Exact, ties);
}

Image render_ref(const RefSpec& ref, const glm::dmat4& m, const Config& cfg, int max_leaves, int bits,
                 TiePolicy ties) {
    Image front = render_ref(transformed(parse_scene_file(ref.front), m), cfg, max_leaves, bits, ties);
    if (ref.back.empty()) return front;
    const Image back = render_ref(transformed(parse_scene_file(ref.back), m), cfg, max_leaves, bits, ties);
    const int key = colour_key(ref.see_through);
    for (size_t i = 0; i < front.size(); ++i)
        if (front[i].hit && front[i].key == key) front[i] = back[i];
    return front;
}

Image render_test(const CompiledScene& cs, Method method, TiePolicy ties) {
    Image img(size_t(cs.width) * cs.height);
    const double one = std::ldexp(1.0, -cs.fmt.frac);
    std::unique_ptr<EpsilonTracer> eps;
    if (method == Method::Epsilon) eps = std::make_unique<EpsilonTracer>(cs);
    for (int y = 0; y < cs.height; ++y)
        for (int x = 0; x < cs.width; ++x) {
            const RayFx r = camera_ray_fx(cs, x, y);
            const TraceResult<i64> tr = eps ? eps->trace(r) : trace_primary_fx(cs, r, ties);
            const glm::dvec3 o(r.o[0] * one, r.o[1] * one, r.o[2] * one), d(r.d[0] * one, r.d[1] * one, r.d[2] * one);
            img[size_t(y) * cs.width + x] = pixel_of(cs, tr, o, d, double(tr.t) * one);
            // count_secondary(cs, r, tr, ...) plugs in here when secondary rays exist
        }
    return img;
}

// Pixels whose 3x3 neighbourhood shows one surface colour at about one depth.
std::vector<uint8_t> stable_mask(const Image& ref, int w, int h, double depth_tol) {
    std::vector<uint8_t> m(ref.size(), 0);
    for (int y = 1; y + 1 < h; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            const Px& c = ref[size_t(y) * w + x];
            bool ok = true;
            for (int dy = -1; dy <= 1 && ok; ++dy)
                for (int dx = -1; dx <= 1 && ok; ++dx) {
                    const Px& n = ref[size_t(y + dy) * w + x + dx];
                    if (n.hit != c.hit || n.key != c.key || (c.hit && std::fabs(n.t - c.t) > 0.5 * depth_tol))
                        ok = false;
                }
            m[size_t(y) * w + x] = ok;
        }
    return m;
}

// The kind of disagreement of a test pixel with a reference pixel, or -1.
int compare(const Px& test, const Px& ref, const Case& c) {
    if (ref.hit && !test.hit) return Hole;
    if (ref.hit && test.t > ref.t + c.depth_tolerance) return Hole;
    if (test.hit != ref.hit || (test.hit && test.key != ref.key)) return c.ghost ? Ghost : Speckle;
    return -1;
}

void count_inside(const Image& test, const Case& c, Counts& out) {
    if (!c.lamina) return;
    const int key = colour_key(c.lamina_rgb);
    for (const Px& p : test)
        if (p.hit && p.key == key && p.from_inside) ++out.v[Inside];
}

Counts check_exact(const Image& test, const Image& ref, const std::vector<uint8_t>& mask, const Case& c) {
    Counts k;
    for (size_t i = 0; i < test.size(); ++i) {
        if (!mask[i]) continue;
        ++k.checked;
        const int v = compare(test[i], ref[i], c);
        if (v >= 0) ++k.v[v];
    }
    count_inside(test, c, k);
    return k;
}

Counts check_epsilon(const Image& test, const Image& ref_p, const Image& ref_r, const std::vector<uint8_t>& mask_p,
                     const std::vector<uint8_t>& mask_r, const Case& c) {
    Counts k;
    long p_only = 0, r_only = 0;
    for (size_t i = 0; i < test.size(); ++i) {
        if (!mask_p[i] || !mask_r[i]) continue;
        ++k.checked;
        const int vp = compare(test[i], ref_p[i], c), vr = compare(test[i], ref_r[i], c);
        if (vp >= 0 && vr >= 0) ++k.v[vr];
        else if (vp < 0 && vr >= 0) ++p_only;
        else if (vp >= 0 && vr < 0) ++r_only;
    }
    k.v[c.ghost ? Ghost : Speckle] += std::min(p_only, r_only);
    count_inside(test, c, k);
    return k;
}

glm::dmat4 random_transform(const Case& c, const Config& cfg, int index) {
    if (index == 0) return glm::dmat4(1.0);
    std::mt19937_64 rng(cfg.seed * 1000003ull + std::hash<std::string>{}(c.name) * 31ull + uint64_t(index));
    const double maxr = c.max_rotate_deg_override >= 0 ? c.max_rotate_deg_override : cfg.max_rotate_deg;
    std::uniform_real_distribution<double> ang(-maxr, maxr), sh(-cfg.max_shift, cfg.max_shift);
    const glm::dvec3 pivot(c.pivot[0], c.pivot[1], c.pivot[2]);
    const double ax = ang(rng), ay = ang(rng), az = ang(rng);
    const glm::dvec3 shift(sh(rng), sh(rng), sh(rng));
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), pivot + shift);
    // POV-Ray's rotate <ax, ay, az>: about x, then y, then z
    m = glm::rotate(m, glm::radians(az), glm::dvec3(0, 0, 1));
    m = glm::rotate(m, glm::radians(ay), glm::dvec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(ax), glm::dvec3(1, 0, 0));
    return glm::translate(m, -pivot);
}

}  // namespace

std::vector<Row> run(const Config& cfg, const std::vector<Case>& list) {
    struct Job {
        size_t c;
        int t;
    };
    std::vector<Job> jobs;
    for (size_t c = 0; c < list.size(); ++c)
        for (int t = 0; t < cfg.transforms; ++t)
            if (list[c].max_transforms <= 0 || t < list[c].max_transforms) jobs.push_back({c, t});
    // rows: case x {exact/paper, exact/regular, epsilon} x bits
    const size_t nb = cfg.bits.size();
    std::vector<Row> rows;
    for (const Case& c : list)
        for (int m = 0; m < 3; ++m)
            for (int b : cfg.bits) {
                Row r;
                r.case_name = c.name;
                r.method = m == 2 ? Method::Epsilon : Method::Exact;
                r.ties = m == 1 ? TiePolicy::Regular : TiePolicy::Paper;
                r.bits = b;
                rows.push_back(r);
            }
    std::mutex mu;
    std::atomic<size_t> next{0}, done{0};
    std::string error;
    auto worker = [&]() {
        for (size_t j; (j = next.fetch_add(1)) < jobs.size();) {
            try {
                const Case& c = list[jobs[j].c];
                const glm::dmat4 m = random_transform(c, cfg, jobs[j].t);
                const Scene scene = transformed(parse_scene_file(c.file), m);
                std::vector<Counts> got(3 * nb);
                for (size_t bi = 0; bi < nb; ++bi) {
                    CompiledScene cs;
                    Image ref_p, ref_r;
                    try {
                        cs = compile_at(scene, cfg.bits[bi], cfg.width, cfg.height, c.max_leaves);
                        ref_p = render_ref(c.ref_paper, m, cfg, c.max_leaves, cfg.bits[bi], TiePolicy::Paper);
                        ref_r = render_ref(c.ref_regular, m, cfg, c.max_leaves, cfg.bits[bi], TiePolicy::Regular);
                    } catch (const SceneError&) {
                        // the scene does not fit this width (a primitive below 4 ulp): not applicable
                        for (int m = 0; m < 3; ++m) got[m * nb + bi].checked = -1;
                        continue;
                    }
                    const auto mask_p = stable_mask(ref_p, cfg.width, cfg.height, c.depth_tolerance);
                    const auto mask_r = stable_mask(ref_r, cfg.width, cfg.height, c.depth_tolerance);
                    got[0 * nb + bi] = check_exact(render_test(cs, Method::Exact, TiePolicy::Paper), ref_p, mask_p, c);
                    got[1 * nb + bi] =
                        check_exact(render_test(cs, Method::Exact, TiePolicy::Regular), ref_r, mask_r, c);
                    got[2 * nb + bi] = check_epsilon(render_test(cs, Method::Epsilon, TiePolicy::Paper), ref_p,
                                                     ref_r, mask_p, mask_r, c);
                }
                std::lock_guard<std::mutex> lock(mu);
                for (size_t k = 0; k < got.size(); ++k) {
                    Counts& dst = rows[jobs[j].c * 3 * nb + k].counts;
                    if (got[k].checked < 0 || dst.checked < 0) {
                        dst.checked = -1;
                        continue;
                    }
                    for (int v = 0; v < kNumKinds; ++v) dst.v[v] += got[k].v[v];
                    dst.checked += got[k].checked;
                }
            } catch (const std::exception& e) {
                std::lock_guard<std::mutex> lock(mu);
                if (error.empty()) error = list[jobs[j].c].name + ": " + e.what();
            }
            const size_t d = done.fetch_add(1) + 1;
            if (cfg.progress) {
                std::lock_guard<std::mutex> lock(mu);
                std::fprintf(stderr, "\rstability: %zu/%zu (case, transform) jobs done", d, jobs.size());
            }
        }
    };
    const int nthreads = cfg.threads > 0 ? cfg.threads : int(std::max(1u, std::thread::hardware_concurrency()));
    std::vector<std::thread> pool;
    for (int i = 1; i < nthreads; ++i) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    if (cfg.progress) std::fprintf(stderr, "\n");
    if (!error.empty()) throw std::runtime_error(error);
    return rows;
}

namespace {
std::string cell(const Counts& k) {
    if (k.checked < 0) return "n/a";
    if (k.total() == 0) return "0";
    std::ostringstream s;
    s << k.total() << " (";
    bool first = true;
    for (int v = 0; v < kNumKinds; ++v)
        if (k.v[v]) {
            s << (first ? "" : " ") << kind_name(v)[0] << k.v[v];
            first = false;
        }
    s << ")";
    return s.str();
}
}  // namespace

void print_table(std::FILE* out, const std::vector<Row>& rows, const std::vector<int>& bits) {
    std::fprintf(out, "%-30s %-14s", "case", "method");
    for (int b : bits) std::fprintf(out, " %16s", (std::to_string(b) + " bits").c_str());
    std::fprintf(out, "\n");
    for (size_t i = 0; i < rows.size(); i += bits.size()) {
        std::fprintf(out, "%-30s %-14s", rows[i].case_name.c_str(), rows[i].label().c_str());
        for (size_t b = 0; b < bits.size(); ++b) std::fprintf(out, " %16s", cell(rows[i + b].counts).c_str());
        std::fprintf(out, "\n");
    }
    std::fprintf(out, "violations summed over the transforms (h: hole, s: speckle, g: ghost colour, i: lamina "
                      "seen from inside; n/a: the scene does not fit that width)\n");
}

std::string markdown_table(const std::vector<Row>& rows, const std::vector<int>& bits, const std::string& name) {
    std::ostringstream s;
    s << "| method |";
    for (int b : bits) s << " " << b << " bits |";
    s << "\n|---|";
    for (size_t b = 0; b < bits.size(); ++b) s << "---|";
    s << "\n";
    for (size_t i = 0; i < rows.size(); i += bits.size()) {
        if (rows[i].case_name != name) continue;
        s << "| " << rows[i].label() << " |";
        for (size_t b = 0; b < bits.size(); ++b) s << " " << cell(rows[i + b].counts) << " |";
        s << "\n";
    }
    return s.str();
}

}  // namespace stability

int stability_main(int argc, char** argv) {
    using namespace stability;
    Config cfg;
    cfg.progress = true;
    std::string only, md;
    bool quick = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto val = [&]() -> std::string {
            if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
            return argv[++i];
        };
        if (a == "--quick") quick = true;
        else if (a == "--transforms") cfg.transforms = std::stoi(val());
        else if (a == "--case") only = val();
        else if (a == "--md") md = val();
        else if (a == "--root") cfg.root = val();
        else if (a == "--threads") cfg.threads = std::stoi(val());
        else if (a == "--seed") cfg.seed = std::stoull(val());
        else if (a == "--size") {
            const std::string v = val();
            if (std::sscanf(v.c_str(), "%dx%d", &cfg.width, &cfg.height) != 2) throw std::runtime_error("--size WxH");
        } else if (a == "--bits") {
            cfg.bits.clear();
            std::stringstream ss(val());
            for (std::string t; std::getline(ss, t, ',');) cfg.bits.push_back(std::stoi(t));
        } else {
            std::fprintf(stderr, "csgrt stability: unknown option %s\n", a.c_str());
            return 2;
        }
    }
    try {
        std::vector<Case> list;
        for (const Case& c : cases(cfg.root)) {
            if (!only.empty() && c.name.find(only) == std::string::npos) continue;
            if (quick && c.large) continue;
            list.push_back(c);
        }
        if (quick) cfg.transforms = std::min(cfg.transforms, 3);
        std::fprintf(stderr, "stability: %zu cases x %d transforms x %zu widths x {exact paper, exact regular, epsilon}, "
                             "%dx%d pixels\n",
                     list.size(), cfg.transforms, cfg.bits.size(), cfg.width, cfg.height);
        const std::vector<Row> rows = run(cfg, list);
        print_table(stdout, rows, cfg.bits);
        long exact = 0, eps = 0;
        for (const Row& r : rows) (r.method == Method::Exact ? exact : eps) += r.counts.total();
        for (const Case& c : list)
            for (const std::string& p : c.pending)
                std::printf("pending (secondary rays): %s: %s\n", c.name.c_str(), p.c_str());
        std::printf("exact method: %ld violations; epsilon method: %ld violations\n", exact, eps);
        if (!md.empty()) {
            std::FILE* f = std::fopen(md.c_str(), "w");
            if (!f) throw std::runtime_error("cannot write " + md);
            for (const Case& c : list)
                std::fprintf(f, "<!-- case %s -->\n%s\n", c.name.c_str(), markdown_table(rows, cfg.bits, c.name).c_str());
            std::fprintf(f, "<!-- config: %d transforms, %dx%d pixels, seed %llu -->\n", cfg.transforms, cfg.width,
                         cfg.height, (unsigned long long)cfg.seed);
            std::fclose(f);
        }
        return (exact == 0 && eps > 0) ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "csgrt stability: %s\n", e.what());
        return 1;
    }
}

}  // namespace csgrt
