// The one way to make the settings of a render: from the scene, which says
// the image's size and how its pixels are sampled, and from whatever a front
// end (the command line, the studio, a test, a benchmark) chooses over it.
// Adding a setting is one field of RenderSettings, with its default, and one
// option line in each front end that offers it.
#pragma once

#include <optional>
#include <stdexcept>

#include "render/render_settings.hpp"
#include "scene/scene.hpp"

namespace rise {

// What a front end may choose over the scene's own `image` block. A width or
// a height alone keeps the scene's aspect ratio; a sample count or a pattern
// alone is completed as chooseSampling (core/sampling.hpp) says.
struct ImageOverrides {
  std::optional<int> width;
  std::optional<int> height;
  std::optional<int> samples;
  std::optional<SamplePattern> pattern;
  std::optional<FilterKind> filter;
  std::optional<float> adaptiveThreshold;
};

// A render as a front end asks for it: every setting that is not the scene's
// (RenderSettings's defaults unless chosen), and its choices over the
// scene's. The width, height and sampling of `settings` are not read: they
// come from the scene and `image`.
struct RenderRequest {
  RenderSettings settings;
  ImageOverrides image;
};

// A request that cannot be rendered; the message says what is wrong and what
// was expected.
class SettingsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The settings for rendering `scene` as asked, the thread count resolved.
// Throws SettingsError.
RenderSettings settingsFor(const Scene& scene, const RenderRequest& request = {});

// The shadows of a comparison, `rise compare`'s and the studio's alike: each
// family at its best, the visible-surface algorithms with the shadows all of
// them draw.
inline constexpr ShadowMethod kComparedShadows = ShadowMethod::Map;

}  // namespace rise
