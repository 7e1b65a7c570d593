// scene_image.h — the binary scene image: the compiled, quantised scene as a
// flat array of 32-bit words, the one file that both the golden model and
// the RTL load (docs/scene-image.md gives the layout word by word).
#pragma once

#include "compile.h"

#include <cstdint>
#include <string>
#include <vector>

namespace csgrt {

constexpr uint32_t kSceneMagic = 0x52475343;   // "CSGR" little-endian
constexpr uint32_t kSceneVersion = 2;   // 2: a light has a flags word (shadowless)

// Header word indices.
enum SceneHeader {
    H_MAGIC, H_VERSION, H_BITS, H_SIZE /* width | height << 16 */, H_LEAVES, H_PROGRAM, H_MATERIALS,
    H_LIGHTS, H_MAX_TRACE, H_STACK, H_OFF_CAMERA, H_OFF_LIGHTS, H_OFF_MATERIALS, H_OFF_LEAVES,
    H_OFF_PROGRAM, H_OFF_TREE, H_TOTAL, kHeaderWords
};
constexpr int kCameraWords = 3 + 3 * 3 * 2 + 3;   // origin, base/dx/dy (2 words each), background
constexpr int kLightWords = 7;                    // position, colour, flags
constexpr uint32_t kLightShadowless = 1;         // light flags bit 0: casts no shadows
constexpr int kMaterialWords = 10;                // rgb, filter, ambient, diffuse, phong, reflection, ior, phong_size
constexpr int kLeafWords = kNumCoefs + 1;         // coefficients, material

std::vector<uint32_t> encode_scene_image(const CompiledScene& cs);

// Decodes the fixed-point parts (the double parts stay empty). Throws
// std::runtime_error on a malformed image.
CompiledScene decode_scene_image(const std::vector<uint32_t>& words);

void write_scene_image(const CompiledScene& cs, const std::string& path_bin, const std::string& path_hex);
std::vector<uint32_t> read_scene_image(const std::string& path_bin);

}  // namespace csgrt
