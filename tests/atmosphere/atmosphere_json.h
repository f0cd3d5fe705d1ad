// A shipped body's "atmosphere" as JSON, for tests that edit one value and
// read the model's verdict.
#pragma once

#include "atmosphere/model.h"
#include "core/data_paths.h"
#include "core/error.h"
#include "core/json_reader.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <functional>
#include <string>

namespace planet {

// data/planets/<body>.json's "atmosphere".
inline nlohmann::json shipped_atmosphere(const std::string& body) {
  std::ifstream in(data_dir() / "planets" / (body + ".json"));
  return nlohmann::json::parse(in)["atmosphere"];
}

// Parses `a` as if it were `file`'s "atmosphere" (the name errors give).
inline AtmosphereModel parse_atmosphere_json(const nlohmann::json& a, const std::string& file) {
  return parse_atmosphere(JsonObject(a, file, "atmosphere"));
}

// Parses `body`'s atmosphere changed by `edit` (as `file`) and returns the
// error message, or "(no error)".
inline std::string atmosphere_error_after(const std::string& body, const std::string& file,
                                          const std::function<void(nlohmann::json&)>& edit) {
  nlohmann::json a = shipped_atmosphere(body);
  edit(a);
  try {
    parse_atmosphere_json(a, file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace planet
