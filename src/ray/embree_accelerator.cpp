#include "ray/embree_accelerator.hpp"

#include <array>
#include <cassert>
#include <stdexcept>
#include <string>

#include "core/shared_library.hpp"

namespace rise {

// Embree's functions, from its library, loaded when the first accelerator of
// it is made: a render without it does not pay for loading it.
struct EmbreeFunctions {
  SharedLibrary library{RISE_EMBREE_LIBRARY};
  RISE_LIBRARY_FUNCTION(library, rtcNewDevice);
  RISE_LIBRARY_FUNCTION(library, rtcGetDeviceError);
  RISE_LIBRARY_FUNCTION(library, rtcReleaseDevice);
  RISE_LIBRARY_FUNCTION(library, rtcNewScene);
  RISE_LIBRARY_FUNCTION(library, rtcCommitScene);
  RISE_LIBRARY_FUNCTION(library, rtcReleaseScene);
  RISE_LIBRARY_FUNCTION(library, rtcNewGeometry);
  RISE_LIBRARY_FUNCTION(library, rtcSetNewGeometryBuffer);
  RISE_LIBRARY_FUNCTION(library, rtcSetGeometryUserData);
  RISE_LIBRARY_FUNCTION(library, rtcSetGeometryUserPrimitiveCount);
  RISE_LIBRARY_FUNCTION(library, rtcSetGeometryBoundsFunction);
  RISE_LIBRARY_FUNCTION(library, rtcSetGeometryIntersectFunction);
  RISE_LIBRARY_FUNCTION(library, rtcSetGeometryOccludedFunction);
  RISE_LIBRARY_FUNCTION(library, rtcSetGeometryOccludedFilterFunction);
  RISE_LIBRARY_FUNCTION(library, rtcCommitGeometry);
  RISE_LIBRARY_FUNCTION(library, rtcAttachGeometryByID);
  RISE_LIBRARY_FUNCTION(library, rtcReleaseGeometry);
  RISE_LIBRARY_FUNCTION(library, rtcIntersect1);
  RISE_LIBRARY_FUNCTION(library, rtcOccluded1);
};

namespace {

const EmbreeFunctions& loadedEmbree() {
  static const EmbreeFunctions functions;
  return functions;
}

// What a query carries into Embree's callbacks. Embree passes the context it
// was given, so ours begins with Embree's and adds the rest.
struct QueryContext {
  RTCIntersectContext embree;
  const Ray* ray;
  float tMin;
  float tMax;                // of a shadow ray
  Hit* userHit;              // the nearest user geometry hit so far
  CrossingVisitor* visitor;  // of a shadow ray
  IntersectionCounters* counters;
};

QueryContext& queryOf(RTCIntersectContext* context) {
  return *reinterpret_cast<QueryContext*>(context);
}

const Shape& shapeOf(void* geometryUserPtr) { return *static_cast<const Shape*>(geometryUserPtr); }

// The callbacks below serve rtcIntersect1 and rtcOccluded1, which pass one
// ray at a time (N = 1), laid out as RTCRay and RTCRayHit.
void boundPrimitive(const RTCBoundsFunctionArguments* args) {
  const Bounds3 box =
      shapeOf(args->geometryUserPtr).primitiveBounds(static_cast<int>(args->primID));
  *args->bounds_o = {box.min.x, box.min.y, box.min.z, 0.0f, box.max.x, box.max.y, box.max.z, 0.0f};
}

void intersectPrimitive(const RTCIntersectFunctionNArguments* args) {
  assert(args->N == 1);
  if (!args->valid[0]) return;
  QueryContext& query = queryOf(args->context);
  RTCRayHit& rayHit = *reinterpret_cast<RTCRayHit*>(args->rayhit);
  Hit candidate;
  candidate.t = rayHit.ray.tfar;
  if (!shapeOf(args->geometryUserPtr)
           .intersectPrimitive(static_cast<int>(args->primID), *query.ray, query.tMin, candidate,
                               *query.counters))
    return;
  rayHit.ray.tfar = candidate.t;
  rayHit.hit.geomID = args->geomID;
  rayHit.hit.primID = args->primID;
  *query.userHit = candidate;
}

// Tells the visitor of a crossing; false when it asks to stop.
bool tell(QueryContext& query, unsigned int shape) {
  return query.visitor->crossed(static_cast<int>(shape));
}

void occludePrimitive(const RTCOccludedFunctionNArguments* args) {
  assert(args->N == 1);
  if (!args->valid[0]) return;
  QueryContext& query = queryOf(args->context);
  if (crossesPrimitive(shapeOf(args->geometryUserPtr), static_cast<int>(args->primID), *query.ray,
                       query.tMin, query.tMax, *query.counters) &&
      !tell(query, args->geomID))
    reinterpret_cast<RTCRay*>(args->ray)->tfar = -kInfinity;  // Embree's sign of an occluded ray
}

// Embree found that a shadow ray crosses a triangle: RISE's own test
// confirms it, the visitor is told, and the hit is refused (valid = 0) so
// that the search goes on, unless the visitor asks to stop.
void filterTriangleCrossing(const RTCFilterFunctionNArguments* args) {
  assert(args->N == 1);
  if (!args->valid[0]) return;
  QueryContext& query = queryOf(args->context);
  const RTCHit& hit = *reinterpret_cast<const RTCHit*>(args->hit);
  const bool crossed =
      crossesPrimitive(shapeOf(args->geometryUserPtr), static_cast<int>(hit.primID), *query.ray,
                       query.tMin, query.tMax, *query.counters);
  if (!crossed || tell(query, hit.geomID)) args->valid[0] = 0;
}

RTCRayHit embreeRay(const Ray& ray, float tMin, float tMax) {
  RTCRayHit rayHit{};
  rayHit.ray = {ray.origin.x,
                ray.origin.y,
                ray.origin.z,
                tMin,
                ray.direction.x,
                ray.direction.y,
                ray.direction.z,
                ray.time,
                tMax,
                0xffffffffu,
                0,
                0};
  rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rayHit;
}

QueryContext makeQuery(const Ray& ray, float tMin, float tMax, IntersectionCounters& counters) {
  QueryContext query{};
  rtcInitIntersectContext(&query.embree);
  query.ray = &ray;
  query.tMin = tMin;
  query.tMax = tMax;
  query.counters = &counters;
  return query;
}

bool allTriangles(const Shape& shape) {
  std::array<Vec3, 3> corners{};
  for (int primitive = 0; primitive < shape.primitiveCount(); ++primitive)
    if (!shape.primitiveTriangle(primitive, corners)) return false;
  return true;
}

void throwOnError(const EmbreeFunctions& embree, RTCDevice device, const char* what) {
  if (const RTCError error = embree.rtcGetDeviceError(device); error != RTC_ERROR_NONE)
    throw std::runtime_error(std::string("Embree: ") + what + " failed (error " +
                             std::to_string(static_cast<int>(error)) + ")");
}

}  // namespace

EmbreeAccelerator::EmbreeAccelerator(const std::vector<std::unique_ptr<Shape>>& shapes, int threads)
    : embree_(loadedEmbree()), shapes_(shapes), isTriangles_(shapes.size(), false) {
  const std::string config = threads > 0 ? "threads=" + std::to_string(threads) : "";
  device_ = embree_.rtcNewDevice(config.c_str());
  if (device_ == nullptr) throw std::runtime_error("Embree: cannot create a device");
  scene_ = embree_.rtcNewScene(device_);
  for (unsigned int shape = 0; shape < shapes.size(); ++shape) {
    if (!shapes[shape]->bounds().isFinite()) {
      unbounded_.push_back(static_cast<int>(shape));
    } else if (allTriangles(*shapes[shape])) {
      isTriangles_[shape] = true;
      addTriangles(shape);
    } else {
      addUserGeometry(shape);
    }
  }
  embree_.rtcCommitScene(scene_);
  throwOnError(embree_, device_, "building the scene");
}

EmbreeAccelerator::~EmbreeAccelerator() {
  embree_.rtcReleaseScene(scene_);
  embree_.rtcReleaseDevice(device_);
}

// Each triangle gets three vertices of its own: the Shape interface gives
// corners, not shared vertices.
void EmbreeAccelerator::addTriangles(unsigned int shape) {
  const Shape& source = *shapes_[shape];
  const auto count = static_cast<std::size_t>(source.primitiveCount());
  RTCGeometry geometry = embree_.rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(embree_.rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * count));
  auto* indices = static_cast<unsigned int*>(embree_.rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned int), count));
  for (std::size_t triangle = 0; triangle < count; ++triangle) {
    std::array<Vec3, 3> corners{};
    source.primitiveTriangle(static_cast<int>(triangle), corners);
    for (int corner = 0; corner < 3; ++corner) {
      const std::size_t vertex = 3 * triangle + corner;
      for (int axis = 0; axis < 3; ++axis) vertices[3 * vertex + axis] = corners[corner][axis];
      indices[vertex] = static_cast<unsigned int>(vertex);
    }
  }
  embree_.rtcSetGeometryUserData(geometry, const_cast<Shape*>(&source));
  embree_.rtcSetGeometryOccludedFilterFunction(geometry, filterTriangleCrossing);
  embree_.rtcCommitGeometry(geometry);
  embree_.rtcAttachGeometryByID(scene_, geometry, shape);
  embree_.rtcReleaseGeometry(geometry);
}

