// The survey's sharp-corner family ("Evaluation & Results", "Sharp Corners"): "a closed
// convex curve ... generated using an arc of a unit circle opening to two tangent lines
// joining at a specified angle to form a sharp corner". The epsilon-sampling condition
// cannot sample a corner (lfs is 0 there), which is what these curves test.
#pragma once

#include "geometry/curves/curve.h"

namespace curvebench::geometry {

// The unit circle about the origin, cut by the two lines tangent to it that meet at the
// apex (1 / sin(angle / 2), 0) at the given opening angle: the line from the apex up to
// the upper tangent point, the arc counterclockwise round to the lower one, the line
// back. One component, three pieces, one corner, at s = 0 (the apex); the tangent turns
// by 180° minus the opening angle there and is continuous at the tangent points. Name
// "corner:angle=A". Throws std::invalid_argument unless 0 < angle < 180 (the survey uses
// 10 to 90 degrees).
Curve sharp_corner_curve(double opening_angle_degrees);

}  // namespace curvebench::geometry
