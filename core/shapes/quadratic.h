// Real roots of a*t^2 + b*t + c = 0 in double precision, using the cancellation-free form
// q = -(b + sign(b) sqrt(disc)) / 2, t0 = q / a, t1 = c / q (Numerical Recipes 5.6).
// Returns false when there is no real root. A tangent ray (disc == 0) yields t0 == t1.
#pragma once

#include <cmath>
#include <utility>

namespace rt {

inline bool solve_quadratic(double a, double b, double c, double& t0, double& t1) {
  if (a == 0.0) {
    if (b == 0.0) return false;
    t0 = t1 = -c / b;
    return true;
  }
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return false;
  const double root = std::sqrt(disc);
  const double q = (b < 0.0) ? -0.5 * (b - root) : -0.5 * (b + root);
  if (q == 0.0) {  // b == 0 and c == 0: double root at 0
    t0 = t1 = 0.0;
    return true;
  }
  t0 = q / a;
  t1 = c / q;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

}  // namespace rt
