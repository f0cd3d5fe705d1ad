#include "atmosphere/gpu/technique.h"

#include "atmosphere/gpu/hillaire/hillaire_technique.h"
#include "atmosphere/gpu/raymarch/raymarch_technique.h"
#include "core/error.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace planet {

std::vector<std::string> technique_names() { return {"raymarch", "hillaire", "hillaire2020"}; }

std::unique_ptr<AtmosphereTechnique> make_technique(const std::string& name) {
  if (name == "raymarch") return std::make_unique<RaymarchTechnique>();
  if (name == "hillaire") return std::make_unique<HillaireTechnique>();
  if (name == "hillaire2020") {
    HillaireTechnique::Settings settings;
    settings.multiple_scattering = HillaireTechnique::MultipleScattering::kPaper;
    return std::make_unique<HillaireTechnique>(settings);
  }
  throw InputError(fmt::format("unknown atmosphere technique '{}' (available: {})", name,
                               fmt::join(technique_names(), ", ")));
}

}  // namespace planet