void EmbreeAccelerator::addUserGeometry(unsigned int shape) {
  const Shape& source = *shapes_[shape];
  RTCGeometry geometry = embree_.rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
  embree_.rtcSetGeometryUserPrimitiveCount(geometry,
                                           static_cast<unsigned int>(source.primitiveCount()));
  embree_.rtcSetGeometryUserData(geometry, const_cast<Shape*>(&source));
  embree_.rtcSetGeometryBoundsFunction(geometry, boundPrimitive, nullptr);
  embree_.rtcSetGeometryIntersectFunction(geometry, intersectPrimitive);
  embree_.rtcSetGeometryOccludedFunction(geometry, occludePrimitive);
  embree_.rtcCommitGeometry(geometry);
  embree_.rtcAttachGeometryByID(scene_, geometry, shape);
  embree_.rtcReleaseGeometry(geometry);
}

bool EmbreeAccelerator::nearest(const Ray& ray, float tMin, Hit& hit,
                                IntersectionCounters& counters) const {
  if (!isFinite(ray)) return false;
  bool found = false;
  for (int shape : unbounded_) found |= shapes_[shape]->intersect(ray, tMin, hit, counters);
  Hit userHit;
  QueryContext query = makeQuery(ray, tMin, hit.t, counters);
  query.userHit = &userHit;
  RTCRayHit rayHit = embreeRay(ray, tMin, hit.t);
  embree_.rtcIntersect1(scene_, &query.embree, &rayHit);
  const unsigned int shape = rayHit.hit.geomID;
  if (shape == RTC_INVALID_GEOMETRY_ID) return found;
  if (!isTriangles_[shape]) {
    hit = userHit;
    return true;
  }
  const Shape& triangles = *shapes_[shape];
  const int triangle = static_cast<int>(rayHit.hit.primID);
  if (triangles.intersectPrimitive(triangle, ray, tMin, hit, counters)) return true;
  // RISE's test misses what Embree's hit, on the triangle's very edge:
  // Embree's answer stands.
  hit.t = rayHit.ray.tfar;
  hit.shape = &triangles;
  hit.primitive = triangle;
  hit.barycentric = Vec2(rayHit.hit.u, rayHit.hit.v);
  return true;
}

void EmbreeAccelerator::visitCrossings(const Ray& ray, float tMin, float tMax,
                                       CrossingVisitor& visitor,
                                       IntersectionCounters& counters) const {
  if (!isFinite(ray)) return;
  for (int shape : unbounded_)
    if (crosses(*shapes_[shape], ray, tMin, tMax, counters) && !visitor.crossed(shape)) return;
  QueryContext query = makeQuery(ray, tMin, tMax, counters);
  query.visitor = &visitor;
  RTCRay shadowRay = embreeRay(ray, tMin, tMax).ray;
  embree_.rtcOccluded1(scene_, &query.embree, &shadowRay);
}

}  // namespace rise
