// The scene's materials while its objects are read: the list, in the order
// defined, and each material's place found by its name at once, however many
// the scene defines (a file of 100,000 objects naming 100,000 materials
// loads in time linear in its size).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "scene/material.hpp"

namespace rise {

class SceneMaterials {
 public:
  explicit SceneMaterials(std::vector<Material>& materials) : materials_(materials) {
    for (int i = 0; i < static_cast<int>(materials_.size()); ++i) byName_.try_emplace(name(i), i);
  }

  // The place of the first material of that name.
  std::optional<int> find(std::string_view name) const {
    const auto found = byName_.find(std::string(name));
    return found == byName_.end() ? std::nullopt : std::optional<int>(found->second);
  }

  // Adds a material made while reading (an MD2 model's skin), returning its place.
  int add(Material material) {
    materials_.push_back(std::move(material));
    const int added = static_cast<int>(materials_.size()) - 1;
    byName_.try_emplace(name(added), added);
    return added;
  }

  const Material& operator[](int i) const { return materials_[static_cast<std::size_t>(i)]; }
  bool empty() const { return materials_.empty(); }

  std::vector<std::string> names() const {
    std::vector<std::string> names;
    names.reserve(materials_.size());
    for (const Material& material : materials_) names.push_back(material.name);
    return names;
  }

 private:
  const std::string& name(int i) const { return materials_[static_cast<std::size_t>(i)].name; }

  std::vector<Material>& materials_;
  std::unordered_map<std::string, int> byName_;
};

}  // namespace rise
