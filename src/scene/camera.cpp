#include "scene/camera.hpp"

#include <cmath>

namespace rise {

ViewFrame::ViewFrame(const Camera& camera, int width, int height)
    : eye_(camera.position),
      width_(width),
      height_(height),
      time_(camera.sceneTime(0.0f)),
      lensRadius_(0.5f * camera.aperture),
      focalDistance_(camera.focalDistance > 0.0f ? camera.focalDistance
                                                 : glm::length(camera.lookAt - camera.position)) {
  forward_ = normalizedOrZero(camera.lookAt - camera.position);
  // A right-handed world seen from behind the eye: x to the right, y up,
  // looking along forward.
  right_ = glm::normalize(glm::cross(forward_, camera.up));
  up_ = glm::cross(right_, forward_);
  halfHeight_ = std::tan(radians(camera.fovDegrees) * 0.5f);
  halfWidth_ = halfHeight_ * static_cast<float>(width) / static_cast<float>(height);
}

Camera cameraForFrame(const Camera& camera, int frame, int frames) {
  Camera framed = camera;
  const float length = 1.0f / static_cast<float>(frames);
  const float start = static_cast<float>(frame) * length;
  framed.sceneTimeOpen = start + camera.shutterOpen * length;
  framed.sceneTimeClose = start + camera.shutterClose * length;
  if (camera.endPlacement) {
    const Camera::Placement& end = *camera.endPlacement;
    framed.position = glm::mix(camera.position, end.position, framed.sceneTimeOpen);
    framed.lookAt = glm::mix(camera.lookAt, end.lookAt, framed.sceneTimeOpen);
    framed.up = glm::normalize(glm::mix(camera.up, end.up, framed.sceneTimeOpen));
  }
  return framed;
}

}  // namespace rise
