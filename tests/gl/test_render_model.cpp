// `motiongp render MODEL`: the model's source clip, showing the model's reconstruction f(x_t).
#include <doctest/doctest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "stb_image_include.h"
#include "test_paths.h"

namespace fs = std::filesystem;

TEST_CASE("render MODEL draws the model's reconstruction, with no display") {
    const std::string mocap = MOTIONGP_TEST_MOCAP;
    REQUIRE_MESSAGE(fs::exists(mocap + "/asf_amc/35_01.amc"), "the mocap folder is missing: " << mocap);
    const std::string dir = std::string(MOTIONGP_GL_OUT_DIR) + "/render_model_" + std::to_string(::getpid());
    fs::create_directories(dir);
    const std::string bin = std::string("env -u DISPLAY -u WAYLAND_DISPLAY '") + MOTIONGP_TEST_BINARY + "' ";
    REQUIRE(std::system((bin + "train '" + mocap + "/asf_amc/35_01.amc' --frames 1:120 --active 60 --iters 1 --out '" +
                         dir + "/walk.model' > /dev/null 2>&1")
                            .c_str()) == 0);
    const std::string common = " --frame 40 --size 200x150 --camera side";
    REQUIRE(std::system((bin + "render '" + dir + "/walk.model'" + common + " --ghost-captured --out '" + dir +
                         "/model.png' > /dev/null")
                            .c_str()) == 0);
    REQUIRE(std::system((bin + "render '" + mocap + "/asf_amc/35_01.amc'" + common + " --out '" + dir +
                         "/clip.png' > /dev/null")
                            .c_str()) == 0);
    int w = 0, h = 0, n = 0;
    REQUIRE(stbi_info((dir + "/model.png").c_str(), &w, &h, &n));
    CHECK(w == 200);
    CHECK(h == 150);
    auto bytes = [](const std::string& p) {
        std::ifstream f(p, std::ios::binary);
        return std::vector<char>(std::istreambuf_iterator<char>(f), {});
    };
    CHECK(bytes(dir + "/model.png") != bytes(dir + "/clip.png"));  // reconstruction + ghost differ from the clip
    // A frame outside the model's clip is an error, and so is a file that is not a model.
    CHECK(std::system(
              (bin + "render '" + dir + "/walk.model' --frame 359 --out '" + dir + "/x.png' 2> /dev/null").c_str()) !=
          0);
    std::ofstream(dir + "/bad.model") << "{\"format\": \"something else\"}";
    CHECK(std::system(
              (bin + "render '" + dir + "/bad.model' --frame 1 --out '" + dir + "/x.png' 2> /dev/null").c_str()) != 0);
}
