// Sharp corners beyond the survey's one convex family ("Evaluation & Results", "Sharp
// Corners"): star polygons, non-convex, with every tip at the same opening angle, their
// corners either sharp or rounded by circular fillets. A sharp star has 2K corners (lfs 0
// at each; samplers put a sample on every one); a rounded star is C1 with lfs > 0, so it
// separates "a sharp corner" from "a tight turn" at the same angle.
#pragma once

#include <cstdint>

#include "geometry/curves/curve.h"

namespace curvebench::geometry {

// K tips at opening `angle` degrees, K drawn from the seed among the six smallest counts
// for which a regular star's inner corners turn by 15° or more the other way (K > 360 /
// (165 - angle)), so that the polygon is a star, not convex. Tip radii in [0.8, 1] and an
// angular jitter of 1/8 of the spacing are drawn from the seed too, and re-drawn until the
// polygon is simple (exact predicates), every inner corner turns right by 10° or more and
// lies 0.15 or more from the centre. Each tip's sides leave it symmetrically about the ray
// to the centre, so its angle is `angle` (up to rounding). `rounding` > 0 replaces every
// corner by a tangent circular arc of that radius (the fillets may take at most 90% of a
// side). One closed component, counterclockwise. Name "star:seed=S,angle=A[,rounding=R]".
// Throws std::invalid_argument unless 0 < angle < 150 and rounding is 0 or at least 1e-6,
// both finite, or if no draw fits the rounding.
Curve star_polygon(std::uint64_t seed, double angle_degrees, double rounding = 0);

}  // namespace curvebench::geometry
