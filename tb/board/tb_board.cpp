// tb_board.cpp — the ULX3S board top (rtl/board/ulx3s/csgrt_ulx3s.v) end to
// end in Verilator: a bit-level UART model drives the FPGA's receive pin
// (ftdi_txd) and decodes its transmit pin (ftdi_rxd); the PLL is the
// behavioural tb/ecp5/EHXPLLL.v (CLKOP = CLKI), and csgrt_mul is built as
// on the FPGA (CSGRT_ECP5_DSP: MULT18X18D tiles, modelled by
// tb/ecp5/MULT18X18D.v). The host protocol of docs/fpga.md: identify, a
// scene image in, status, the pixels and the cycle count out; each frame
// pixel for pixel against the golden model rendering the very same image;
// a refused image and recovery after it.
// Built with -GUART_DIV=BOARD_UART_DIV (a few clocks per bit, so that a frame
// takes seconds) and a short IDLE_CLOCKS.
#include "Vcsgrt_ulx3s.h"
#include "compile.h"
#include "parse.h"
#include "raytree.h"
#include "render.h"
#include "scene_image.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

using namespace csgrt;

namespace {

const int kDiv = BOARD_UART_DIV;          // clocks per bit, as the top was built
const int kIdle = BOARD_IDLE_CLOCKS;      // the top's IDLE_CLOCKS

// The board and the host's end of the serial line, one bit period = kDiv clocks.
class Board {
  public:
    Board() : ctx_(new VerilatedContext) {
        ctx_->randReset(2);
        top_.reset(new Vcsgrt_ulx3s(ctx_.get()));
        top_->btn = 1;        // btn[0] released (high)
        top_->ftdi_txd = 1;   // line idle
        for (int i = 0; i < 64; ++i) tick();
    }
    ~Board() { top_->final(); }

    void tick() {
        // host -> FPGA: the next bit of the queued bytes
        if (tx_phase_ == 0 && tx_bits_.empty() && !tx_bytes_.empty()) {
            const uint8_t b = tx_bytes_.front();
            tx_bytes_.pop_front();
            tx_bits_.push_back(0);
            for (int i = 0; i < 8; ++i) tx_bits_.push_back((b >> i) & 1);
            tx_bits_.push_back(1);
        }
        top_->ftdi_txd = tx_bits_.empty() ? 1 : tx_bits_.front();
        top_->clk_25mhz = 0;
        top_->eval();
        top_->clk_25mhz = 1;
        top_->eval();
        ++cycles_;
        if (!tx_bits_.empty() && ++tx_phase_ == kDiv) {
            tx_phase_ = 0;
            tx_bits_.pop_front();
        }
        // FPGA -> host: sample in the middle of each bit
        const int line = top_->ftdi_rxd;
        if (rx_bit_ < 0) {
            if (!line) { rx_bit_ = 0; rx_count_ = kDiv / 2; }
        } else if (--rx_count_ == 0) {
            rx_count_ = kDiv;
            if (rx_bit_ == 0) {
                if (line) rx_bit_ = -1;      // not a start bit
                else ++rx_bit_;
            } else if (rx_bit_ <= 8) {
                rx_shift_ = uint8_t((rx_shift_ >> 1) | (line << 7));
                ++rx_bit_;
            } else {
                if (line) received_.push_back(rx_shift_);
                else ++framing_errors_;
                rx_bit_ = -1;
            }
        }
    }

    void send(const std::vector<uint8_t>& bytes) { tx_bytes_.insert(tx_bytes_.end(), bytes.begin(), bytes.end()); }
    void send_words(const std::vector<uint32_t>& words) {
        for (uint32_t w : words)
            for (int i = 0; i < 4; ++i) tx_bytes_.push_back(uint8_t(w >> (8 * i)));
    }
    bool sending() const { return !tx_bytes_.empty() || !tx_bits_.empty(); }

    // Clocks until n bytes have arrived from the FPGA (false: timeout).
    bool receive(size_t n, uint64_t max_cycles) {
        const uint64_t end = cycles_ + max_cycles;
        while (received_.size() < n && cycles_ < end) tick();
        return received_.size() >= n;
    }
    std::vector<uint8_t> take(size_t n) {
        std::vector<uint8_t> v(received_.begin(), received_.begin() + std::min(n, received_.size()));
        received_.erase(received_.begin(), received_.begin() + v.size());
        return v;
    }
    void idle(uint64_t n) { for (uint64_t i = 0; i < n; ++i) tick(); }
    void clear() { received_.clear(); framing_errors_ = 0; }
    size_t pending() const { return received_.size(); }
    int framing_errors() const { return framing_errors_; }
    uint64_t cycles() const { return cycles_; }
    Vcsgrt_ulx3s& top() { return *top_; }

