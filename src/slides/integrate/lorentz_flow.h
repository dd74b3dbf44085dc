// The exact flow of a charged particle under drag, a constant acceleration and the Lorentz
// force (Eq. 2.93) with the gas velocity u and the drag rate λ = 1/τ frozen over the step:
//
//   dv/dt = g + λ (u − v) + v × Ω,   dx/dt = v,   g = qE/m + body acceleration, Ω = qB/m.
//
// Reference: Eq. 2.93 of the reference with the drag of Eq. 3.16; the rotation-exact
// (exponential) integrator of the gyration, of which Boris' kick–rotate–kick is the
// second-order approximation. Along Ω the motion is relaxExactly's (integrate/integrator.h);
// across it, with the perpendicular plane as the complex plane (n × w ≡ i w, n = −Ω/|Ω|, so
// w × Ω ≡ iω w), dv/dt = f − z v with z = λ − iω and f = g + λu, whose exact solution is
//   v(h) = e^(−zh) v + h φ(zh) f,   x(h) = x + h φ(zh) v + h² ψ(zh) f,
//   φ(y) = (1 − e^(−y))/y,   ψ(y) = (y − 1 + e^(−y))/y²   (series near 0, so λ = 0 or Ω = 0
// is no special case: the free gyration, the E × B drift and the terminal drift of Stokes drag
// are all exact, to round-off, at any step, and a stiff drag relaxes stably).
//
//     physics { electromagnetic { model lorentz; E (0 1e4 0); B (0 0 0.5); } }
#pragma once

#include "slides/core/vector.h"

#include <cmath>
#include <complex>

namespace slides {

namespace lorentz_detail {

/// φ(y) = (1 − e^(−y))/y and ψ(y) = (y − 1 + e^(−y))/y² of complex y, to round-off.
inline void phiFunctions(std::complex<double> y, std::complex<double>& phi,
                         std::complex<double>& psi) {
    if (std::abs(y) < 0.5) { // Σ (−y)^k/(k+1)! and Σ (−y)^k/(k+2)!, 16 terms: below 1e-17
        phi = psi = 0;       // Horner, from k = 16 down
        for (int k = 16; k >= 0; --k) {
            phi = phi * (-y) / double(k + 2) + 1.0;
            psi = psi * (-y) / double(k + 3) + 1.0;
        }
        psi *= 0.5;
        return;
    }
    const std::complex<double> decay = std::exp(-y);
    phi = (1.0 - decay) / y;
    psi = (y - 1.0 + decay) / (y * y);
}

} // namespace lorentz_detail

/// Advances x and v over h exactly under g + λ (u − v) + v × Ω (λ = 0: no drag).
inline void flowInFields(Vec3& x, Vec3& v, const Vec3& u, double dragRate, const Vec3& acceleration,
                         const Vec3& gyration, double h) {
    const double frequency = gyration.norm();
    // Along Ω (or everything, when Ω = 0) and across it; n × acts as i across it.
    const Vec3 axis = frequency > 0 ? Vec3(gyration / frequency) : Vec3::Zero();
    const Vec3 n = -axis;
    const Vec3 f = acceleration + dragRate * u;
    const auto along = [&](const Vec3& w) { return Vec3(axis * axis.dot(w)); };
    const auto times = [&](std::complex<double> c, const Vec3& w) { // c·w across Ω
        return Vec3(c.real() * w + c.imag() * n.cross(w));
    };
    std::complex<double> phiAcross, psiAcross, phiAlong, psiAlong;
    lorentz_detail::phiFunctions({dragRate * h, 0.0}, phiAlong, psiAlong);
    const double decayAlong = std::exp(-dragRate * h);
    std::complex<double> decayAcross = decayAlong;
    if (frequency > 0) { // else across is along (an uncharged particle: the drag's relaxation)
        lorentz_detail::phiFunctions({dragRate * h, -frequency * h}, phiAcross, psiAcross);
        decayAcross = std::exp(std::complex<double>(-dragRate * h, frequency * h));
    } else {
        phiAcross = phiAlong;
        psiAcross = psiAlong;
    }
    const Vec3 vAlong = along(v), fAlong = along(f);
    const Vec3 vAcross = v - vAlong, fAcross = f - fAlong;
    x += h * (phiAlong.real() * vAlong + times(phiAcross, vAcross)) +
         h * h * (psiAlong.real() * fAlong + times(psiAcross, fAcross));
    v = decayAlong * vAlong + h * phiAlong.real() * fAlong + times(decayAcross, vAcross) +
        h * times(phiAcross, fAcross);
}

} // namespace slides
