#include "ray/ray_tree_builder.hpp"

#include <algorithm>

namespace rise {
namespace {

template <typename Pointers, typename T>
int indexOf(const Pointers& pointers, const T* item) {
  const auto found = std::find_if(pointers.begin(), pointers.end(),
                                  [&](const auto& pointer) { return pointer.get() == item; });
  return found == pointers.end() ? -1 : static_cast<int>(found - pointers.begin());
}

}  // namespace

RayNode RayTreeBuilder::shadowFromCurrent(const Ray& ray) {
  RayNode node;
  node.kind = RayKind::Shadow;
  node.depth = current().depth;
  node.origin = ray.origin;
  node.direction = glm::normalize(ray.direction);
  node.weight = current().weight;
  return node;
}

int RayTreeBuilder::add(RayNode node) {
  node.parent = current_;
  const int index = static_cast<int>(tree_.rays.size());
  if (current_ >= 0) current().children.push_back(index);
  tree_.rays.push_back(std::move(node));
  return index;
}

void RayTreeBuilder::begin(RayKind kind, const Ray& ray, int depth, const Color& weight) {
  RayNode node;
  node.kind = kind;
  node.depth = depth;
  node.origin = ray.origin;
  node.direction = glm::normalize(ray.direction);
  node.weight = current_ >= 0 ? current().weight * weight : weight;
  current_ = add(std::move(node));
}

void RayTreeBuilder::hit(const Hit& hit, const SurfacePoint& surface) {
  RayNode& node = current();
  node.hit = true;
  node.object = indexOf(scene_.shapes, hit.shape);
  node.distance = glm::distance(node.origin, surface.position);
  node.point = surface.position;
  node.normal = surface.normal;
  node.uv = surface.uv;
}

void RayTreeBuilder::ambient(const Color& term) {
  current().ambient = term;
  current().contribution = current().weight * term;
}

void RayTreeBuilder::shadow(const Ray& ray, const Light& light, float distance,
                            const Color& visible, const Color& diffuse, const Color& specular) {
  RayNode node = shadowFromCurrent(ray);
  node.light = indexOf(scene_.lights, &light);
  node.distance = distance;
  node.transmittance = visible;
  node.diffuse = diffuse;
  node.specular = specular;
  node.color = visible * (diffuse + specular);
  node.contribution = node.weight * node.color;
  add(std::move(node));
}

PathVertex& RayTreeBuilder::pathVertex() {
  if (!current().path) current().path.emplace();
  return *current().path;
}

void RayTreeBuilder::emitterShadow(const Ray& ray, float distance, bool reaches, const Color& lit,
                                   float weight) {
  RayNode node = shadowFromCurrent(ray);
  node.distance = distance;
  node.transmittance = Color(reaches ? 1.0f : 0.0f);
  node.diffuse = lit;
  node.misWeight = weight;
  node.color = node.transmittance * lit * weight;
  node.contribution = node.weight * node.color;
  add(std::move(node));
}

void RayTreeBuilder::end(const Color& color) {
  RayNode& node = current();
  node.color = color;
  if (!node.hit) node.contribution = node.weight * color;
  if (node.path) node.contribution = node.weight * node.path->emitted;
  current_ = node.parent;
}

}  // namespace rise
