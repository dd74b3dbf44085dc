#include "slides/surfaces/deposit.h"

#include "slides/collide/swept_contact.h"

#include <algorithm>

namespace slides {

void Deposit::add(const Vec3& position, double radius, int surface, std::int32_t species) {
    species_.push_back(species);
    position_.push_back(position);
    radius_.push_back(radius);
    surface_.push_back(surface);
}

void Deposit::index() {
    if (indexed_ == position_.size()) return;
    for (std::size_t k = indexed_; k < position_.size(); ++k) {
        largestRadius_ = std::max(largestRadius_, radius_[k]);
        lower_ = lower_.cwiseMin(position_[k]);
        upper_ = upper_.cwiseMax(position_[k]);
    }
    grid_.build(position_, 2 * largestRadius_);
    indexed_ = position_.size();
}

std::optional<DepositTouch> Deposit::firstTouch(const Vec3& start, const Vec3& end,
                                                double radius) const {
    if (indexed_ == 0) return std::nullopt;
    const Vec3 centre = 0.5 * (start + end);
    const double reach = 0.5 * (end - start).norm() + radius + largestRadius_;
    // Most of the spray is far from the deposit: one box test before any cell is visited.
    if (((centre.array() + reach) < lower_.array()).any() ||
        ((centre.array() - reach) > upper_.array()).any())
        return std::nullopt;
    std::optional<DepositTouch> first;
    grid_.forEachPointWithin(centre, reach, [&](std::uint32_t k) {
        const auto fraction =
            sweptContactFraction(start - position_[k], end - position_[k], radius + radius_[k]);
        if (fraction && (!first || *fraction < first->fraction)) first = DepositTouch{k, *fraction};
    });
    return first;
}

} // namespace slides
