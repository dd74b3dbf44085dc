// e^{z²} erfc(z) for complex z, the function of closed forms of the history terms (the Basset,
// Michaelides–Feng and Candelier solutions): Faddeeva's w of Debian's libcerf, E(z) = w(iz).
#pragma once

#include <cerf.h>

#include <complex>

namespace slides::test {

inline std::complex<double> scaledComplementaryError(std::complex<double> z) {
    const double x = -z.imag(), y = z.real(); // iz = x + iy
    return {re_w_of_z(x, y), im_w_of_z(x, y)};
}

} // namespace slides::test
