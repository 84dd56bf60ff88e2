// The arithmetic of repeated protocol runs (docs/maths.md §14.5): spreads, the exact Wilcoxon
// signed-rank test against published values, the verdict rule, and the runs' frame subsets.
#include <doctest/doctest.h>

#include <atomic>
#include <cmath>
#include <set>

#include "eval/claim_test.h"
#include "eval/protocol_runs.h"

namespace mgp {

TEST_CASE("spread: mean and sample sd over the runs, sd 0 for one value, a NaN refused") {
    const Spread s = spreadOf({1.0, 2.0, 3.0, 4.0});
    CHECK(s.n == 4);
    CHECK(s.mean == doctest::Approx(2.5));
    CHECK(s.sd == doctest::Approx(std::sqrt(5.0 / 3.0)));  // Σ(x − 2.5)² = 5, n − 1 = 3
    CHECK(s.min == 1.0);
    CHECK(s.max == 4.0);
    CHECK(formatSpread(s, 1) == "2.5 ± 1.3");
    const Spread one = spreadOf({7.0});
    CHECK(one.mean == 7.0);
    CHECK(one.sd == 0.0);
    CHECK(std::isnan(spreadOf({}).mean));
    CHECK_THROWS_AS(spreadOf({1.0, std::nan("")}), std::invalid_argument);
}

TEST_CASE("Wilcoxon signed-rank: the exact two-sided p of published examples") {
    // Hollander & Wolfe's depression scores (R's ?wilcox.test): V = 40, p = 0.03906 = 20/512.
    const double x[] = {1.83, 0.50, 1.62, 2.48, 1.68, 1.88, 1.55, 3.06, 1.30};
    const double y[] = {0.878, 0.647, 0.598, 2.05, 1.06, 1.29, 1.06, 3.14, 1.29};
    std::vector<double> d;
    for (int i = 0; i < 9; ++i) d.push_back(x[i] - y[i]);
    const SignedRankTest t = wilcoxonSignedRank(d);
    CHECK(t.pairs == 9);
    CHECK(t.positive == 7);
    CHECK(t.negative == 2);
    CHECK(t.wPlus == 40.0);
    CHECK(t.wMinus == 5.0);
    CHECK(t.p == doctest::Approx(20.0 / 512.0));
    CHECK(claimVerdict(t) == ClaimVerdict::kConfirmed);
    // The mirror image refutes the claim at the same p.
    for (double& v : d) v = -v;
    const SignedRankTest m = wilcoxonSignedRank(d);
    CHECK(m.p == doctest::Approx(t.p));
    CHECK(claimVerdict(m) == ClaimVerdict::kRefuted);
}

TEST_CASE("Wilcoxon signed-rank: five agreeing runs cannot reach 0.05 two-sided, six can") {
    const SignedRankTest five = wilcoxonSignedRank({0.1, 0.2, 0.3, 0.4, 0.5});
    CHECK(five.p == doctest::Approx(2.0 / 32.0));
    CHECK(claimVerdict(five) == ClaimVerdict::kInconclusive);
    const SignedRankTest six = wilcoxonSignedRank({0.1, 0.2, 0.3, 0.4, 0.5, 0.6});
    CHECK(six.p == doctest::Approx(2.0 / 64.0));
    CHECK(claimVerdict(six) == ClaimVerdict::kConfirmed);
}

TEST_CASE("Wilcoxon signed-rank: zeros are dropped, tied magnitudes share their mid-rank") {
    // {1, 1, −1, 2} and two zeros: |d| ranks 2, 2, 2, 4; W+ = 8, W− = 2. Over the 16 sign patterns
    // of those ranks, W+ ≤ 2 or ≥ 8 in 8: p = 0.5.
    const SignedRankTest t = wilcoxonSignedRank({1.0, 0.0, 1.0, -1.0, 2.0, 0.0});
    CHECK(t.pairs == 6);
    CHECK(t.zero == 2);
    CHECK(t.wPlus == 8.0);
    CHECK(t.wMinus == 2.0);
    CHECK(t.p == doctest::Approx(0.5));
    const SignedRankTest none = wilcoxonSignedRank({0.0, 0.0});
    CHECK(none.p == 1.0);
    CHECK(claimVerdict(none) == ClaimVerdict::kInconclusive);
    CHECK_THROWS_AS(wilcoxonSignedRank({1.0, std::nan("")}), std::invalid_argument);
}

TEST_CASE("claim JSON: per-group tests, the pooled test decides, empty groups are left out") {
    const nlohmann::json c =
        claimJson("A beats B", "A - B", {"kick", "run", "none"}, {{1.0, 2.0, 3.0}, {4.0, 5.0, 6.0}, {}});
    CHECK(c["per_group"].size() == 2);
    CHECK(c["per_group"][0]["group"] == "kick");
    CHECK(c["per_group"][0]["test"]["p"].get<double>() == doctest::Approx(0.25));
    CHECK(c["pooled"]["pairs"] == 6);
    CHECK(c["pooled"]["p"].get<double>() == doctest::Approx(2.0 / 64.0));
    CHECK(c["pooled_difference"]["mean"].get<double>() == doctest::Approx(3.5));
    CHECK(c["verdict"] == "confirmed");
    CHECK_THROWS_AS(claimJson("x", "y", {"a"}, {}), std::invalid_argument);
}

TEST_CASE("run frames: one run is every frame, K runs each drop a different tenth and keep the anchor") {
    CHECK(runFrames(25, 0, 1, 7).size() == 25u);
    std::set<std::vector<int>> distinct;
    for (int run = 0; run < 9; ++run) {
        const std::vector<int> kept = runFrames(100, run, 9, 37);
        CHECK(kept.size() == 90u);
        CHECK(std::find(kept.begin(), kept.end(), 37) != kept.end());
        CHECK(std::is_sorted(kept.begin(), kept.end()));
        distinct.insert(kept);
    }
    CHECK(distinct.size() == 9u);
    // Run 0 drops f with (f − anchor) mod 10 = 1, before the anchor too.
    const std::vector<int> r0 = runFrames(20, 0, 5, 7);
    CHECK(std::find(r0.begin(), r0.end(), 8) == r0.end());
    CHECK(std::find(r0.begin(), r0.end(), 18) == r0.end());
    CHECK(r0.size() == 18u);
    const std::vector<int> early = runFrames(20, 0, 5, 15);
    CHECK(std::find(early.begin(), early.end(), 6) == early.end());
    CHECK(std::find(early.begin(), early.end(), 16) == early.end());
    CHECK(runStartNoise(1, 0.05) == 0.0);
    CHECK(runStartNoise(5, 0.05) == 0.05);
}

TEST_CASE("run jobs: every job once on several workers, and a worker exception reaches the caller") {
    std::vector<std::atomic<int>> seen(37);
    forEachJob(37, 2, [&](int j) { ++seen[j]; });
    for (const auto& s : seen) CHECK(s.load() == 1);
    CHECK_THROWS_AS(forEachJob(5, 2,
                               [](int j) {
                                   if (j == 3) throw std::runtime_error("job 3");
                               }),
                    std::runtime_error);
}

}  // namespace mgp
