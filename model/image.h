// image.h — reading and writing 8-bit RGB images through OpenImageIO.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace csgrt {

struct ImageRGB8 {
    int width = 0, height = 0;
    std::vector<uint8_t> rgb;   // width * height * 3, row 0 at the top
};

// Writes PNG (or any format OIIO knows from the extension). Throws
// std::runtime_error with OIIO's message on failure.
void write_image(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb);

// Reads any image OIIO can read, converted to 8-bit RGB.
ImageRGB8 read_image(const std::string& path);

}  // namespace csgrt
