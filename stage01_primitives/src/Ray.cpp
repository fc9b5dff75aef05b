#include "primitives/Ray.h"

#include <ostream>

namespace rt {

std::ostream& operator<<(std::ostream& os, const Ray& r) {
  return os << "Ray{head " << r.head() << ", direction " << r.direction() << "}";
}

}  // namespace rt
