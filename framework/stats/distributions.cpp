// Not needed for the assignment: the definitions of framework/stats/distributions.h.
#include "framework/stats/distributions.h"

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/students_t.hpp>

namespace pt {

double chi_squared_upper_tail(double dof, double statistic) {
  return boost::math::cdf(boost::math::complement(boost::math::chi_squared(dof), statistic));
}

double students_t_two_sided_critical(double dof, double alpha) {
  return boost::math::quantile(boost::math::complement(boost::math::students_t(dof), alpha / 2));
}

}  // namespace pt
