// Earth's ground materials by rule, written once in the common subset of
// GLSL and C++-with-GLM (as sea_brdf.glsl is): terrain.frag includes it in
// float for the day image's far field, terrain/ground_material.cpp compiles
// it in double for the tiles' vertices and the tests. The including side
// defines Real and Real3. See docs/surfaces.md#materials.
//
// Each material's albedo is an RGB whose mean is the broadband albedo of
// its kind in Oke 1987 (Boundary Layer Climates, 2nd ed., table 1.1) or,
// for rock, in the ASTER spectral library (Baldridge et al. 2009, Remote
// Sens. Environ. 113, 711): granite and limestone 0.2 to 0.35 in the
// visible.

// Fresh snow, 0.80-0.95 (Oke): mean 0.867, bluish as snow is in the visible.
const Real3 kSnowAlbedo = Real3(0.84, 0.86, 0.90);
// Bare rock and scree, granite and limestone (ASTER): mean 0.247.
const Real3 kRockAlbedo = Real3(0.27, 0.25, 0.22);
// Coniferous and tropical forest, 0.05-0.15 (Oke): mean 0.090.
const Real3 kForestAlbedo = Real3(0.08, 0.12, 0.07);
// Grass, crops and steppe, 0.16-0.26 (Oke): mean 0.203.
const Real3 kGrassAlbedo = Real3(0.19, 0.28, 0.14);
// Sand desert, 0.20-0.45 (Oke): mean 0.343.
const Real3 kDesertAlbedo = Real3(0.45, 0.35, 0.23);

// The shares of each material at a point of land, summing to 1, and their
// albedo.
struct GroundMaterial {
  Real snow;
  Real rock;
  Real forest;
  Real grass;
  Real desert;
  Real3 albedo;
};

// Earth's climatic snow line against |latitude| (radians), metres above the
// sea: linear between the levels tabulated in Wikipedia's "Snow line"
// (climatic snow lines, from Wilhelmy's Geomorphologie): about 4700 m at
// the equator, highest in the dry subtropics (5300 m at 25 deg: the
// Himalaya's 5700 m, the Andes' 5000 m), 2800 m in the Alps at 47 deg
// (2500-3200 m), 1700 m in southern Scandinavia at 62 deg (1200-2200 m),
// 1250 m at the polar circle (1000-1500 m), 450 m on Svalbard at 78 deg
// (300-600 m), the sea at the poles.
Real earth_snow_line(Real latitude) {
  Real deg = abs(latitude) * Real(57.29577951308232);
  if (deg < Real(25.0)) return mix(Real(4700.0), Real(5300.0), deg / Real(25.0));
  if (deg < Real(47.0)) return mix(Real(5300.0), Real(2800.0), (deg - Real(25.0)) / Real(22.0));
  if (deg < Real(62.0)) return mix(Real(2800.0), Real(1700.0), (deg - Real(47.0)) / Real(15.0));
  if (deg < Real(67.0)) return mix(Real(1700.0), Real(1250.0), (deg - Real(62.0)) / Real(5.0));
  if (deg < Real(78.0)) return mix(Real(1250.0), Real(450.0), (deg - Real(67.0)) / Real(11.0));
  return mix(Real(450.0), Real(0.0), min((deg - Real(78.0)) / Real(12.0), Real(1.0)));
}

// What the day image's colour (display sRGB in [0, 1]) says the land is:
// its white is snow and ice; of the rest, green over red is vegetation
// (dark: forest, light: grass), and the bright red-yellow of the Sahara or
// Arabia is sand. The dull yellow-browns between (Kansas, India, the
// steppes) are counted as grass, dry or cropped, which is what they are.
GroundMaterial image_material(Real3 c) {
  GroundMaterial m;
  Real mean = (c.r + c.g + c.b) / Real(3.0);
  m.snow = smoothstep(Real(0.75), Real(0.9), min(c.r, min(c.g, c.b)));
  Real vegetation = smoothstep(Real(-0.02), Real(0.06), c.g - c.r);
  Real forest = vegetation * (Real(1.0) - smoothstep(Real(0.14), Real(0.26), mean));
  Real desert = (Real(1.0) - vegetation) * smoothstep(Real(0.45), Real(0.75), mean);
  m.rock = Real(0.0);
  m.forest = (Real(1.0) - m.snow) * forest;
  m.desert = (Real(1.0) - m.snow) * desert;
  m.grass = (Real(1.0) - m.snow) * (Real(1.0) - forest - desert);
  m.albedo = m.snow * kSnowAlbedo + m.forest * kForestAlbedo + m.grass * kGrassAlbedo +
             m.desert * kDesertAlbedo;
  return m;
}

// The share of rock that the slope and the height lay bare. `slope`:
// 1 - cos of the ground's tilt. Soil and plants give way from 30 deg
// (0.134), near scree's angle of repose, and are gone by 45 deg (0.293);
// above the tree line, some 900 m below the snow line in the Alps (2000
// m against 2900 m), alpine ground is most of it scree and rock.
Real rock_share(Real slope, Real height, Real snow_line) {
  Real steep = smoothstep(Real(0.134), Real(0.293), slope);
  Real alpine = Real(0.7) * smoothstep(snow_line - Real(1000.0), snow_line - Real(300.0), height);
  return max(steep, alpine);
}

// The share of snow that lies above the snow line, on slopes it does not
// slide off (it holds to 40 deg, 0.234, and is gone by 55 deg, 0.426).
Real snow_share(Real slope, Real height, Real snow_line) {
  return smoothstep(snow_line - Real(150.0), snow_line + Real(150.0), height) *
         (Real(1.0) - smoothstep(Real(0.234), Real(0.426), slope));
}

// The ground's material at a point of land: rock where the slope or the
// height lays it bare, snow above the snow line, and where neither, what
// the day image's colour `c` says (`has_image` 0: no image, then grass and
// forest in equal shares). `height`: metres above the sea; `latitude`:
// geodetic, radians.
GroundMaterial ground_material(Real slope, Real height, Real latitude, Real3 c, bool has_image) {
  GroundMaterial m;
  if (has_image) {
    m = image_material(c);
  } else {
    m.snow = Real(0.0);
    m.rock = Real(0.0);
    m.forest = Real(0.5);
    m.grass = Real(0.5);
    m.desert = Real(0.0);
  }
  Real line = earth_snow_line(latitude);
  Real snow = snow_share(slope, height, line);
  Real rock = (Real(1.0) - snow) * rock_share(slope, height, line);
  // What the rules leave to the image: its snow (the ice caps) stays.
  Real rest = Real(1.0) - snow - rock;
  m.snow = snow + rest * m.snow;
  m.rock = rock;
  m.forest *= rest;
  m.grass *= rest;
  m.desert *= rest;
  m.albedo = m.snow * kSnowAlbedo + m.rock * kRockAlbedo + m.forest * kForestAlbedo +
             m.grass * kGrassAlbedo + m.desert * kDesertAlbedo;
  return m;
}

// How much of a land point's colour the day image can give, in [0, 1]:
// all of it but where the rules' rock and snow show (which its 20 km
// pixels do not resolve). terrain.frag mixes the image's materials in by
// this beyond the distance at which the image takes over.
Real ground_image_cover(Real slope, Real height, Real latitude) {
  Real line = earth_snow_line(latitude);
  Real snow = snow_share(slope, height, line);
  return (Real(1.0) - snow) * (Real(1.0) - rock_share(slope, height, line));
}
