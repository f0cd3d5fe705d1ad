// The cloud layer's density field (the shared cloud math, see
// cloud_definitions.glsl): deterministic procedural weather, cumulus and
// stratus profiles, a shape noise and an erosion of its edges, after
// Schneider and Vos 2015 ("The real-time volumetric cloudscapes of Horizon
// Zero Dawn") and Hillaire 2016, written with arithmetic noise instead of
// their noise textures. Positions are planet-centred, in metres.

// x remapped from [lo, 1] to [0, 1], clamped.
Real cloud_remap(Real x, Real lo) {
  return clamp((x - lo) / max(Real(1.0) - lo, Real(1e-3)), Real(0.0), Real(1.0));
}

// The weather at a point, the same along each vertical: x the local cover
// (0 clear, 1 overcast), y the cloud type (0 stratus, 1 cumulus). A
// field's mean value is 1/2, shifted by the layer's cover and share.
Real2 cloud_weather(IN(CloudLayer) layer, Real3 p) {
  Real3 q = normalize(p) * (layer.top_radius / layer.weather_scale);
  uint seed = uint(layer.seed);
  Real w = cloud_fbm(q, seed, 3);
  Real t = cloud_fbm(q * Real(0.5) + Real3(17.0, 3.0, 11.0), seed + 1000u, 2);
  Real cover = clamp((w - Real(0.5)) * Real(4.0) + (layer.coverage - Real(0.5)) * Real(3.0) +
                         Real(0.5),
                     Real(0.0), Real(1.0));
  Real type = clamp((t - Real(0.5)) * Real(4.0) + (layer.cumulus_share - Real(0.5)) * Real(3.0) +
                        Real(0.5),
                    Real(0.0), Real(1.0));
  return Real2(cover, type);
}

// The fraction of the layer's height a cloud of the type fills, by height
// h in [0, 1] from the base: stratus a flat sheet in the lowest fifth,
// cumulus a rounded tower over the whole depth.
Real cloud_height_profile(Real h, Real type) {
  Real stratus = smoothstep(Real(0.0), Real(0.04), h) * (Real(1.0) - smoothstep(Real(0.12), Real(0.22), h));
  Real cumulus = smoothstep(Real(0.0), Real(0.08), h) * (Real(1.0) - smoothstep(Real(0.45), Real(1.0), h));
  return mix(stratus, cumulus, type);
}

// The density of the clouds' shapes in [0, 1] at a point under the
// weather there (cloud_weather), before erosion: what a march toward the
// sun may take over its few kilometres, where the weather does not change.
Real cloud_shape_density(IN(CloudLayer) layer, Real3 p, Real2 weather) {
  Real r = length(p);
  if (r <= layer.bottom_radius || r >= layer.top_radius) return Real(0.0);
  Real h = (r - layer.bottom_radius) / (layer.top_radius - layer.bottom_radius);
  Real fill = weather.x * cloud_height_profile(h, weather.y);
  if (fill <= Real(0.0)) return Real(0.0);
  Real shape = cloud_fbm(p / layer.shape_scale, uint(layer.seed) + 2000u, 3);
  return cloud_remap(shape, Real(1.0) - fill);
}

// A shape's density eroded at its edges by the finer noise.
Real cloud_eroded_density(IN(CloudLayer) layer, Real3 p, Real shape_density) {
  if (shape_density <= Real(0.0) || layer.erosion <= Real(0.0)) return shape_density;
  Real e = cloud_fbm(p / layer.erosion_scale, uint(layer.seed) + 3000u, 2);
  return cloud_remap(shape_density, layer.erosion * e);
}

// Density in [0, 1] (extinction over the layer's `extinction`) at a point.
Real cloud_density(IN(CloudLayer) layer, Real3 p) {
  Real r = length(p);
  if (r <= layer.bottom_radius || r >= layer.top_radius) return Real(0.0);
  return cloud_eroded_density(layer, p, cloud_shape_density(layer, p, cloud_weather(layer, p)));
}

// Extinction (1/m) at a point.
Real cloud_extinction(IN(CloudLayer) layer, Real3 p) {
  return layer.extinction * cloud_density(layer, p);
}
