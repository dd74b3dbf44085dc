#include "slides/carrier/bickley_batch.h"

// Compiled once per instruction set (Highway's foreach_target), dispatched at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "slides/carrier/bickley_batch.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include "slides/core/simd_math-inl.h"

#include <hwy/highway.h>

#include <array>

HWY_BEFORE_NAMESPACE();
namespace slides::HWY_NAMESPACE {
namespace {

/// U at the points of one vector starting at `first` (as JetFrame::sample, without ∇U).
struct JetVelocityVector {
    const JetFrame& frame;
    const BickleyProfile& profile;
    Vec3 across; ///< e_y (planar), or the e_r used on the axis

    void run(std::size_t first, const Vec3* points, Vec3* velocity) const {
        const hn::ScalableTag<double> d;
        using V = hn::Vec<decltype(d)>;
        const JetNozzle& nozzle = frame.nozzle();
        const Vec3& axis = nozzle.axis;
        V p0, p1, p2;
        hn::LoadInterleaved3(d, points[first].data(), p0, p1, p2);
        p0 = hn::Sub(p0, hn::Set(d, nozzle.centre.x()));
        p1 = hn::Sub(p1, hn::Set(d, nozzle.centre.y()));
        p2 = hn::Sub(p2, hn::Set(d, nozzle.centre.z()));
        const auto dot = [&](const Vec3& e) {
            return hn::MulAdd(p0, hn::Set(d, e.x()),
                              hn::MulAdd(p1, hn::Set(d, e.y()), hn::Mul(p2, hn::Set(d, e.z()))));
        };
        const V axial = dot(axis);
        const auto inCore = hn::Lt(axial, hn::Set(d, frame.coreLength()));
        const V origin = hn::Set(d, frame.virtualOrigin());
        const V s = hn::IfThenElse(inCore, origin,
                                   hn::Add(hn::Sub(axial, hn::Set(d, frame.coreLength())), origin));
        // Cross-span coordinate y and its direction (e0, e1, e2).
        V y, e0 = hn::Set(d, across.x()), e1 = hn::Set(d, across.y()), e2 = hn::Set(d, across.z());
        if (frame.geometry() == JetGeometry::planar) {
            y = dot(across);
        } else {
            const V r0 = hn::NegMulAdd(axial, hn::Set(d, axis.x()), p0);
            const V r1 = hn::NegMulAdd(axial, hn::Set(d, axis.y()), p1);
            const V r2 = hn::NegMulAdd(axial, hn::Set(d, axis.z()), p2);
            y = hn::Sqrt(hn::MulAdd(r0, r0, hn::MulAdd(r1, r1, hn::Mul(r2, r2))));
            const auto offAxis = hn::Gt(y, hn::Zero(d));
            const V inverseY =
                hn::Div(hn::Set(d, 1.0), hn::IfThenElse(offAxis, y, hn::Set(d, 1.0)));
            e0 = hn::IfThenElse(offAxis, hn::Mul(r0, inverseY), e0);
            e1 = hn::IfThenElse(offAxis, hn::Mul(r1, inverseY), e1);
            e2 = hn::IfThenElse(offAxis, hn::Mul(r2, inverseY), e2);
        }
        // BickleyProfile::at: with e = expm1(−2|η|), tanh|η| = −e/(2 + e),
        // sech²η = 4(1 + e)/(2 + e)²;  u = C1 s^(−1/3) sech²η,  v = C2 s^(−2/3) (2η sech²η − tanh
        // η).
        const V inverseCbrtS = hn::Exp(d, hn::Mul(hn::Set(d, -1.0 / 3.0), hn::Log(d, s)));
        const V inverseS23 = hn::Mul(inverseCbrtS, inverseCbrtS);
        const V eta = hn::Mul(hn::Mul(hn::Set(d, profile.C3), y), inverseS23);
        const V e = hn::Expm1(d, hn::Mul(hn::Set(d, -2.0), hn::Abs(eta)));
        const V inverseTwoPlusE = hn::Div(hn::Set(d, 1.0), hn::Add(hn::Set(d, 2.0), e));
        const V tanhEta = hn::CopySign(hn::Mul(hn::Neg(e), inverseTwoPlusE), eta);
        const V sech2 = hn::Mul(hn::Mul(hn::Set(d, 4.0), hn::Add(hn::Set(d, 1.0), e)),
                                hn::Mul(inverseTwoPlusE, inverseTwoPlusE));
        const V g = hn::MulSub(hn::Mul(hn::Set(d, 2.0), eta), sech2, tanhEta);
        const V u = hn::Mul(hn::Mul(hn::Set(d, profile.C1), sech2), inverseCbrtS);
        // In the core the profile is frozen at s0 with v = 0; behind the exit plane U = 0.
        const V v =
            hn::IfThenZeroElse(inCore, hn::Mul(hn::Mul(hn::Set(d, profile.C2), g), inverseS23));
        const auto behind = hn::Lt(axial, hn::Zero(d));
        const auto component = [&](double a, V e_) {
            return hn::IfThenZeroElse(behind, hn::MulAdd(u, hn::Set(d, a), hn::Mul(v, e_)));
        };
        hn::StoreInterleaved3(component(axis.x(), e0), component(axis.y(), e1),
                              component(axis.z(), e2), d, velocity[first].data());
    }

    /// The last `count` points from `first`, padded to a whole vector with copies of the first.
    void pad(std::size_t first, std::size_t count, std::span<const Vec3> points,
             std::span<Vec3> velocity) const {
        std::array<Vec3, maxDoubleLanes> paddedPoints, paddedVelocity;
        for (std::size_t k = 0; k < maxDoubleLanes; ++k)
            paddedPoints[k] = points[first + (k < count ? k : 0)];
        run(0, paddedPoints.data(), paddedVelocity.data());
        for (std::size_t k = 0; k < count; ++k) velocity[first + k] = paddedVelocity[k];
    }
};

} // namespace

void SampleBickleyVelocity(const JetFrame& frame, const BickleyProfile& profile,
                           std::span<const Vec3> points, std::span<Vec3> velocity) {
    const Vec3& axis = frame.nozzle().axis;
    const JetVelocityVector kernel{frame, profile,
                                   frame.geometry() == JetGeometry::planar
                                       ? frame.nozzle().crossSpanDirection
                                       : Vec3(axis.unitOrthogonal())};
    forEachVector(
        points.size(), hn::Lanes(hn::ScalableTag<double>()),
        [&](std::size_t first) { kernel.run(first, points.data(), velocity.data()); },
        [&](std::size_t first, std::size_t count) { kernel.pad(first, count, points, velocity); });
}

} // namespace slides::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace slides {

HWY_EXPORT(SampleBickleyVelocity);

void sampleBickleyVelocity(const JetFrame& frame, const BickleyProfile& profile,
                           std::span<const Vec3> points, std::span<Vec3> velocity) {
    HWY_DYNAMIC_DISPATCH(SampleBickleyVelocity)(frame, profile, points, velocity);
}

} // namespace slides
#endif
