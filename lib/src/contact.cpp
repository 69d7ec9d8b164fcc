// The mixing rule of contact coefficients (Box2D's, so both engines see the same numbers).
#include "impulse2d/contact.h"

#include <algorithm>
#include <cmath>

namespace impulse2d {

double mixFriction(double frictionA, double frictionB) {
  return std::sqrt(frictionA * frictionB);
}

double mixRestitution(double restitutionA, double restitutionB) {
  return std::max(restitutionA, restitutionB);
}

}  // namespace impulse2d
