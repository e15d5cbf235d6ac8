#include "scene/transform.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace rise {

Mat4 worldFromObject(const TransformSpec& spec) {
  // Each call multiplies on the right, so the last one written acts first on
  // a point: the scale, then x, y and z rotations, then the translation.
  Mat4 m = glm::translate(Mat4(1.0f), spec.translate);
  m = glm::rotate(m, radians(spec.rotateDegrees.z), Vec3(0.0f, 0.0f, 1.0f));
  m = glm::rotate(m, radians(spec.rotateDegrees.y), Vec3(0.0f, 1.0f, 0.0f));
  m = glm::rotate(m, radians(spec.rotateDegrees.x), Vec3(1.0f, 0.0f, 0.0f));
  return glm::scale(m, spec.scale);
}

}  // namespace rise
