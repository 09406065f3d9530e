// An edge of a reconstructed or ground-truth curve, as the pair of indices of its two
// points. A plain pair (not a class) so that edge lists sort, compare and hash with the
// standard library, and so that geometry/ need not know about Boost.Graph.
#pragma once

#include <cstddef>
#include <utility>

namespace curvebench::geometry {

using Edge = std::pair<std::size_t, std::size_t>;

}  // namespace curvebench::geometry
