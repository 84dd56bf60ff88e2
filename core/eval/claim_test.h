#pragma once
// The arithmetic that turns repeated protocol runs into a verdict on a claim (docs/maths.md
// §14.5): a cell's spread (mean ± sample sd over its runs) and the exact two-sided Wilcoxon
// signed-rank test on paired differences, oriented so that a positive difference favours the
// claim. Confirmed / refuted needs p < α in the claim's / the opposite direction; anything else
// is inconclusive at this spread.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace mgp {

struct Spread {
    int n = 0;
    double mean = 0.0;
    double sd = 0.0;  // sample sd (n − 1); 0 for one value, NaN for none
    double min = 0.0, max = 0.0;
};
// NaN values are not allowed (std::invalid_argument): a run that produced none is not a value.
Spread spreadOf(const std::vector<double>& values);
// "12.4 ± 3.1" with `decimals` places.
std::string formatSpread(const Spread& s, int decimals);

struct SignedRankTest {
    int pairs = 0;  // all differences given
    int positive = 0, negative = 0, zero = 0;
    double wPlus = 0.0, wMinus = 0.0;  // rank sums over the non-zero differences (mid-ranks on ties)
    double p = 1.0;                    // exact two-sided p under H0 (signs ±1 equally likely)
};
// Zero differences are dropped (Wilcoxon's rule); ties in |d| get mid-ranks and the exact null
// distribution is taken over those ranks. Throws std::invalid_argument on a NaN difference.
SignedRankTest wilcoxonSignedRank(const std::vector<double>& differences);

enum class ClaimVerdict { kConfirmed, kRefuted, kInconclusive };
const char* claimVerdictName(ClaimVerdict v);
// Confirmed when p < alpha and W+ > W−, refuted when p < alpha and W− > W+.
ClaimVerdict claimVerdict(const SignedRankTest& test, double alpha = 0.05);

// {"n", "mean", "sd", "min", "max"}.
nlohmann::json spreadJson(const Spread& s);

// A claim judged over groups (a protocol's rows) of paired differences (one per run), positive
// favouring the claim: per group its spread and test, pooled over every pair the test that
// decides, and the verdict. Groups without differences are left out of the pool; a non-finite
// difference is left out and counted.
nlohmann::json claimJson(const std::string& claim, const std::string& difference,
                         const std::vector<std::string>& groups, const std::vector<std::vector<double>>& differences,
                         double alpha = 0.05);

}  // namespace mgp
