#pragma once
// stb_image for the GL tests (reading PNGs back), with its own warnings silenced. The
// implementation is compiled once, in test_golden.cpp (STB_IMAGE_IMPLEMENTATION).
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#endif
#include <stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
