#pragma once
// A GPU technique's spectral radiance in the measured directions
// (measured_comparison.h). A technique draws three wavelengths, its RGB
// channels; the model's spectral samples are drawn three at a time, each
// triple through a model whose RGB coefficients are the spectrum's at
// those wavelengths (with_rgb_at_spectral_samples), as Bruneton 2017
// renders a full spectrum. Each triple draws five faces of a cube about
// the camera (north, east, south and west at the horizon, and the zenith;
// 90 degrees, 96 px a side), in which every measured direction lies, and
// reads each direction bilinearly from the face it is most central in.
// Needs a current GL context.
#include "lab/measured_comparison.h"

#include <functional>
#include <string>
#include <vector>

namespace planet {

// One SkySpectra per view, at every spectral sample of the views' model
// (they share their body). on_progress(done) counts triples.
std::vector<SkySpectra> technique_spectra(const std::string& technique,
                                          const std::vector<MeasuredView>& views,
                                          const std::function<void(int, int)>& on_progress = {});

}  // namespace planet
