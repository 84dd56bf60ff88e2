#pragma once
// What one UI frame would put on the screen, as a 64-bit hash: ImGui's draw data (vertices,
// indices, draw commands with their clip rectangles and textures, the display rectangle) and the
// versions of the GL images the draw data shows by reference (the viewport's scene, the latent
// map's textures). Two frames with the same signature draw the same pixels, so the second need
// not be rasterised again (docs/architecture.md §3, "Present"): on llvmpipe the viewport's blit and
// ImGui's rendering take about 13 ms of a frame.
#include <cstdint>
#include <initializer_list>

struct ImDrawData;

namespace mgp::ui {

std::uint64_t frameSignature(const ImDrawData& data, std::initializer_list<std::int64_t> imageVersions);

}  // namespace mgp::ui
