#include "eval/claim_test.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace mgp {

Spread spreadOf(const std::vector<double>& values) {
    Spread s;
    s.n = static_cast<int>(values.size());
    if (values.empty()) {
        s.mean = s.sd = s.min = s.max = std::numeric_limits<double>::quiet_NaN();
        return s;
    }
    for (double v : values)
        if (std::isnan(v)) throw std::invalid_argument("expected a value from every run, found NaN");
    s.mean = std::accumulate(values.begin(), values.end(), 0.0) / s.n;
    double ss = 0.0;
    for (double v : values) ss += (v - s.mean) * (v - s.mean);
    s.sd = s.n > 1 ? std::sqrt(ss / (s.n - 1)) : 0.0;
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    s.min = *lo;
    s.max = *hi;
    return s;
}

std::string formatSpread(const Spread& s, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f ± %.*f", decimals, s.mean, decimals, s.sd);
    return buf;
}

SignedRankTest wilcoxonSignedRank(const std::vector<double>& differences) {
    SignedRankTest t;
    t.pairs = static_cast<int>(differences.size());
    std::vector<double> d;
    for (double x : differences) {
        if (std::isnan(x)) throw std::invalid_argument("expected a paired difference from every run, found NaN");
        if (x == 0.0)
            ++t.zero;
        else
            d.push_back(x);
    }
    const int n = static_cast<int>(d.size());
    if (n == 0) return t;
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return std::abs(d[a]) < std::abs(d[b]); });
    // Twice the mid-ranks, so that every rank is an integer and the null distribution is a
    // count over integer sums.
    std::vector<int> rank2(n);
    for (int i = 0; i < n;) {
        int j = i;
        while (j + 1 < n && std::abs(d[order[j + 1]]) == std::abs(d[order[i]])) ++j;
        for (int k = i; k <= j; ++k) rank2[order[k]] = i + j + 2;  // 2 · (i + j + 2) / 2
        i = j + 1;
    }
    int w2Plus = 0, total2 = 0;
    for (int i = 0; i < n; ++i) {
        total2 += rank2[i];
        if (d[i] > 0) {
            ++t.positive;
            w2Plus += rank2[i];
        } else {
            ++t.negative;
        }
    }
    t.wPlus = w2Plus / 2.0;
    t.wMinus = (total2 - w2Plus) / 2.0;
    // Under H0 each sign is ±1 with probability 1/2: count the sign patterns by their W+ (doubled).
    std::vector<double> count(total2 + 1, 0.0);
    count[0] = 1.0;
    int reach = 0;
    for (int r : rank2) {
        for (int s = reach; s >= 0; --s)
            if (count[s] != 0.0) count[s + r] += count[s];
        reach += r;
    }
    // Two-sided: patterns at least as far from the centre total2/2 as the observed one.
    const int far2 = std::abs(2 * w2Plus - total2);
    double tail = 0.0;
    for (int s = 0; s <= total2; ++s)
        if (std::abs(2 * s - total2) >= far2) tail += count[s];
    t.p = std::min(1.0, tail / std::ldexp(1.0, n));
    return t;
}

const char* claimVerdictName(ClaimVerdict v) {
    switch (v) {
        case ClaimVerdict::kConfirmed: return "confirmed";
        case ClaimVerdict::kRefuted: return "refuted";
        case ClaimVerdict::kInconclusive: return "inconclusive";
    }
    return "inconclusive";
}

ClaimVerdict claimVerdict(const SignedRankTest& test, double alpha) {
    if (!(test.p < alpha)) return ClaimVerdict::kInconclusive;
    if (test.wPlus > test.wMinus) return ClaimVerdict::kConfirmed;
    if (test.wMinus > test.wPlus) return ClaimVerdict::kRefuted;
    return ClaimVerdict::kInconclusive;
}

nlohmann::json spreadJson(const Spread& s) {
    return {{"n", s.n}, {"mean", s.mean}, {"sd", s.sd}, {"min", s.min}, {"max", s.max}};
}

namespace {

nlohmann::json testJson(const SignedRankTest& t) {
    return {{"pairs", t.pairs}, {"positive", t.positive}, {"negative", t.negative},
            {"zero", t.zero},   {"w_plus", t.wPlus},      {"w_minus", t.wMinus},
            {"p", t.p}};
}

}  // namespace

nlohmann::json claimJson(const std::string& claim, const std::string& difference,
                         const std::vector<std::string>& groups, const std::vector<std::vector<double>>& differences,
                         double alpha) {
    if (groups.size() != differences.size())
        throw std::invalid_argument("expected one list of differences per group, found " +
                                    std::to_string(differences.size()) + " for " + std::to_string(groups.size()));
    nlohmann::json perGroup = nlohmann::json::array();
    std::vector<double> pooled;
    int dropped = 0;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        // A pair without a finite difference (both measures 0 in a ratio) has no sign to count.
        std::vector<double> d;
        for (double x : differences[g])
            if (std::isfinite(x))
                d.push_back(x);
            else
                ++dropped;
        if (d.empty()) continue;
        pooled.insert(pooled.end(), d.begin(), d.end());
        perGroup.push_back(
            {{"group", groups[g]}, {"difference", spreadJson(spreadOf(d))}, {"test", testJson(wilcoxonSignedRank(d))}});
    }
    const SignedRankTest all = wilcoxonSignedRank(pooled);
    return {{"claim", claim},
            {"difference", difference + " (positive favours the claim)"},
            {"test", "exact two-sided Wilcoxon signed-rank over every (row, run) pair, alpha = " +
                         std::to_string(alpha).substr(0, 4)},
            {"scope", "runs of a row share its motion: the verdict is about these motions under this perturbation"},
            {"per_group", perGroup},
            {"pooled", testJson(all)},
            {"pooled_difference", spreadJson(spreadOf(pooled))},
            {"pairs_without_a_finite_difference", dropped},
            {"verdict", claimVerdictName(claimVerdict(all, alpha))}};
}

}  // namespace mgp
