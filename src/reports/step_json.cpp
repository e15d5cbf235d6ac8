#include "reports/step_json.hpp"

#include <nlohmann/json.hpp>

#include "core/text.hpp"

namespace rise {
namespace {

using Json = nlohmann::ordered_json;

Json vector2(const Vec2& v) { return {v.x, v.y}; }
Json vector3(const Vec3& v) { return {v.x, v.y, v.z}; }

const char* shapeKindName(StepShape::Kind kind) {
  switch (kind) {
    case StepShape::Kind::Rectangle:
      return "rectangle";
    case StepShape::Kind::Polygon:
      return "polygon";
    case StepShape::Kind::Segment:
      return "segment";
    case StepShape::Kind::Point:
      return "point";
  }
  return "?";
}

// The pixels of `writes` whose `kept` is as asked, as runs [y, x0, x1] along
// the rows, x1 included.
Json pixelRuns(const std::vector<PixelWrite>& writes, bool kept) {
  std::vector<std::pair<int, int>> pixels;
  for (const PixelWrite& write : writes)
    if (write.kept == kept) pixels.emplace_back(write.y, write.x);
  std::sort(pixels.begin(), pixels.end());
  pixels.erase(std::unique(pixels.begin(), pixels.end()), pixels.end());
  Json runs = Json::array();
  for (std::size_t i = 0; i < pixels.size();) {
    std::size_t end = i + 1;
    while (end < pixels.size() && pixels[end].first == pixels[i].first &&
           pixels[end].second == pixels[end - 1].second + 1)
      ++end;
    runs.push_back({pixels[i].first, pixels[i].second, pixels[end - 1].second});
    i = end;
  }
  return runs;
}

Json rayJson(const Scene& scene, const RayNode& ray, int index) {
  Json json = {{"index", index},
               {"kind", toString(ray.kind)},
               {"depth", ray.depth},
               {"parent", ray.parent},
               {"children", ray.children},
               {"origin", vector3(ray.origin)},
               {"direction", vector3(ray.direction)},
               {"weight", vector3(ray.weight)},
               {"contribution", vector3(ray.contribution)},
               {"color", vector3(ray.color)}};
  if (ray.kind == RayKind::Shadow) {
    json["light"] = ray.light;
    json["distance"] = ray.distance;
    json["transmittance"] = vector3(ray.transmittance);
    json["diffuse"] = vector3(ray.diffuse);
    json["specular"] = vector3(ray.specular);
    return json;
  }
  json["hit"] = ray.hit;
  if (!ray.hit) return json;
  json["object"] = ray.object;
  json["object_name"] = objectName(scene, ray.object);
  json["distance"] = ray.distance;
  json["point"] = vector3(ray.point);
  json["normal"] = vector3(ray.normal);
  json["uv"] = vector2(ray.uv);
  json["ambient"] = vector3(ray.ambient);
  return json;
}

Json treeJson(const Scene& scene, const RayTree& tree) {
  Json json = {
      {"sample", tree.sample}, {"raster", vector2(tree.raster)}, {"color", vector3(tree.color)}};
  if (tree.dimensions) {
    json["lens"] = vector2(tree.dimensions->lens);
    json["time"] = tree.dimensions->time;
    json["light"] = vector2(tree.dimensions->light);
    json["gloss"] = vector2(tree.dimensions->gloss);
  }
  Json rays = Json::array();
  for (std::size_t i = 0; i < tree.rays.size(); ++i)
    rays.push_back(rayJson(scene, tree.rays[i], static_cast<int>(i)));
  json["rays"] = std::move(rays);
  return json;
}

}  // namespace

std::string objectName(const Scene& scene, int object) {
  std::string name = "object " + std::to_string(object);
  if (object >= 0 && object < static_cast<int>(scene.shapeNames.size()))
    name += ", " + scene.shapeNames[static_cast<std::size_t>(object)];
  return name;
}

std::string stepJson(const Step& step, int index, const std::string& frame,
                     const std::string& depthFrame) {
  Json values = Json::object();
  for (const auto& [name, value] : step.values) values[name] = value;
  Json tables = Json::array();
  for (const StepTable& table : step.tables) {
    Json rows = Json::array();
    for (const std::vector<StepCell>& row : table.rows) {
      Json cells = Json::array();
      for (const StepCell& cell : row)
        std::visit([&](const auto& value) { cells.push_back(value); }, cell);
      rows.push_back(std::move(cells));
    }
    tables.push_back({{"title", table.title}, {"columns", table.columns}, {"rows", rows}});
  }
  Json settled = Json::array();
  for (const PixelRect& area : step.settled)
    settled.push_back({area.x0, area.y0, area.width(), area.height()});
  Json shapes = Json::array();
  for (const StepShape& shape : step.shapes) {
    Json points = Json::array();
    for (const Vec2& point : shape.points) points.push_back(vector2(point));
    shapes.push_back(
        {{"kind", shapeKindName(shape.kind)}, {"role", shape.role}, {"points", std::move(points)}});
  }
  Json kinds = Json::object();
  for (const auto& [kind, count] : step.soFar.kinds) kinds[kind] = count;
  const Json soFar = {{"kinds", std::move(kinds)},
                      {"painted", step.soFar.painted},
                      {"hidden", step.soFar.hidden},
                      {"settled", step.soFar.settled}};
  Json json = {{"index", index},
               {"kind", step.kind},
               {"text", step.text},
               {"skipped_before", step.skippedBefore},
               {"values", std::move(values)},
               {"tables", std::move(tables)},
               {"shapes", std::move(shapes)},
               {"painted", pixelRuns(step.writes, true)},
               {"hidden", pixelRuns(step.writes, false)},
               {"settled", std::move(settled)},
               {"so_far", soFar},
               {"frame", frame}};
  if (!depthFrame.empty()) json["depth_frame"] = depthFrame;
  return json.dump();
}

std::string stepsJson(const StepsHeader& header, const std::vector<std::string>& steps) {
  Json stats = Json::object();
  for (const auto& [name, value] : header.stats->entries()) stats[name] = value;
  Json json = {{"rise", "steps"},
               {"version", 1},
               {"scene", header.scene},
               {"algorithm", header.algorithm},
               {"width", header.width},
               {"height", header.height},
               {"every", header.every},
               {"region", nullptr},
               {"steps_recorded", header.stepsRecorded},
               {"steps_not_detailed", header.stepsNotDetailed},
               {"stats", std::move(stats)},
               {"buffers", header.buffers},
               {"steps", Json::array()}};
  if (header.region)
    json["region"] = {header.region->x0, header.region->y0, header.region->width(),
                      header.region->height()};
  // The steps are already JSON: splice them in rather than parse them again.
  std::string text = json.dump();
  text.replace(text.rfind("[]"), 2, "[\n" + joined(steps, ",\n") + "\n]");
  return text;
}

std::string rayTreesJson(const Scene& scene, std::string_view algorithm,
                         const std::vector<RayTree>& trees, const Color& color) {
  Json samples = Json::array();
  for (const RayTree& tree : trees) samples.push_back(treeJson(scene, tree));
  Json json = {{"rise", "ray-tree"},
               {"version", 1},
               {"scene", scene.source},
               {"algorithm", algorithm},
               {"pixel", trees.empty() ? Json::array() : Json{trees[0].pixel.x, trees[0].pixel.y}},
               {"color", vector3(color)},
               {"samples", std::move(samples)}};
  return json.dump(2);
}

}  // namespace rise
