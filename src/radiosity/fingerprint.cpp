#include "radiosity/fingerprint.hpp"

#include <array>
#include <cstring>
#include <span>

namespace rise {

namespace {

// The FNV-1a hash, 64 bits (Fowler, Noll and Vo), of bytes fed in turn.
class Fingerprint {
 public:
  template <typename Value>
  void add(const Value& value) {
    std::array<unsigned char, sizeof(Value)> bytes;
    std::memcpy(bytes.data(), &value, sizeof(Value));
    for (const unsigned char byte : bytes) hash_ = (hash_ ^ byte) * 0x100000001b3ull;
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ull;
};

void addMesh(Fingerprint& fingerprint, const ElementMesh& mesh) {
  for (const SurfaceVertex& vertex : mesh.triangles.vertices) {
    fingerprint.add(vertex.position);
    fingerprint.add(vertex.normal);
  }
  for (const SceneFace& face : mesh.triangles.faces) {
    fingerprint.add(face.vertices);
    fingerprint.add(face.material);
  }
  for (const Element& element : mesh.elements) fingerprint.add(element.twoSided);
}

void addMaterials(Fingerprint& fingerprint, const Scene& scene) {
  for (const Material& material : scene.materials) {
    fingerprint.add(material.kd);
    fingerprint.add(material.color);
    fingerprint.add(material.transmission);
    fingerprint.add(material.emission);
  }
}

// A light is known by what it gives: its direction, distance and colour at
// the mesh's corners and centre, for four points of its area.
void addLights(Fingerprint& fingerprint, const Scene& scene, const ElementMesh& mesh) {
  Bounds3 bounds;
  for (const SurfaceVertex& vertex : mesh.triangles.vertices) bounds.grow(vertex.position);
  if (bounds.isEmpty()) bounds.grow(Vec3(0.0f));
  std::vector<Vec3> points = {0.5f * (bounds.min + bounds.max)};
  for (int corner = 0; corner < 8; ++corner)
    points.push_back({corner & 1 ? bounds.max.x : bounds.min.x,
                      corner & 2 ? bounds.max.y : bounds.min.y,
                      corner & 4 ? bounds.max.z : bounds.min.z});
  for (const auto& light : scene.lights)
    for (const Vec3& point : points)
      for (const Vec2 u : {Vec2(0.2f, 0.3f), Vec2(0.8f, 0.1f), Vec2(0.4f, 0.9f), Vec2(0.6f)}) {
        const LightSample sample = light->illuminate(point, u);
        fingerprint.add(sample.toLight);
        fingerprint.add(sample.distance);
        fingerprint.add(sample.color);
      }
}

}  // namespace

std::uint64_t fingerprintOf(const Scene& scene, const RadiosityMesh& mesh,
                            const RadiositySettings& settings) {
  Fingerprint fingerprint;
  addMesh(fingerprint, mesh.elementMesh);
  addMaterials(fingerprint, scene);
  addLights(fingerprint, scene, mesh.elementMesh);
  fingerprint.add(scene.lights.size());
  fingerprint.add(settings.patchSize);
  fingerprint.add(settings.residual);
  fingerprint.add(settings.solver);
  fingerprint.add(settings.formFactors);
  fingerprint.add(settings.hemicubeSize);
  fingerprint.add(mesh.patchSide);
  return fingerprint.value();
}

}  // namespace rise
