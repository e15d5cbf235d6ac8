#include "scene/camera.hpp"

#include <gtest/gtest.h>

namespace rise {
namespace {

TEST(CameraForFrame, CutsTheScenesTimeIntoEqualFramesAndMovesTheCamera) {
  Camera camera;
  camera.position = Vec3(0.0f, 0.0f, -4.0f);
  camera.lookAt = Vec3(0.0f);
  camera.shutterClose = 0.5f;
  camera.endPlacement =
      Camera::Placement{Vec3(4.0f, 0.0f, -4.0f), Vec3(4.0f, 0.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f)};
  const Camera third = cameraForFrame(camera, 2, 8);
  EXPECT_FLOAT_EQ(third.sceneTimeOpen, 0.25f);
  EXPECT_FLOAT_EQ(third.sceneTimeClose, 0.3125f);  // half of the frame's eighth
  EXPECT_FLOAT_EQ(third.sceneTime(0.5f), 0.28125f);
  EXPECT_FLOAT_EQ(third.position.x, 1.0f);
  EXPECT_FLOAT_EQ(third.lookAt.x, 1.0f);
  EXPECT_EQ(ViewFrame(third, 4, 3).primaryRay(2.0f, 1.5f).time, 0.25f);
}

TEST(CameraForFrame, AnInstantShutterSeesTheFramesBeginning) {
  const Camera frame = cameraForFrame(Camera{}, 3, 4);
  EXPECT_FALSE(frame.hasMotionBlur());
  EXPECT_FLOAT_EQ(frame.sceneTime(0.9f), 0.75f);
}

TEST(Camera, AStillImagesShutterCoversTheWholeMotion) {
  Camera camera;
  camera.shutterClose = 1.0f;
  EXPECT_EQ(camera.sceneTime(0.3f), 0.3f);  // as before animations: the fraction itself
}

}  // namespace
}  // namespace rise
