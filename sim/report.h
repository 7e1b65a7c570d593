// report.h — the readable first-mismatch report shared by `make sim` and the
// frame testbench: the pixel, both sides' colours, and for the pixel's ray
// the model's sorted events, origin flags and classification beside what
// the RTL's intersection unit and walk unit produced.
#pragma once

#include "render.h"
#include "top_sim.h"

#include <sstream>
#include <string>

namespace csgrt_sim {

inline const char* range_name(int r) { return r == 0 ? "-inf" : r == 2 ? "+inf" : ""; }

// model_rgb < 0: the model's colour of the primary ray alone (builds
// without effects); else the model's colour with the build's effects (the
// ray details below are the primary ray's).
inline std::string mismatch_report(const csgrt::CompiledScene& cs, csgrt::TiePolicy ties, int x, int y,
                                   uint32_t rtl_rgb, const RayLog* rtl, int64_t model_with_effects = -1) {
    using namespace csgrt;
    std::ostringstream s;
    const PixelTrace pt = render_pixel_fx(cs, x, y, ties, true);
    const uint32_t model_rgb = model_with_effects >= 0 ? uint32_t(model_with_effects)
                                                       : uint32_t(pt.rgb[0]) << 16 | uint32_t(pt.rgb[1]) << 8 | pt.rgb[2];
    char buf[256];
    std::snprintf(buf, sizeof buf, "first mismatch at pixel (%d,%d): RTL rgb %06x, model rgb %06x\n", x, y, rtl_rgb,
                  model_rgb);
    s << buf;
    s << "  ray o = (" << pt.ray.o[0] << ", " << pt.ray.o[1] << ", " << pt.ray.o[2] << ") d = (" << pt.ray.d[0]
      << ", " << pt.ray.d[1] << ", " << pt.ray.d[2] << ")\n";
    s << "  model origin flags: ";
    for (uint8_t f : pt.trace.origin_flags) s << int(f);
    s << "\n  model events ahead (sorted, ties " << (ties == TiePolicy::Paper ? "paper" : "regular") << "):\n";
    for (const auto& e : pt.trace.events)
        s << "    t " << e.t << " leaf " << e.leaf << (e.entering ? " entering" : " leaving") << "\n";
    s << "  model hit: " << (pt.trace.hit ? "yes" : "no");
    if (pt.trace.hit)
        s << " t " << pt.trace.t << " leaf " << pt.trace.leaf << (pt.trace.entering ? " entering " : " leaving ")
          << pt.trace.border.str();
    s << "\n";
    if (!rtl) {
        s << "  (no RTL log kept for this ray" << (model_with_effects >= 0 ? ": secondary rays interleave" : "")
          << ")\n";
        return s.str();
    }
    s << "  RTL intersection results (leaf: count, events, inside at -inf):\n";
    for (const LeafResultLog& r : rtl->results) {
        const LeafEvents<i64> m = intersect_fx(cs.fmt, cs.leaves[r.leaf].coef, pt.ray);
        s << "    leaf " << r.leaf << " slot " << r.slot << ": " << r.count;
        for (int k = 0; k < r.count && k < 2; ++k) {
            const int64_t t = k ? r.t1 : r.t0;
            const int rg = k ? r.range1 : r.range0;
            s << (k ? ", " : " [") << (rg == 1 ? std::to_string(t) : range_name(rg))
              << ((k ? r.enter1 : r.enter0) ? " in" : " out");
        }
        s << (r.count ? "]" : "") << " inside " << r.inside;
        bool same = m.count == r.count && m.inside_at_minus_inf == bool(r.inside);
        for (int k = 0; same && k < m.count; ++k) {
            const int64_t t = k ? r.t1 : r.t0;
            same = int(m.ev[k].range) == (k ? r.range1 : r.range0) && m.ev[k].entering == bool(k ? r.enter1 : r.enter0) &&
                   (m.ev[k].range != TRange::Finite || m.ev[k].t == t);
        }
        s << (same ? "" : "   <-- model differs") << "\n";
    }
    if (rtl->has_hit_record) {
        s << "  RTL hit: " << (rtl->hit ? "yes" : "no");
        if (rtl->hit)
            s << " t " << rtl->t << " leaf " << rtl->leaf << (rtl->entering ? " entering" : " leaving") << " BORDER "
              << rtl->from << "," << rtl->to;
        s << "\n";
    }
    return s.str();
}

}  // namespace csgrt_sim
