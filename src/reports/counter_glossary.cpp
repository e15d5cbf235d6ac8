#include "reports/counter_glossary.hpp"

#include <array>
#include <utility>

namespace rise {
namespace {

using Entry = std::pair<std::string_view, std::string_view>;

constexpr std::array kMeanings = {
    // Every algorithm
    Entry{"render_seconds", "the time the render took, in seconds"},
    Entry{"samples_per_pixel",
          "samples taken in each pixel (passes, for the visible-surface algorithms)"},
    // The projective pipeline of the visible-surface algorithms
    Entry{"polygons_in", "polygons of the tessellated scene"},
    Entry{"polygons_culled", "polygons facing away from the eye, left out (back-face culling)"},
    Entry{"polygons_outside_view", "polygons wholly outside the view volume"},
    Entry{"polygons_clipped", "polygons cut by the view volume's planes"},
    Entry{"polygons_drawn", "polygons left on the screen to draw"},
    Entry{"depth_tests", "depths compared at a pixel"},
    Entry{"pixels_written", "pixels set, the overwritten ones included"},
    Entry{"covered_pixels", "pixels showing a surface rather than the background"},
    Entry{"overdraw", "pixels written per covered pixel: 1 is each drawn once"},
    Entry{"transparent_blends", "transparent surfaces blended over a pixel"},
    Entry{"visible_surface_seconds",
          "of the render's time, the seconds spent finding the surface seen at each pixel"},
    Entry{"shading_seconds",
          "of the render's time, the seconds spent shading: the vertices or faces lit first "
          "(Gouraud's and flat shading), then each pixel, timed at one pixel in 31"},
    // Shadows of the visible-surface algorithms
    Entry{"shadow_map_texels", "texels of all the shadow maps"},
    Entry{"shadow_map_polygons", "polygons drawn into the shadow maps"},
    Entry{"shadow_map_seconds", "of the render's time, the seconds spent drawing the shadow maps"},
    Entry{"shadow_lookups", "points asked whether a light reaches them"},
    Entry{"shadow_tests", "depth comparisons in the shadow maps, one a filter texel"},
    Entry{"shadow_volume_faces", "faces of the shadow volumes"},
    Entry{"shadow_volume_polygons", "shadow-volume polygons on the screen"},
    Entry{"shadow_volume_seconds",
          "of the render's time, the seconds spent building the shadow volumes"},
    Entry{"eye_in_volumes", "shadow volumes the eye is inside"},
    Entry{"shadow_volume_tests", "shadow-volume faces tested at a pixel"},
    Entry{"shadow_volume_crossings", "shadow-volume faces found in front of a pixel's surface"},
    Entry{"shadowed_pixel_lights", "pairs of a pixel and a light it is in the shadow of"},
    // The z-buffer
    Entry{"z_buffer_bytes", "memory of the depth buffer"},
    Entry{"a_buffer_fragments", "transparent fragments added to the A-buffer's lists"},
    Entry{"a_buffer_fragments_cut", "fragments cut from a list by an opaque surface in front"},
    Entry{"a_buffer_most_fragments", "the longest fragment list of a pixel"},
    Entry{"a_buffer_bytes", "memory of the A-buffer's fragment lists"},
    // Depth sort
    Entry{"comparisons", "pairs of polygons compared"},
    Entry{"settled_by_depth", "comparisons settled by test 1: the depth extents"},
    Entry{"settled_by_x_extent", "comparisons settled by test 2: the x extents"},
    Entry{"settled_by_y_extent", "comparisons settled by test 3: the y extents"},
    Entry{"settled_by_behind_plane", "comparisons settled by test 4: P behind Q's plane"},
    Entry{"settled_by_front_of_plane", "comparisons settled by test 5: Q in front of P's plane"},
    Entry{"settled_by_projection", "comparisons settled by test 6: the projections"},
    Entry{"moves", "polygons moved before another in the order"},
    Entry{"splits", "polygons split along another's plane"},
    Entry{"unresolved_overlaps", "overlaps no split could undo, painted as sorted"},
    Entry{"polygons_painted", "polygons and pieces painted, back to front"},
    // Area subdivision
    Entry{"windows", "windows looked at"},
    Entry{"subdivisions", "windows cut into four"},
    Entry{"windows_empty", "windows settled as background (rule 1)"},
    Entry{"windows_one_polygon", "windows settled by one polygon alone (rule 2)"},
    Entry{"windows_surrounder_in_front",
          "windows filled by a surrounding polygon in front (rule 3)"},
    Entry{"windows_pixel", "windows of one pixel, settled by depth at its centre (rule 4)"},
    Entry{"classified_surrounding", "classifications of a polygon holding the whole window"},
    Entry{"classified_intersecting", "classifications of a polygon crossing the window's border"},
    Entry{"classified_contained", "classifications of a polygon inside the window"},
    Entry{"classified_disjoint", "classifications of a polygon outside the window"},
    // The scanline algorithm
    Entry{"edge_table_entries", "edges put in the edge tables"},
    Entry{"active_edges_per_scanline", "edges in the active edge list, on average over the rows"},
    Entry{"active_edges_max", "the longest active edge list"},
    Entry{"scanline_buffer_bytes", "memory of the one-row depth and face buffers"},
    // The ray tracers
    Entry{"rays", "rays traced, of every kind"},
    Entry{"primary_rays", "rays from the eye"},
    Entry{"shadow_rays", "rays from a surface towards a light"},
    Entry{"reflection_rays", "rays in the mirror direction"},
    Entry{"refraction_rays", "rays through a transparent surface"},
    Entry{"intersection_tests", "ray-primitive intersection tests"},
    Entry{"intersection_tests_per_ray", "intersection tests per ray: what the acceleration saves"},
    Entry{"nodes_visited", "acceleration-structure nodes a ray entered"},
    Entry{"nodes_visited_per_ray", "nodes entered per ray"},
    Entry{"accel_build_seconds", "seconds spent building the acceleration structure"},
    Entry{"bvh_subtrees_deferred", "BVH subtrees left to be built when a ray first enters them"},
    Entry{"bvh_subtrees_built", "deferred subtrees that rays came to, and were built"},
    Entry{"rays_per_second", "rays traced per second of the render"},
    // The hybrid
    Entry{"primary_rays_from_item_buffer",
          "pixels whose first hit the item buffer gave, no ray traced"},
    Entry{"fallback_pixels", "pixels whose first hit a primary ray had to find"},
    Entry{"fallback_pixels_outside_outline", "fallback pixels outside every polygon's outline"},
    Entry{"fallback_pixels_inside_outline",
          "fallback pixels on an outline, where the item buffer is unsure"},
    Entry{"item_buffer_tests", "exact-surface tests of the item buffer's first hits"},
    Entry{"pixels_spawning_rays", "pixels that trace rays after the first hit"},
    Entry{"pixels_spawning_reflection_or_refraction",
          "pixels that trace a reflected or refracted ray"},
    Entry{"item_buffer_seconds", "seconds of the item-buffer pass (scanline)"},
    Entry{"ray_pass_seconds", "seconds of the ray pass"},
    Entry{"intersection_tests_saved",
          "intersection tests fewer than the algorithm it is compared with"},
    // Path tracing
    Entry{"paths", "paths from the eye, one a sample"},
    Entry{"path_vertices", "surfaces the paths met, the rays that escaped included"},
    Entry{"vertices_per_path", "surfaces a path met, on average, the ray that escaped included"},
    Entry{"paths_escaped", "paths whose last ray left the scene, taking the background's light"},
    Entry{"emitter_shadow_rays", "shadow rays to points chosen on the emitting surfaces"},
    Entry{"roulette_terminations", "paths that Russian roulette ended"},
    Entry{"passes", "passes of a few samples a pixel that refined the image"},
    Entry{"noise",
          "the estimated noise left: the pixels' standard errors over the image's brightness"},
    Entry{"samples_per_second", "samples taken per second of the passes"},
    // Radiosity
    Entry{"patches", "surfaces the light was solved between, each one or more elements"},
    Entry{"elements", "triangles the surfaces were cut into, each showing one light"},
    Entry{"elements_cut",
          "elements cut into four where the direct light changes fast, or beside finer ones"},
    Entry{"form_factors", "form factors found: a number for every ordered pair of patches"},
    Entry{"visibility_rays",
          "rays between two patches, to find what blocks the light between them"},
    Entry{"hemicube_texels",
          "texels of the patches' hemicubes that showed another patch: its share of the form "
          "factor"},
    Entry{"shots", "shots of progressive refinement: a patch passing on its unshot light"},
    Entry{"sweeps", "sweeps of Gauss-Seidel over the equations"},
    Entry{"residual",
          "the light still to pass on (or still changing) over the sources': 0.01 is 1%"},
    Entry{"solve_seconds",
          "seconds spent meshing and solving, before the display: next to none where the last "
          "render's solution was drawn again"},
    // rise render --reference
    Entry{"reference_rmse",
          "the root mean square of the linear colours' differences from the reference image"},
    Entry{"reference_relative_error",
          "reference_rmse over the reference's own root mean square: 0.01 is an error of 1%"},
};

constexpr std::array kMeaningsByPrefix = {
    Entry{"pixels_differing_from_",
          "pixels that differ by more than 2 levels from the other's image"},
    Entry{"speedup_over_", "times faster than the other algorithm"},
    Entry{"paths_of_",
          "paths that met that many surfaces, the ray that escaped included: the histogram of "
          "the paths' lengths"},
};

}  // namespace

std::optional<std::string_view> counterMeaning(std::string_view name) {
  for (const auto& [counter, meaning] : kMeanings)
    if (counter == name) return meaning;
  for (const auto& [prefix, meaning] : kMeaningsByPrefix)
    if (name.starts_with(prefix)) return meaning;
  return std::nullopt;
}

}  // namespace rise
