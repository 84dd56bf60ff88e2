#include "ui/shell/frame_signature.h"

#include <imgui.h>

#include <cstring>
#include <functional>
#include <string_view>

namespace mgp::ui {

namespace {

// Mixes `v` into `h` (boost::hash_combine's constant, widened to 64 bits).
void combine(std::uint64_t& h, std::uint64_t v) { h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2); }

template <typename T>
std::uint64_t bytesHash(const T* data, int count) {
    return std::hash<std::string_view>{}(
        std::string_view(reinterpret_cast<const char*>(data), sizeof(T) * static_cast<std::size_t>(count)));
}

std::uint64_t floatBits(float f) {
    std::uint32_t u = 0;
    static_assert(sizeof u == sizeof f);
    std::memcpy(&u, &f, sizeof u);
    return u;
}

}  // namespace

std::uint64_t frameSignature(const ImDrawData& data, std::initializer_list<std::int64_t> imageVersions) {
    std::uint64_t h = 0;
    for (std::int64_t v : imageVersions) combine(h, static_cast<std::uint64_t>(v));
    for (float f : {data.DisplayPos.x, data.DisplayPos.y, data.DisplaySize.x, data.DisplaySize.y,
                    data.FramebufferScale.x, data.FramebufferScale.y})
        combine(h, floatBits(f));
    combine(h, static_cast<std::uint64_t>(data.CmdListsCount));
    for (int l = 0; l < data.CmdListsCount; ++l) {
        const ImDrawList& list = *data.CmdLists[l];
        combine(h, bytesHash(list.VtxBuffer.Data, list.VtxBuffer.Size));
        combine(h, bytesHash(list.IdxBuffer.Data, list.IdxBuffer.Size));
        combine(h, static_cast<std::uint64_t>(list.CmdBuffer.Size));
        for (const ImDrawCmd& c : list.CmdBuffer) {
            for (float f : {c.ClipRect.x, c.ClipRect.y, c.ClipRect.z, c.ClipRect.w}) combine(h, floatBits(f));
            combine(h, reinterpret_cast<std::uintptr_t>(c.TextureId));
            combine(h, c.VtxOffset);
            combine(h, c.IdxOffset);
            combine(h, c.ElemCount);
            combine(h, reinterpret_cast<std::uintptr_t>(c.UserCallback));
            combine(h, reinterpret_cast<std::uintptr_t>(c.UserCallbackData));
        }
    }
    return h;
}

}  // namespace mgp::ui
