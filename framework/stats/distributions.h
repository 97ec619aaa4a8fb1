// Not needed for the assignment.
// The tails of the chi-square and Student's t distributions that the statistical tests judge by,
// compiled once here (with Boost.Math) so that a test including a helper does not parse Boost.
#pragma once

namespace pt {

/// P(X >= statistic) for X chi-square distributed with `dof` degrees of freedom: a chi-square
/// test's p-value.
double chi_squared_upper_tail(double dof, double statistic);

/// The t with P(|T| > t) = alpha for T Student-t distributed with `dof` degrees of freedom: the
/// critical value of a two-sided t-test at significance alpha.
double students_t_two_sided_critical(double dof, double alpha);

}  // namespace pt
