#pragma once
// Draws a body's quadtree terrain: selects tiles for the camera, mirrors
// the cache's tiles into GL buffers, and draws each tile placed by its
// centre minus the camera, formed in double here every frame, so that no
// double reaches the GPU and vertices stay still to well under a pixel
// from 1 m above the ground to 1e8 m away.
#include "terrain/lod.h"
#include "terrain/tile_cache.h"

#include "gl/program.h"
#include "gl/texture.h"
#include "sim/body.h"
#include "sim/camera.h"

#include <limits>
#include <memory>
#include <unordered_map>

namespace planet {

struct TerrainOptions {
  double pixel_budget = 1.0;
  size_t cache_bytes = size_t(256) << 20;  // tiles resident, CPU and GPU copies alike
  int workers = 1;
};

struct TerrainStats {
  int tiles_drawn = 0;
  int64_t triangles = 0;
  size_t tiles_resident = 0, bytes_resident = 0;
  size_t tiles_on_gpu = 0;  // of the resident, those with their GL buffer (one each)
  int tiles_wanted = 0;     // wanted but not resident when drawn
  double max_error_px = 0;  // largest projected error bound of a drawn tile
  int max_level = 0;
  // No drawn tile is nearer to the eye than this (the distance to its
  // bounding sphere), metres; +inf when none was drawn.
  double nearest_m = std::numeric_limits<double>::infinity();
};

// What the terrain's shading needs from the frame: the sun and the
// atmosphere (uniform block bound by the caller) in atmosphere space.
struct TerrainLighting {
  glm::dvec3 sun_dir_body{0, 0, 1};
  bool has_atmosphere = false;
  glm::dvec3 atmo_scale{1.0};
  glm::vec3 solar_irradiance{1.0f};
  // The sky's irradiance on the ground from the atmosphere technique
  // (AtmosphereTechnique::ground_irradiance), or 0: then a one-bounce
  // estimate of the shader's own.
  GLuint sky_irradiance = 0;
  // False: the ground is lit by the sun alone, as in single scattering
  // (the sky's light on it is the second order).
  bool sky_light = true;
  // The terrain's shadows from the sun (its horizons, terrain/horizon.h),
  // and the sun's angular radius, which softens their edges.
  bool shadows = true;
  double sun_angular_radius = 0.00465;
  // The Moon before the sun (an eclipse): its centre in the body frame and
  // its radius, metres (0: none). The sun's light on the ground is then the
  // visible share of its disk there (occluded_sun.glsl).
  glm::dvec3 moon_pos_body{0.0};
  double moon_radius = 0;
};

class TerrainRenderer {
 public:
  // Needs a current GL context. Reads the body's terrain block.
  TerrainRenderer(const Body& body, const TerrainOptions& options);
  ~TerrainRenderer();

  // Draws into the bound framebuffer, depth test as set by the caller.
  // With a `coverage` framebuffer (multisampled, cleared by the caller) the
  // same tiles are drawn into it first without light (terrain_coverage.frag:
  // depth, and the ground below the datum at location 0), so that the
  // lighting runs once a pixel in the bound one and the coverage is
  // counted per sample (render/surface_antialiasing.h).
  TerrainStats draw(const Camera& camera, int width, int height, const TerrainLighting& lighting,
                    GLuint coverage = 0);

  // Waits until every tile this view needs is resident (capture). Throws
  // SystemError naming the missing tiles after `timeout_s`.
  void wait_until_complete(const Camera& camera, int width, int height, double timeout_s);

  void set_pixel_budget(double px) { options_.pixel_budget = px; }
  const TerrainSurface& surface() const { return *surface_; }
  const TileCache& cache() const { return *cache_; }

  static LodView lod_view(const Camera& camera, int width, int height, double pixel_budget);

 private:
  struct GpuTile;
  // The uniforms of `program` that every tile shares.
  void set_uniforms(const Program& program, const Camera& camera, const LodView& view, int width,
                    int height, const TerrainLighting& lighting);
  // Draws `tiles` with `program` (bound), nearest first.
  void draw_tiles(const Program& program, const Camera& camera,
                  const std::vector<std::pair<const SelectedTile*, const GpuTile*>>& tiles);

  struct GpuTile {
    Buffer vertices;
    glm::dvec3 center_body;
    glm::vec3 axis_i, axis_j;  // TileMesh's
  };

  TerrainOptions options_;
  std::unique_ptr<TerrainSurface> surface_;
  std::unique_ptr<TileCache> cache_;
  LodSelector selector_;
  // The lit surfaces (terrain.frag), and their coverage alone
  // (terrain_coverage.frag), made on the first draw that asks for it.
  Program program_, coverage_program_;
  Buffer indices_;
  VertexArray vao_;
  // The body's day and night imagery (TerrainConfig::maps), mipmapped;
  // 0 where it has none.
  Texture day_map_, night_map_;
  std::unordered_map<TileKey, GpuTile, TileKeyHash> gpu_tiles_;
  uint64_t frame_ = 0;
};

}  // namespace planet
