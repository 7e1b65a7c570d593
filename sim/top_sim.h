// top_sim.h — the one harness that drives a Verilated csgrt_top: reset, load
// a scene image through the load port, render a frame with optional random
// back-pressure on the pixel stream, collect pixels and statistics, and
// keep a log of the last rays' intersection results and hit records for
// mismatch reports. Used by `make sim` (sim/sim_main.cpp) and by the frame
// testbench (tb/frame/).
//
// The top must be Verilated with --public so that the log can read the
// intersection unit's output and the walk unit's hit records.
#pragma once

#include <verilated.h>
#if VM_TRACE_FST   // Verilated with --trace-fst (make sim; the frame benches are not)
#include <verilated_fst_c.h>
#endif

#include <cstdint>
#include <cstdio>
#include <deque>
#include <functional>
#include <memory>
#include <random>
#include <stdexcept>
#include <sstream>
#include <string>
#include <vector>

namespace csgrt_sim {

struct LeafResultLog {
    int leaf, slot, count, inside;
    int64_t t0, t1;
    int range0, range1, enter0, enter1;
};
struct RayLog {
    std::vector<LeafResultLog> results;
    bool has_hit_record = false;
    int hit = 0, leaf = 0, entering = 0, from = 0, to = 0;
    int64_t t = 0;
};

struct SimStats {
    uint64_t cycles = 0;        // csgrt_top's own count, start to last pixel
    uint64_t pairs = 0;         // ray-primitive pairs issued
    uint64_t total_cycles = 0;  // everything the harness clocked, loading included
    double wall_seconds = 0;
};

inline int64_t sign_extend(uint64_t v, int bits) {
    const uint64_t m = uint64_t(1) << (bits - 1);
    v &= (bits == 64) ? ~uint64_t(0) : ((uint64_t(1) << bits) - 1);
    return int64_t((v ^ m) - m);
}

template <class Top>
class TopSim {
  public:
    // `lanes`: the top's NUM_UNITS. With more than one lane only the hit
    // records are logged (the results signals show lane 0 alone).
    TopSim(int bits, int leaf_bits, int tree_height, int lanes = 1, const std::string& fst_path = "")
        : bits_(bits), leaf_bits_(leaf_bits), tree_height_(tree_height), log_results_(lanes == 1),
          ctx_(new VerilatedContext) {
        ctx_->randReset(2);
#if VM_TRACE_FST
        if (!fst_path.empty()) ctx_->traceEverOn(true);
        top_.reset(new Top(ctx_.get()));
        if (!fst_path.empty()) {
            fst_.reset(new VerilatedFstC);
            top_->trace(fst_.get(), 99);
            fst_->open(fst_path.c_str());
        }
#else
        if (!fst_path.empty()) throw std::runtime_error("this build has no waveform tracing (Verilate with --trace-fst)");
        top_.reset(new Top(ctx_.get()));
#endif
    }
    ~TopSim() {
#if VM_TRACE_FST
        if (fst_) fst_->close();
#endif
        top_->final();
    }
    Top& top() { return *top_; }

    void tick() {
        top_->clk_i = 0;
        top_->eval();
#if VM_TRACE_FST
        if (fst_) fst_->dump(time_++);
#endif
        top_->clk_i = 1;
        top_->eval();
#if VM_TRACE_FST
        if (fst_) fst_->dump(time_++);
#endif
        ++cycles_;
    }

    void reset() {
        top_->rst_ni = 0;
        top_->load_valid_i = 0;
        top_->start_i = 0;
        top_->pix_ready_i = 0;
        for (int i = 0; i < 4; ++i) tick();
        top_->rst_ni = 1;
        tick();
    }

    // Loads the scene image; returns the loader's error code (0: none).
    int load(const std::vector<uint32_t>& words) {
        for (uint32_t w : words) {
            top_->load_valid_i = 1;
            top_->load_word_i = w;
            do tick(); while (!top_->load_ready_o);
        }
        top_->load_valid_i = 0;
        // the loader's pipeline (three stages) finishes the last word a few
        // clocks after taking it
        for (int i = 0; i < 8 && !top_->loaded_o; ++i) tick();
        if (!top_->loaded_o) return 15;
        return top_->load_error_o;
    }

