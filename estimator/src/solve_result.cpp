#include "anchorbench/estimator/solve_result.hpp"

namespace anchorbench::estimator {

}  // namespace anchorbench::estimator
