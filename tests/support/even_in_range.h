// rc::gen::inRange scales its range with RapidCheck's size, so the first cases of a run
// only see the low end. For parameters that pick a curve family, a seed or a target,
// every value should be as likely in every case: draw at the nominal size.
#pragma once

#include <rapidcheck.h>

namespace curvebench::testing {

template <class T>
rc::Gen<T> even_in_range(T low, T high) {
  return rc::gen::resize(rc::kNominalSize, rc::gen::inRange(low, high));
}

}  // namespace curvebench::testing
