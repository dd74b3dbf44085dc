// Which particles of a step may have reached another rank's part, without walking them.
//
// About each cell's centre, the radius of a ball no face of a processor patch reaches: the
// distance to the nearest such face's point-average less the largest reach of a processor face
// from its point-average. A particle in that cell whose end position lies inside the ball (its
// start does: the cell lies inside it too) moved along a segment inside the ball, so it crossed
// no processor face; its walk can wait for the next step's sample, as in a serial run. The
// exchange walks only the others (run/rank_exchange.h).
//
//     ProcessorClearance clearance(mesh, locator, firstProcessorPatch);
//     if (clearance.stayed(tet, endPoint)) ...  // no processor face between
#pragma once

#include "slides/carrier/foam_locator.h"
#include "slides/carrier/foam_mesh.h"

#include <vector>

namespace slides {

class ProcessorClearance {
public:
    ProcessorClearance(const FoamMesh& mesh, const FoamLocator& locator, int firstProcessorPatch);

    /// Whether a particle in tetrahedron tet (of this part) that moved to point crossed no
    /// processor face.
    bool stayed(int tet, const Vec3& point) const {
        const int cell = locator_.tetAt(tet).cell;
        return (point - mesh_.cellCentres[cell]).squaredNorm() < squaredReach_[cell];
    }

private:
    const FoamMesh& mesh_;
    const FoamLocator& locator_;
    /// Per cell, the squared radius of its processor-free ball; 0 where it does not hold the cell.
    std::vector<double> squaredReach_;
};

} // namespace slides
