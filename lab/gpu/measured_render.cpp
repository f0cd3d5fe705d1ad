#include "lab/gpu/measured_render.h"

#include "atmosphere/gpu/registry.h"
#include "core/error.h"
#include "core/image_io.h"
#include "render/frame.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace planet {

namespace {

struct Face {
  double heading_deg, pitch_deg;
};
constexpr std::array<Face, 5> kFaces = {
    {{0.0, 0.0}, {90.0, 0.0}, {180.0, 0.0}, {270.0, 0.0}, {0.0, 90.0}}};

// Where each measured direction is read: the face it is most central in,
// and its pixel coordinates there (continuous, rows top-down, pixel
// centres at .5).
struct Lookup {
  size_t face = 0;
  double x = 0, y = 0;
};

Scene face_scene(const MeasuredView& view, const Face& face) {
  ScenePlacement p = view.placement;
  p.heading_deg = face.heading_deg;
  p.pitch_deg = face.pitch_deg;
  Scene s = placed(view.scene, p);
  s.sun_dir_body = view.scene.sun_dir_body;
  return s;
}

std::vector<Lookup> lookups(const MeasuredView& view, const std::vector<Scene>& faces,
                            const Body& body, const AtmosphereModel& model) {
  std::vector<glm::dmat3> ndc_from_ray;
  for (const Scene& s : faces) {
    ndc_from_ray.push_back(glm::inverse(reference_view(s, body, model).ray_from_ndc));
  }
  std::vector<Lookup> out;
  for (const glm::dvec3& d : view.directions_atmo) {
    Lookup best;
    double best_extent = 2.0;
    for (size_t f = 0; f < faces.size(); ++f) {
      glm::dvec3 v = ndc_from_ray[f] * d;
      if (v.z <= 0.0) continue;
      glm::dvec2 ndc(v.x / v.z, v.y / v.z);
      double extent = std::max(std::abs(ndc.x), std::abs(ndc.y));
      if (extent < best_extent) {
        best_extent = extent;
        const Scene& s = faces[f];
        best = {f, 0.5 * (ndc.x + 1.0) * s.width, 0.5 * (1.0 - ndc.y) * s.height};
      }
    }
    if (best_extent > 1.0) {
      throw InputError(fmt::format("{}: a measured direction lies in no face of the cube",
                                   view.scene.name));
    }
    out.push_back(best);
  }
  return out;
}

// Bilinear, between the centres of the four nearest pixels.
glm::dvec3 bilinear(const ImageRGB& image, double x, double y) {
  double fx = std::clamp(x - 0.5, 0.0, double(image.width - 1));
  double fy = std::clamp(y - 0.5, 0.0, double(image.height - 1));
  int x0 = std::min(int(fx), image.width - 2), y0 = std::min(int(fy), image.height - 2);
  double tx = fx - x0, ty = fy - y0;
  auto at = [&](int px, int py) {
    const float* p = image.pixels.data() + 3 * (size_t(py) * size_t(image.width) + size_t(px));
    return glm::dvec3(p[0], p[1], p[2]);
  };
  return (1.0 - ty) * ((1.0 - tx) * at(x0, y0) + tx * at(x0 + 1, y0)) +
         ty * ((1.0 - tx) * at(x0, y0 + 1) + tx * at(x0 + 1, y0 + 1));
}

}  // namespace

std::vector<SkySpectra> technique_spectra(const std::string& technique,
                                          const std::vector<MeasuredView>& views,
                                          const std::function<void(int, int)>& on_progress) {
  if (views.empty()) return {};
  Body body = scene_body(views.front().scene);
  AtmosphereModel model = scene_atmosphere(views.front().scene, body);
  if (!model.spectrum) {
    throw InputError(fmt::format("{}: the atmosphere has no spectrum to compare with a measured one",
                                 body.file.string()));
  }
  size_t samples = model.spectrum->wavelengths_nm.size();
  int triples = int((samples + 2) / 3);

  std::vector<std::vector<Scene>> faces(views.size());
  std::vector<std::vector<Lookup>> where(views.size());
  for (size_t v = 0; v < views.size(); ++v) {
    for (const Face& f : kFaces) faces[v].push_back(face_scene(views[v], f));
    where[v] = lookups(views[v], faces[v], body, model);
  }
  std::vector<SkySpectra> out(views.size());
  for (size_t v = 0; v < views.size(); ++v) {
    out[v].radiance.assign(views[v].directions_atmo.size(), std::vector<double>(samples, 0.0));
  }

  const Scene& any = faces.front().front();
  FrameRenderer renderer(any.width, any.height);
  for (int t = 0; t < triples; ++t) {
    // The last triple repeats its last sample where the count is not a multiple of 3.
    std::array<size_t, 3> s;
    for (size_t c = 0; c < 3; ++c) s[c] = std::min(size_t(3 * t) + c, samples - 1);
    renderer.set_body(body, with_rgb_at_spectral_samples(model, s[0], s[1], s[2]),
                      make_technique(technique));
    for (size_t v = 0; v < views.size(); ++v) {
      std::vector<ImageRGB> images;
      for (const Scene& f : faces[v]) {
        renderer.render(f.camera, f.sun_dir_body, f.exposure);
        images.push_back(image_from_gl(f.width, f.height, renderer.read_hdr()));
      }
      for (size_t i = 0; i < where[v].size(); ++i) {
        const Lookup& l = where[v][i];
        glm::dvec3 rgb = bilinear(images[l.face], l.x, l.y);
        for (size_t c = 0; c < 3; ++c) out[v].radiance[i][s[c]] = rgb[int(c)];
      }
    }
    if (on_progress) on_progress(t + 1, triples);
  }
  return out;
}

}  // namespace planet
