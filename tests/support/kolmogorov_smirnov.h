// The one-sample Kolmogorov–Smirnov test, for the tests of sampled distributions.
//
// Reference: Smirnov's limit law: √n D_n exceeds 1.628 with probability 1 % as n grows (the
// 1 % critical value of D_n is 1.628/√n for n of a few hundred or more).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

namespace slides::test {

/// D_n = sup |F_n − F| of the sample against the cumulative distribution F.
inline double kolmogorovSmirnov(std::vector<double> sample,
                                const std::function<double(double)>& F) {
    std::sort(sample.begin(), sample.end());
    const auto n = static_cast<double>(sample.size());
    double largest = 0;
    for (std::size_t k = 0; k < sample.size(); ++k) {
        const double f = F(sample[k]);
        largest = std::max(
            {largest, (static_cast<double>(k) + 1) / n - f, f - static_cast<double>(k) / n});
    }
    return largest;
}

/// The 1 % critical value of D_n for a sample of n.
inline double kolmogorovSmirnovCritical(std::size_t n) {
    return 1.628 / std::sqrt(static_cast<double>(n));
}

} // namespace slides::test
