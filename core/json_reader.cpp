#include "core/json_reader.h"

#include "core/error.h"
#include "core/paths.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <memory>

namespace planet {

namespace {

std::string format_number(double v) { return fmt::format("{:g}", v); }

}  // namespace

JsonObject JsonObject::load(const std::filesystem::path& file) {
  check_readable_file(file);
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("{}: cannot open file", file.string()));
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(in, nullptr, true, /*ignore_comments=*/false);
  } catch (const nlohmann::json::exception& e) {
    // A syntax error (parse_error), or a number beyond a double's range
    // (out_of_range 406, "number overflow parsing '-2e308'").
    // nlohmann's message starts with "[json.exception.parse_error.101] parse error at line 3, ..."
    std::string what = e.what();
    auto bracket = what.find("] ");
    if (bracket != std::string::npos) what = what.substr(bracket + 2);
    throw InputError(fmt::format("{}: malformed JSON: {}", file.string(), what));
  }
  if (!document.is_object()) {
    throw InputError(fmt::format("{}: the top level must be a JSON object", file.string()));
  }
  auto kept = std::make_shared<const nlohmann::json>(std::move(document));
  return JsonObject(kept, *kept, file.string(), "");
}

JsonObject::JsonObject(const nlohmann::json& value, std::string file, std::string path)
    : JsonObject(nullptr, value, std::move(file), std::move(path)) {}

JsonObject::JsonObject(std::shared_ptr<const nlohmann::json> document, const nlohmann::json& value,
                       std::string file, std::string path)
    : document_(std::move(document)), value_(&value), file_(std::move(file)),
      path_(std::move(path)) {
  if (!value_->is_object()) fail("must be a JSON object");
}

std::string JsonObject::where(const std::string& key) const {
  if (path_.empty()) return key;
  if (key.empty()) return path_;
  return path_ + "." + key;
}

void JsonObject::fail(const std::string& key, const std::string& reason) const {
  throw InputError(fmt::format("{}: {}: {}", file_, where(key), reason));
}

void JsonObject::fail(const std::string& reason) const {
  if (path_.empty()) throw InputError(fmt::format("{}: {}", file_, reason));
  throw InputError(fmt::format("{}: {}: {}", file_, path_, reason));
}

bool JsonObject::has(const std::string& key) const { return value_->contains(key); }

const nlohmann::json& JsonObject::require(const std::string& key) {
  auto it = value_->find(key);
  if (it == value_->end()) fail(key, "missing");
  read_.insert(key);
  return *it;
}

const nlohmann::json& JsonObject::raw(const std::string& key) { return require(key); }

static double checked_number(const JsonObject& obj, const std::string& key, const nlohmann::json& v,
                             double min, double max) {
  if (!v.is_number()) obj.fail(key, "must be a number");
  double x = v.get<double>();
  if (!std::isfinite(x)) obj.fail(key, "must be finite");
  if (x < min || x > max) {
    obj.fail(key, fmt::format("{} is out of range [{}, {}]", format_number(x), format_number(min),
                              format_number(max)));
  }
  return x;
}

double JsonObject::number(const std::string& key, double min, double max) {
  return checked_number(*this, key, require(key), min, max);
}

double JsonObject::number_or(const std::string& key, double fallback, double min, double max) {
  return has(key) ? number(key, min, max) : fallback;
}

int JsonObject::integer(const std::string& key, int min, int max) {
  const auto& v = require(key);
  if (!v.is_number_integer()) fail(key, "must be a whole number");
  auto x = v.get<long long>();
  if (x < min || x > max) {
    fail(key, fmt::format("{} is out of range [{}, {}]", x, min, max));
  }
  return static_cast<int>(x);
}

int JsonObject::integer_or(const std::string& key, int fallback, int min, int max) {
  return has(key) ? integer(key, min, max) : fallback;
}

bool JsonObject::boolean_or(const std::string& key, bool fallback) {
  if (!has(key)) return fallback;
  const auto& v = require(key);
  if (!v.is_boolean()) fail(key, "must be true or false");
  return v.get<bool>();
}

std::string JsonObject::string(const std::string& key) {
  const auto& v = require(key);
  if (!v.is_string()) fail(key, "must be a string");
  return v.get<std::string>();
}

std::string JsonObject::string_or(const std::string& key, const std::string& fallback) {
  return has(key) ? string(key) : fallback;
}

std::vector<double> JsonObject::numbers(const std::string& key, size_t count, double min,
                                        double max) {
  const auto& v = require(key);
  if (!v.is_array() || v.size() != count) {
    fail(key, fmt::format("must be an array of {} numbers", count));
  }
  std::vector<double> out;
  for (size_t i = 0; i < count; ++i) {
    out.push_back(checked_number(*this, fmt::format("{}[{}]", key, i), v[i], min, max));
  }
  return out;
}

std::vector<double> JsonObject::number_list(const std::string& key, double min, double max) {
  const auto& v = require(key);
  if (!v.is_array() || v.empty()) fail(key, "must be a non-empty array of numbers");
  std::vector<double> out;
  for (size_t i = 0; i < v.size(); ++i) {
    out.push_back(checked_number(*this, fmt::format("{}[{}]", key, i), v[i], min, max));
  }
  return out;
}

JsonObject JsonObject::object(const std::string& key) {
  const auto& v = require(key);
  if (!v.is_object()) fail(key, "must be a JSON object");
  return JsonObject(document_, v, file_, where(key));
}

std::vector<JsonObject> JsonObject::objects(const std::string& key) {
  const auto& v = require(key);
  if (!v.is_array()) fail(key, "must be an array of objects");
  std::vector<JsonObject> out;
  for (size_t i = 0; i < v.size(); ++i) {
    if (!v[i].is_object()) fail(fmt::format("{}[{}]", key, i), "must be a JSON object");
    out.push_back(JsonObject(document_, v[i], file_, fmt::format("{}[{}]", where(key), i)));
  }
  return out;
}

void JsonObject::finish() const {
  for (const auto& [key, value] : value_->items()) {
    if (!read_.count(key)) fail(key, "unknown key");
  }
}

}  // namespace planet
