#include "render/png_capture.h"

#include <GL/gl.h>

#include <cstring>
#include <stdexcept>

#include "io/atomic_file.h"
#include "render/gl_context.h"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#endif
#include <stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace mgp::render {

Image readFramebuffer(int width, int height) {
    Image img;
    img.width = width;
    img.height = height;
    img.rgba.resize(static_cast<std::size_t>(width) * height * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
    const std::size_t row = static_cast<std::size_t>(width) * 4;
    std::vector<std::uint8_t> tmp(row);
    for (int y = 0; y < height / 2; ++y) {
        std::uint8_t* a = img.rgba.data() + row * y;
        std::uint8_t* b = img.rgba.data() + row * (height - 1 - y);
        std::memcpy(tmp.data(), a, row);
        std::memcpy(a, b, row);
        std::memcpy(b, tmp.data(), row);
    }
    return img;
}

std::vector<std::uint8_t> encodePng(const Image& image) {
    if (image.width < 1 || image.height < 1 ||
        image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4)
        throw RenderError("PNG encode: expected a non-empty RGBA8 image, found " + std::to_string(image.width) + "x" +
                          std::to_string(image.height) + " with " + std::to_string(image.rgba.size()) + " bytes");

    std::vector<std::uint8_t> out;
    auto sink = [](void* ctx, void* data, int size) {
        auto* v = static_cast<std::vector<std::uint8_t>*>(ctx);
        const auto* p = static_cast<const std::uint8_t*>(data);
        v->insert(v->end(), p, p + size);
    };
    // Frames are opaque: write RGB when every alpha is 255 (a quarter less to filter and deflate).
    bool opaque = true;
    for (std::size_t i = 3; i < image.rgba.size() && opaque; i += 4) opaque = image.rgba[i] == 255;
    std::vector<std::uint8_t> rgb;
    if (opaque) {
        rgb.resize(image.rgba.size() / 4 * 3);
        for (std::size_t p = 0, q = 0; p < image.rgba.size(); p += 4, q += 3) {
            rgb[q] = image.rgba[p];
            rgb[q + 1] = image.rgba[p + 1];
            rgb[q + 2] = image.rgba[p + 2];
        }
    }
    const int channels = opaque ? 3 : 4;
    const void* data = opaque ? static_cast<const void*>(rgb.data()) : static_cast<const void*>(image.rgba.data());
    if (!stbi_write_png_to_func(sink, &out, image.width, image.height, channels, data, image.width * channels))
        throw RenderError("PNG encode failed");
    return out;
}

void writePng(const Image& image, const std::string& path) {
    const std::vector<std::uint8_t> bytes = encodePng(image);
    try {
        writeFileAtomically(path, std::string(bytes.begin(), bytes.end()));
    } catch (const std::runtime_error& e) {
        throw RenderError(std::string("cannot write PNG: ") + e.what());
    }
}

}  // namespace mgp::render
