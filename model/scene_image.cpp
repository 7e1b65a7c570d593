// scene_image.cpp — encoding and decoding of the binary scene image.
#include "scene_image.h"

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace csgrt {

namespace {

// A 64-bit signed value as two words, low word first.
void put64(std::vector<uint32_t>& w, i64 v) {
    w.push_back(uint32_t(u64(v)));
    w.push_back(uint32_t(u64(v) >> 32));
}
i64 get64(const std::vector<uint32_t>& w, size_t& i) {
    const u64 lo = w.at(i), hi = w.at(i + 1);
    i += 2;
    return i64(lo | (hi << 32));
}
// Values that fit 32 bits are stored sign-extended in one word.
void put32(std::vector<uint32_t>& w, i64 v) {
    if (v < INT32_MIN || v > INT32_MAX) throw std::logic_error("scene image: value does not fit 32 bits");
    w.push_back(uint32_t(int32_t(v)));
}
i64 get32(const std::vector<uint32_t>& w, size_t& i) { return int32_t(w.at(i++)); }

}  // namespace

std::vector<uint32_t> encode_scene_image(const CompiledScene& cs) {
    std::vector<uint32_t> w(kHeaderWords, 0);
    w[H_MAGIC] = kSceneMagic;
    w[H_VERSION] = kSceneVersion;
    w[H_BITS] = uint32_t(cs.fmt.bits);
    w[H_SIZE] = uint32_t(cs.width) | (uint32_t(cs.height) << 16);
    w[H_LEAVES] = uint32_t(cs.leaves.size());
    w[H_PROGRAM] = uint32_t(cs.program.size());
    w[H_MATERIALS] = uint32_t(cs.materials.size());
    w[H_LIGHTS] = uint32_t(cs.lights.size());
    w[H_MAX_TRACE] = uint32_t(cs.max_trace_level);
    w[H_STACK] = uint32_t(cs.stack_depth);

    w[H_OFF_CAMERA] = uint32_t(w.size());
    for (i64 v : cs.camera.origin_fx) put32(w, v);
    for (const auto* vec : {&cs.camera.base_fx, &cs.camera.dx_fx, &cs.camera.dy_fx})
        for (i64 v : *vec) put64(w, v);
    for (i64 v : cs.background_fx) put32(w, v);

    w[H_OFF_LIGHTS] = uint32_t(w.size());
    for (const LightInfo& l : cs.lights) {
        for (i64 v : l.pos_fx) put32(w, v);
        for (i64 v : l.color_fx) put32(w, v);
        w.push_back(l.shadowless ? kLightShadowless : 0);
    }
    w[H_OFF_MATERIALS] = uint32_t(w.size());
    for (size_t m = 1; m < cs.materials.size(); ++m) {
        const MaterialInfo& mi = cs.materials[m];
        for (i64 v : mi.rgb) put32(w, v);
        for (i64 v : {mi.filter, mi.ambient, mi.diffuse, mi.phong, mi.reflection, mi.ior, i64(mi.phong_size)})
            put32(w, v);
    }
    w[H_OFF_LEAVES] = uint32_t(w.size());
    for (const LeafInfo& l : cs.leaves) {
        for (i64 v : l.coef) put32(w, v);
        put32(w, l.material);
    }
    w[H_OFF_PROGRAM] = uint32_t(w.size());
    for (const Instr& ins : cs.program) w.push_back(uint32_t(ins.op) | (uint32_t(ins.arg) << 8));
    w[H_OFF_TREE] = uint32_t(w.size());
    w.push_back(uint32_t(cs.layout.height));
    if (cs.layout.height > 0) {
        for (LayoutOp op : cs.layout.node_op) w.push_back(uint32_t(op));
        for (int slot : cs.layout.leaf_slot) w.push_back(uint32_t(slot));
    }
    w[H_TOTAL] = uint32_t(w.size());
    return w;
}

CompiledScene decode_scene_image(const std::vector<uint32_t>& w) {
    if (w.size() < kHeaderWords || w[H_MAGIC] != kSceneMagic)
        throw std::runtime_error("scene image: bad magic (not a csgrt scene image)");
    if (w[H_VERSION] != kSceneVersion)
        throw std::runtime_error("scene image: version " + std::to_string(w[H_VERSION]) + ", expected " +
                                 std::to_string(kSceneVersion));
    if (w[H_TOTAL] != w.size()) throw std::runtime_error("scene image: truncated");
    CompiledScene cs;
    cs.fmt = Formats(int(w[H_BITS]));
    cs.width = int(w[H_SIZE] & 0xffff);
    cs.height = int(w[H_SIZE] >> 16);
    cs.max_trace_level = int(w[H_MAX_TRACE]);
    cs.stack_depth = int(w[H_STACK]);

    size_t i = w[H_OFF_CAMERA];
    for (i64& v : cs.camera.origin_fx) v = get32(w, i);
    for (auto* vec : {&cs.camera.base_fx, &cs.camera.dx_fx, &cs.camera.dy_fx})
        for (i64& v : *vec) v = get64(w, i);
    for (i64& v : cs.background_fx) v = get32(w, i);

    i = w[H_OFF_LIGHTS];
    cs.lights.resize(w[H_LIGHTS]);
    for (LightInfo& l : cs.lights) {
        for (i64& v : l.pos_fx) v = get32(w, i);
        for (i64& v : l.color_fx) v = get32(w, i);
        l.shadowless = (w.at(i++) & kLightShadowless) != 0;
    }
    i = w[H_OFF_MATERIALS];
    cs.materials.resize(w[H_MATERIALS]);
    for (size_t m = 1; m < cs.materials.size(); ++m) {
        MaterialInfo& mi = cs.materials[m];
        for (i64& v : mi.rgb) v = get32(w, i);
        for (i64* v : {&mi.filter, &mi.ambient, &mi.diffuse, &mi.phong, &mi.reflection, &mi.ior}) *v = get32(w, i);
        mi.phong_size = int(get32(w, i));
    }
    i = w[H_OFF_LEAVES];
    cs.leaves.resize(w[H_LEAVES]);
    for (LeafInfo& l : cs.leaves) {
        for (i64& v : l.coef) v = get32(w, i);
        l.material = int(get32(w, i));
        cs.leaf_material.push_back(uint8_t(l.material));
    }
    i = w[H_OFF_PROGRAM];
    for (uint32_t k = 0; k < w[H_PROGRAM]; ++k) {
        const uint32_t v = w.at(i++);
        cs.program.push_back({Op(v & 0xff), uint16_t(v >> 8)});
    }
    cs.class_tree = ClassTree(cs.program);
    i = w[H_OFF_TREE];
    cs.layout.height = int(w.at(i++));
    if (cs.layout.height > 0) {
        cs.layout.node_op.resize(size_t(1) << cs.layout.height);
        for (LayoutOp& op : cs.layout.node_op) op = LayoutOp(w.at(i++));
        cs.layout.leaf_slot.resize(cs.leaves.size());
        for (int& slot : cs.layout.leaf_slot) slot = int(w.at(i++));
    }
    return cs;
}

void write_scene_image(const CompiledScene& cs, const std::string& path_bin, const std::string& path_hex) {
    const std::vector<uint32_t> w = encode_scene_image(cs);
    if (!path_bin.empty()) {
        std::ofstream f(path_bin, std::ios::binary);
        for (uint32_t v : w) {
            const unsigned char b[4] = {uint8_t(v), uint8_t(v >> 8), uint8_t(v >> 16), uint8_t(v >> 24)};
            f.write(reinterpret_cast<const char*>(b), 4);
        }
        if (!f) throw std::runtime_error("cannot write " + path_bin);
    }
    if (!path_hex.empty()) {
        FILE* f = std::fopen(path_hex.c_str(), "w");
        if (!f) throw std::runtime_error("cannot write " + path_hex);
        for (uint32_t v : w) std::fprintf(f, "%08x\n", v);
        std::fclose(f);
    }
}

std::vector<uint32_t> read_scene_image(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw std::runtime_error("cannot read " + path);
    std::vector<uint32_t> w;
    unsigned char b[4];
    while (f.read(reinterpret_cast<char*>(b), 4))
        w.push_back(uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24);
    return w;
}

}  // namespace csgrt