  private:
    std::unique_ptr<VerilatedContext> ctx_;
    std::unique_ptr<Vcsgrt_ulx3s> top_;
    uint64_t cycles_ = 0;
    std::deque<uint8_t> tx_bytes_;
    std::deque<int> tx_bits_;
    int tx_phase_ = 0;
    int rx_bit_ = -1, rx_count_ = 0, framing_errors_ = 0;
    uint8_t rx_shift_ = 0;
    std::deque<uint8_t> received_;
};

std::vector<uint32_t> compile_words(const Scene& s, int w, int h, int bits = BOARD_BITS) {
    CompileOptions o;
    o.bits = bits;
    o.width = w;
    o.height = h;
    o.max_leaves = 64;
    o.tree_height = 8;
    return encode_scene_image(compile_scene(s, o));
}

Scene scene_file(const std::string& name) { return parse_scene_file("scenes/" + name + ".pov"); }

// One P / R command with the image; the frame must equal the model's.
void expect_frame(Board& b, const std::string& name, const std::vector<uint32_t>& words, TiePolicy ties) {
    const CompiledScene cs = decode_scene_image(words);
    RenderOptions ro;
    ro.ties = ties;
    ro.threads = 1;
    ro.effects = rtl_effects(cs, false, false, false, true);   // the units of this build: specular only
    const Frame model = render(cs, ro);
    const size_t n = size_t(cs.width) * cs.height;

    const uint64_t start = b.cycles();
    b.send({uint8_t(ties == TiePolicy::Regular ? 'R' : 'P')});
    b.send_words(words);
    const uint64_t budget = uint64_t(words.size() * 4 + n * 3 + 64) * 10 * kDiv + n * 20000;
    ASSERT_TRUE(b.receive(2, budget)) << name << ": no status";
    const std::vector<uint8_t> status = b.take(2);
    ASSERT_EQ(status[0], 0xA5);
    ASSERT_EQ(status[1], 0) << name << ": the board refused the image";
    ASSERT_TRUE(b.receive(n * 3 + 8, budget)) << name << ": got " << b.pending() << " of " << n * 3 + 8 << " bytes";
    const std::vector<uint8_t> pix = b.take(n * 3);
    const std::vector<uint8_t> trailer = b.take(8);
    size_t matched = 0;
    std::string first;
    for (size_t i = 0; i < n; ++i) {
        const bool eq = pix[3 * i] == model.rgb[3 * i] && pix[3 * i + 1] == model.rgb[3 * i + 1] &&
                        pix[3 * i + 2] == model.rgb[3 * i + 2];
        matched += eq;
        if (!eq && first.empty()) {
            char buf[160];
            std::snprintf(buf, sizeof buf, "first mismatch at (%zu, %zu): board %02x%02x%02x, model %02x%02x%02x",
                          i % cs.width, i / cs.width, pix[3 * i], pix[3 * i + 1], pix[3 * i + 2], model.rgb[3 * i],
                          model.rgb[3 * i + 1], model.rgb[3 * i + 2]);
            first = buf;
        }
    }
    uint64_t frame_cycles = 0;
    for (int i = 7; i >= 0; --i) frame_cycles = frame_cycles << 8 | trailer[i];
    std::printf("[ board    ] %-8s %dx%d, %2d bits, ties %-7s: matched %zu of %zu pixels; frame %llu cycles "
                "(UART-bound), session %llu cycles\n",
                name.c_str(), cs.width, cs.height, BOARD_BITS, ties == TiePolicy::Paper ? "paper" : "regular", matched,
                n, (unsigned long long)frame_cycles, (unsigned long long)(b.cycles() - start));
    EXPECT_EQ(matched, n) << name << ": " << first;
    EXPECT_GT(frame_cycles, uint64_t(n * 3 * 10 * kDiv) - 64) << "the frame's cycle count";
    EXPECT_EQ(b.framing_errors(), 0);
    b.idle(20 * kDiv);
    EXPECT_EQ(b.pending(), 0u) << "bytes after the trailer";
}

}  // namespace

TEST(Board, IdentifiesItself) {
    Board b;
    b.send({'I'});
    ASSERT_TRUE(b.receive(6, 200 * kDiv));
    const std::vector<uint8_t> r = b.take(6);
    // EFFECTS: no shadow, reflection or refraction unit; the specular unit (bit 3)
    EXPECT_EQ(r, (std::vector<uint8_t>{0xA5, 'I', uint8_t(BOARD_BITS), 64, 8, 8}));
    EXPECT_TRUE(b.top().led & 1) << "PLL lock LED";
}

TEST(Board, DefaultSceneThenBasicPixelExact) {
    Board b;
    expect_frame(b, "default", compile_words(scene_file("default"), 16, 12), TiePolicy::Paper);
    expect_frame(b, "basic", compile_words(scene_file("basic"), 12, 9), TiePolicy::Regular);
}

TEST(Board, RefusesAnImageAndRecovers) {
    Board b;
    std::vector<uint32_t> bad = compile_words(scene_file("basic"), 8, 6);
    bad[H_BITS] = BOARD_BITS == 24 ? 16 : 24;       // compiled for another width
    b.send({'P'});
    b.send_words(bad);
    ASSERT_TRUE(b.receive(2, 200 * kDiv));
    EXPECT_EQ(b.take(2), (std::vector<uint8_t>{0xA5, 2}));
    while (b.sending()) b.tick();                   // the host sends the rest anyway
    b.idle(kIdle + 100);                            // the board discards it until the line is idle
    EXPECT_EQ(b.pending(), 0u);
    EXPECT_TRUE(b.top().led & 0x08) << "refused-image LED";
    expect_frame(b, "basic", compile_words(scene_file("basic"), 8, 6), TiePolicy::Paper);
}

TEST(Board, ResetButtonAbortsAFrame) {
    Board b;
    b.send({'P'});
    b.send_words(compile_words(scene_file("basic"), 8, 6));
    ASSERT_TRUE(b.receive(8, 200000 * kDiv));       // status and two pixels
    b.take(8);
    b.top().btn = 0;                                // press PWR
    b.idle(100);
    b.top().btn = 1;
    b.idle(30 * 10 * kDiv);                         // whatever byte was on the line ends
    b.clear();                                      // a byte cut short by the reset
    expect_frame(b, "basic", compile_words(scene_file("basic"), 8, 6), TiePolicy::Paper);
}
