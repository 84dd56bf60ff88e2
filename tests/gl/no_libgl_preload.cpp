// LD_PRELOAD shim for one test (test_gui_command_line.cpp): the machine without a GLX library.
// dlopen("libGL.so.1") fails as it does there, with the dynamic loader's own message; every other
// library opens as usual. Dear ImGui's OpenGL loader asks for exactly that name.
#include <dlfcn.h>

#include <cstring>

extern "C" void* dlopen(const char* file, int mode) noexcept {
    static auto* const real = reinterpret_cast<void* (*)(const char*, int)>(dlsym(RTLD_NEXT, "dlopen"));
    if (file && std::strcmp(file, "libGL.so.1") == 0) return real("/nonexistent/libGL.so.1", mode);
    return real(file, mode);
}
