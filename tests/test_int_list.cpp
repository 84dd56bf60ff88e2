// parseIntList (io/text_reader.h): the one parser behind `edit --keys` and
// `evaluate --heldout-offsets`.
#include <doctest/doctest.h>

#include <vector>

#include "io/text_reader.h"

using mgp::parseIntList;

TEST_CASE("parseIntList: comma-separated integers, trimmed, each within its range") {
    std::vector<long long> v;
    REQUIRE(parseIntList("3, 5,8", 0, 9, v));
    CHECK(v == std::vector<long long>{3, 5, 8});
    REQUIRE(parseIntList(" 7 ", 0, 9, v));
    CHECK(v == std::vector<long long>{7});
    REQUIRE(parseIntList("+1,-2", -5, 5, v));
    CHECK(v == std::vector<long long>{1, -2});
    REQUIRE(parseIntList("0,9", 0, 9, v));  // both ends are inside
    CHECK(v == std::vector<long long>{0, 9});
}

TEST_CASE("parseIntList: an empty item, a non-number or an out-of-range value fails the whole list") {
    std::vector<long long> v;
    CHECK_FALSE(parseIntList("", 0, 9, v));
    CHECK_FALSE(parseIntList(",", 0, 9, v));
    CHECK_FALSE(parseIntList("1,,2", 0, 9, v));
    CHECK_FALSE(parseIntList("1,", 0, 9, v));
    CHECK_FALSE(parseIntList("1,x", 0, 9, v));
    CHECK_FALSE(parseIntList("1.5", 0, 9, v));
    CHECK_FALSE(parseIntList("10", 0, 9, v));
    CHECK_FALSE(parseIntList("-1", 0, 9, v));
    CHECK_FALSE(parseIntList("99999999999999999999", 0, 9, v));  // beyond long long
}
