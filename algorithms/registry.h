// Every reconstruction algorithm by name: the table that the command line, the
// benchmarks, the fuzzer and the certifier iterate. Adding a built-in algorithm is one
// file pair (its function and its Algorithm description) and one entry in registry.cpp;
// a program built on the installed library adds its own with a Registration
// (docs/own-algorithm.md), and they stand beside the built-ins in every verb.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::algorithms {

// The built-in algorithms in the survey's order of Table 1, then the registered ones in
// the order they were registered. Reading it closes the registry to registration.
std::span<const Algorithm> registry();

// The algorithms a program registered itself: the tail of registry().
std::span<const Algorithm> registered_algorithms();

// Adds `algorithm` after the built-ins. Its texts (name, title, ...) are views, so they
// must live as long as the program: string literals. Throws std::invalid_argument for an
// empty or taken name, a name a curvebench argument could not carry (it may hold only
// lowercase letters, digits, '-', '_' and '.', and must not end in "+outlier-filter"),
// no reconstruct function, or a parameter whose default is outside its range; throws
// std::logic_error once the registry has been read, since pointers into it are out then.
void register_algorithm(Algorithm algorithm);

// Registers an algorithm while the program starts, before main, as a namespace-scope
// object in the file that defines it:
//
//   const curvebench::algorithms::Registration naive_nn_crust{{
//       .name = "naive-nn-crust", .title = "naive NN-Crust", ...,
//       .reconstruct = curvebench::algorithms::edges_on_input(naive_nn_crust_edges)}};
//
// An invalid description ends the program at start with register_algorithm's message.
struct Registration {
  // Calls register_algorithm(algorithm).
  explicit Registration(Algorithm algorithm);
};

// Adds an algorithm while the program runs, at any time, also after the registry has been
// read: a Python function (python/), say. It is found by find_algorithm, and so by every
// verb that takes a name, but registry() does not list it, since a span of the registry
// may be held. Its texts and parameters are copied and kept, with it, for the program's
// lifetime (any strings will do, not only literals). Returns it; its address is stable.
// Throws std::invalid_argument as register_algorithm does, and for a name taken by a
// registered or an earlier session algorithm.
const Algorithm& add_session_algorithm(Algorithm algorithm);

// The algorithms add_session_algorithm added, in the order added.
std::vector<const Algorithm*> session_algorithms();

// A registered algorithm behind the outlier pre-filter: "nn-crust+outlier-filter".
inline constexpr std::string_view outlier_filter_suffix = "+outlier-filter";

// nullptr if no algorithm has that name: a registered one, then a session one.
// NAME+outlier-filter is NAME behind the outlier pre-filter (outlier_filter.h), for any
// registered or session NAME.
const Algorithm* find_algorithm(std::string_view name);

// Runs `algorithm` on any point list: checks the parameters, merges exact duplicates
// into their first occurrence (which alone gets edges; geometry::PointSet) and returns
// edges between input indices, sorted. Throws std::invalid_argument for a bad parameter
// or a non-finite coordinate.
Reconstruction reconstruct(const Algorithm& algorithm, std::span<const Point> points,
                           const Parameter_values& values = {});

}  // namespace curvebench::algorithms
