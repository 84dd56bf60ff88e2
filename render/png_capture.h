#pragma once
// Reading the current framebuffer back and writing it as PNG (stb_image_write, libstb-dev).
// Images are RGBA8, rows top to bottom (GL's bottom-up rows are flipped on read).
#include <cstdint>
#include <string>
#include <vector>

namespace mgp::render {

struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // width*height*4, first row = top of the picture
};

// Reads framebuffer 0 (or the currently bound read framebuffer) of the current context.
Image readFramebuffer(int width, int height);

// Encodes to PNG bytes in memory (deterministic: same pixels -> same bytes). An image whose
// alpha is 255 everywhere is written as RGB.
std::vector<std::uint8_t> encodePng(const Image& image);

// Writes PNG atomically: to "<path>.tmp-<pid>" then rename, so a crash never leaves a half-written
// file. Throws RenderError naming the path on failure.
void writePng(const Image& image, const std::string& path);

}  // namespace mgp::render
