// image.cpp — OpenImageIO glue for image.h.
#include "image.h"

#include <OpenImageIO/imageio.h>

#include <stdexcept>

namespace csgrt {

void write_image(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) throw std::runtime_error("cannot write " + path + ": " + OIIO::geterror());
    OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
    if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::UINT8, rgb.data()) || !out->close())
        throw std::runtime_error("cannot write " + path + ": " + out->geterror());
}

ImageRGB8 read_image(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error("cannot read " + path + ": " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    ImageRGB8 img;
    img.width = spec.width;
    img.height = spec.height;
    std::vector<uint8_t> all(size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, all.data()))
        throw std::runtime_error("cannot read " + path + ": " + in->geterror());
    img.rgb.resize(size_t(spec.width) * spec.height * 3);
    for (size_t i = 0; i < size_t(spec.width) * spec.height; ++i)
        for (int c = 0; c < 3; ++c)
            img.rgb[i * 3 + c] = all[i * spec.nchannels + std::min(c, spec.nchannels - 1)];
    return img;
}

}  // namespace csgrt
