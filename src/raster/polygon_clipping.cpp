#include "raster/polygon_clipping.hpp"

namespace rise {

void splitPolygon(std::span<const Vec3> polygon, const glm::vec4& plane, float tolerance,
                  std::vector<Vec3>& positive, std::vector<Vec3>& negative) {
  positive.clear();
  negative.clear();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec3& from = polygon[i];
    const Vec3& to = polygon[nextCorner(i, polygon.size())];
    const float fromDistance = signedDistance(plane, from);
    const float toDistance = signedDistance(plane, to);
    if (fromDistance >= -tolerance) positive.push_back(from);
    if (fromDistance <= tolerance) negative.push_back(from);
    const bool crossesDown = fromDistance > tolerance && toDistance < -tolerance;
    const bool crossesUp = fromDistance < -tolerance && toDistance > tolerance;
    if (!crossesDown && !crossesUp) continue;
    const Vec3& above = crossesDown ? from : to;
    const Vec3& below = crossesDown ? to : from;
    const float aboveDistance = crossesDown ? fromDistance : toDistance;
    const float belowDistance = crossesDown ? toDistance : fromDistance;
    const Vec3 crossing =
        above + (aboveDistance / (aboveDistance - belowDistance)) * (below - above);
    positive.push_back(crossing);
    negative.push_back(crossing);
  }
  if (positive.size() < 3) positive.clear();
  if (negative.size() < 3) negative.clear();
}

}  // namespace rise