    // Renders one frame. `pixel(x, y, rgb)` receives each pixel in order;
    // `ready_percent` < 100 applies random back-pressure. `progress(row)`
    // is called when a row completes. Returns false on a timeout.
    bool render(int width, int height, bool ties_regular, int ready_percent,
                const std::function<void(int, int, uint32_t)>& pixel, const std::function<void(int)>& progress,
                SimStats& stats, uint64_t max_cycles) {
        std::mt19937 rng(12345);
        top_->ties_regular_i = ties_regular;
        top_->start_i = 1;
        tick();
        top_->start_i = 0;
        const uint64_t start = cycles_;
        const size_t npix = size_t(width) * height;
        size_t got = 0;
        while (got < npix) {
            top_->pix_ready_i = (ready_percent >= 100) || int(rng() % 100) < ready_percent;
            top_->eval();
            const bool fire = top_->pix_valid_o && top_->pix_ready_i;
            const int x = top_->pix_x_o, y = top_->pix_y_o;
            const uint32_t rgb = top_->pix_rgb_o;
            log_signals();
            tick();
            if (fire) {
                pixel(x, y, rgb);
                ++got;
                if (x == width - 1 && progress) progress(y);
            }
            if (cycles_ - start > max_cycles) return false;
        }
        top_->pix_ready_i = 0;
        for (int i = 0; i < 4; ++i) tick();
        stats.cycles = top_->stat_cycles_o;
        stats.pairs = top_->stat_pairs_o;
        stats.total_cycles = cycles_;
        return true;
    }

    // The logs of the most recent rays, oldest first; ray_index() of the
    // newest. Rays are numbered in raster order from 0.
    const std::deque<RayLog>& ray_logs() const { return logs_; }
    uint64_t first_logged_ray() const { return first_logged_; }
    const RayLog* log_for(uint64_t ray) const {
        if (ray < first_logged_ || ray >= first_logged_ + logs_.size()) return nullptr;
        return &logs_[ray - first_logged_];
    }
    void set_logging(bool on) { logging_ = on; }

  private:
    RayLog& log_at(uint64_t ray) {
        while (first_logged_ + logs_.size() <= ray) logs_.emplace_back();
        while (logs_.size() > kKeepRays) {
            logs_.pop_front();
            ++first_logged_;
        }
        return logs_[ray - first_logged_];
    }

    // Reads the intersection unit's results and the walk unit's hit
    // records as they are handed on (before the clock edge).
    void log_signals() {
        if (!logging_) return;
        auto* r = top_->rootp;
        if (log_results_ && r->csgrt_top__DOT__res_valid && r->csgrt_top__DOT__res_ready) {
            const uint64_t side = r->csgrt_top__DOT__res_side;
            LeafResultLog lr;
            lr.leaf = int(side & ((1u << leaf_bits_) - 1));
            lr.slot = int((side >> leaf_bits_) & ((1u << tree_height_) - 1));
            const bool last = (side >> (leaf_bits_ + tree_height_)) & 1;
            lr.count = r->csgrt_top__DOT__res_count;
            lr.inside = r->csgrt_top__DOT__res_inside;
            lr.t0 = sign_extend(r->csgrt_top__DOT__res_t0, bits_ - 1);
            lr.t1 = sign_extend(r->csgrt_top__DOT__res_t1, bits_ - 1);
            lr.range0 = r->csgrt_top__DOT__res_range0;
            lr.range1 = r->csgrt_top__DOT__res_range1;
            lr.enter0 = r->csgrt_top__DOT__res_enter0;
            lr.enter1 = r->csgrt_top__DOT__res_enter1;
            log_at(results_ray_).results.push_back(lr);
            if (last) ++results_ray_;
        }
        if (r->csgrt_top__DOT__hit_valid && r->csgrt_top__DOT__hit_ready) {
            RayLog& l = log_at(hits_ray_++);
            l.has_hit_record = true;
            l.hit = r->csgrt_top__DOT__hit_hit;
            l.t = sign_extend(r->csgrt_top__DOT__hit_t, bits_ - 1);
            l.leaf = r->csgrt_top__DOT__hit_leaf;
            l.entering = r->csgrt_top__DOT__hit_entering;
            l.from = r->csgrt_top__DOT__hit_from;
            l.to = r->csgrt_top__DOT__hit_to;
        }
    }

    static constexpr size_t kKeepRays = 4096;
    int bits_, leaf_bits_, tree_height_;
    bool log_results_;
    std::unique_ptr<VerilatedContext> ctx_;
    std::unique_ptr<Top> top_;
#if VM_TRACE_FST
    std::unique_ptr<VerilatedFstC> fst_;
#endif
    uint64_t time_ = 0, cycles_ = 0;
    bool logging_ = true;
    std::deque<RayLog> logs_;
    uint64_t first_logged_ = 0, results_ray_ = 0, hits_ray_ = 0;
};

}  // namespace csgrt_sim
